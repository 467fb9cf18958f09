"""Shared fixtures of the raylab Python suites.

CTest (tests/python/CMakeLists.txt) sets PYTHONPATH to the build tree's package and names
the C++ command line in RAYLAB_EXE, the repository in RAYLAB_SOURCE_DIR.
"""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import raylab

SOURCE_DIR = pathlib.Path(os.environ.get("RAYLAB_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SCENES = SOURCE_DIR / "lessons" / "scenes"


@pytest.fixture
def raylab_exe():
    exe = os.environ.get("RAYLAB_EXE")
    if not exe or not os.path.exists(exe):
        pytest.fail("RAYLAB_EXE must name the built raylab executable (CTest sets it)")
    return exe


def run_cli(exe, *args):
    """Runs the raylab command line; fails the test with its stderr when it fails."""
    done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, f"raylab {' '.join(map(str, args))}: {done.stderr}"
    return done


def read_pfm(path):
    """A PFM file as an H x W x 3 float32 array, rows from the top (PFM stores them from
    the bottom), read here with NumPy alone so it does not depend on raylab's reader."""
    data = pathlib.Path(path).read_bytes()
    header, rest = data.split(b"\n", 1)
    assert header == b"PF"
    size, rest = rest.split(b"\n", 1)
    scale, pixels = rest.split(b"\n", 1)
    width, height = map(int, size.split())
    dtype = "<f4" if float(scale) < 0 else ">f4"
    image = np.frombuffer(pixels, dtype=dtype, count=width * height * 3)
    return image.reshape(height, width, 3)[::-1].astype(np.float32)


def small_scene(path=None, width=32, height=24):
    """A scene (the default one, or a shipped file) at a small image size."""
    scene = raylab.load_scene(str(path)) if path else raylab.default_scene()
    scene.set_camera(width=width, height=height)
    return scene
