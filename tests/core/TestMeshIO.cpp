// Tests of MeshIO: each format (OBJ, OFF, PLY and STL, ASCII and binary) and each error,
// on the small files of tests/data/meshes (made by tests/data/meshes/generate.py).

#include "raylab/core/MeshIO.h"

#include "raylab/core/MeshFactory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace raylab {
namespace {

std::string meshPath(const std::string& name) {
  return std::string(RAYLAB_TEST_DATA_DIR) + "/meshes/" + name;
}

double signedVolume(const TriangleMesh& m) {
  double v6 = 0.0;
  for (const auto& t : m.triangles())
    v6 += glm::dot(m.vertices()[t[0]], glm::cross(m.vertices()[t[1]], m.vertices()[t[2]]));
  return v6 / 6.0;
}

/// Every undirected edge is used by exactly two triangles.
bool isClosed(const TriangleMesh& m) {
  std::map<std::pair<int, int>, int> use;
  for (const auto& t : m.triangles())
    for (int k = 0; k < 3; ++k)
      use[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}]++;
  for (const auto& e : use)
    if (e.second != 2) return false;
  return true;
}

/// The message of the ReadError that loading `path` throws ("" and a failure if none).
std::string readError(const std::string& path, const MeshIO::Options& options = {}) {
  try {
    MeshIO::load(path, options);
  } catch (const MeshIO::ReadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no MeshIO::ReadError for " << path;
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void expectUnitCube(const TriangleMesh& cube) {
  EXPECT_EQ(cube.triangleCount(), 12u);
  EXPECT_EQ(cube.vertices().size(), 8u);
  EXPECT_EQ(cube.bounds().lower, Point3(0.0));
  EXPECT_EQ(cube.bounds().upper, Point3(1.0));
  EXPECT_TRUE(isClosed(cube));
  EXPECT_NEAR(signedVolume(cube), 1.0, 1e-12);  // outward normals
  EXPECT_TRUE(cube.inside(Point3(0.5, 0.25, 0.75)));
  EXPECT_FALSE(cube.inside(Point3(1.5, 0.25, 0.75)));
}

TEST(MeshIO, 01_LoadsObjAndTriangulatesQuads) {
  const TriangleMesh cube = MeshIO::load(meshPath("cube.obj"));
  expectUnitCube(cube);
  const auto hit = cube.closestHit(Ray::make(Point3(0.5, 0.5, 3.0), Vec3(0, 0, -1)));
  ASSERT_TRUE(hit.has_value());
  EXPECT_DOUBLE_EQ(hit->t, 2.0);
  EXPECT_EQ(hit->n, Normal3(0, 0, 1));
}

TEST(MeshIO, 02_LoadsAsciiOff) {
  const TriangleMesh tet = MeshIO::load(meshPath("tetrahedron.off"));
  EXPECT_EQ(tet.triangleCount(), 4u);
  EXPECT_EQ(tet.vertices().size(), 4u);
  EXPECT_NEAR(signedVolume(tet), 1.0 / 6.0, 1e-15);
  EXPECT_TRUE(tet.inside(Point3(0.1, 0.1, 0.1)));
}

TEST(MeshIO, 03_LoadsAsciiAndBinaryPlyIdentically) {
  const TriangleMesh ascii = MeshIO::load(meshPath("icosphere.ply"));
  const TriangleMesh binary = MeshIO::load(meshPath("icosphere_binary.ply"));
  EXPECT_EQ(ascii.triangleCount(), 80u);
  EXPECT_EQ(ascii.vertices().size(), 42u);
  EXPECT_TRUE(isClosed(ascii));
  EXPECT_EQ(ascii.vertices(), binary.vertices());  // repr() round-trips doubles exactly
  EXPECT_EQ(ascii.triangles(), binary.triangles());
  for (const Point3& p : ascii.vertices()) EXPECT_NEAR(glm::length(p), 1.0, 1e-15);
  EXPECT_GT(signedVolume(ascii), 2.5);  // outward; a unit sphere has 4.19
}

TEST(MeshIO, 04_LoadsAsciiAndBinaryStlAndMergesVertices) {
  // STL stores three corners per facet; the repaired soup shares the cube's 8 corners.
  expectUnitCube(MeshIO::load(meshPath("cube_ascii.stl")));
  expectUnitCube(MeshIO::load(meshPath("cube_binary.stl")));
}

TEST(MeshIO, 05_MissingFile) {
  const std::string msg = readError(meshPath("no_such_mesh.obj"));
  EXPECT_TRUE(contains(msg, "no_such_mesh.obj: file not found")) << msg;
}

TEST(MeshIO, 06_UnknownExtension) {
  const std::string msg = readError(meshPath("mesh.xyz"));
  EXPECT_TRUE(contains(msg, "mesh.xyz: unknown mesh extension '.xyz'")) << msg;
  EXPECT_TRUE(contains(msg, ".obj, .off, .ply, .stl")) << msg;
}

TEST(MeshIO, 07_EmptyFileAndFileWithoutFaces) {
  const std::string empty = readError(meshPath("empty.obj"));
  EXPECT_TRUE(contains(empty, "empty.obj: ")) << empty;
  EXPECT_TRUE(contains(empty, "no faces")) << empty;
  const std::string noFaces = readError(meshPath("vertices_only.obj"));
  EXPECT_TRUE(contains(noFaces, "vertices_only.obj: no faces")) << noFaces;
}

TEST(MeshIO, 08_GarbageObjLineIsLocated) {
  const std::string msg = readError(meshPath("garbage.obj"));
  EXPECT_TRUE(contains(msg, "garbage.obj:6: cannot parse OBJ file")) << msg;
  EXPECT_TRUE(contains(msg, "'hello world'")) << msg;
  EXPECT_TRUE(contains(msg, "CGAL: error: unrecognized line: hello")) << msg;
}

TEST(MeshIO, 09_OffFaceIndexOutOfRangeIsLocated) {
  const std::string msg = readError(meshPath("bad_index.off"));
  EXPECT_TRUE(contains(msg, "bad_index.off:8: cannot parse OFF file")) << msg;
  EXPECT_TRUE(contains(msg, "face index 7 out of range [0, 4)")) << msg;
}

TEST(MeshIO, 10_TruncatedBinaryStl) {
  const std::string msg = readError(meshPath("truncated.stl"));
  EXPECT_TRUE(contains(msg, "truncated.stl: cannot parse STL file")) << msg;
  EXPECT_TRUE(contains(msg, "premature end of file")) << msg;
}

TEST(MeshIO, 11_NonManifoldBeyondRepair) {
  const std::string msg = readError(meshPath("nonmanifold.obj"));
  EXPECT_TRUE(contains(msg, "nonmanifold.obj: non-manifold mesh beyond repair")) << msg;
  EXPECT_TRUE(contains(msg, "duplicated vertices")) << msg;
  // On request the duplicated result is kept: three triangles, the hinge edge split.
  MeshIO::Options keep;
  keep.allowNonManifold = true;
  const TriangleMesh m = MeshIO::load(meshPath("nonmanifold.obj"), keep);
  EXPECT_EQ(m.triangleCount(), 3u);
  EXPECT_GT(m.vertices().size(), 5u);
}

TEST(MeshIO, 12_ErrorsAreRaylabExceptions) {
  EXPECT_THROW(MeshIO::load(meshPath("garbage.obj")), Exception);
  EXPECT_THROW(MeshIO::load(meshPath("no_such_mesh.stl")), Exception);
}

TEST(MeshIO, 13_IcosphereRoundTripsThroughObj) {
  // Write a factory icosphere with 17 digits, read it back: same triangles, still closed
  // and watertight to a ray through a vertex.
  const TriangleMesh ico = MeshFactory::makeIcosphere(Point3(0.0), 2.0, 2);
  std::filesystem::create_directories(RAYLAB_TEMP_DIR);
  const std::string path = std::string(RAYLAB_TEMP_DIR) + "/TestMeshIO_icosphere.obj";
  {
    std::ofstream out(path);
    out.precision(17);
    for (const Point3& p : ico.vertices()) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : ico.triangles())
      out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  const TriangleMesh back = MeshIO::load(path);
  EXPECT_EQ(back.triangleCount(), ico.triangleCount());
  EXPECT_EQ(back.vertices(), ico.vertices());
  EXPECT_TRUE(isClosed(back));
  const Point3 vertex = back.vertices()[0];
  const auto h = back.intersect(Ray::make(3.0 * vertex, -vertex));
  ASSERT_TRUE(h.has_value());
  EXPECT_NEAR(h->t, 2.0 * glm::length(vertex), 1e-12);
}

}  // namespace
}  // namespace raylab
