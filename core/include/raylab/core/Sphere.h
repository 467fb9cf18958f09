#pragma once

#include "raylab/core/Shape.h"
#include "raylab/core/Transform.h"

#include <cmath>
#include <optional>
#include <utility>

namespace raylab {

/**
 * \brief A sphere (centre, radius), optionally mapped by an affine transform into an
 * ellipsoid.
 *
 * The original course program's Sphere, with its tessellation hints for drawing: `m` slices
 * along the polar (z) direction and `n` around the axis. `apply` with a similarity (rotation,
 * translation, uniform scale) updates centre and radius directly, so textbook rays stay
 * exact; any other affine map (non-uniform scale) is kept as `worldFromObject`, and rays
 * are intersected in object space. Intersection uses the numerically careful quadratic
 * of Haines et al., "Precision Improvements for Ray/Sphere Intersection" (Ray Tracing
 * Gems, ch. 7).
 */
class Sphere final : public Shape {
 public:
  Sphere(const Point3& centre, double radius, int m = 24, int n = 24);

  ShapeKind kind() const override { return ShapeKind::Sphere; }
  bool isClosed() const override { return true; }
  bool isFlat() const override { return false; }
  /// Shape's interface (RAYLAB_SHAPE_INTERFACE in Shape.h). area(): exact for a sphere; for an
  /// ellipsoid by Gauss-Legendre quadrature (no closed form), computed once per apply().
  RAYLAB_SHAPE_INTERFACE;
  /// surfaceAt without the surface parameters (si.uv stays (0, 0)): the same point, normal
  /// and error bound, bit for bit, minus an atan2 and an acos. What the renderer asks
  /// (SceneIntersector): no material reads uv, and a texture would ask uvAt.
  SurfaceInteraction geometryAt(const Ray& ray, const Hit& hit) const;
  /// Spherical parameters of a world-space point on the surface: u = azimuth / 2pi about the
  /// object-space z axis, v = polar angle / pi (what surfaceAt puts in si.uv).
  Vec2 uvAt(const Point3& p) const;
  std::unique_ptr<Shape> clone() const override { return std::make_unique<Sphere>(*this); }

  /// Centre in object space (equals world space while worldFromObject is the identity).
  const Point3& centre() const { return m_centre; }
  /// Radius in object space.
  double radius() const { return m_radius; }
  /// Tessellation hint: slices along the polar direction.
  int m() const { return m_m; }
  /// Tessellation hint: slices around the axis.
  int n() const { return m_n; }
  void setTessellation(int m, int n);
  /// True while no non-similarity map was applied: the sphere is round in world space and
  /// centre() and radius() are world-space values (solid-angle light sampling needs that).
  bool isRound() const { return !m_hasTransform; }
  /// Affine map from object space (where the sphere is round) to world space.
  const Transform& worldFromObject() const { return m_worldFromObject; }

  /// The t of intersect(ray) for a round sphere (isRound()), without the virtual call: the
  /// scene's inner loop. Same arithmetic, same result, bit for bit.
  std::optional<double> nearestRoot(const Ray& ray) const {
    const auto t = roots(ray);
    if (!t) return std::nullopt;
    // Pick the nearest root in [tMin, tMax].
    if (t->first >= ray.tMin && t->first <= ray.tMax) return t->first;
    if (t->second >= ray.tMin && t->second <= ray.tMax) return t->second;
    return std::nullopt;
  }

 private:
  /// Both roots of the ray in object space, t0 <= t1; nothing when the ray misses.
  std::optional<std::pair<double, double>> roots(const Ray& r) const {
    // Solve |o + t d - c|^2 = radius^2 for t, with d not necessarily unit length.
    const Vec3 f = r.origin - m_centre;
    const double a = glm::dot(r.direction, r.direction);
    // 1 / a once: a ray's spheres share it (SceneIntersector computes it once per ray).
    const double inverseA = 1.0 / a;
    const double halfB = glm::dot(f, r.direction);
    // Compute the discriminant from the distance between the centre and the line, which
    // loses far less precision than halfB^2 - a c when the sphere is small or far away:
    // a (r^2 - l^2), both squares correctly rounded and their difference exact where it is
    // small (Sterbenz), within a few ulps of r^2 like (r - l)(r + l), without its root.
    const Vec3 l = f - (halfB * inverseA) * r.direction;
    const double lineDistance2 = glm::dot(l, l);
    const double radius2 = m_radius * m_radius;
    // A clear miss: the line passes farther than the radius even allowing for the
    // rounding of the test below.
    if (lineDistance2 > radius2 * (1.0 + 1e-9)) return std::nullopt;
    const double discriminant = a * (radius2 - lineDistance2);
    if (discriminant < 0.0) return std::nullopt;

    // Stable roots: q has the sign of -halfB, so no cancellation happens in either root.
    const double c = glm::dot(f, f) - radius2;
    const double q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
    double t0, t1;
    if (q == 0.0) {
      t0 = t1 = 0.0;
    } else {
      t0 = q * inverseA;
      t1 = c / q;
    }
    if (t0 > t1) std::swap(t0, t1);
    return std::make_pair(t0, t1);
  }
  /// Ratio of world to object area at the object-space unit normal n of the sphere:
  /// |det L| |L^-T n| for the linear part L of worldFromObject (1 without a transform).
  double areaScale(const Vec3& objectNormal) const;
  /// Recomputes m_area after a change of radius or transform.
  void updateArea();

  Point3 m_centre;
  double m_radius;
  int m_m;
  int m_n;
  Transform m_worldFromObject;
  bool m_hasTransform = false;
  double m_area = 0.0;  ///< World-space surface area.
};

}  // namespace raylab
