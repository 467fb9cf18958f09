#include "raylab/core/Box.h"

#include "raylab/core/Scene.h"
#include "scene/ObjectWriter.h"
#include "scene/SceneFields.h"
#include "shapes/ShapeFormat.h"

#include "raylab/core/RayOffset.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

Transform boxTransform(const Point3& centre, const Vec3& size, const Vec3& ax, const Vec3& ay,
                       const Vec3& az) {
  if (!isFinite(centre)) throw Shape::InvalidGeometry("box centre must be finite");
  const Vec3 axes[3] = {ax, ay, az};
  Mat4 m(1.0);
  for (int i = 0; i < 3; ++i) {
    const double length = glm::length(axes[i]);
    if (!(length > 0.0) || !isFinite(axes[i]))
      throw Shape::InvalidGeometry("box axis " + std::to_string(i) +
                                   " must be a non-zero finite vector, got " +
                                   raylab::toString(axes[i]));
    if (!(size[i] > 0.0) || !std::isfinite(size[i]))
      throw Shape::InvalidGeometry("box size must be positive and finite, got " +
                                   raylab::toString(size));
    // Column i maps the canonical coordinate in [-1, 1] to half the edge length.
    m[i] = glm::dvec4(axes[i] / length * (0.5 * size[i]), 0.0);
  }
  m[3] = glm::dvec4(centre, 1.0);
  if (glm::determinant(Mat3(m)) == 0.0)
    throw Shape::InvalidGeometry("box axes must be linearly independent");
  return Transform(m);
}

}  // namespace

Box::Box(const Point3& centre, const Vec3& size)
    : Box(centre, size, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}) {}

Box::Box(const Point3& centre, const Vec3& size, const Vec3& axisX, const Vec3& axisY,
         const Vec3& axisZ)
    : m_worldFromBox(boxTransform(centre, size, axisX, axisY, axisZ)) {
  updateSlabs();
}

Box::Box(const Transform& worldFromBox) : m_worldFromBox(worldFromBox) {
  if (!isAffine(worldFromBox.matrix()) || glm::determinant(Mat3(worldFromBox.matrix())) == 0.0)
    throw InvalidGeometry("box: worldFromBox must be an invertible affine matrix");
  updateSlabs();
}

void Box::updateSlabs() {
  const Mat4& m = m_worldFromBox.matrix();
  const Point3 c(m[3]);
  const Vec3 columns[3] = {Vec3(m[0]), Vec3(m[1]), Vec3(m[2])};
  for (int i = 0; i < 3; ++i) {
    // The faces of slab i contain columns j and k; their normal is perpendicular to both.
    const Vec3& a = columns[(i + 1) % 3];
    const Vec3& b = columns[(i + 2) % 3];
    Vec3 n = glm::cross(a, b);
    // Exact unit normals for axis-aligned faces (the cross product of exact axes is
    // exact, but normalising could round).
    const double length = glm::length(n);
    n = (n.x == 0.0 && n.y == 0.0) || (n.y == 0.0 && n.z == 0.0) || (n.x == 0.0 && n.z == 0.0)
            ? glm::sign(n)
            : n / length;
    if (glm::dot(n, columns[i]) < 0.0) n = -n;
    m_slabNormal[i] = n;
    m_slabCentre[i] = glm::dot(n, c);
    m_slabHalf[i] = glm::dot(n, columns[i]);
  }
}

std::optional<Box::Span> Box::span(const Ray& ray) const {
  // Slab test: for each pair of parallel faces, the interval of t between their planes;
  // the box is the intersection of the three intervals.
  Span s{-kInfinity, kInfinity, -1, -1};
  for (int axis = 0; axis < 3; ++axis) {
    // Signed distance of the origin from the slab's middle plane, and the speed along n.
    const double o = glm::dot(m_slabNormal[axis], ray.origin) - m_slabCentre[axis];
    const double d = glm::dot(m_slabNormal[axis], ray.direction);
    const double h = m_slabHalf[axis];
    if (d == 0.0) {
      // Parallel to this slab: either always between its planes, or never.
      if (o < -h || o > h) return std::nullopt;
      continue;
    }
    // Entering and leaving parameters of the slab; which plane comes first depends on
    // the sign of d.
    double tNear = (-h - o) / d;
    double tFar = (h - o) / d;
    int faceNear = 2 * axis, faceFar = 2 * axis + 1;
    if (tNear > tFar) {
      std::swap(tNear, tFar);
      std::swap(faceNear, faceFar);
    }
    if (tNear > s.t0) {
      s.t0 = tNear;
      s.face0 = faceNear;
    }
    if (tFar < s.t1) {
      s.t1 = tFar;
      s.face1 = faceFar;
    }
    if (s.t0 > s.t1) return std::nullopt;
  }
  if (s.face0 < 0 || s.face1 < 0) return std::nullopt;  // zero direction
  return s;
}

std::optional<Hit> Box::intersect(const Ray& ray) const {
  const auto s = span(ray);
  if (!s) return std::nullopt;
  // Nearest of entry (ray starts outside) and exit (ray starts inside) within range.
  if (s->t0 >= ray.tMin && s->t0 <= ray.tMax) return Hit{s->t0, s->face0, {}};
  if (s->t1 >= ray.tMin && s->t1 <= ray.tMax) return Hit{s->t1, s->face1, {}};
  return std::nullopt;
}

SurfaceInteraction Box::surfaceAt(const Ray& ray, const Hit& hit) const {
  const int axis = hit.primitive / 2;
  const double side = (hit.primitive % 2) ? 1.0 : -1.0;
  // Snap the hit onto its face in box space so secondary rays start on the surface.
  Point3 b = m_worldFromBox.inverseTransformPoint(ray.at(hit.t));
  b = glm::clamp(b, Point3(-1.0), Point3(1.0));
  b[axis] = side;

  SurfaceInteraction si;
  si.t = hit.t;
  si.p = m_worldFromBox.transformPoint(b);
  // b lies exactly on its face (b[axis] = +-1): only the map to the world rounds.
  si.pError = transformedPointError(m_worldFromBox.matrix(), b, Vec3(0.0));
  si.n = faceNormal(hit.primitive);
  si.frontFace = glm::dot(ray.direction, si.n) < 0.0;
  // uv: the two other box coordinates mapped to [0, 1].
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  si.uv = {0.5 * (b[a1] + 1.0), 0.5 * (b[a2] + 1.0)};
  si.primitive = hit.primitive;
  return si;
}

std::vector<Crossing> Box::intersectAll(const Ray& ray) const {
  std::vector<Crossing> out;
  const auto s = span(ray);
  if (!s) return out;
  if (s->t0 >= ray.tMin && s->t0 <= ray.tMax) out.push_back({s->t0, true, s->face0});
  if (s->t1 >= ray.tMin && s->t1 <= ray.tMax) out.push_back({s->t1, false, s->face1});
  return out;
}

Normal3 Box::faceNormal(int face) const {
  return (face % 2) ? m_slabNormal[face / 2] : -m_slabNormal[face / 2];
}

Normal3 Box::normal(const Point3& p) const {
  // The face whose plane is nearest in box coordinates.
  const Point3 b = m_worldFromBox.inverseTransformPoint(p);
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(b[i]) > std::abs(b[axis])) axis = i;
  return faceNormal(2 * axis + (b[axis] > 0.0 ? 1 : 0));
}

bool Box::inside(const Point3& p) const {
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(glm::dot(m_slabNormal[i], p) - m_slabCentre[i]) < m_slabHalf[i])) return false;
  return true;
}

void Box::apply(const Mat4& m) {
  if (!isAffine(m) || glm::determinant(Mat3(m)) == 0.0)
    throw InvalidGeometry("box: apply() needs an invertible affine matrix");
  m_worldFromBox = Transform(m) * m_worldFromBox;
  updateSlabs();
}

Bounds3 Box::bounds() const {
  Bounds3 b;
  for (const Point3& v : vertices()) b.extend(v);
  return b;
}

Point3 Box::centre() const { return Point3(m_worldFromBox.matrix()[3]); }

Vec3 Box::axis(int i) const { return glm::normalize(Vec3(m_worldFromBox.matrix()[i])); }

Vec3 Box::size() const {
  const Mat4& m = m_worldFromBox.matrix();
  return 2.0 * Vec3(glm::length(Vec3(m[0])), glm::length(Vec3(m[1])), glm::length(Vec3(m[2])));
}

Point3 Box::canonicalVertex(int k) {
  return {(k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0};
}

std::array<Point3, 8> Box::vertices() const {
  std::array<Point3, 8> v;
  for (int k = 0; k < 8; ++k) v[k] = m_worldFromBox.transformPoint(canonicalVertex(k));
  return v;
}

Vec3 Box::faceAreas() const {
  // Face pair i spans columns j and k of worldFromBox over [-1, 1]^2: the parallelogram
  // of edges 2 col_j and 2 col_k.
  const Mat4& m = m_worldFromBox.matrix();
  Vec3 areas;
  for (int i = 0; i < 3; ++i)
    areas[i] = 4.0 * glm::length(glm::cross(Vec3(m[(i + 1) % 3]), Vec3(m[(i + 2) % 3])));
  return areas;
}

double Box::area() const {
  const Vec3 a = faceAreas();
  return 2.0 * (a.x + a.y + a.z);
}

ShapeSample Box::sampleArea(const Vec2& u) const {
  // Pick one of the six faces in proportion to its area, reusing u.x for the position
  // within the face after rescaling it to [0, 1).
  const Vec3 a = faceAreas();
  const double total = 2.0 * (a.x + a.y + a.z);
  double target = u.x * total;
  int face = 5;
  for (int f = 0; f < 6; ++f) {
    if (target < a[f / 2]) {
      face = f;
      break;
    }
    target -= a[f / 2];
  }
  const double s = std::clamp(target / a[face / 2], 0.0, 1.0);
  // Place the point on the face in box coordinates, then map it to the world.
  const int axis = face / 2, a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  Point3 b;
  b[axis] = (face % 2) ? 1.0 : -1.0;
  b[a1] = 2.0 * s - 1.0;
  b[a2] = 2.0 * u.y - 1.0;
  ShapeSample sample;
  sample.p = m_worldFromBox.transformPoint(b);
  sample.n = faceNormal(face);
  sample.pdfArea = 1.0 / total;
  return sample;
}

double Box::pdfArea(const Point3&) const { return 1.0 / area(); }

std::string Box::toString() const {
  return "Box[centre=" + raylab::toString(centre()) + ", size=" + raylab::toString(size()) +
         ", axes=" + raylab::toString(axis(0)) + " " + raylab::toString(axis(1)) + " " +
         raylab::toString(axis(2)) + "]";
}

// The scene file's "box": centre, size and axes, or the exact matrix.
namespace detail {
const ShapeFormat& boxFormat();  // below
}  // namespace detail

namespace {

using nlohmann::json;

std::unique_ptr<Shape> readBox(const json& j, const std::string& path, const SceneFields& in,
                               SceneObject&) {
  in.onlyKeys(j, path, detail::boxFormat().keys);
  if (j.contains("matrix")) {
    // Either form, not both: a "size" beside the matrix would be silently ignored.
    for (const char* key : {"centre", "size", "axes"})
      if (j.contains(key))
        in.fail(path + "/" + key, std::string("a box is given either by \"matrix\" or by "
                                              "centre, size and axes, not both (\"") +
                                      key + "\" beside \"matrix\")");
    return std::make_unique<Box>(Transform(in.matrix(j["matrix"], path + "/matrix")));
  }
  const Vec3 centre = in.vec3(in.member(j, path, "centre"), path + "/centre");
  const json& sizes = in.member(j, path, "size");
  const Vec3 size = in.vec3(sizes, path + "/size");
  for (int i = 0; i < 3; ++i)
    if (size[i] <= 0.0) in.fail(path + "/size/" + std::to_string(i), "box size must be positive");
  for (int i = 0; i < 3; ++i) in.length(sizes[i], path + "/size/" + std::to_string(i), "box size");
  if (!j.contains("axes")) return std::make_unique<Box>(centre, size);
  const json& axes = j["axes"];
  if (!axes.is_array() || axes.size() != 3)
    in.fail(path + "/axes", "expected three axes [x, y, z]");
  Vec3 a[3];
  for (int i = 0; i < 3; ++i) a[i] = in.nonZero(axes[i], path + "/axes/" + std::to_string(i));
  return std::make_unique<Box>(centre, size, a[0], a[1], a[2]);
}

ojson writeBox(const SceneObject& object, const std::string&, ojson&) {
  const auto& b = static_cast<const Box&>(*object.shape);
  const Box readable(b.centre(), b.size(), b.axis(0), b.axis(1), b.axis(2));
  ObjectWriter box(detail::boxFormat().keys);
  box.add("type", "box");
  // Prefer centre/size/axes; fall back to the exact matrix when they do not
  // reproduce the box bit for bit.
  if (readable.worldFromBox().matrix() == b.worldFromBox().matrix()) {
    box.add("centre", toJson(b.centre())).add("size", toJson(b.size()));
    if (b.axis(0) != Vec3(1, 0, 0) || b.axis(1) != Vec3(0, 1, 0) || b.axis(2) != Vec3(0, 0, 1))
      box.add("axes", ojson::array({toJson(b.axis(0)), toJson(b.axis(1)), toJson(b.axis(2))}));
    return box.take();
  }
  return box.add("matrix", toJson(b.worldFromBox().matrix())).take();
}

ojson boxExample(const Point3& p, double size, const Vec3&, const Vec3&) {
  return {{"type", "box"}, {"centre", toJson(p)}, {"size", toJson(Vec3(size))}};
}

}  // namespace

namespace detail {
const ShapeFormat& boxFormat() {
  static const ShapeFormat format{
      ShapeKind::Box, "box",    {"type", "centre", "size", "axes", "matrix"},
      readBox,        writeBox, boxExample};
  return format;
}
}  // namespace detail

}  // namespace raylab
