#pragma once

#include "raylab/core/Shape.h"

#include <array>
#include <optional>

namespace raylab {

/// Result of the watertight ray/triangle test: t and barycentrics (b0 + b1 + b2 = 1)
/// with the hit point at b0 * p0 + b1 * p1 + b2 * p2.
struct TriangleHit {
  double t;
  double b0, b1, b2;
};

/**
 * \brief Watertight ray/triangle intersection (Woop, Benthin and Wald, "Watertight
 * Ray/Triangle Intersection", JCGT 2013).
 *
 * The triangle is moved into a ray-aligned frame (the ray along +z through the origin);
 * the 2D edge functions of a shared edge are then the same numbers with opposite sign
 * in both triangles, so a ray through an edge or a vertex is never lost between
 * neighbours. Edges exactly on the ray (edge function 0) count as hits. Triangles
 * facing either way are hit. Returns nothing for a miss, a degenerate triangle, a ray
 * in the triangle's plane, or t outside [ray.tMin, ray.tMax].
 */
std::optional<TriangleHit> intersectTriangle(const Ray& ray, const Point3& p0, const Point3& p1,
                                             const Point3& p2);

/**
 * \brief A single triangle with vertices p0, p1, p2 (counter-clockwise seen from the
 * front, so the normal is normalize((p1 - p0) x (p2 - p0))).
 */
class Triangle final : public Shape {
 public:
  Triangle(const Point3& p0, const Point3& p1, const Point3& p2);

  ShapeKind kind() const override { return ShapeKind::Triangle; }
  bool isClosed() const override { return false; }
  bool isFlat() const override { return true; }
  /// Shape's interface (RAYLAB_SHAPE_INTERFACE in Shape.h). area(): half |(p1 - p0) x (p2 - p0)|;
  /// sampled uniformly (square-root warp).
  RAYLAB_SHAPE_INTERFACE;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Triangle>(*this); }

  const Point3& vertex(int i) const { return m_p[i]; }

 private:
  std::array<Point3, 3> m_p;
};

}  // namespace raylab
