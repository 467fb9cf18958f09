"""Ray trees and scenes as vtkPolyData of Debian's VTK Python package (python3-vtk9).

The polydata are built in C++ by RayLab's vis library and handed to VTK's Python wrappers
in the same process by address: VTK wraps an existing C++ object from its pointer string
(``vtkPolyData('_<address>_p_vtkPolyData')``) and takes its own reference to it, so the
Python object owns the data once the C++ holder is dropped. Both sides must use the same
VTK libraries (Debian's libvtk9.1, which python3-vtk9 wraps and RayLab links).
"""

from . import _raylab


def _wrap(holder):
    try:
        from vtkmodules.vtkCommonDataModel import vtkPolyData
    except ImportError as error:
        raise ImportError(
            "VTK's Python package is needed for polydata: sudo apt-get install python3-vtk9"
        ) from error
    polydata = vtkPolyData(holder.address)  # takes a reference of its own
    del holder  # drops RayLab's reference: the Python object now owns the data
    return polydata


def tree_polydata(trace, colouring="energy"):
    """The ray tree of a raylab.Trace as a vtkPolyData: one line cell per ray (origin to
    end point, world space), cell data "colour" (RGB bytes: the 3D view's colours by
    energy, kind or depth), "segment" (ray id), "energy", "depth" and "kind" (RayKind
    code: camera 0, reflection 1, refraction 2, diffuse 3, glossy 4, shadow 5)."""
    return _wrap(_raylab._tree_polydata(trace, colouring))


def scene_polydata(scene):
    """Every object of a raylab.Scene as the 3D view draws it (world space), in one
    vtkPolyData with cell data "object" (index in the scene) and "colour" (RGB bytes)."""
    return _wrap(_raylab._scene_polydata(scene))
