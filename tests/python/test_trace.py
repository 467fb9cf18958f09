"""raylab.trace and raylab.Stepper: the tree of `raylab trace --json`, field by field."""

import gc
import json

import numpy as np
import pytest

import raylab
from conftest import SCENES, run_cli, small_scene

CASES = [("raycast", (150, 200), 0), ("whitted", (95, 95), 0), ("distributed", (200, 150), 1),
         ("path", (160, 120), 3)]


@pytest.mark.parametrize("algorithm,pixel,sample", CASES)
def test01_the_tree_equals_raylab_trace_json(tmp_path, raylab_exe, algorithm, pixel, sample):
    """to_json() is byte for byte the CLI's dump, so the estimate is the CLI's too."""
    dump = tmp_path / "tree.json"
    run_cli(raylab_exe, "trace", "--algorithm", algorithm, "--seed", 5, "--pixel", *pixel,
            "--sample", sample, "--out", tmp_path / "tree.png", "--json", dump)
    trace = raylab.trace(raylab.default_scene(), pixel, sample, algorithm=algorithm, seed=5)
    assert trace.to_json() == dump.read_text()
    cli = json.loads(dump.read_text())
    assert list(trace.tree_estimate) == cli["estimate"]
    assert trace.algorithm == algorithm and trace.pixel == pixel and trace.sample == sample


def test02_every_segment_has_every_field_of_the_dump():
    trace = raylab.trace(raylab.load_scene(str(SCENES / "materials.json")), (64, 150),
                         algorithm="whitted")
    dumped = json.loads(trace.to_json())["segments"]
    assert len(trace) == len(dumped) > 3
    for segment, expected in zip(trace.segments, dumped):
        fields = {k: list(v) if isinstance(v, tuple) else v for k, v in segment.to_dict().items()}
        assert fields == expected
        assert set(expected) <= set(dir(segment))
        for key, value in expected.items():
            got = getattr(segment, key)
            assert (list(got) if isinstance(got, tuple) else got) == value


def test02b_a_shadow_ray_names_its_light():
    # A point light beside the light box: a floor point sends one shadow ray to each.
    scene = raylab.load_scene(str(SCENES / "materials.json"))
    key = scene.add_point_light()
    index = scene.point_light_names.index(key)
    scene.update({f"/point_lights/{index}/position": [2, 4, 2],
                  f"/point_lights/{index}/intensity": [10, 10, 10]})
    trace = raylab.trace(scene, (160, 220), algorithm="raycast")  # the floor
    shadows = [s for s in trace.segments if s.kind == "shadow"]
    assert sorted(s.light_name for s in shadows) == sorted([key, "light"])
    for s in shadows:
        if s.light_name == key:
            assert s.point_light == index and s.light_object == -1
        else:
            assert s.light_object == scene.object_names.index("light") and s.point_light == -1
    assert all(s.light_name == "" for s in trace.segments if s.kind != "shadow")


@pytest.mark.parametrize("algorithm", raylab.ALGORITHMS)
def test03_the_estimates_are_the_rendered_pixel(algorithm):
    """A pixel of a render is the mean of its samples' traced estimates (same spp, which
    the film samples are stratified over, and seed)."""
    scene = small_scene()
    one = raylab.render(scene, algorithm=algorithm, spp=1, seed=9)
    four = raylab.render(scene, algorithm=algorithm, spp=4, seed=9)
    for x, y in [(3, 4), (16, 12), (30, 20)]:
        trace = raylab.trace(scene, (x, y), algorithm=algorithm, spp=1, seed=9)
        assert np.array_equal(np.float32(trace.estimate), one[y, x])
        samples = [raylab.trace(scene, (x, y), s, algorithm=algorithm, spp=4, seed=9).estimate
                   for s in range(4)]
        assert np.array_equal(np.float32(np.mean(samples, axis=0)), four[y, x])


def test04_arrays_hold_the_tree_for_plotting():
    trace = raylab.trace(raylab.default_scene(), (200, 150), algorithm="distributed")
    arrays = trace.arrays()
    n = len(trace)
    assert arrays["origins"].shape == (n, 3) and arrays["ends"].shape == (n, 3)
    assert arrays["energies"].shape == (n,)
    for i, segment in enumerate(trace.segments):
        assert tuple(arrays["origins"][i]) == segment.origin
        assert tuple(arrays["ends"][i]) == segment.end_point
        assert arrays["energies"][i] == segment.energy
        assert arrays["kinds"][i] == segment.kind
        assert arrays["end_reasons"][i] == segment.end_reason
        assert arrays["parents"][i] == segment.parent
    assert arrays["energies"][0] == pytest.approx(np.dot(trace.tree_estimate, [0.2126, 0.7152, 0.0722]),
                                                  rel=1e-6)


def test05_the_stepper_steps_the_real_algorithm_to_the_same_tree():
    scene = raylab.default_scene()
    stepper = raylab.Stepper(scene, (95, 95), algorithm="whitted")
    assert stepper.queue[0]["kind"] == "camera"
    events = list(stepper)
    assert stepper.done and not stepper.step()
    trace = raylab.trace(scene, (95, 95), algorithm="whitted")
    assert stepper.tree().to_json() == trace.to_json()
    assert [e["text"] for e in events] == trace.step_texts
    assert stepper.estimate == trace.estimate


def test06_a_tree_taken_while_stepping_is_a_snapshot():
    stepper = raylab.Stepper(raylab.default_scene(), (200, 150), algorithm="distributed")
    stepper.step()
    early = stepper.tree()
    early_json = early.to_json()
    stepper.run_to_end()
    assert early.to_json() == early_json
    assert len(stepper.tree()) > len(early)
    stepper.reset()
    assert not stepper.done and stepper.queue[0]["kind"] == "camera"


def test07_segments_keep_their_trace_alive():
    """No dangling views: a segment outlives the Trace object it came from."""
    segment = raylab.trace(raylab.default_scene(), (95, 95), algorithm="whitted")[1]
    expected = segment.to_dict()
    children = segment.children
    gc.collect()
    for _ in range(5):
        raylab.trace(raylab.default_scene(), (10, 10), algorithm="path")
    assert segment.to_dict() == expected
    assert all(c.parent == segment.id for c in children)


def test08_a_pixel_outside_the_image_is_refused():
    with pytest.raises(ValueError, match=r"pixel \(400, 10\) is outside the 320x240 image"):
        raylab.trace(raylab.default_scene(), (400, 10))
    with pytest.raises(ValueError, match="sample must be 0 or more"):
        raylab.Stepper(raylab.default_scene(), (1, 1), -1)


def test08b_a_pixel_that_is_not_two_integers_is_named():
    scene = raylab.default_scene()
    for bad in [(10.5, 10), "10,20", (1, 2, 3), 7, (True, 2)]:
        with pytest.raises(ValueError, match=r"pixel must be \(x, y\), two integers, not "):
            raylab.trace(scene, bad)
    # NumPy's integers are integers.
    assert raylab.trace(scene, (np.int64(10), np.int32(20))).pixel == (10, 20)


def test09_a_chosen_ray_is_traced_in_place_of_the_camera_ray(tmp_path, raylab_exe):
    """ray=: lesson 2's ray level with the top of its sphere, exactly tangent (the oracle
    says so, double precision finds t = 5): the tree's root is that ray, and its dump is the
    CLI's `raylab trace --ray` dump byte for byte."""
    scene = raylab.load_scene(str(SCENES / "shapes.json"))
    ray = raylab.Ray((-8, 2, 0), (2, 0, 0))  # normalised to (1, 0, 0)
    trace = raylab.trace(scene, ray=ray, algorithm="raycast")
    root = trace[0]
    assert tuple(root.origin) == (-8, 2, 0) and tuple(root.direction) == (1, 0, 0)
    assert tuple(root.end_point) == (-3, 2, 0)
    sphere = scene.shape("sphere")
    assert str(raylab.exact_classify(sphere, ray).classification).endswith("Tangent")
    dump = tmp_path / "tangent.json"
    run_cli(raylab_exe, "trace", "--scene", SCENES / "shapes.json", "--algorithm", "raycast",
            "--ray", "-8,2,0,2,0,0", "--out", tmp_path / "tangent.png", "--json", dump)
    assert trace.to_json() == dump.read_text()
