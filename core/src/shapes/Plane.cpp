#include "raylab/core/Plane.h"

#include "raylab/core/Scene.h"
#include "scene/ObjectWriter.h"
#include "scene/SceneFields.h"
#include "shapes/ShapeFormat.h"

#include "raylab/core/RayOffset.h"
#include "raylab/core/Transform.h"

#include <cmath>

namespace raylab {

namespace {

/// Two unit tangents completing n to a right-handed orthonormal frame (Duff et al.,
/// "Building an Orthonormal Basis, Revisited", JCGT 2017).
void tangentFrame(const Normal3& n, Vec3& t1, Vec3& t2) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  t1 = Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  t2 = Vec3(b, sign + n.y * n.y * a, -n.y);
}

}  // namespace

Plane::Plane(const Point3& point, const Normal3& normal) : m_point(point) {
  const double length = glm::length(normal);
  if (!(length > 0.0) || !std::isfinite(length))
    throw InvalidGeometry("plane normal must be a non-zero finite vector, got " +
                          raylab::toString(normal));
  if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
    throw InvalidGeometry("plane point must be finite");
  m_normal = normal / length;
}

std::optional<Hit> Plane::intersect(const Ray& ray) const {
  // Solve (o + t d - point) . n = 0; a ray parallel to the plane (also one lying in it)
  // has no single crossing.
  const double denominator = glm::dot(m_normal, ray.direction);
  if (denominator == 0.0) return std::nullopt;
  const double t = glm::dot(m_point - ray.origin, m_normal) / denominator;
  if (!(t >= ray.tMin && t <= ray.tMax)) return std::nullopt;
  return Hit{t, 0, {}};
}

SurfaceInteraction Plane::surfaceAt(const Ray& ray, const Hit& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  // Project onto the plane to remove the rounding of t.
  const Point3 p = ray.at(hit.t);
  si.p = p - glm::dot(p - m_point, m_normal) * m_normal;
  // The projection: a difference, a dot product, a product and a difference.
  si.pError = kRoundingGamma<7> * (absolute(p) + absolute(m_point));
  si.n = m_normal;
  si.frontFace = glm::dot(ray.direction, m_normal) < 0.0;
  Vec3 t1, t2;
  tangentFrame(m_normal, t1, t2);
  si.uv = {glm::dot(si.p - m_point, t1), glm::dot(si.p - m_point, t2)};
  si.primitive = 0;
  return si;
}

std::vector<Crossing> Plane::intersectAll(const Ray& ray) const {
  const auto hit = intersect(ray);
  if (!hit) return {};
  // Going against the normal means going into the half-space behind it.
  return {Crossing{hit->t, glm::dot(ray.direction, m_normal) < 0.0, 0}};
}

Normal3 Plane::normal(const Point3&) const { return m_normal; }

bool Plane::inside(const Point3& p) const { return glm::dot(p - m_point, m_normal) < 0.0; }

void Plane::apply(const Mat4& m) {
  if (!isAffine(m) || glm::determinant(Mat3(m)) == 0.0)
    throw InvalidGeometry("plane: apply() needs an invertible affine matrix");
  const Transform t(m);
  m_point = t.transformPoint(m_point);
  m_normal = t.transformNormal(m_normal);
}

Bounds3 Plane::bounds() const {
  // Infinite, except along an axis the plane is perpendicular to.
  Bounds3 b(Point3(-kInfinity), Point3(kInfinity));
  for (int i = 0; i < 3; ++i) {
    if (std::abs(m_normal[i]) == 1.0) {
      b.lower[i] = m_point[i];
      b.upper[i] = m_point[i];
    }
  }
  return b;
}

double Plane::area() const { return kInfinity; }

ShapeSample Plane::sampleArea(const Vec2&) const {
  throw InvalidGeometry("a plane cannot be a light: its area is infinite (" + toString() +
                        "); use a quad for an area light");
}

double Plane::pdfArea(const Point3&) const { return 0.0; }

std::string Plane::toString() const {
  return "Plane[point=" + raylab::toString(m_point) + ", normal=" + raylab::toString(m_normal) +
         "]";
}

// The scene file's "plane": a point and the normal.
namespace detail {
const ShapeFormat& planeFormat();  // below
}  // namespace detail

namespace {

using nlohmann::json;

std::unique_ptr<Shape> readPlane(const json& j, const std::string& path, const SceneFields& in,
                                 SceneObject&) {
  in.onlyKeys(j, path, detail::planeFormat().keys);
  return std::make_unique<Plane>(in.vec3(in.member(j, path, "point"), path + "/point"),
                                 in.nonZero(in.member(j, path, "normal"), path + "/normal"));
}

ojson writePlane(const SceneObject& object, const std::string&, ojson&) {
  const auto& p = static_cast<const Plane&>(*object.shape);
  return ObjectWriter(detail::planeFormat().keys)
      .add("type", "plane")
      .add("point", toJson(p.point()))
      .add("normal", toJson(p.planeNormal()))
      .take();
}

ojson planeExample(const Point3& p, double, const Vec3&, const Vec3&) {
  return {{"type", "plane"}, {"point", toJson(p)}, {"normal", toJson(Vec3(0, 1, 0))}};
}

}  // namespace

namespace detail {
const ShapeFormat& planeFormat() {
  static const ShapeFormat format{ShapeKind::Plane, "plane",    {"type", "point", "normal"},
                                  readPlane,        writePlane, planeExample};
  return format;
}
}  // namespace detail

}  // namespace raylab
