"""The examples in examples/python run as a user runs them, and the notebook runs top to
bottom headless (nbconvert --execute), each checked by what it writes."""

import json
import subprocess
import sys

import numpy as np
import pytest

import raylab
from conftest import SCENES, SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run(*args, cwd=None):
    done = subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True,
                          cwd=cwd)
    assert done.returncode == 0, done.stderr
    return done.stdout


def read_png(path):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    width, height, _ = reader.GetOutput().GetDimensions()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[::-1, :, :3]


def test01_compare_algorithms_writes_the_four_pictures_side_by_side(tmp_path):
    out = tmp_path / "compare.png"
    printed = run(EXAMPLES / "compare_algorithms.py", "--scene", SCENES / "cornell.json",
                  "--size", "40x30", "--spp", 2, "--reference-spp", 8, "--out", out)
    assert "Whitted" in printed and str(out) in printed
    picture = read_png(out)
    assert picture.shape == (30, 4 * 40 + 3 * 4, 3)
    # Each quarter is that algorithm's render, as sRGB.
    scene = raylab.load_scene(str(SCENES / "cornell.json"))
    scene.set_camera(width=40, height=30)
    path = raylab.to_srgb(raylab.render(scene, algorithm="path", spp=2))
    assert np.array_equal(picture[:, 3 * 44:], path)


def test02_trace_energies_plots_the_tree(tmp_path):
    out = tmp_path / "energies.png"
    printed = run(EXAMPLES / "trace_energies.py", "--scene", SCENES / "materials.json",
                  "--pixel", 64, 150, "--out", out)
    assert printed.splitlines()[0] == raylab.trace(
        raylab.load_scene(str(SCENES / "materials.json")), (64, 150),
        algorithm="distributed").summary()
    assert read_png(out).shape[0] > 100


def test03_the_lesson_notebook_runs_headless(tmp_path):
    pytest.importorskip("nbconvert")
    pytest.importorskip("ipykernel")
    out = tmp_path / "executed.ipynb"
    run("-m", "nbconvert", "--to", "notebook", "--execute", "--output", out,
        EXAMPLES / "lesson04_whitted.ipynb", cwd=EXAMPLES)
    notebook = json.loads(out.read_text())
    outputs = [o for cell in notebook["cells"] if cell["cell_type"] == "code"
               for o in cell["outputs"]]
    assert not [o for o in outputs if o["output_type"] == "error"]
    text = "".join("".join(o.get("text", "")) for o in outputs)
    assert "sin ratio = 1.500000" in text
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(images) == 2  # the figure of the two renders, and the 3D view
