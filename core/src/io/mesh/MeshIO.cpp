// MeshIO::load: a mesh file checked, read, repaired and triangulated, in six steps; the
// steps' parts live beside it in io/mesh/ (MeshReaders.h lists them).
#include "raylab/core/MeshIO.h"

#include "io/mesh/MeshNormals.h"
#include "io/mesh/MeshReaders.h"
#include "io/mesh/MeshSoupChecks.h"
#include "raylab/core/FilePaths.h"
#include "raylab/core/Limits.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace raylab {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using namespace meshio;

/// One load of one file: what each step found, for the steps after it and for messages.
class Loader {
 public:
  Loader(const std::string& path, const MeshIO::Options& options)
      : m_path(path), m_options(options) {}

  TriangleMesh load() {
    checkFile();
    checkAnnounced();
    readSoup();
    checkSoup();
    readNormals();
    repair();
    std::vector<Point3> vertices;
    std::vector<TriangleMesh::Index3> triangles;
    triangulate(vertices, triangles);
    return finish(std::move(vertices), std::move(triangles));
  }

 private:
  std::string m_path;
  MeshIO::Options m_options;
  std::string m_ext;          ///< ".obj", ".off", ".ply" or ".stl".
  std::string m_upperFormat;  ///< "OBJ", "OFF", "PLY" or "STL", for messages.
  std::uintmax_t m_size = 0;
  std::optional<meshnormals::PlyHeader> m_plyHeader;  ///< Read once: size check and normals.
  OffSoup m_offSoup;                                  ///< An OFF file, read by RayLab, whole.
  std::vector<CgalPoint> m_points;
  std::vector<Polygon> m_polygons;
  std::string m_report;  ///< What CGAL's reader printed.
  std::optional<meshnormals::FileNormals> m_fileNormals;
  std::vector<Point3> m_soupPoints;  ///< The soup as read, when the file has normals.
  std::vector<Polygon> m_soupPolygons;

  MeshIO::ReadError fail(const std::string& what, int line = 0) const {
    return MeshIO::ReadError(m_path + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                             ": " + what);
  }
  void throwLocated(const std::optional<Located>& located) const {
    if (located)
      throw fail("cannot parse " + m_upperFormat + " file: " + located->what +
                     (m_report.empty() ? std::string() : " (CGAL: " + m_report + ")"),
                 located->line);
  }
  std::optional<Located> locate() const {
    return m_ext == ".obj" ? locateObjError(m_path) : std::nullopt;
  }

  void checkFile();
  void checkAnnounced();
  void readSoup();
  void checkSoup();
  void readNormals();
  void repair();
  void triangulate(std::vector<Point3>& vertices, std::vector<TriangleMesh::Index3>& triangles);
  void triangulatePolygons(std::vector<Point3>& vertices,
                           std::vector<TriangleMesh::Index3>& triangles);
  /// "face N" of the file (1-based, with its line in an OBJ or OFF file) whose corners are
  /// `corners`, found again in the file as read: a face after repair has other indices.
  std::pair<std::string, int> fileFace(const std::vector<CgalPoint>& corners) const;
  TriangleMesh finish(std::vector<Point3> vertices, std::vector<TriangleMesh::Index3> triangles);
};

// Step 1: the file must exist, be readable and have a known extension.
void Loader::checkFile() {
  std::error_code ec;
  if (!std::filesystem::exists(m_path, ec)) throw fail("file not found");
  if (!std::filesystem::is_regular_file(m_path, ec)) throw fail("not a regular file");
  m_ext = lowerExtension(m_path);
  const auto known = MeshIO::supportedExtensions();
  if (std::find(known.begin(), known.end(), m_ext) == known.end())
    throw fail("unknown mesh extension '" + m_ext + "' (supported: .obj, .off, .ply, .stl)");
  if (!std::ifstream(m_path).good()) throw fail("cannot open the file for reading");
  m_size = std::filesystem::file_size(m_path, ec);
  if (m_size == 0) throw fail("file is empty (no faces)");
  if (m_size > limits::kMaxMeshFileBytes)
    throw fail("file is " + std::to_string(m_size >> 20) + " MiB; RayLab reads meshes of at most " +
               std::to_string(limits::kMaxMeshFileBytes >> 20) + " MiB");
  m_upperFormat = m_ext.substr(1);
  std::transform(m_upperFormat.begin(), m_upperFormat.end(), m_upperFormat.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
}

// Step 1b: what the file announces must fit in it and in the limits (CGAL trusts it), and
// a text file's lines must end as the readers expect.
void Loader::checkAnnounced() {
  if (m_ext != ".stl" && endsLinesWithCrOnly(m_path))
    throw fail("cannot parse " + m_upperFormat +
                   " file: its lines end in a carriage return alone (classic Mac OS); "
                   "RayLab reads lines that end in LF or CR LF (convert it, e.g. with "
                   "tr '\\r' '\\n')",
               1);
  SizeProblem announced;
  if (m_ext == ".ply") {
    std::ifstream in(m_path, std::ios::binary);
    try {
      m_plyHeader = meshnormals::readPlyHeader(in);
      announced = checkPly(in, *m_plyHeader, m_size);
    } catch (const meshnormals::Problem& problem) {
      announced = Located{problem.line(), problem.what()};
    }
  } else {
    announced = m_ext == ".off"   ? readOff(m_path, m_size, m_offSoup)
                : m_ext == ".stl" ? checkStl(m_path, m_size)
                                  : checkObj(m_path);
  }
  if (announced)
    throw fail("cannot parse " + m_upperFormat + " file: " + announced->what, announced->line);
}

// Step 2: the polygon soup, read by CGAL (OFF: read by RayLab in step 1b); a failure is
// located at its line in a text format, else named "no faces" when nothing was wrong.
void Loader::readSoup() {
  bool ok = true;
  if (m_ext == ".off") {
    m_points = std::move(m_offSoup.points);
    m_polygons = std::move(m_offSoup.polygons);
  } else {
    ok = readCgalSoup(m_path, m_points, m_polygons, m_report);
  }
  if (!ok) {
    throwLocated(locate());
    if (m_polygons.empty() && (m_report.empty() || m_report.find("empty") != std::string::npos))
      throw fail("no faces in the file (empty mesh)");
    throw fail("cannot parse " + m_upperFormat + " file" +
               (m_report.empty() ? std::string(": the reader gave no reason") : ": " + m_report));
  }
  if (m_polygons.empty()) throw fail("no faces in the file (empty mesh)");
}

// Step 3: every face of at least three existing corners, every coordinate in bounds.
void Loader::checkSoup() {
  // Corners counted and repeated vertices found in linear time, before CGAL's repair
  // (quadratic in a face repeating its vertices) and the polygon checks (issue 38).
  if (auto problem = meshsoup::checkFaces(m_polygons)) throw fail(*problem);
  for (std::size_t f = 0; f < m_polygons.size(); ++f) {
    const Polygon& polygon = m_polygons[f];
    const bool bad =
        polygon.size() < 3 || std::any_of(polygon.begin(), polygon.end(),
                                          [&](std::size_t i) { return i >= m_points.size(); });
    if (bad) throwLocated(locate());
    for (std::size_t index : polygon)
      if (index >= m_points.size())
        throw fail("corrupt " + m_upperFormat + " file: face " + std::to_string(f) +
                   " refers to vertex " + std::to_string(index) + " but there are only " +
                   std::to_string(m_points.size()) + " vertices");
    if (polygon.size() < 3)
      throw fail("corrupt " + m_upperFormat + " file: face " + std::to_string(f) + " has only " +
                 std::to_string(polygon.size()) + " vertices");
  }
  // As in a scene file: a vertex at 1e300 overflowed the BVH build's bin index (found by
  // Fuzzply, issue 14).
  for (std::size_t i = 0; i < m_points.size(); ++i) {
    for (const double c : {m_points[i].x(), m_points[i].y(), m_points[i].z()}) {
      if (std::abs(c) <= limits::kMaxCoordinate) continue;
      std::ostringstream value;
      value << c;
      throw fail("vertex " + std::to_string(i + 1) + " has the coordinate " + value.str() +
                 ", beyond RayLab's largest coordinate, 1e12 (or not a number)");
    }
  }
}

// Step 3b: the file's vertex normals, if it has any, beside the soup as it was read.
void Loader::readNormals() {
  try {
    if (m_ext == ".obj") m_fileNormals = meshnormals::readObj(m_path);
    if (m_ext == ".ply") m_fileNormals = meshnormals::readPly(m_path, *m_plyHeader);
  } catch (const meshnormals::Problem& problem) {
    throw fail("cannot read the normals of the " + m_upperFormat + " file: " + problem.what(),
               problem.line());
  }
  if (!m_fileNormals) return;
  const meshnormals::FileNormals& n = *m_fileNormals;
  const std::size_t have = n.perVertex ? n.normals.size() : n.corners.size();
  const std::size_t want = n.perVertex ? m_points.size() : m_polygons.size();
  if (have != want)
    throw fail("the file's normals do not match its " +
               std::string(n.perVertex ? "vertices" : "faces") + " (" + std::to_string(have) +
               " for " + std::to_string(want) + ")");
  m_soupPoints.reserve(m_points.size());
  for (const CgalPoint& p : m_points) m_soupPoints.emplace_back(p.x(), p.y(), p.z());
  m_soupPolygons = m_polygons;
}

// Step 4: repair (merge duplicate points, drop degenerate / duplicate faces), orient.
void Loader::repair() {
  PMP::repair_polygon_soup(m_points, m_polygons);
  if (m_polygons.empty()) throw fail("no faces left after removing degenerate faces");
  const std::size_t pointsBefore = m_points.size();
  const bool oriented = PMP::orient_polygon_soup(m_points, m_polygons);
  if (!m_options.allowNonManifold && !oriented)
    throw fail("non-manifold mesh beyond repair: orienting it needed " +
               std::to_string(m_points.size() - pointsBefore) +
               " duplicated vertices (an edge shared by more than two faces, faces touching "
               "only at a vertex, or a non-orientable surface)");
  if (!PMP::is_polygon_soup_a_polygon_mesh(m_polygons))
    throw fail("non-manifold mesh beyond repair: not a polygon mesh after repair and orientation");
}

// Step 5: faces of more than three corners triangulated, then copied out.
void Loader::triangulate(std::vector<Point3>& vertices,
                         std::vector<TriangleMesh::Index3>& triangles) {
  const bool allTriangles = std::all_of(m_polygons.begin(), m_polygons.end(),
                                        [](const Polygon& p) { return p.size() == 3; });
  if (!allTriangles) return triangulatePolygons(vertices, triangles);
  vertices.reserve(m_points.size());
  for (const CgalPoint& p : m_points) vertices.emplace_back(p.x(), p.y(), p.z());
  triangles.reserve(m_polygons.size());
  for (const Polygon& p : m_polygons)
    triangles.push_back({static_cast<int>(p[0]), static_cast<int>(p[1]), static_cast<int>(p[2])});
}

void Loader::triangulatePolygons(std::vector<Point3>& vertices,
                                 std::vector<TriangleMesh::Index3>& triangles) {
  CgalMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(m_points, m_polygons, mesh);
  const auto corners = [&](CgalMesh::Face_index f) {
    std::vector<CgalPoint> c;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) c.push_back(mesh.point(v));
    return c;
  };
  // The face, where it is in the file, and why it cannot be triangulated.
  const auto refuse = [&](CgalMesh::Face_index f, const std::string& why) {
    const auto [face, line] = fileFace(corners(f));
    return fail(
        "cannot triangulate " + face + " (" + std::to_string(mesh.degree(f)) + " corners): " + why,
        line);
  };
  // CGAL triangulates a face of more than four corners in its projection along the face's
  // normal, with a constrained Delaunay triangulation: two corners that coincide there
  // made it join a vertex to itself (a null pointer), and edges that cross there made it
  // insert constraints for ever (both found by Fuzzobj, issue 14). Such a face is
  // refused first, with the same normal and the exact predicates of that projection.
  for (auto f : mesh.faces())
    if (mesh.degree(f) > 4)
      if (auto problem = checkSimplePolygon(mesh, f)) throw refuse(f, *problem);
  if (!PMP::triangulate_faces(mesh)) {
    // The faces CGAL could not triangulate are left as they were (a bow-tie quad).
    for (auto f : mesh.faces())
      if (mesh.degree(f) > 3)
        throw refuse(f, checkSimplePolygon(mesh, f).value_or(
                            "its edges cross, or it encloses no area, seen along "
                            "any direction (a bow-tie, or a face folded onto "
                            "itself)"));
    throw fail("could not triangulate a polygonal face");
  }
  vertices.reserve(mesh.number_of_vertices());
  for (auto v : mesh.vertices()) {
    const CgalPoint& p = mesh.point(v);
    vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto f : mesh.faces()) {
    TriangleMesh::Index3 tri{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k < 3) tri[k] = static_cast<int>(static_cast<std::size_t>(v));
      // A face cycle broken by a bad soup would never close (found by fuzzing).
      if (++k > 3) break;
    }
    if (k != 3) throw fail("could not triangulate a polygonal face");
    triangles.push_back(tri);
  }
}

std::pair<std::string, int> Loader::fileFace(const std::vector<CgalPoint>& corners) const {
  // Read again (only for this message): the soup as the file holds it.
  std::vector<CgalPoint> points;
  std::vector<Polygon> polygons;
  OffSoup off;
  std::string report;
  if (m_ext == ".off") {
    readOff(m_path, m_size, off);
    points = std::move(off.points);
    polygons = std::move(off.polygons);
  } else {
    readCgalSoup(m_path, points, polygons, report);
  }
  std::vector<CgalPoint> wanted = corners;
  std::sort(wanted.begin(), wanted.end());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() != wanted.size()) continue;
    std::vector<CgalPoint> have;
    for (std::size_t i : polygons[f]) have.push_back(i < points.size() ? points[i] : CgalPoint());
    std::sort(have.begin(), have.end());
    if (have != wanted) continue;
    const int line = m_ext == ".off" && f < off.faceLines.size() ? off.faceLines[f]
                     : m_ext == ".obj"                           ? objFaceLine(m_path, f)
                                                                 : 0;
    return {"face " + std::to_string(f + 1), line};
  }
  return {"a face", 0};
}

// Step 6: outward normals, the limit on triangles, and the file's normals at the corners of
// the final triangles.
TriangleMesh Loader::finish(std::vector<Point3> vertices,
                            std::vector<TriangleMesh::Index3> triangles) {
  if (triangles.size() > limits::kMaxMeshTriangles)
    throw fail("the mesh has " + std::to_string(triangles.size()) +
               " triangles once its faces are triangulated; RayLab reads meshes of at most " +
               std::to_string(limits::kMaxMeshTriangles));
  orientOutward(vertices, triangles);
  std::vector<Normal3> normals;
  std::vector<TriangleMesh::Index3> normalIndices;
  if (m_fileNormals)
    meshnormals::attach(*m_fileNormals, m_soupPoints, m_soupPolygons, vertices, triangles, normals,
                        normalIndices);
  try {
    if (m_fileNormals)
      return TriangleMesh(std::move(vertices), std::move(triangles), std::move(normals),
                          std::move(normalIndices));
    return TriangleMesh(std::move(vertices), std::move(triangles));
  } catch (const Exception& e) {
    throw fail(e.what());
  }
}

}  // namespace

std::vector<std::string> MeshIO::supportedExtensions() { return {".obj", ".off", ".ply", ".stl"}; }

TriangleMesh MeshIO::load(const std::string& path, const Options& options) {
  return Loader(path, options).load();
}

}  // namespace raylab
