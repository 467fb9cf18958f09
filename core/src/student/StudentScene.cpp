// A scene whose shapes answer intersect() with a student's hooks (StudentHooks.h): each
// hooked object's shape is wrapped in a StudentShape that asks the student for t and lets
// the engine's own shape make the hit's geometry at that t.

#include "raylab/core/StudentHooks.h"

#include "raylab/core/Box.h"
#include "raylab/core/Plane.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Triangle.h"

#include <cmath>
#include <utility>

namespace raylab {

namespace {

/// Whether a box's map from [-1, 1]^3 is a scale and a translation (axis-aligned).
bool axisAligned(const Box& box) {
  const Mat4& m = box.worldFromBox().matrix();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (r != c && m[c][r] != 0.0) return false;
  return true;
}

/// The box face (2 * axis + positive side) nearest to the box-space point b.
int boxFace(const Point3& b) {
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(b[i]) > std::abs(b[axis])) axis = i;
  return 2 * axis + (b[axis] > 0.0 ? 1 : 0);
}

/// Barycentrics (b1, b2) of the point p in the triangle's plane.
Vec2 barycentrics(const Triangle& tri, const Point3& p) {
  const Vec3 e1 = tri.vertex(1) - tri.vertex(0), e2 = tri.vertex(2) - tri.vertex(0);
  const Vec3 q = p - tri.vertex(0);
  const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const double q1 = glm::dot(q, e1), q2 = glm::dot(q, e2);
  const double det = d11 * d22 - d12 * d12;
  if (!(det != 0.0)) return Vec2(0.0);
  return {(d22 * q1 - d12 * q2) / det, (d11 * q2 - d12 * q1) / det};
}

/**
 * \brief A shape that answers intersect() with a student's hook: the student's t becomes
 * the Hit, and the engine's own shape (kept inside) makes the geometry there (surfaceAt),
 * samples it, draws it and answers everything else.
 *
 * kind() reports Quad for a wrapped sphere, so that the scene intersector searches it
 * through this virtual intersect (never its SIMD sphere batch, which would bypass the
 * student) and samples it by area if it is a light; other shapes report their own kind.
 */
class StudentShape final : public Shape {
 public:
  StudentShape(std::unique_ptr<Shape> inner, const StudentHooks& hooks, StudentLog* log, int object)
      : m_inner(std::move(inner)), m_hooks(&hooks), m_log(log), m_object(object) {}

  ShapeKind kind() const override {
    return m_inner->kind() == ShapeKind::Sphere ? ShapeKind::Quad : m_inner->kind();
  }
  bool isClosed() const override { return m_inner->isClosed(); }
  bool isFlat() const override { return m_inner->isFlat(); }

  std::optional<Hit> intersect(const Ray& ray) const override {
    StudentCall call;
    call.object = m_object;
    call.query = ray;
    try {
      call.student = ask(ray, call.piece);
    } catch (const StudentHooks::Failure& failure) {
      call.error = failure.what();
    }
    std::optional<Hit> hit;
    if (call.error.empty() && call.student && std::isfinite(*call.student) &&
        *call.student >= ray.tMin && *call.student <= ray.tMax)
      hit = hitAt(ray, *call.student);
    if (m_log) m_log->calls.push_back(std::move(call));
    return hit;
  }
  SurfaceInteraction surfaceAt(const Ray& ray, const Hit& hit) const override {
    return m_inner->surfaceAt(ray, hit);
  }
  std::vector<Crossing> intersectAll(const Ray& ray) const override {
    return m_inner->intersectAll(ray);
  }
  Normal3 normal(const Point3& p) const override { return m_inner->normal(p); }
  bool inside(const Point3& p) const override { return m_inner->inside(p); }
  void apply(const Mat4& m) override { m_inner->apply(m); }
  Bounds3 bounds() const override { return m_inner->bounds(); }
  std::unique_ptr<Shape> clone() const override {
    return std::make_unique<StudentShape>(m_inner->clone(), *m_hooks, m_log, m_object);
  }
  std::string toString() const override { return "student " + m_inner->toString(); }
  double area() const override { return m_inner->area(); }
  ShapeSample sampleArea(const Vec2& u) const override { return m_inner->sampleArea(u); }
  double pdfArea(const Point3& p) const override { return m_inner->pdfArea(p); }

 private:
  /// The student's answer for `ray`; names the piece asked.
  std::optional<double> ask(const Ray& ray, const char*& piece) const {
    const Point3& o = ray.origin;
    const Vec3& d = ray.direction;
    switch (m_inner->kind()) {
      case ShapeKind::Sphere: {
        const auto& s = static_cast<const Sphere&>(*m_inner);
        piece = "intersect_sphere";
        return m_hooks->intersectSphere(o, d, s.centre(), s.radius(), ray.tMin, ray.tMax);
      }
      case ShapeKind::Plane: {
        const auto& p = static_cast<const Plane&>(*m_inner);
        piece = "intersect_plane";
        return m_hooks->intersectPlane(o, d, p.point(), p.planeNormal(), ray.tMin, ray.tMax);
      }
      case ShapeKind::Box: {
        const auto& b = static_cast<const Box&>(*m_inner);
        piece = "intersect_box";
        if (axisAligned(b)) {
          const Bounds3 box = b.bounds();
          return m_hooks->intersectBox(o, d, box.lower, box.upper, ray.tMin, ray.tMax);
        }
        const Ray local = b.worldFromBox().inverseTransformRay(ray);
        return m_hooks->intersectBox(local.origin, local.direction, Point3(-1.0), Point3(1.0),
                                     ray.tMin, ray.tMax);
      }
      case ShapeKind::Triangle: {
        const auto& t = static_cast<const Triangle&>(*m_inner);
        piece = "intersect_triangle";
        return m_hooks->intersectTriangle(o, d, t.vertex(0), t.vertex(1), t.vertex(2), ray.tMin,
                                          ray.tMax);
      }
      default:
        return std::nullopt;
    }
  }

  /// The Hit the engine's shape would give at parameter t (face, barycentrics).
  Hit hitAt(const Ray& ray, double t) const {
    Hit hit{t, 0, Vec2(0.0)};
    if (m_inner->kind() == ShapeKind::Box) {
      const auto& b = static_cast<const Box&>(*m_inner);
      hit.primitive = boxFace(b.worldFromBox().inverseTransformPoint(ray.at(t)));
    } else if (m_inner->kind() == ShapeKind::Triangle) {
      hit.uv = barycentrics(static_cast<const Triangle&>(*m_inner), ray.at(t));
    }
    return hit;
  }

  std::unique_ptr<Shape> m_inner;
  const StudentHooks* m_hooks;
  StudentLog* m_log;
  int m_object;
};

/// Whether `hooks` has a piece for this shape.
bool hooked(const Shape& shape, const StudentHooks& hooks) {
  switch (shape.kind()) {
    case ShapeKind::Sphere:
      return hooks.intersectSphere && static_cast<const Sphere&>(shape).isRound();
    case ShapeKind::Plane:
      return bool(hooks.intersectPlane);
    case ShapeKind::Box:
      return bool(hooks.intersectBox);
    case ShapeKind::Triangle:
      return bool(hooks.intersectTriangle);
    default:
      return false;
  }
}

}  // namespace

std::shared_ptr<Scene> studentScene(const Scene& scene, const StudentHooks& hooks,
                                    StudentLog* log) {
  auto copy = std::make_shared<Scene>(scene);
  for (std::size_t i = 0; i < copy->objects.size(); ++i) {
    SceneObject& object = copy->objects[i];
    if (!object.shape || !hooked(*object.shape, hooks)) continue;
    object.shape = std::make_unique<StudentShape>(std::move(object.shape), hooks, log, int(i));
  }
  return copy;
}

}  // namespace raylab
