#include "raylab/core/Triangle.h"

#include "raylab/core/Sampling.h"
#include "raylab/core/Transform.h"

#include <cmath>

namespace raylab {

namespace {

int maxDimension(const Vec3& v) { return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }

}  // namespace

std::optional<TriangleHit> intersectTriangle(const Ray& ray, const Point3& p0, const Point3& p1,
                                             const Point3& p2) {
  const Vec3& d = ray.direction;
  // Choose the ray-aligned frame: z is the dominant axis of d, x and y follow it;
  // swap x and y when d.z is negative to keep the triangle's winding.
  const int kz = maxDimension(glm::abs(d));
  int kx = (kz + 1) % 3;
  int ky = (kx + 1) % 3;
  if (d[kz] < 0.0) std::swap(kx, ky);

  // Shear constants that take d to (0, 0, 1).
  const double sx = d[kx] / d[kz];
  const double sy = d[ky] / d[kz];
  const double sz = 1.0 / d[kz];

  // Vertices relative to the ray origin, sheared into the ray's frame.
  const Vec3 a = p0 - ray.origin;
  const Vec3 b = p1 - ray.origin;
  const Vec3 c = p2 - ray.origin;
  const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
  const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
  const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];

  // 2D edge functions. A shared edge gives exactly opposite values in both triangles,
  // which is what makes the test watertight.
  double u = cx * by - cy * bx;
  double v = ax * cy - ay * cx;
  double w = bx * ay - by * ax;
  if (u == 0.0 || v == 0.0 || w == 0.0) {
    // On an edge in double precision: recompute in extended precision (the paper's
    // fallback), symmetrically for both triangles of the edge.
    using Wide = long double;
    u = static_cast<double>(Wide(cx) * Wide(by) - Wide(cy) * Wide(bx));
    v = static_cast<double>(Wide(ax) * Wide(cy) - Wide(ay) * Wide(cx));
    w = static_cast<double>(Wide(bx) * Wide(ay) - Wide(by) * Wide(ax));
  }

  // The ray passes the triangle when all edge functions have the same sign (zero counts
  // as inside, so edges and vertices are hit).
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return std::nullopt;
  const double det = u + v + w;
  if (det == 0.0) return std::nullopt;  // ray in the triangle's plane, or degenerate

  // Scaled hit distance, then divide once.
  const double az = sz * a[kz], bz = sz * b[kz], cz = sz * c[kz];
  const double tScaled = u * az + v * bz + w * cz;
  const double invDet = 1.0 / det;
  const double t = tScaled * invDet;
  if (!(t >= ray.tMin && t <= ray.tMax)) return std::nullopt;
  return TriangleHit{t, u * invDet, v * invDet, w * invDet};
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

}  // namespace raylab
