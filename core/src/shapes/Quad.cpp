#include "raylab/core/Quad.h"

#include "raylab/core/Scene.h"
#include "scene/ObjectWriter.h"
#include "scene/SceneFields.h"
#include "shapes/ShapeFormat.h"

#include "raylab/core/RayOffset.h"
#include "raylab/core/Transform.h"

#include <cmath>

namespace raylab {

Quad::Quad(const Point3& corner, const Vec3& edgeU, const Vec3& edgeV)
    : m_corner(corner), m_u(edgeU), m_v(edgeV) {
  update();
}

void Quad::update() {
  const Vec3 n = glm::cross(m_u, m_v);
  const double n2 = glm::dot(n, n);
  if (!(n2 > 0.0) || !std::isfinite(n2))
    throw InvalidGeometry("quad edges must be finite and not parallel, got u=" +
                          raylab::toString(m_u) + ", v=" + raylab::toString(m_v));
  m_normal = n / std::sqrt(n2);
  m_w = n / n2;
}

std::optional<Hit> Quad::intersect(const Ray& ray) const {
  // Hit the supporting plane first.
  const double denominator = glm::dot(m_normal, ray.direction);
  if (denominator == 0.0) return std::nullopt;
  const double t = glm::dot(m_corner - ray.origin, m_normal) / denominator;
  if (!(t >= ray.tMin && t <= ray.tMax)) return std::nullopt;
  // Express the plane point as corner + s u + r v and keep it when s, r are in [0, 1].
  const Vec3 q = ray.at(t) - m_corner;
  const double s = glm::dot(m_w, glm::cross(q, m_v));
  const double r = glm::dot(m_w, glm::cross(m_u, q));
  if (s < 0.0 || s > 1.0 || r < 0.0 || r > 1.0) return std::nullopt;
  return Hit{t, 0, {s, r}};
}

SurfaceInteraction Quad::surfaceAt(const Ray& ray, const Hit& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  si.p = m_corner + hit.uv.x * m_u + hit.uv.y * m_v;
  // Two products and two sums: within gamma(4) of the sum of the magnitudes.
  si.pError = kRoundingGamma<4> *
              (absolute(m_corner) + absolute(hit.uv.x * m_u) + absolute(hit.uv.y * m_v));
  si.n = m_normal;
  si.frontFace = glm::dot(ray.direction, m_normal) < 0.0;
  si.uv = hit.uv;
  si.primitive = 0;
  return si;
}

std::vector<Crossing> Quad::intersectAll(const Ray& ray) const {
  const auto hit = intersect(ray);
  if (!hit) return {};
  return {Crossing{hit->t, glm::dot(ray.direction, m_normal) < 0.0, 0}};
}

Normal3 Quad::normal(const Point3&) const { return m_normal; }

bool Quad::inside(const Point3&) const { return false; }

void Quad::apply(const Mat4& m) {
  if (!isAffine(m) || glm::determinant(Mat3(m)) == 0.0)
    throw InvalidGeometry("quad: apply() needs an invertible affine matrix");
  const Transform t(m);
  m_corner = t.transformPoint(m_corner);
  m_u = t.transformVector(m_u);
  m_v = t.transformVector(m_v);
  update();
}

Bounds3 Quad::bounds() const {
  Bounds3 b(m_corner, m_corner + m_u);
  b.extend(m_corner + m_v);
  b.extend(m_corner + m_u + m_v);
  return b;
}

double Quad::area() const { return glm::length(glm::cross(m_u, m_v)); }

ShapeSample Quad::sampleArea(const Vec2& u) const {
  // (s, t) uniform in [0, 1]^2 is uniform on a parallelogram (the map is linear).
  ShapeSample s;
  s.p = m_corner + u.x * m_u + u.y * m_v;
  s.n = m_normal;
  s.pdfArea = 1.0 / area();
  return s;
}

double Quad::pdfArea(const Point3&) const { return 1.0 / area(); }

std::string Quad::toString() const {
  return "Quad[corner=" + raylab::toString(m_corner) + ", u=" + raylab::toString(m_u) +
         ", v=" + raylab::toString(m_v) + "]";
}

// The scene file's "quad": a corner and its two edges u and v.
namespace detail {
const ShapeFormat& quadFormat();  // below
}  // namespace detail

namespace {

using nlohmann::json;

std::unique_ptr<Shape> readQuad(const json& j, const std::string& path, const SceneFields& in,
                                SceneObject&) {
  in.onlyKeys(j, path, detail::quadFormat().keys);
  return std::make_unique<Quad>(in.vec3(in.member(j, path, "corner"), path + "/corner"),
                                in.nonZero(in.member(j, path, "u"), path + "/u"),
                                in.nonZero(in.member(j, path, "v"), path + "/v"));
}

ojson writeQuad(const SceneObject& object, const std::string&, ojson&) {
  const auto& q = static_cast<const Quad&>(*object.shape);
  return ObjectWriter(detail::quadFormat().keys)
      .add("type", "quad")
      .add("corner", toJson(q.corner()))
      .add("u", toJson(q.edgeU()))
      .add("v", toJson(q.edgeV()))
      .take();
}

/// Edges along the camera's right and up: the normal u x v faces the camera.
ojson quadExample(const Point3& p, double size, const Vec3& right, const Vec3& up) {
  return {{"type", "quad"},
          {"corner", toJson(p - 0.5 * size * (right + up))},
          {"u", toJson(size * right)},
          {"v", toJson(size * up)}};
}

}  // namespace

namespace detail {
const ShapeFormat& quadFormat() {
  static const ShapeFormat format{ShapeKind::Quad, "quad",    {"type", "corner", "u", "v"},
                                  readQuad,        writeQuad, quadExample};
  return format;
}
}  // namespace detail

}  // namespace raylab
