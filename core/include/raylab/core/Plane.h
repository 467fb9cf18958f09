#pragma once

#include "raylab/core/Shape.h"

namespace raylab {

/**
 * \brief An infinite plane through `point` with unit normal `normal`.
 *
 * Inside is the half-space behind the normal: {x : (x - point) . normal < 0}, so a
 * floor with normal +y holds the space below it. A ray parallel to the plane misses it,
 * also when it lies in the plane (the coplanar case is the oracle's "tangent").
 */
class Plane final : public Shape {
 public:
  Plane(const Point3& point, const Normal3& normal);

  ShapeKind kind() const override { return ShapeKind::Plane; }
  bool isClosed() const override { return true; }
  bool isFlat() const override { return true; }
  /// Shape's interface (RAYLAB_SHAPE_INTERFACE in Shape.h). area(): infinite; a plane cannot be an
  /// area light: sampleArea throws InvalidGeometry and pdfArea is 0.
  RAYLAB_SHAPE_INTERFACE;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Plane>(*this); }

  const Point3& point() const { return m_point; }
  const Normal3& planeNormal() const { return m_normal; }

 private:
  Point3 m_point;
  Normal3 m_normal;
};

}  // namespace raylab
