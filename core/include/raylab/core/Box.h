#pragma once

#include "raylab/core/Shape.h"
#include "raylab/core/Transform.h"

#include <array>

namespace raylab {

/**
 * \brief The original course program's oriented cube: a box with three axes, extents and a
 * centre.
 *
 * Stored as the affine map `worldFromBox` that takes the canonical cube [-1, 1]^3 to the
 * box: its columns are `axis_i * extent_i / 2` and its translation is the centre. Any
 * affine `apply` (including non-uniform scale after a rotation) composes exactly onto
 * it; the result is then a parallelepiped, which is what a scaled rotated box is.
 * `boxFromWorld()` is the original course program's matrix T (world -> cube coordinates).
 * Intersection is the slab test (Kay & Kajiya 1986) against the three pairs of face
 * planes, kept in world units (unit normal, centre offset, half width) so that an
 * axis-aligned box with exactly representable planes gives exact t.
 */
class Box final : public Shape {
 public:
  /// Axis-aligned box with full edge lengths `size` around `centre`.
  Box(const Point3& centre, const Vec3& size);
  /// Oriented box: unit axes (need not be orthogonal), full edge lengths, centre.
  Box(const Point3& centre, const Vec3& size, const Vec3& axisX, const Vec3& axisY,
      const Vec3& axisZ);
  /// From the map of the canonical cube [-1, 1]^3.
  explicit Box(const Transform& worldFromBox);

  ShapeKind kind() const override { return ShapeKind::Box; }
  bool isClosed() const override { return true; }
  bool isFlat() const override { return false; }
  /// Shape's interface (RAYLAB_SHAPE_INTERFACE in Shape.h). area(): uniform over the six faces (a
  /// parallelepiped's faces are parallelograms).
  RAYLAB_SHAPE_INTERFACE;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Box>(*this); }

  Point3 centre() const;
  /// Unit direction of box axis i (0, 1, 2), world space.
  Vec3 axis(int i) const;
  /// Full edge lengths along the three axes (the original course program's "extend").
  Vec3 size() const;
  /// The 8 corners in world space; corner k has box coordinates
  /// ((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1).
  std::array<Point3, 8> vertices() const;
  /// Box coordinates of corner k, in [-1, 1]^3.
  static Point3 canonicalVertex(int k);
  /// Face f = 2 * axis + (positive side ? 1 : 0); unit outward normal, world space.
  Normal3 faceNormal(int face) const;
  const Transform& worldFromBox() const { return m_worldFromBox; }
  /// The original course program's T: world coordinates -> box coordinates in [-1, 1]^3.
  const Mat4& boxFromWorld() const { return m_worldFromBox.inverseMatrix(); }

 private:
  /// Entry and exit parameters (and faces) of the ray's line with the box, or nothing.
  struct Span {
    double t0, t1;
    int face0, face1;
  };
  std::optional<Span> span(const Ray& ray) const;
  /// Recomputes the slab planes from worldFromBox.
  void updateSlabs();
  /// Area of one face of each pair (faces 2i and 2i + 1 are congruent), world units^2.
  Vec3 faceAreas() const;

  Transform m_worldFromBox;
  /// Slab i is {x : |dot(m_slabNormal[i], x) - m_slabCentre[i]| <= m_slabHalf[i]}.
  Vec3 m_slabNormal[3];
  double m_slabCentre[3];
  double m_slabHalf[3];
};

}  // namespace raylab
