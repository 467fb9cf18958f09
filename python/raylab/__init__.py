"""RayLab from Python: scenes, geometry and the exact oracle, renders, ray trees, the
stepper, comparisons, and VTK polydata / offscreen views.

Built from the same C++ core and vis libraries as the ``raylab`` command. From the build
tree::

    PYTHONPATH=build/release/python python3 -c \\
        "import raylab; print(raylab.render(raylab.default_scene(), spp=1).shape)"

Everything that reads a scene raises ``raylab.SceneError`` with the scene loader's message
(file, JSON place, problem); all RayLab errors derive from ``raylab.Error``.
"""

import sys as _sys


def _find_numpy():
    """Makes the NumPy raylab was compiled against importable.

    The module is built for one interpreter (Debian's /usr/bin/python3, whose NumPy is
    python3-numpy). Another python3 of the same version found first on PATH (pyenv, a
    virtualenv without NumPy) would otherwise fail to import raylab; it gets the folder
    that NumPy was found in at build time, appended at the end of sys.path.
    """
    try:
        import numpy  # noqa: F401
        return
    except ImportError:
        pass
    from . import _build
    if _sys.version_info[:2] != _build.python_version:
        raise ImportError(
            "raylab was built for Python %d.%d (%s), this is Python %d.%d (%s)"
            % (*_build.python_version, _build.python_executable, *_sys.version_info[:2],
               _sys.executable))
    if _build.site_packages and _build.site_packages not in _sys.path:
        _sys.path.append(_build.site_packages)


_find_numpy()

from . import _raylab  # noqa: E402
from ._raylab import (  # noqa: E402
    Box,
    ComparisonError,
    Crossing,
    Error,
    ExactResult,
    GeometryError,
    Hit,
    ImageError,
    NotImplementedInRayLab,
    OracleComparison,
    Plane,
    Quad,
    Ray,
    RayTreeError,
    SaveError,
    Scene,
    SceneError,
    Segment,
    Shape,
    Sphere,
    Stepper,
    SurfaceInteraction,
    Trace,
    Triangle,
    TriangleMesh,
    compare,
    default_scene,
    display_rmse,
    exact_classify,
    load_scene,
    oracle_compare,
    read_pfm,
    render,
    rmse,
    save_view,
    to_srgb,
    trace,
    view_image,
    write_image,
)
from ._vtk import scene_polydata, tree_polydata  # noqa: E402

for _name in dir(_raylab):
    _value = getattr(_raylab, _name)
    if isinstance(_value, type) and not _name.startswith("_"):
        _value.__module__ = "raylab"  # raylab.SceneError, not raylab._raylab.SceneError

ALGORITHMS = _raylab.ALGORITHMS
"""The algorithms, in historical order (the names every function takes)."""

__all__ = [name for name in dir() if not name.startswith("_")]
