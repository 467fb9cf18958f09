#include "raylab/core/Sphere.h"

#include "raylab/core/Scene.h"
#include "scene/ObjectWriter.h"
#include "scene/SceneFields.h"
#include "shapes/ShapeFormat.h"

#include "raylab/core/Check.h"
#include "raylab/core/Limits.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/Sampling.h"

#include <array>
#include <cmath>

namespace raylab {

namespace {

/// Spherical parameters of a unit vector about the z axis: u = azimuth / 2pi, v = polar / pi.
Vec2 sphericalUv(const Vec3& unit) {
  double phi = std::atan2(unit.y, unit.x);
  if (phi < 0.0) phi += 2.0 * kPi;
  const double theta = std::acos(glm::clamp(unit.z, -1.0, 1.0));
  return {phi / (2.0 * kPi), theta / kPi};
}

/// Nodes and weights of the N-point Gauss-Legendre rule on [-1, 1] (exact for
/// polynomials of degree 2N - 1), found by Newton's method on P_N (Numerical Recipes 4.6).
template <int N>
struct GaussLegendre {
  std::array<double, N> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < N; ++i) {
      // Start from the Chebyshev-like estimate of root i, then polish with Newton.
      double z = std::cos(kPi * (i + 0.75) / (N + 0.5));
      double dp = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        // P_N(z) and its derivative by the three-term recurrence.
        double p0 = 1.0, p1 = 0.0;
        for (int k = 1; k <= N; ++k) {
          const double p2 = p1;
          p1 = p0;
          p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
        }
        dp = N * (z * p0 - p1) / (z * z - 1.0);
        const double step = p0 / dp;
        z -= step;
        if (std::abs(step) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

/// Refuses a sphere past RayLab's largest coordinate.
void checkSize(const Point3& centre, double radius) {
  // Past RayLab's largest coordinate the hit's quadratic overflows: a sphere of radius
  // 1e300 was hit at t = inf (issue 38). The scene format has the same limit.
  const auto tooLarge = [](double v) { return !(std::abs(v) <= limits::kMaxCoordinate); };
  if (tooLarge(radius) || tooLarge(centre.x) || tooLarge(centre.y) || tooLarge(centre.z))
    throw Shape::InvalidGeometry("sphere centre " + raylab::toString(centre) + " and radius " +
                                 std::to_string(radius) +
                                 " must lie within RayLab's largest coordinate, 1e12");
}

}  // namespace

Sphere::Sphere(const Point3& centre, double radius, int m, int n)
    : m_centre(centre), m_radius(radius), m_m(m), m_n(n) {
  if (!isFinite(centre))
    throw InvalidGeometry("sphere centre must be finite, got " + raylab::toString(centre));
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InvalidGeometry("sphere radius must be positive and finite, got " +
                          std::to_string(radius));
  checkSize(m_centre, m_radius);
  setTessellation(m, n);
  updateArea();
}

void Sphere::setTessellation(int m, int n) {
  if (m < 2 || n < 3)
    throw InvalidGeometry("sphere tessellation needs m >= 2 and n >= 3, got m=" +
                          std::to_string(m) + ", n=" + std::to_string(n));
  m_m = m;
  m_n = n;
}

std::optional<Hit> Sphere::intersect(const Ray& ray) const {
  const Ray r = m_hasTransform ? m_worldFromObject.inverseTransformRay(ray) : ray;
  const auto t = roots(r);
  if (!t) return std::nullopt;
  // Pick the nearest root in [tMin, tMax].
  if (t->first >= ray.tMin && t->first <= ray.tMax) return Hit{t->first, 0, {}};
  if (t->second >= ray.tMin && t->second <= ray.tMax) return Hit{t->second, 0, {}};
  return std::nullopt;
}

SurfaceInteraction Sphere::surfaceAt(const Ray& ray, const Hit& hit) const {
  SurfaceInteraction si = geometryAt(ray, hit);
  si.uv = uvAt(si.p);
  return si;
}

Vec2 Sphere::uvAt(const Point3& p) const {
  const Point3 object = m_hasTransform ? m_worldFromObject.inverseTransformPoint(p) : p;
  const Vec3 radial = object - m_centre;
  const double length = glm::length(radial);
  return sphericalUv(length > 0.0 ? radial / length : Vec3(0.0, 0.0, 1.0));
}

SurfaceInteraction Sphere::geometryAt(const Ray& ray, const Hit& hit) const {
  const Transform& m = m_worldFromObject;
  const Point3 world = ray.at(hit.t);
  // Project the hit back onto the surface in object space: ray.at(t) is off by the
  // rounding of t, and secondary rays start from this point.
  const Point3 object = m_hasTransform ? m.inverseTransformPoint(world) : world;
  Vec3 radial = object - m_centre;
  const double length = glm::length(radial);
  // By the reciprocal: one division instead of three (a rounding more, counted below).
  radial = length > 0.0 ? radial * (1.0 / length) : Vec3(0.0, 0.0, 1.0);

  SurfaceInteraction si;
  si.t = hit.t;
  const Point3 onSurface = m_centre + m_radius * radial;
  si.p = m_hasTransform ? m.transformPoint(onSurface) : onSurface;
  // Error of centre + r * radial (normalising by a reciprocal, scaling, adding: gamma(6)),
  // then of the map.
  const Vec3 objectError = kRoundingGamma<6> * (absolute(m_centre) + absolute(m_radius * radial));
  si.pError =
      m_hasTransform ? transformedPointError(m.matrix(), onSurface, objectError) : objectError;
  si.n = m_hasTransform ? m.transformNormal(radial) : radial;
  si.frontFace = glm::dot(ray.direction, si.n) < 0.0;
  si.primitive = 0;
  return si;
}

std::vector<Crossing> Sphere::intersectAll(const Ray& ray) const {
  const Ray r = m_hasTransform ? m_worldFromObject.inverseTransformRay(ray) : ray;
  std::vector<Crossing> out;
  const auto t = roots(r);
  if (!t) return out;
  // The line enters at the smaller root and leaves at the larger one; a tangent ray
  // enters and leaves at the same point.
  if (t->first >= ray.tMin && t->first <= ray.tMax) out.push_back({t->first, true, 0});
  if (t->second >= ray.tMin && t->second <= ray.tMax) out.push_back({t->second, false, 0});
  return out;
}

Normal3 Sphere::normal(const Point3& p) const {
  const Point3 object = m_hasTransform ? m_worldFromObject.inverseTransformPoint(p) : p;
  const Vec3 radial = glm::normalize(object - m_centre);
  return m_hasTransform ? m_worldFromObject.transformNormal(radial) : radial;
}

bool Sphere::inside(const Point3& p) const {
  const Point3 object = m_hasTransform ? m_worldFromObject.inverseTransformPoint(p) : p;
  const Vec3 f = object - m_centre;
  return glm::dot(f, f) < m_radius * m_radius;
}

void Sphere::apply(const Mat4& matrix) {
  if (!isAffine(matrix) || glm::determinant(Mat3(matrix)) == 0.0)
    throw InvalidGeometry("sphere: apply() needs an invertible affine matrix");
  const Transform t(matrix);
  if (!m_hasTransform && t.isSimilarity()) {
    // Rotation, translation and uniform scale keep a sphere a sphere.
    m_centre = t.transformPoint(m_centre);
    m_radius *= t.uniformScale();
    checkSize(m_centre, m_radius);
    updateArea();
    return;
  }
  m_worldFromObject = t * m_worldFromObject;
  m_hasTransform = !m_worldFromObject.isIdentity();
  updateArea();
}

double Sphere::areaScale(const Vec3& objectNormal) const {
  if (!m_hasTransform) return 1.0;
  // A small patch dA with normal n maps to |det L| |L^-T n| dA (Nanson's formula).
  const Mat3 linear(m_worldFromObject.matrix());
  return std::abs(glm::determinant(linear)) *
         glm::length(m_worldFromObject.normalMatrix() * objectNormal);
}

void Sphere::updateArea() {
  const double sphereArea = 4.0 * kPi * m_radius * m_radius;
  if (!m_hasTransform) {
    m_area = sphereArea;
    return;
  }
  // The ellipsoid's area is the sphere's area weighted by areaScale: integrate over the
  // unit sphere, Gauss-Legendre in z = cos(theta) and the trapezoid rule in phi (exact
  // to rounding for smooth periodic integrands).
  static const GaussLegendre<64> rule;
  constexpr int kPhiSteps = 128;
  double sum = 0.0;
  for (int i = 0; i < 64; ++i) {
    const double z = rule.x[i];
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    double ring = 0.0;
    for (int j = 0; j < kPhiSteps; ++j) {
      const double phi = 2.0 * kPi * j / kPhiSteps;
      ring += areaScale(Vec3(s * std::cos(phi), s * std::sin(phi), z));
    }
    sum += rule.w[i] * ring * (2.0 * kPi / kPhiSteps);
  }
  m_area = m_radius * m_radius * sum;
}

double Sphere::area() const { return m_area; }

ShapeSample Sphere::sampleArea(const Vec2& u) const {
  // Uniform on the round sphere in object space; the transform stretches the density by
  // 1 / areaScale at each point, which pdfArea reports.
  const Vec3 radial = sampleUniformSphere(u);
  const Point3 object = m_centre + m_radius * radial;
  ShapeSample s;
  s.p = m_hasTransform ? m_worldFromObject.transformPoint(object) : object;
  s.n = m_hasTransform ? m_worldFromObject.transformNormal(radial) : radial;
  s.pdfArea = 1.0 / (4.0 * kPi * m_radius * m_radius * areaScale(radial));
  return s;
}

double Sphere::pdfArea(const Point3& p) const {
  if (!m_hasTransform) return 1.0 / m_area;
  const Vec3 radial = glm::normalize(m_worldFromObject.inverseTransformPoint(p) - m_centre);
  return 1.0 / (4.0 * kPi * m_radius * m_radius * areaScale(radial));
}

Bounds3 Sphere::bounds() const {
  if (!m_hasTransform) return {m_centre - Vec3(m_radius), m_centre + Vec3(m_radius)};
  // An ellipsoid's half-extent along world axis i is radius * |row i of the linear part|.
  const Mat3 l(m_worldFromObject.matrix());
  const Point3 c = m_worldFromObject.transformPoint(m_centre);
  Vec3 half;
  for (int i = 0; i < 3; ++i) half[i] = m_radius * glm::length(Vec3(l[0][i], l[1][i], l[2][i]));
  return {c - half, c + half};
}

std::string Sphere::toString() const {
  std::string s = "Sphere[centre=" + raylab::toString(m_centre) +
                  ", radius=" + std::to_string(m_radius) + ", m=" + std::to_string(m_m) +
                  ", n=" + std::to_string(m_n);
  if (m_hasTransform) s += ", worldFromObject=" + m_worldFromObject.toString();
  return s + "]";
}

// The scene file's "sphere": centre, radius and the slices m, n its mesh is drawn with.
namespace detail {
const ShapeFormat& sphereFormat();  // below
}  // namespace detail

namespace {

using nlohmann::json;

std::unique_ptr<Shape> readSphere(const json& j, const std::string& path, const SceneFields& in,
                                  SceneObject&) {
  in.onlyKeys(j, path, detail::sphereFormat().keys);
  const double radius = in.length(in.member(j, path, "radius"), path + "/radius", "radius");
  const int m = j.contains("m") ? in.integer(j["m"], path + "/m") : 24;
  const int n = j.contains("n") ? in.integer(j["n"], path + "/n") : 24;
  if (m < 2) in.fail(path + "/m", "m (polar slices) must be at least 2");
  if (n < 3) in.fail(path + "/n", "n (azimuthal slices) must be at least 3");
  if (m > limits::kMaxSphereSlices || n > limits::kMaxSphereSlices)
    in.fail(path + (m > limits::kMaxSphereSlices ? "/m" : "/n"),
            "m and n (sphere slices) must be at most " + std::to_string(limits::kMaxSphereSlices));
  return std::make_unique<Sphere>(in.vec3(in.member(j, path, "centre"), path + "/centre"), radius,
                                  m, n);
}

/// A sphere's own transform, which its parameters cannot hold, goes to `transform`.
ojson writeSphere(const SceneObject& object, const std::string&, ojson& transform) {
  const auto& s = static_cast<const Sphere&>(*object.shape);
  if (!s.worldFromObject().isIdentity()) transform = matrixTransform(s.worldFromObject().matrix());
  return ObjectWriter(detail::sphereFormat().keys)
      .add("type", "sphere")
      .add("centre", toJson(s.centre()))
      .add("radius", s.radius())
      .add("m", s.m())
      .add("n", s.n())
      .take();
}

ojson sphereExample(const Point3& p, double size, const Vec3&, const Vec3&) {
  return {{"type", "sphere"}, {"centre", toJson(p)}, {"radius", 0.5 * size}};
}

}  // namespace

namespace detail {
const ShapeFormat& sphereFormat() {
  static const ShapeFormat format{
      ShapeKind::Sphere, "sphere",    {"type", "centre", "radius", "m", "n"},
      readSphere,        writeSphere, sphereExample};
  return format;
}
}  // namespace detail

}  // namespace raylab
