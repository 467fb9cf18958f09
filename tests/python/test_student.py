"""raylab.student (issue 35): a student's functions run inside the engine and are judged."""

import inspect
import math
import time

import numpy as np
import pytest

import raylab
import raylab.student as student


def good_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = np.dot(oc, direction)
    disc = b * b - (np.dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    s = math.sqrt(disc)
    for t in (-b - s, -b + s):
        if t_min <= t <= t_max:
            return t
    return None


def far_root_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = np.dot(oc, direction)
    disc = b * b - (np.dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    t = -b + math.sqrt(disc)
    return t if t_min <= t <= t_max else None


@pytest.fixture(autouse=True)
def _reset():
    yield
    student.use()


def _sphere_pixel(scene):
    width, height = scene.size
    for y in range(0, height, 6):
        for x in range(0, width, 6):
            t = raylab.trace(scene, (x, y), algorithm="path", spp=1)
            if t.segments[0].object_name == "red sphere":
                return x, y
    raise AssertionError("no pixel sees the red sphere")


def test_01_every_piece_has_a_bilingual_docstring_and_the_course_signature():
    assert len(student.PIECES) >= 13
    for name, (params, _, en, zh) in student.PIECES.items():
        fn = getattr(student, name)
        assert en in fn.__doc__ and zh in fn.__doc__
        assert any("\u4e00" <= ch <= "\u9fff" for ch in zh), name
        assert tuple(inspect.signature(fn).parameters) == params
        with pytest.raises(NotImplementedError, match=name):
            fn(*range(len(params)))


def test_02_a_correct_sphere_gives_the_engines_tree():
    scene = raylab.default_scene()
    pixel = _sphere_pixel(scene)
    student.use(intersect_sphere=good_sphere)
    t = student.trace(scene, pixel, algorithm="path", spp=1)
    assert t.passes and t.first_divergent == -1
    assert len(t.student.segments) == len(t.reference.segments)
    assert t.verdicts[0] == "agrees"
    assert np.allclose(t.student.estimate, t.reference.estimate, atol=1e-9)
    assert any(c["piece"] == "intersect_sphere" for c in t.calls)


def test_03_the_wrong_root_is_named_on_the_first_ray_with_both_values():
    scene = raylab.default_scene()
    pixel = _sphere_pixel(scene)
    student.use(intersect_sphere=far_root_sphere)
    t = student.trace(scene, pixel, algorithm="path", spp=1)
    assert not t.passes
    assert t.first_divergent == 0 and t.verdicts[0] == "wrong_hit"
    call = t.calls[t.deciding_calls[0]]
    assert call["student"] > call["reference"] > 0


def test_04_exceptions_and_bad_types_are_verdicts_not_crashes():
    scene = raylab.default_scene()
    pixel = _sphere_pixel(scene)

    def raises(origin, direction, center, radius, t_min, t_max):
        return 1 / 0

    student.use(intersect_sphere=raises)
    t = student.trace(scene, pixel, algorithm="path", spp=1)
    assert t.verdicts[0] == "exception"
    error = t.calls[t.deciding_calls[0]]["error"]
    assert "ZeroDivisionError" in error and "test_student.py" in error and "line" in error
    student.use(intersect_sphere=lambda o, d, c, r, t0, t1: "far")
    t = student.trace(scene, pixel, algorithm="path", spp=1)
    assert t.verdicts[0] == "exception"
    assert "expected a float t or None" in t.calls[t.deciding_calls[0]]["error"]


def test_05_a_wrong_signature_names_the_file_line_and_the_expected_one():
    def two(origin, direction):
        return None

    with pytest.raises(student.StudentCodeError) as info:
        student.use(intersect_sphere=two)
    text = str(info.value)
    assert "test_student.py, line" in text
    assert "intersect_sphere(origin, direction, center, radius, t_min, t_max)" in text
    assert "参数" in text
    with pytest.raises(student.StudentCodeError, match="unknown piece"):
        student.use(intersect_spheres=good_sphere)


def test_06_render_160x120_with_a_student_sphere_in_seconds():
    scene = raylab.default_scene()
    scene.set_camera(width=160, height=120)
    student.use(intersect_sphere=good_sphere)
    start = time.perf_counter()
    image = student.render(scene, algorithm="whitted", spp=1, threads=1)
    seconds = time.perf_counter() - start
    reference = raylab.render(scene, algorithm="whitted", spp=1, threads=1)
    assert image.shape == reference.shape
    assert np.abs(image - reference).max() < 1e-4
    print("student render %dx%d: %.2f s" % (image.shape[1], image.shape[0], seconds))
    student.use(intersect_sphere=far_root_sphere)
    wrong = student.render(scene, algorithm="whitted", spp=1, threads=2)
    assert np.abs(wrong - reference).max() > 0.05


def good_plane(origin, direction, point, normal, t_min, t_max):
    denom = np.dot(direction, normal)
    if denom == 0:
        return None
    t = np.dot(point - origin, normal) / denom
    return t if t_min <= t <= t_max else None


def good_box(origin, direction, box_min, box_max, t_min, t_max):
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (box_min - origin) / direction
        t1 = (box_max - origin) / direction
    near = np.nanmax(np.minimum(t0, t1))
    far = np.nanmin(np.maximum(t0, t1))
    if near > far:
        return None
    for t in (near, far):
        if t_min <= t <= t_max:
            return float(t)
    return None


def good_triangle(origin, direction, v0, v1, v2, t_min, t_max):
    e1, e2 = v1 - v0, v2 - v0
    p = np.cross(direction, e2)
    det = np.dot(e1, p)
    if det == 0:
        return None
    s = origin - v0
    u = np.dot(s, p) / det
    q = np.cross(s, e1)
    v = np.dot(direction, q) / det
    if u < 0 or v < 0 or u + v > 1:
        return None
    t = np.dot(e2, q) / det
    return t if t_min <= t <= t_max else None


GOOD = {"intersect_sphere": good_sphere, "intersect_plane": good_plane,
        "intersect_box": good_box, "intersect_triangle": good_triangle}


@pytest.mark.parametrize("piece", sorted(student.GEOMETRY))
def test_07_judge_geometry_cases_against_the_oracle(piece):
    result = student.judge(piece, GOOD[piece])
    assert result["passes"], [c for c in result["cases"] if c["verdict"] != "agrees"]
    names = {c["case"] for c in result["cases"]}
    assert "huge scale" in names and "tiny scale" in names


def test_08_judge_names_a_missed_and_a_wrong_hit():
    result = student.judge("intersect_sphere", far_root_sphere)
    verdicts = {c["case"]: c["verdict"] for c in result["cases"]}
    assert not result["passes"]
    assert verdicts["front hit"] == "wrong_hit"
    assert verdicts["from inside"] == "agrees"
    result = student.judge("intersect_sphere", lambda o, d, c, r, t0, t1: None)
    assert {c["case"]: c["verdict"] for c in result["cases"]}["front hit"] == "missed_hit"


def test_09_judge_optics_and_the_sampler():
    def reflect(d, n):
        return d - 2 * np.dot(d, n) * n

    def refract(d, n, eta):
        c = -np.dot(d, n)
        k = 1 - eta * eta * (1 - c * c)
        return None if k < 0 else eta * d + (eta * c - math.sqrt(k)) * n

    def sample(u1, u2):
        r, phi = math.sqrt(u1), 2 * math.pi * u2
        z = math.sqrt(max(0.0, 1 - u1))
        return np.array([r * math.cos(phi), r * math.sin(phi), z]), z / math.pi

    def uniform(u1, u2):  # the uniform hemisphere: a typical mistake
        z, phi = u1, 2 * math.pi * u2
        r = math.sqrt(max(0.0, 1 - z * z))
        return np.array([r * math.cos(phi), r * math.sin(phi), z]), z / math.pi

    assert student.judge("reflect", reflect)["passes"]
    assert student.judge("refract", refract)["passes"]
    inverted = student.judge("refract", lambda d, n, eta: refract(d, n, 1 / eta))
    assert not inverted["passes"]
    assert student.judge("sample_cosine_hemisphere", sample)["passes"]
    wrong = student.judge("sample_cosine_hemisphere", uniform)
    assert not wrong["passes"]
    assert any("chi-squared" in c["case"] and c["verdict"] == "differs" for c in wrong["cases"])
    assert student.judge("lambert", lambda n, l: max(0.0, float(np.dot(n, l))))["passes"]
    assert not student.judge("lambert", lambda n, l: 1.0)["passes"]
    assert student.judge("spawn_offset", lambda p, n, d: p + np.sign(np.dot(d, n)) * 1e-6 * n
                         * max(1.0, np.abs(p).max()))["passes"]
    assert not student.judge("spawn_offset", lambda p, n, d: p)["passes"]
