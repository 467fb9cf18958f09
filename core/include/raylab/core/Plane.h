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
  std::optional<Hit> intersect(const Ray& ray) const override;
  SurfaceInteraction surfaceAt(const Ray& ray, const Hit& hit) const override;
  std::vector<Crossing> intersectAll(const Ray& ray) const override;
  Normal3 normal(const Point3& p) const override;
  bool inside(const Point3& p) const override;
  void apply(const Mat4& m) override;
  Bounds3 bounds() const override;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Plane>(*this); }
  std::string toString() const override;
  /// Infinite; a plane cannot be an area light: sampleArea throws InvalidGeometry and
  /// pdfArea is 0.
  double area() const override;
  ShapeSample sampleArea(const Vec2& u) const override;
  double pdfArea(const Point3& p) const override;

  const Point3& point() const { return m_point; }
  const Normal3& planeNormal() const { return m_normal; }

 private:
  Point3 m_point;
  Normal3 m_normal;
};

}  // namespace raylab
