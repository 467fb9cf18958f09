"""Rays, shapes, all hits along a ray and the exact oracle from Python."""

import math

import pytest

import raylab


def test01_a_ray_hits_a_unit_sphere_at_distance_four():
    sphere = raylab.Sphere((0, 0, 0), 1.0)
    ray = raylab.Ray((0, 0, 5), (0, 0, -2))  # normalised
    assert ray.direction == (0.0, 0.0, -1.0)
    hit = sphere.intersect(ray)
    assert hit.t == pytest.approx(4.0, abs=1e-12)
    surface = sphere.closest_hit(ray)
    assert surface.point == pytest.approx((0, 0, 1))
    assert surface.normal == pytest.approx((0, 0, 1))
    assert surface.front_face


def test02_all_hits_enter_then_leave():
    sphere = raylab.Sphere((0, 0, 0), 1.0)
    crossings = sphere.intersect_all(raylab.Ray((0, 0, 5), (0, 0, -1)))
    assert [c.entering for c in crossings] == [True, False]
    assert [c.t for c in crossings] == pytest.approx([4.0, 6.0])
    box = raylab.Box((0, 0, 0), (2, 2, 2))
    assert [c.entering for c in box.intersect_all(raylab.Ray((-5, 0, 0), (1, 0, 0)))] == [True, False]


def test03_a_miss_is_none_for_doubles_and_the_oracle():
    sphere = raylab.Sphere((0, 0, 0), 1.0)
    ray = raylab.Ray((0, 3, 5), (0, 0, -1))
    assert sphere.intersect(ray) is None
    assert raylab.exact_classify(sphere, ray).classification == "Miss"


def test04_the_oracle_gives_the_exact_hit_beside_the_double_one():
    sphere = raylab.Sphere((0.1, 0.2, 0.3), 0.7)
    ray = raylab.Ray((0.3, -0.1, 4.0), (-0.05, 0.1, -1.0))
    compared = raylab.oracle_compare(sphere, ray)
    assert compared.agree
    assert compared.exact.classification == "Hit"
    assert compared.exact.t_lower <= compared.exact.t <= compared.exact.t_upper
    assert compared.floating.t == pytest.approx(compared.exact.t, rel=1e-12)
    assert compared.t_error_ulps < 8


def test05_the_oracle_sees_tangents_and_edges_exactly():
    sphere = raylab.Sphere((0, 0, 0), 1.0)
    assert raylab.exact_classify(sphere, raylab.Ray((1, 0, 5), (0, 0, -1))).classification == "Tangent"
    triangle = raylab.Triangle((0, 0, 0), (1, 0, 0), (0, 1, 0))
    through_edge = raylab.Ray((0.5, 0.0, 1.0), (0, 0, -1))
    assert raylab.exact_classify(triangle, through_edge).classification == "ThroughEdge"
    corner = raylab.Ray((0.0, 0.0, 1.0), (0, 0, -1))
    assert raylab.exact_classify(triangle, corner).classification == "ThroughVertex"


def test06_the_scene_intersect_meets_what_the_camera_ray_met():
    scene = raylab.default_scene()
    trace = raylab.trace(scene, (160, 120), algorithm="whitted")
    camera_ray = trace[0]
    hit = scene.intersect(raylab.Ray(camera_ray.origin, camera_ray.direction))
    assert hit["object"] == camera_ray.object
    assert hit["name"] == camera_ray.object_name
    assert hit["surface"].point == pytest.approx(camera_ray.end_point, abs=1e-9)


def test07_scene_shapes_are_copies_for_the_oracle():
    scene = raylab.default_scene()
    shape = scene.shape("red sphere")
    assert shape.kind == "sphere" and isinstance(shape, raylab.Sphere)
    lower, upper = shape.bounds()
    centre = [(a + b) / 2 for a, b in zip(lower, upper)]
    ray = raylab.Ray((centre[0], centre[1], centre[2] + 10), (0, 0, -1))
    assert raylab.exact_classify(shape, ray).hit
    shape.apply([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]])
    assert scene.shape("red sphere").bounds() == (lower, upper)  # the scene's is unchanged


def test08_bad_geometry_raises():
    with pytest.raises(raylab.GeometryError):
        raylab.Sphere((0, 0, 0), -1.0)
    with pytest.raises(ValueError):
        raylab.Ray((0, 0, 0), (0, 0, 0))
    with pytest.raises(TypeError):
        raylab.Ray((0, 0), (0, 0, 1))


def test09_a_mesh_is_hit_through_its_bvh_and_by_the_oracle():
    mesh = raylab.TriangleMesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2), (0, 2, 3)])
    ray = raylab.Ray((0.25, 0.75, 1), (0, 0, -1))
    assert mesh.intersect(ray).t == pytest.approx(1.0)
    assert raylab.exact_classify(mesh, ray).t == 1.0
    assert math.isclose(mesh.area(), 1.0)
