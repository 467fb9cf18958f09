#pragma once

#include "raylab/core/Shape.h"

namespace raylab {

/**
 * \brief A flat parallelogram `corner + s * edgeU + t * edgeV`, s, t in [0, 1]: a
 * rectangle when the edges are perpendicular (walls, floors, area lights).
 *
 * The front side is the one `normalize(edgeU x edgeV)` points to. Affine maps send
 * parallelograms to parallelograms, so `apply` is exact. uv of a hit are (s, t).
 */
class Quad final : public Shape {
 public:
  Quad(const Point3& corner, const Vec3& edgeU, const Vec3& edgeV);

  ShapeKind kind() const override { return ShapeKind::Quad; }
  bool isClosed() const override { return false; }
  bool isFlat() const override { return true; }
  /// Shape's interface (RAYLAB_SHAPE_INTERFACE in Shape.h). area(): |edgeU x edgeV|; sampled
  /// uniformly in (s, t).
  RAYLAB_SHAPE_INTERFACE;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Quad>(*this); }

  const Point3& corner() const { return m_corner; }
  const Vec3& edgeU() const { return m_u; }
  const Vec3& edgeV() const { return m_v; }

 private:
  void update();

  Point3 m_corner;
  Vec3 m_u, m_v;
  Normal3 m_normal;  ///< Unit normal, edgeU x edgeV.
  Vec3 m_w;          ///< n / (n . n) with unnormalised n = u x v, for solving (s, t).
};

}  // namespace raylab
