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
 *
 * Smooth shading (Phong 1975's normal interpolation): a mesh may carry normals at its
 * triangles' corners, read from the file (OBJ `vn`, PLY `nx ny nz`) or computed with a
 * crease angle (computeCreaseNormals). surfaceAt then fills SurfaceInteraction::ns with
 * the corners' normals interpolated at the hit's barycentrics and normalised, turned to
 * the geometric normal's side; n stays the triangle's own normal, so hits, inside/outside,
 * ray offsets and the exact oracle do not change. Where the ray arrives between the two
 * surfaces (its direction on different sides of n and ns), the hit shades flat (ns = 0).
 *
 * Copies share the immutable data (vertices, triangles, BVH, corner normals): a lesson's
 * steps each hold a copy of a scene, and with a 200,000-triangle mesh each copy held its
 * own 30 MB (issue 38). An edit (apply, setNormals, computeCreaseNormals, clearNormals) gives
 * the edited mesh new data and leaves its copies as they were. The same edit of the same
 * data gives the same shared result (a mesh moved by the same matrix, or smoothed with the
 * same crease angle, in every step of a lesson is stored once).
 */
class TriangleMesh final : public Shape {
 public:
  using Index3 = std::array<int, 3>;

  TriangleMesh(std::vector<Point3> vertices, std::vector<Index3> triangles);
  /// A smooth mesh: `normalIndices[i][k]` is the index in `normals` of the normal at corner
  /// k of triangle i (world space, any positive length; they are normalised). Throws
  /// InvalidGeometry as setNormals does.
  TriangleMesh(std::vector<Point3> vertices, std::vector<Index3> triangles,
               std::vector<Normal3> normals, std::vector<Index3> normalIndices);
  TriangleMesh(const TriangleMesh& other);
  TriangleMesh& operator=(const TriangleMesh& other);
  TriangleMesh(TriangleMesh&&) noexcept;
  TriangleMesh& operator=(TriangleMesh&&) noexcept;
  ~TriangleMesh() override;

  ShapeKind kind() const override { return ShapeKind::TriangleMesh; }
  bool isClosed() const override { return true; }
  bool isFlat() const override { return false; }
  /// Shape's interface (RAYLAB_SHAPE_INTERFACE in Shape.h). area(): sum of the triangles' areas;
  /// sampled by picking a triangle from the area CDF, then a uniform point on it. sampleArea throws
  /// InvalidGeometry for a mesh of zero area.
  RAYLAB_SHAPE_INTERFACE;
  std::unique_ptr<Shape> clone() const override;

  const std::vector<Point3>& vertices() const { return m_geometry->vertices; }
  const std::vector<Index3>& triangles() const { return m_geometry->triangles; }
  std::size_t triangleCount() const { return m_geometry->triangles.size(); }
  const Bvh& bvh() const { return *m_geometry->bvh; }

  /// Sets the corner normals (see the constructor). Throws InvalidGeometry naming the
  /// triangle or normal when there is not one index triple per triangle, an index is out
  /// of range, or a normal is not finite or has zero length.
  void setNormals(std::vector<Normal3> normals, std::vector<Index3> normalIndices);
  /**
   * \brief Computes corner normals with a crease angle, in radians in [0, pi]: the normal
   * at a corner of triangle t is the sum of the normals of the triangles around that
   * vertex whose normal is within `creaseAngle` of t's, each weighted by its angle at the
   * vertex (Thuermer and Wuethrich 1998), normalised. Edges sharper than the crease angle
   * stay sharp (a cube at 30 degrees keeps flat faces); 0 keeps every face flat but for
   * coplanar neighbours. Only triangles that share the vertex index are averaged.
   */
  void computeCreaseNormals(double creaseAngle);
  /// Drops the corner normals: every triangle shades flat.
  void clearNormals();
  /// True when the mesh has corner normals (smooth shading).
  bool hasNormals() const { return !m_shading->indices.empty(); }
  /// The unit corner normals, world space (empty for a flat mesh).
  const std::vector<Normal3>& normals() const { return m_shading->normals; }
  /// Per triangle, the indices of its three corners' normals in normals().
  const std::vector<Index3>& normalIndices() const { return m_shading->indices; }
  /// The shading normal of triangle `triangle` at barycentrics (b1, b2) (point b0 p0 +
  /// b1 p1 + b2 p2, b0 = 1 - b1 - b2): b0 n0 + b1 n1 + b2 n2 normalised, turned to the
  /// triangle's geometric normal's side; the geometric normal for a flat mesh, or when
  /// the interpolated normal vanishes.
  Normal3 shadingNormal(int triangle, double b1, double b2) const;

 private:
  struct Memo;
  struct Geometry {
    std::vector<Point3> vertices;
    std::vector<Index3> triangles;
    std::shared_ptr<const Bvh> bvh;
    std::vector<double> areaCdf;  ///< Running sum of triangle areas (unnormalised).
    double area = 0.0;            ///< Total area, world units^2.
    std::shared_ptr<Memo> edits;  ///< The results of apply and computeCreaseNormals.
  };
  struct Shading {
    std::vector<Normal3> normals;  ///< Unit corner normals (smooth shading), world.
    std::vector<Index3> indices;   ///< Per triangle, its corners' normals; empty: flat.
    std::shared_ptr<Memo> edits;   ///< The results of apply.
  };
  static std::shared_ptr<const Geometry> makeGeometry(std::vector<Point3> vertices,
                                                      std::vector<Index3> triangles);
  static std::shared_ptr<const Shading> makeShading(std::vector<Normal3> normals,
                                                    std::vector<Index3> indices);
  static std::shared_ptr<const Shading> creaseNormals(const std::vector<Point3>& vertices,
                                                      const std::vector<Index3>& triangles,
                                                      double creaseAngle);
  /// Vertices and triangles with what follows from them; shared by copies, never changed.
  std::shared_ptr<const Geometry> m_geometry;
  /// The corner normals (smooth shading); shared by copies, never changed.
  std::shared_ptr<const Shading> m_shading;
};

}  // namespace raylab
