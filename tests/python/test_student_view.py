"""raylab.student.save_view (issue 35): the student's tree coloured by verdict beside the
engine's. Needs an X server (with-display.sh)."""

import math
import os

import numpy as np

import raylab
import raylab.student as student

TMP = os.environ.get("RAYLAB_TEST_TMP", "/tmp")


def far_root_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = np.dot(oc, direction)
    disc = b * b - (np.dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    t = -b + math.sqrt(disc)
    return t if t_min <= t <= t_max else None


def test_01_a_wrong_hit_is_drawn_red_beside_the_engines_tree():
    scene = raylab.default_scene()
    width, height = scene.size
    pixel = next((x, y) for y in range(0, height, 6) for x in range(0, width, 6)
                 if raylab.trace(scene, (x, y), algorithm="path", spp=1)
                 .segments[0].object_name == "red sphere")
    student.use(intersect_sphere=far_root_sphere)
    try:
        t = student.trace(scene, pixel, algorithm="path", spp=1)
    finally:
        student.use()
    assert t.verdicts[0] == "wrong_hit"
    path = os.path.join(TMP, "TestStudentView.png")
    student.save_view(path, scene, t, width=400, height=300)
    image = raylab.read_png(path) if hasattr(raylab, "read_png") else None
    if image is None:
        import vtk  # python3-vtk9 reads the PNG back
        reader = vtk.vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        data = reader.GetOutput()
        from vtk.util.numpy_support import vtk_to_numpy
        w, h, _ = data.GetDimensions()
        image = vtk_to_numpy(data.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    assert image.shape[1] == 800 and image.shape[0] == 300
    left, right = image[:, :400].astype(int), image[:, 400:].astype(int)
    # The wrong-hit colour (0.9, 0.1, 0.1: bytes 230, 26, 26; lines are unlit) in the
    # student's half (its camera ray and the legend's entry), not in the engine's.
    def wrong_hit_pixels(half):
        return int((np.abs(half - np.array([230, 26, 26])).max(axis=2) <= 6).sum())

    assert wrong_hit_pixels(left) > 20
    assert wrong_hit_pixels(right) < wrong_hit_pixels(left) / 4
