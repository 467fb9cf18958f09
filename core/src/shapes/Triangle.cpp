#include "raylab/core/Triangle.h"

#include "raylab/core/Scene.h"
#include "scene/ObjectWriter.h"
#include "scene/SceneFields.h"
#include "shapes/ShapeFormat.h"

#include "raylab/core/RayOffset.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/Transform.h"
#include "shapes/WatertightTriangle.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace raylab {

std::optional<TriangleHit> intersectTriangle(const Ray& ray, const Point3& p0, const Point3& p1,
                                             const Point3& p2) {
  // The ray's frame and shear for this one triangle; the Bvh computes them once per ray.
  return hitTriangle(ShearedRay(ray), glm::value_ptr(p0), glm::value_ptr(p1), glm::value_ptr(p2),
                     ray.tMax);
}

Triangle::Triangle(const Point3& p0, const Point3& p1, const Point3& p2) : m_p{p0, p1, p2} {
  const double area2 = glm::length(glm::cross(p1 - p0, p2 - p0));
  if (!(area2 > 0.0) || !std::isfinite(area2))
    throw InvalidGeometry(
        "triangle is degenerate (zero area or non-finite vertex): " + raylab::toString(p0) + " " +
        raylab::toString(p1) + " " + raylab::toString(p2));
}

std::optional<Hit> Triangle::intersect(const Ray& ray) const {
  const auto h = intersectTriangle(ray, m_p[0], m_p[1], m_p[2]);
  if (!h) return std::nullopt;
  return Hit{h->t, 0, {h->b1, h->b2}};
}

SurfaceInteraction Triangle::surfaceAt(const Ray& ray, const Hit& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  const double b1 = hit.uv.x, b2 = hit.uv.y, b0 = 1.0 - b1 - b2;
  // The barycentric point lies on the triangle up to rounding, unlike ray.at(t).
  si.p = b0 * m_p[0] + b1 * m_p[1] + b2 * m_p[2];
  // The barycentric sum (pbrt 4th ed., 6.8.5): gamma(7) of the terms' magnitudes.
  si.pError =
      kRoundingGamma<7> * (absolute(b0 * m_p[0]) + absolute(b1 * m_p[1]) + absolute(b2 * m_p[2]));
  si.n = normal(si.p);
  si.frontFace = glm::dot(ray.direction, si.n) < 0.0;
  si.uv = hit.uv;
  si.primitive = 0;
  return si;
}

std::vector<Crossing> Triangle::intersectAll(const Ray& ray) const {
  const auto hit = intersect(ray);
  if (!hit) return {};
  return {Crossing{hit->t, glm::dot(ray.direction, normal(m_p[0])) < 0.0, 0}};
}

Normal3 Triangle::normal(const Point3&) const {
  return glm::normalize(glm::cross(m_p[1] - m_p[0], m_p[2] - m_p[0]));
}

bool Triangle::inside(const Point3&) const { return false; }

void Triangle::apply(const Mat4& m) {
  if (!isAffine(m) || glm::determinant(Mat3(m)) == 0.0)
    throw InvalidGeometry("triangle: apply() needs an invertible affine matrix");
  const Transform t(m);
  for (Point3& p : m_p) p = t.transformPoint(p);
}

Bounds3 Triangle::bounds() const {
  Bounds3 b(m_p[0], m_p[1]);
  b.extend(m_p[2]);
  return b;
}

double Triangle::area() const {
  return 0.5 * glm::length(glm::cross(m_p[1] - m_p[0], m_p[2] - m_p[0]));
}

ShapeSample Triangle::sampleArea(const Vec2& u) const {
  const Vec2 b = sampleUniformTriangle(u);
  ShapeSample s;
  s.p = (1.0 - b.x - b.y) * m_p[0] + b.x * m_p[1] + b.y * m_p[2];
  s.n = normal(s.p);
  s.pdfArea = 1.0 / area();
  return s;
}

double Triangle::pdfArea(const Point3&) const { return 1.0 / area(); }

std::string Triangle::toString() const {
  return "Triangle[" + raylab::toString(m_p[0]) + ", " + raylab::toString(m_p[1]) + ", " +
         raylab::toString(m_p[2]) + "]";
}

// The scene file's "triangle": its three vertices.
namespace detail {
const ShapeFormat& triangleFormat();  // below
}  // namespace detail

namespace {

using nlohmann::json;

std::unique_ptr<Shape> readTriangle(const json& j, const std::string& path, const SceneFields& in,
                                    SceneObject&) {
  in.onlyKeys(j, path, detail::triangleFormat().keys);
  const json& v = in.member(j, path, "vertices");
  if (!v.is_array() || v.size() != 3) in.fail(path + "/vertices", "expected three points");
  return std::make_unique<Triangle>(in.vec3(v[0], path + "/vertices/0"),
                                    in.vec3(v[1], path + "/vertices/1"),
                                    in.vec3(v[2], path + "/vertices/2"));
}

ojson writeTriangle(const SceneObject& object, const std::string&, ojson&) {
  const auto& t = static_cast<const Triangle&>(*object.shape);
  return ObjectWriter(detail::triangleFormat().keys)
      .add("type", "triangle")
      .add("vertices",
           ojson::array({toJson(t.vertex(0)), toJson(t.vertex(1)), toJson(t.vertex(2))}))
      .take();
}

ojson triangleExample(const Point3& p, double size, const Vec3& right, const Vec3& up) {
  return {{"type", "triangle"},
          {"vertices", ojson::array({toJson(p + size * (-0.5 * right - 0.4 * up)),
                                     toJson(p + size * (0.5 * right - 0.4 * up)),
                                     toJson(p + size * 0.6 * up)})}};
}

}  // namespace

namespace detail {
const ShapeFormat& triangleFormat() {
  static const ShapeFormat format{ShapeKind::Triangle, "triangle",    {"type", "vertices"},
                                  readTriangle,        writeTriangle, triangleExample};
  return format;
}
}  // namespace detail

}  // namespace raylab
