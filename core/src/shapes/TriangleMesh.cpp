#include "raylab/core/TriangleMesh.h"

#include "raylab/core/Bvh.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/Transform.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace raylab {

namespace {

/// Directions for the parity test of inside(): irrational-looking components, so a ray
/// from a point on a grid almost never runs exactly through an edge or a vertex. The
/// next one is used only when the previous ray did touch an edge (a zero barycentric).
const Vec3 kParityDirections[3] = {
    glm::normalize(Vec3(0.5773502691896258, 0.6180339887498949, 0.5345224838248488)),
    glm::normalize(Vec3(-0.7071067811865476, 0.3183098861837907, 0.6324555320336759)),
    glm::normalize(Vec3(0.2718281828459045, -0.8660254037844386, 0.4142135623730950)),
};

}  // namespace

TriangleMesh::TriangleMesh(std::vector<Point3> vertices, std::vector<Index3> triangles)
    : m_vertices(std::move(vertices)), m_triangles(std::move(triangles)) {
  // Validate: finite vertices, indices in range.
  for (std::size_t i = 0; i < m_vertices.size(); ++i) {
    const Point3& p = m_vertices[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InvalidGeometry("triangle mesh: vertex " + std::to_string(i) +
                            " is not finite: " + raylab::toString(p));
  }
  const long long n = static_cast<long long>(m_vertices.size());
  for (std::size_t i = 0; i < m_triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const int index = m_triangles[i][k];
      if (index < 0 || index >= n)
        throw InvalidGeometry("triangle mesh: triangle " + std::to_string(i) +
                              " has vertex index " + std::to_string(index) + " out of range [0, " +
                              std::to_string(n) + ") (" + std::to_string(n) + " vertices)");
    }
  }
  rebuild();
}

TriangleMesh::TriangleMesh(const TriangleMesh& other)
    : m_vertices(other.m_vertices),
      m_triangles(other.m_triangles),
      m_bvh(std::make_unique<Bvh>(*other.m_bvh)),
      m_areaCdf(other.m_areaCdf),
      m_area(other.m_area) {}

TriangleMesh& TriangleMesh::operator=(const TriangleMesh& other) {
  if (this != &other) {
    m_vertices = other.m_vertices;
    m_triangles = other.m_triangles;
    m_bvh = std::make_unique<Bvh>(*other.m_bvh);
    m_areaCdf = other.m_areaCdf;
    m_area = other.m_area;
  }
  return *this;
}

TriangleMesh::TriangleMesh(TriangleMesh&&) noexcept = default;
TriangleMesh& TriangleMesh::operator=(TriangleMesh&&) noexcept = default;
TriangleMesh::~TriangleMesh() = default;

void TriangleMesh::rebuild() {
  m_bvh = std::make_unique<Bvh>(m_vertices, m_triangles);
  // The running sum of triangle areas: the CDF that area sampling inverts.
  m_areaCdf.resize(m_triangles.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < m_triangles.size(); ++i) {
    const Index3& tri = m_triangles[i];
    const Point3& p0 = m_vertices[tri[0]];
    sum += 0.5 * glm::length(glm::cross(m_vertices[tri[1]] - p0, m_vertices[tri[2]] - p0));
    m_areaCdf[i] = sum;
  }
  m_area = sum;
}

double TriangleMesh::area() const { return m_area; }

ShapeSample TriangleMesh::sampleArea(const Vec2& u) const {
  if (!(m_area > 0.0))
    throw InvalidGeometry("triangle mesh has no area to sample (" + toString() + ")");
  // Pick triangle i with probability area_i / area: the first running sum above
  // u.x * area (zero-area triangles are never picked).
  const double target = u.x * m_area;
  auto it = std::upper_bound(m_areaCdf.begin(), m_areaCdf.end(), target);
  if (it == m_areaCdf.end()) it = std::lower_bound(m_areaCdf.begin(), m_areaCdf.end(), m_area);
  const std::size_t i = static_cast<std::size_t>(it - m_areaCdf.begin());
  const double before = i == 0 ? 0.0 : m_areaCdf[i - 1];
  // Reuse u.x, rescaled to [0, 1) within the chosen triangle's interval.
  const double reused = std::clamp((target - before) / (m_areaCdf[i] - before), 0.0, 1.0);
  const Vec2 b = sampleUniformTriangle({reused, u.y});
  const Index3& tri = m_triangles[i];
  const Point3& p0 = m_vertices[tri[0]];
  const Point3& p1 = m_vertices[tri[1]];
  const Point3& p2 = m_vertices[tri[2]];
  ShapeSample s;
  s.p = (1.0 - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
  s.n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  s.pdfArea = 1.0 / m_area;
  return s;
}

double TriangleMesh::pdfArea(const Point3&) const { return m_area > 0.0 ? 1.0 / m_area : 0.0; }

std::optional<Hit> TriangleMesh::intersect(const Ray& ray) const { return m_bvh->intersect(ray); }

SurfaceInteraction TriangleMesh::surfaceAt(const Ray& ray, const Hit& hit) const {
  const Index3& tri = m_triangles[static_cast<std::size_t>(hit.primitive)];
  const Point3& p0 = m_vertices[tri[0]];
  const Point3& p1 = m_vertices[tri[1]];
  const Point3& p2 = m_vertices[tri[2]];
  SurfaceInteraction si;
  si.t = hit.t;
  // The barycentric point lies on the triangle up to rounding, unlike ray.at(t).
  const double b1 = hit.uv.x, b2 = hit.uv.y, b0 = 1.0 - b1 - b2;
  si.p = b0 * p0 + b1 * p1 + b2 * p2;
  // The barycentric sum (pbrt 4th ed., 6.8.5): gamma(7) of the terms' magnitudes.
  si.pError = roundingGamma(7) * (glm::abs(b0 * p0) + glm::abs(b1 * p1) + glm::abs(b2 * p2));
  si.n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  si.frontFace = glm::dot(ray.direction, si.n) < 0.0;
  si.uv = hit.uv;
  si.primitive = hit.primitive;
  return si;
}

std::vector<Crossing> TriangleMesh::intersectAll(const Ray& ray) const {
  const std::vector<Hit> hits = m_bvh->intersectAll(ray);
  std::vector<Crossing> crossings;
  crossings.reserve(hits.size());
  for (const Hit& h : hits) {
    const Index3& tri = m_triangles[static_cast<std::size_t>(h.primitive)];
    const Point3& p0 = m_vertices[tri[0]];
    // Entering when the ray meets the front (outer) side: dot(direction, normal) < 0.
    const Vec3 n = glm::cross(m_vertices[tri[1]] - p0, m_vertices[tri[2]] - p0);
    crossings.push_back(Crossing{h.t, glm::dot(ray.direction, n) < 0.0, h.primitive});
  }
  return crossings;
}

Normal3 TriangleMesh::normal(const Point3& p) const {
  const int id = m_bvh->closestTriangle(p);
  if (id < 0) return Normal3(0.0);
  const Index3& tri = m_triangles[static_cast<std::size_t>(id)];
  const Point3& p0 = m_vertices[tri[0]];
  return glm::normalize(glm::cross(m_vertices[tri[1]] - p0, m_vertices[tri[2]] - p0));
}

bool TriangleMesh::inside(const Point3& p) const {
  if (!m_bvh->bounds().contains(p)) return false;
  // Count crossings of a ray from p (parity: odd = inside a closed mesh). A ray through
  // an edge or a vertex would count its triangles twice; retry with another direction.
  int parity = 0;
  for (const Vec3& d : kParityDirections) {
    const std::vector<Hit> hits = m_bvh->intersectAll(Ray{p, d, 0.0, kInfinity, 0.0});
    bool touchesEdge = false;
    for (const Hit& h : hits) {
      const double b0 = 1.0 - h.uv.x - h.uv.y;
      if (h.uv.x == 0.0 || h.uv.y == 0.0 || b0 == 0.0) touchesEdge = true;
    }
    parity = static_cast<int>(hits.size() % 2);
    if (!touchesEdge) break;
  }
  return parity == 1;
}

void TriangleMesh::apply(const Mat4& m) {
  const double det = glm::determinant(Mat3(m));
  if (!isAffine(m) || det == 0.0 || !std::isfinite(det))
    throw InvalidGeometry("triangle mesh: apply() needs an invertible affine matrix");
  // Transform the vertices; a mirroring map (det < 0) would turn the triangles
  // clockwise seen from outside, so swap two indices to keep normals outward.
  const Transform t(m);
  for (Point3& p : m_vertices) p = t.transformPoint(p);
  if (det < 0.0)
    for (Index3& tri : m_triangles) std::swap(tri[1], tri[2]);
  rebuild();
}

Bounds3 TriangleMesh::bounds() const { return m_bvh->bounds(); }

std::unique_ptr<Shape> TriangleMesh::clone() const { return std::make_unique<TriangleMesh>(*this); }

std::string TriangleMesh::toString() const {
  std::ostringstream out;
  out << "TriangleMesh[vertices=" << m_vertices.size() << ", triangles=" << m_triangles.size()
      << ", bounds=" << bounds().toString() << "]";
  return out.str();
}

}  // namespace raylab
