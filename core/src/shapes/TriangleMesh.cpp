#include "raylab/core/TriangleMesh.h"

#include "io/MeshCache.h"
#include "raylab/core/MeshIO.h"
#include "raylab/core/Scene.h"
#include "raylab/core/SceneIO.h"
#include "scene/ObjectWriter.h"
#include "scene/SceneFields.h"
#include "shapes/ShapeFormat.h"

#include "raylab/core/Bvh.h"
#include "raylab/core/RayOffset.h"
#include "raylab/core/Sampling.h"
#include "raylab/core/Transform.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
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

TriangleMesh::TriangleMesh(std::vector<Point3> vertices, std::vector<Index3> triangles,
                           std::vector<Normal3> normals, std::vector<Index3> normalIndices)
    : TriangleMesh(std::move(vertices), std::move(triangles)) {
  setNormals(std::move(normals), std::move(normalIndices));
}

void TriangleMesh::setNormals(std::vector<Normal3> normals, std::vector<Index3> normalIndices) {
  // Validate: one index triple per triangle, indices in range, normals finite and not zero.
  if (normalIndices.size() != m_triangles.size())
    throw InvalidGeometry("triangle mesh: " + std::to_string(normalIndices.size()) +
                          " normal index triples for " + std::to_string(m_triangles.size()) +
                          " triangles (one per triangle is needed)");
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const Normal3& n = normals[i];
    const double length = glm::length(n);
    if (!isFinite(n) || !(length > 0.0) || !std::isfinite(length))
      throw InvalidGeometry("triangle mesh: normal " + std::to_string(i) + " " +
                            raylab::toString(n) +
                            (isFinite(n) ? " has zero length" : " is not finite"));
    normals[i] = n / length;
  }
  const long long count = static_cast<long long>(normals.size());
  for (std::size_t i = 0; i < normalIndices.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int index = normalIndices[i][k];
      if (index < 0 || index >= count)
        throw InvalidGeometry("triangle mesh: triangle " + std::to_string(i) +
                              " has normal index " + std::to_string(index) + " out of range [0, " +
                              std::to_string(count) + ") (" + std::to_string(count) + " normals)");
    }
  m_normals = std::move(normals);
  m_normalIndices = std::move(normalIndices);
}

void TriangleMesh::clearNormals() {
  m_normals.clear();
  m_normalIndices.clear();
}

void TriangleMesh::computeCreaseNormals(double creaseAngle) {
  if (!(creaseAngle >= 0.0 && creaseAngle <= kPi))
    throw InvalidGeometry("triangle mesh: crease angle " + std::to_string(creaseAngle) +
                          " rad is outside [0, pi]");
  const std::size_t triangleCount = m_triangles.size();
  // Each triangle's unit normal, and its angle at each corner (the averaging weight).
  std::vector<Normal3> faceNormal(triangleCount, Normal3(0.0));
  std::vector<std::array<double, 3>> cornerAngle(triangleCount, {0.0, 0.0, 0.0});
  for (std::size_t t = 0; t < triangleCount; ++t) {
    const Index3& tri = m_triangles[t];
    const Vec3 cross = glm::cross(m_vertices[tri[1]] - m_vertices[tri[0]],
                                  m_vertices[tri[2]] - m_vertices[tri[0]]);
    const double length = glm::length(cross);
    if (length > 0.0 && std::isfinite(length)) faceNormal[t] = cross / length;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = m_vertices[tri[(k + 1) % 3]] - m_vertices[tri[k]];
      const Vec3 b = m_vertices[tri[(k + 2) % 3]] - m_vertices[tri[k]];
      const double la = glm::length(a), lb = glm::length(b);
      if (la > 0.0 && lb > 0.0)
        cornerAngle[t][k] = std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
    }
  }
  // The corners around each vertex (compressed rows: vertex -> (triangle, corner)).
  std::vector<std::size_t> start(m_vertices.size() + 1, 0);
  for (const Index3& tri : m_triangles)
    for (int k = 0; k < 3; ++k) ++start[std::size_t(tri[k]) + 1];
  for (std::size_t v = 0; v < m_vertices.size(); ++v) start[v + 1] += start[v];
  std::vector<std::pair<int, int>> corners(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < triangleCount; ++t)
    for (int k = 0; k < 3; ++k) corners[fill[std::size_t(m_triangles[t][k])]++] = {int(t), k};

  // Per corner: the angle-weighted sum of the neighbours within the crease angle (a small
  // tolerance keeps coplanar neighbours together at 0); equal normals at a vertex are
  // stored once.
  const double cosCrease = std::cos(creaseAngle) - 1e-12;
  std::vector<Normal3> normals;
  std::vector<Index3> indices(triangleCount, Index3{0, 0, 0});
  for (std::size_t v = 0; v < m_vertices.size(); ++v) {
    const std::size_t firstNormal = normals.size();
    for (std::size_t c = start[v]; c < start[v + 1]; ++c) {
      const auto [t, k] = corners[c];
      const Normal3& own = faceNormal[std::size_t(t)];
      Vec3 sum(0.0);
      for (std::size_t o = start[v]; o < start[v + 1]; ++o) {
        const auto [t2, k2] = corners[o];
        const Normal3& other = faceNormal[std::size_t(t2)];
        if (glm::dot(own, other) >= cosCrease)
          sum += cornerAngle[std::size_t(t2)][std::size_t(k2)] * other;
      }
      const double length = glm::length(sum);
      // A degenerate corner (never hit: the watertight test skips zero-area triangles).
      Normal3 n = length > 0.0 ? sum / length : (isZero(own) ? Normal3(0, 0, 1) : own);
      int index = -1;
      for (std::size_t i = firstNormal; i < normals.size() && index < 0; ++i)
        if (normals[i] == n) index = int(i);
      if (index < 0) {
        index = int(normals.size());
        normals.push_back(n);
      }
      indices[std::size_t(t)][std::size_t(k)] = index;
    }
  }
  m_normals = std::move(normals);
  m_normalIndices = std::move(indices);
}

Normal3 TriangleMesh::shadingNormal(int triangle, double b1, double b2) const {
  const Index3& tri = m_triangles[static_cast<std::size_t>(triangle)];
  const Point3& p0 = m_vertices[tri[0]];
  const Normal3 ng = glm::normalize(glm::cross(m_vertices[tri[1]] - p0, m_vertices[tri[2]] - p0));
  if (m_normalIndices.empty()) return ng;
  // Interpolate the corner normals with the barycentrics, normalise, and turn the result
  // to the geometric normal's side.
  const Index3& ni = m_normalIndices[static_cast<std::size_t>(triangle)];
  const Vec3 sum = (1.0 - b1 - b2) * m_normals[std::size_t(ni[0])] +
                   b1 * m_normals[std::size_t(ni[1])] + b2 * m_normals[std::size_t(ni[2])];
  const double length = glm::length(sum);
  if (!(length > 0.0) || !std::isfinite(length)) return ng;
  const Normal3 ns = sum / length;
  return glm::dot(ns, ng) < 0.0 ? -ns : ns;
}

TriangleMesh::TriangleMesh(const TriangleMesh& other)
    : m_vertices(other.m_vertices),
      m_triangles(other.m_triangles),
      m_normals(other.m_normals),
      m_normalIndices(other.m_normalIndices),
      m_bvh(std::make_unique<Bvh>(*other.m_bvh)),
      m_areaCdf(other.m_areaCdf),
      m_area(other.m_area) {}

TriangleMesh& TriangleMesh::operator=(const TriangleMesh& other) {
  if (this != &other) {
    m_vertices = other.m_vertices;
    m_triangles = other.m_triangles;
    m_normals = other.m_normals;
    m_normalIndices = other.m_normalIndices;
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
  si.pError = kRoundingGamma<7> * (absolute(b0 * p0) + absolute(b1 * p1) + absolute(b2 * p2));
  si.n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  si.frontFace = glm::dot(ray.direction, si.n) < 0.0;
  if (!m_normalIndices.empty()) {
    // Smooth shading: the interpolated normal, unless the ray arrives between the two
    // surfaces (on the back of the shading surface, in front of the geometric one, or the
    // other way round): such a hit shades flat.
    const Normal3 ns = shadingNormal(hit.primitive, b1, b2);
    if ((glm::dot(ray.direction, ns) < 0.0) == si.frontFace) si.ns = ns;
  }
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
  // Normals go through the inverse transpose (they stay outward, mirrored or not).
  for (Normal3& n : m_normals) n = glm::normalize(t.transformNormal(n));
  if (det < 0.0) {
    for (Index3& tri : m_triangles) std::swap(tri[1], tri[2]);
    for (Index3& tri : m_normalIndices) std::swap(tri[1], tri[2]);
  }
  rebuild();
}

Bounds3 TriangleMesh::bounds() const { return m_bvh->bounds(); }

std::unique_ptr<Shape> TriangleMesh::clone() const { return std::make_unique<TriangleMesh>(*this); }

std::string TriangleMesh::toString() const {
  std::ostringstream out;
  out << "TriangleMesh[vertices=" << m_vertices.size() << ", triangles=" << m_triangles.size()
      << (hasNormals() ? ", normals=" + std::to_string(m_normals.size()) : std::string())
      << ", bounds=" << bounds().toString() << "]";
  return out.str();
}

// The scene file's "mesh": a mesh file by reference (its path relative to the scene file),
// the source of its shading normals and the crease angle of computed ones.
namespace detail {
const ShapeFormat& meshFormat();  // below
}  // namespace detail

namespace {

using nlohmann::json;

/// Reads "normals" and "crease_angle" into `object`.
void readMeshNormals(const json& j, const std::string& path, const SceneFields& in,
                     SceneObject& object) {
  if (j.contains("normals")) {
    const std::string normals = in.string(j["normals"], path + "/normals");
    if (normals == "file")
      object.meshNormals = MeshNormals::File;
    else if (normals == "flat")
      object.meshNormals = MeshNormals::Flat;
    else if (normals == "smooth")
      object.meshNormals = MeshNormals::Smooth;
    else
      in.fail(path + "/normals",
              "unknown normals \"" + normals + "\" (expected file, flat or smooth)");
  }
  if (j.contains("crease_angle")) {
    object.creaseAngle = in.number(j["crease_angle"], path + "/crease_angle");
    if (!(object.creaseAngle >= 0.0 && object.creaseAngle <= 180.0))
      in.fail(path + "/crease_angle",
              "crease angle " + excerpt(j["crease_angle"]) + " must be in [0, 180] degrees");
  }
}

std::unique_ptr<Shape> readMesh(const json& j, const std::string& path, const SceneFields& in,
                                SceneObject& object) {
  in.onlyKeys(j, path, detail::meshFormat().keys);
  readMeshNormals(j, path, in, object);
  const std::string file = in.string(in.member(j, path, "file"), path + "/file");
  if (file.empty()) in.fail(path + "/file", "mesh file name is empty");
  // Mesh paths are relative to the scene file's folder.
  const std::filesystem::path filePath(file);
  std::string& source = object.source;
  source = (filePath.is_absolute() ? filePath : std::filesystem::path(in.baseDir()) / filePath)
               .lexically_normal()
               .string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(source, ec))
    in.fail(path + "/file", "mesh file \"" + file + "\" not found (looked for " + source + ")");
  try {
    auto mesh = std::make_unique<TriangleMesh>(meshcache::load(source));
    if (object.meshNormals == MeshNormals::Flat) mesh->clearNormals();
    if (object.meshNormals == MeshNormals::Smooth)
      mesh->computeCreaseNormals(radians(object.creaseAngle));
    return mesh;
  } catch (const MeshIO::ReadError& e) {
    in.fail(path + "/file", "cannot load mesh \"" + file + "\": " + e.what());
  }
}

/// The path to write for a mesh file `source` (see SceneObject::source) in a scene file
/// in folder `sceneDir` ("" = the current directory): relative to that folder, as the
/// format says.
std::string meshPathFrom(const std::string& source, const std::string& sceneDir) {
  namespace fs = std::filesystem;
  fs::path file = fs::path(source).lexically_normal();
  fs::path base = fs::path(sceneDir.empty() ? "." : sceneDir).lexically_normal();
  if (file.is_absolute() || base.is_absolute()) {
    file = fs::absolute(file).lexically_normal();
    base = fs::absolute(base).lexically_normal();
  }
  const fs::path relative = file.lexically_relative(base);
  return relative.empty() ? file.generic_string() : relative.generic_string();
}

/// Meshes are saved by reference: the file and the transform applied to it.
ojson writeMesh(const SceneObject& o, const std::string& sceneDir, ojson& transform) {
  if (o.source.empty())
    throw SceneIO::SaveError("mesh object \"" + o.name +
                             "\" has no source file (meshes are saved as a path to their file)");
  ObjectWriter mesh(detail::meshFormat().keys);
  mesh.add("type", "mesh").add("file", meshPathFrom(o.source, sceneDir));
  // The normals' source when it is not the default; the crease angle of computed ones.
  if (o.meshNormals != MeshNormals::File) mesh.add("normals", toString(o.meshNormals));
  if (o.meshNormals == MeshNormals::Smooth) mesh.add("crease_angle", o.creaseAngle);
  if (o.worldFromSource != Mat4(1.0)) transform = matrixTransform(o.worldFromSource);
  return mesh.take();
}

}  // namespace

namespace detail {
const ShapeFormat& meshFormat() {
  static const ShapeFormat format{ShapeKind::TriangleMesh,
                                  "mesh",
                                  {"type", "file", "normals", "crease_angle"},
                                  readMesh,
                                  writeMesh,
                                  nullptr};
  return format;
}
}  // namespace detail

}  // namespace raylab
