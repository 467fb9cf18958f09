#pragma once

#include "raylab/core/Scene.h"
#include "raylab/core/Shape.h"
#include "raylab/core/Types.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>

/// \file ShapeGeometry.h
/// Triangle/line geometry (VTK polydata, world space) for every kind of scene shape and
/// for the scene camera's glyph. Private to vis: the public API never shows vtkPolyData.

namespace raylab {
class Sphere;
}

namespace raylab::vis {

/// Depth of the drawn frustum in camera glyph sizes (see cameraGlyphSize): long enough to
/// read as "the camera looks this way", short enough to stay inside a room around it.
constexpr double kFrustumLengthInGlyphs = 3.0;

/// What drawing needs beyond the shape itself.
struct DrawingFrame {
  /// A point inside the room, world space: open surfaces (planes, quads, triangles) are
  /// turned to face it, so that drawn one-sided they show the room's inner side.
  Point3 inside{0.0};
  /// Half the edge of the finite square that stands in for an infinite plane, world units.
  double planeHalfSize = 10.0;
};

/**
 * \brief Polydata of a shape in world space, with point normals for shading.
 *
 * Sphere: a latitude/longitude mesh with the shape's tessellation hints (m slices along
 * the polar axis, n around it), mapped by worldFromObject (so ellipsoids draw right).
 * Box: a hexahedron from its 8 world corners, 4 points per face with the face normal
 * (flat shading, exact for rotated and sheared boxes). Plane: a square of half-edge
 * planeHalfSize centred on the point of the plane closest to `frame.inside`. Quad,
 * Triangle: their corners. TriangleMesh: its triangles with normals split at 30 degrees.
 */
vtkSmartPointer<vtkPolyData> shapeGeometry(const Shape& shape, const DrawingFrame& frame);

/// An enclosing wall (a huge sphere, see enclosingWalls): the patch of the sphere around
/// the room, `halfSize` world units from the point of the sphere nearest frame.inside,
/// finely tessellated (every vertex exactly on the sphere), faces turned towards
/// frame.inside so that, drawn one-sided, the wall shows its room side and vanishes where
/// it stands between the viewer and the room.
vtkSmartPointer<vtkPolyData> wallPatchGeometry(const Sphere& sphere, const DrawingFrame& frame,
                                               double halfSize);

/// A closed hexahedron with flat faces from 8 corners in Box::vertices() order (corner k
/// at box coordinates ((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1)), world space.
/// Face normals point away from the corners' centroid, whatever the corners' handedness.
vtkSmartPointer<vtkPolyData> hexahedronGeometry(const std::array<Point3, 8>& corners);

/// The scene camera's body: a box of edge about `size` just behind the eye, aligned with
/// the camera's right / up / backward axes, world space.
vtkSmartPointer<vtkPolyData> cameraBodyGeometry(const CameraSpec& camera, double size);

/// The scene camera's view frustum as lines: four edges from the eye to the corners of an
/// image rectangle `length` in front of the eye, and that rectangle, world space. The
/// rectangle has the camera's aspect (width / height) and vertical field of view.
vtkSmartPointer<vtkPolyData> cameraFrustumGeometry(const CameraSpec& camera, double length);

}  // namespace raylab::vis
