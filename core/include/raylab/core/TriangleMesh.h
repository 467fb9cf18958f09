#pragma once

#include "raylab/core/Shape.h"

#include <array>
#include <memory>
#include <vector>

namespace raylab {

class Bvh;

/**
 * \brief An indexed triangle mesh with a bounding volume hierarchy (see Bvh.h).
 *
 * Triangles are counter-clockwise seen from outside; for a closed mesh `inside` counts
 * crossings of a ray (parity). Each triangle is hit with the watertight test of
 * Triangle.h, so rays through shared edges and vertices never leak. `apply` transforms
 * the vertices and rebuilds the BVH. Hit::primitive is the triangle index and Hit::uv
 * the barycentrics (b1, b2) of that triangle.
 */
class TriangleMesh final : public Shape {
 public:
  using Index3 = std::array<int, 3>;

  TriangleMesh(std::vector<Point3> vertices, std::vector<Index3> triangles);
  TriangleMesh(const TriangleMesh& other);
  TriangleMesh& operator=(const TriangleMesh& other);
  TriangleMesh(TriangleMesh&&) noexcept;
  TriangleMesh& operator=(TriangleMesh&&) noexcept;
  ~TriangleMesh() override;

  ShapeKind kind() const override { return ShapeKind::TriangleMesh; }
  std::optional<Hit> intersect(const Ray& ray) const override;
  SurfaceInteraction surfaceAt(const Ray& ray, const Hit& hit) const override;
  std::vector<Crossing> intersectAll(const Ray& ray) const override;
  Normal3 normal(const Point3& p) const override;
  bool inside(const Point3& p) const override;
  void apply(const Mat4& m) override;
  Bounds3 bounds() const override;
  std::unique_ptr<Shape> clone() const override;
  std::string toString() const override;
  /// Sum of the triangles' areas; sampled by picking a triangle from the area CDF, then
  /// a uniform point on it. sampleArea throws InvalidGeometry for a mesh of zero area.
  double area() const override;
  ShapeSample sampleArea(const Vec2& u) const override;
  double pdfArea(const Point3& p) const override;

  const std::vector<Point3>& vertices() const { return m_vertices; }
  const std::vector<Index3>& triangles() const { return m_triangles; }
  std::size_t triangleCount() const { return m_triangles.size(); }
  const Bvh& bvh() const { return *m_bvh; }

 private:
  void rebuild();

  std::vector<Point3> m_vertices;
  std::vector<Index3> m_triangles;
  std::unique_ptr<Bvh> m_bvh;
  std::vector<double> m_areaCdf;  ///< Running sum of triangle areas (unnormalised).
  double m_area = 0.0;            ///< Total area, world units^2.
};

}  // namespace raylab
