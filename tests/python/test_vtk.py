"""VTK from Python: RayLab's polydata in python3-vtk9's pipeline, the 3D view offscreen."""

import gc

import numpy as np
import pytest

import raylab

vtk_data = pytest.importorskip("vtkmodules.vtkCommonDataModel")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


@pytest.fixture(scope="module")
def trace():
    return raylab.trace(raylab.default_scene(), (200, 150), algorithm="distributed")


def test01_the_tree_polydata_holds_every_ray_from_origin_to_end(trace):
    polydata = raylab.tree_polydata(trace)
    assert isinstance(polydata, vtk_data.vtkPolyData)
    segments = vtk_to_numpy(polydata.GetCellData().GetArray("segment"))
    drawn = [s for s in trace.segments if s.origin != s.end_point]
    assert sorted(segments) == sorted(s.id for s in drawn)
    points = vtk_to_numpy(polydata.GetPoints().GetData())
    arrays = trace.arrays()
    for cell, segment in enumerate(segments):
        ids = polydata.GetCell(cell).GetPointIds()
        assert points[ids.GetId(0)] == pytest.approx(arrays["origins"][segment])
        assert points[ids.GetId(1)] == pytest.approx(arrays["ends"][segment])
    energy = vtk_to_numpy(polydata.GetCellData().GetArray("energy"))
    assert np.array_equal(energy, arrays["energies"][segments])
    colours = vtk_to_numpy(polydata.GetCellData().GetArray("colour"))
    assert colours.shape == (len(segments), 3) and len(np.unique(colours, axis=0)) > 1


def test02_the_python_object_owns_the_polydata(trace):
    """VTK's wrapper holds the only reference once RayLab's holder is gone, and the data
    outlive the trace they were made from."""
    polydata = raylab.tree_polydata(raylab.trace(raylab.default_scene(), (95, 95),
                                                 algorithm="whitted"))
    gc.collect()
    assert polydata.GetReferenceCount() == 1
    cells = polydata.GetNumberOfCells()
    for _ in range(3):
        raylab.tree_polydata(trace)
    assert polydata.GetNumberOfCells() == cells > 0
    assert polydata.GetPoints().GetNumberOfPoints() == 2 * cells


def test03_the_scene_polydata_has_every_object():
    scene = raylab.default_scene()
    polydata = raylab.scene_polydata(scene)
    objects = vtk_to_numpy(polydata.GetCellData().GetArray("object"))
    assert set(objects) == set(range(len(scene.object_names)))
    bounds = polydata.GetBounds()
    lower, upper = scene.shape("red sphere").bounds()
    assert bounds[0] <= lower[0] and upper[0] <= bounds[1]


def test04_raylab_polydata_render_in_a_vtk_python_pipeline(trace):
    """A VTK script adds RayLab's tree to its own pipeline and renders it offscreen."""
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                             vtkRenderWindow, vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

    mapper = vtkPolyDataMapper()
    mapper.SetInputData(raylab.tree_polydata(trace, colouring="kind"))
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray("colour")
    mapper.SetColorModeToDirectScalars()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(120, 90)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    assert len(np.unique(pixels[:, :3], axis=0)) > 2  # rays drawn in their kind colours


def test05_view_image_is_the_3d_view_with_the_tree(tmp_path, trace):
    scene = raylab.default_scene()
    without = raylab.view_image(scene, width=200, height=150)
    with_tree = raylab.view_image(scene, trace, width=200, height=150)
    assert without.shape == (150, 200, 3) and without.dtype == np.uint8
    assert np.count_nonzero(np.any(without != with_tree, axis=2)) > 50
    again = raylab.view_image(scene, trace, width=200, height=150)
    assert np.array_equal(with_tree, again)  # a frame is repeatable
    png = tmp_path / "view.png"
    raylab.save_view(str(png), scene, trace, width=200, height=150)
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(str(png))
    reader.Update()
    read = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
    assert np.array_equal(read.reshape(150, 200, 3)[::-1], with_tree)  # VTK rows go up
    behind = raylab.view_image(scene, width=200, height=150, view="camera")
    assert not np.array_equal(behind, without)


def test06_a_plain_trace_refuses_the_verdict_colouring_and_names_every_colouring(trace):
    """A plain trace has no verdicts (every ray would be grey): the message says what draws
    them; an unknown colouring's message names the four colourings."""
    with pytest.raises(ValueError, match=r"'verdict' needs a trace judged.*raylab\.student"):
        raylab.tree_polydata(trace, colouring="verdict")
    with pytest.raises(ValueError, match=r"'verdict' needs a trace judged"):
        raylab.view_image(raylab.default_scene(), trace, width=8, height=8, colouring="verdict")
    with pytest.raises(ValueError, match=r"unknown colouring 'rainbow': use energy, kind or "
                                         r"depth \(verdict: a student's judged trace"):
        raylab.tree_polydata(trace, colouring="rainbow")
