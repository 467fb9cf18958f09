// Smooth triangles (issue 13): corner normals on a TriangleMesh, interpolated at the hit
// (SurfaceInteraction::ns) beside the unchanged geometric normal; normals read from OBJ and
// PLY files or computed with a crease angle; the no-leak rule of the engine; and a picture
// of a tessellated sphere that smooth shading brings closer to the analytic sphere's.

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Bsdf.h"
#include "raylab/core/Camera.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/MeshFactory.h"
#include "raylab/core/MeshIO.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/Quad.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Tracer.h"
#include "raylab/core/TriangleMesh.h"

#include "TransportScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace raylab {
namespace {

using testing::addMaterial;
using testing::addObject;
using testing::makeMaterial;

std::string tempPath(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "raylab_smooth_triangles";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string writeText(const std::string& name, const std::string& text) {
  const std::string path = tempPath(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string readError(const std::string& path) {
  try {
    MeshIO::load(path);
  } catch (const MeshIO::ReadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no MeshIO::ReadError for " << path;
  return "";
}

std::string loadError(const std::string& path) {
  try {
    SceneIO::load(path);
  } catch (const SceneIO::LoadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneIO::LoadError for " << path;
  return "";
}

double angleBetween(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

/// The triangle (0,0,0), (1,0,0), (0,1,0) (geometric normal +z) with corner normals
/// n0 = (0,0,1), n1 = (1,0,1)/sqrt 2, n2 = (0,1,1)/sqrt 2 (given unnormalised).
TriangleMesh tiltedTriangle() {
  return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}},
                      {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, {{0, 1, 2}});
}

void expectNear(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << toString(actual) << " vs " << toString(expected);
  EXPECT_NEAR(actual.y, expected.y, tolerance) << toString(actual) << " vs " << toString(expected);
  EXPECT_NEAR(actual.z, expected.z, tolerance) << toString(actual) << " vs " << toString(expected);
}

TEST(SmoothTriangles, 01_InterpolatedNormalAtKnownBarycentrics) {
  const TriangleMesh mesh = tiltedTriangle();
  ASSERT_TRUE(mesh.hasNormals());
  // (b0, b1, b2) = (0.5, 0.25, 0.25): sum = (0.25/sqrt2, 0.25/sqrt2, 0.5 + 0.5/sqrt2)
  // = (0.1767767, 0.1767767, 0.8535534), length 0.8894118, so
  // ns = (0.19875685, 0.19875685, 0.95968298).
  expectNear(mesh.shadingNormal(0, 0.25, 0.25),
             {0.19875685341551338, 0.19875685341551338, 0.9596829822606673}, 1e-14);
  // (0.2, 0.3, 0.5): sum = (0.3/sqrt2, 0.5/sqrt2, 0.2 + 0.8/sqrt2)
  // = (0.2121320, 0.3535534, 0.7656854), length 0.8696403, so
  // ns = (0.24393079, 0.40655132, 0.88046226).
  expectNear(mesh.shadingNormal(0, 0.3, 0.5),
             {0.24393079043459212, 0.4065513173909869, 0.880462262567572}, 1e-14);
  // At a corner the normal is that corner's own: (1,0,1)/sqrt 2 at b1 = 1.
  expectNear(mesh.shadingNormal(0, 1.0, 0.0), {std::sqrt(0.5), 0.0, std::sqrt(0.5)}, 1e-15);
}

TEST(SmoothTriangles, 02_HitCarriesShadingNormalBesideGeometricNormal) {
  const TriangleMesh mesh = tiltedTriangle();
  // A ray straight down onto (0.25, 0.5): barycentrics b1 = 0.25, b2 = 0.5, b0 = 0.25.
  const Ray ray = Ray::make({0.25, 0.5, 2.0}, {0.0, 0.0, -1.0});
  const std::optional<SurfaceInteraction> si = mesh.closestHit(ray);
  ASSERT_TRUE(si);
  // The geometric normal and the hit are those of the flat triangle.
  EXPECT_EQ(si->n, Normal3(0.0, 0.0, 1.0));
  EXPECT_NEAR(si->t, 2.0, 1e-15);
  // ns: sum = (0.25/sqrt2, 0.5/sqrt2, 0.25 + 0.75/sqrt2) = (0.1767767, 0.3535534, 0.7803301),
  // length 0.8746, the same as mesh.shadingNormal(0, 0.25, 0.5).
  expectNear(si->ns, mesh.shadingNormal(0, 0.25, 0.5), 1e-12);
  const Vec3 sum(0.25 / std::sqrt(2.0), 0.5 / std::sqrt(2.0), 0.25 + 0.75 / std::sqrt(2.0));
  expectNear(si->ns, glm::normalize(sum), 1e-12);
  EXPECT_EQ(si->shadingNormal(), si->ns);
  expectNear(si->facingShadingNormal(), si->ns, 0.0);
  // From below, the facing shading normal turns with the geometric side.
  const std::optional<SurfaceInteraction> below =
      mesh.closestHit(Ray::make({0.25, 0.5, -2.0}, {0.0, 0.0, 1.0}));
  ASSERT_TRUE(below);
  EXPECT_FALSE(below->frontFace);
  expectNear(below->facingShadingNormal(), -below->ns, 0.0);
  // A flat mesh leaves ns zero and shades with n.
  const TriangleMesh flat({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const std::optional<SurfaceInteraction> f = flat.closestHit(ray);
  ASSERT_TRUE(f);
  EXPECT_TRUE(isZero(f->ns));
  EXPECT_EQ(f->shadingNormal(), f->n);
}

TEST(SmoothTriangles, 03_NormalsTurnToTheGeometricSideAndWedgeHitsShadeFlat) {
  // Inward normals (a file wound the other way): ns is turned to n's side.
  const TriangleMesh inward({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}},
                            {{0, 0, -1}, {-1, 0, -1}, {0, -1, -1}}, {{0, 1, 2}});
  EXPECT_GT(glm::dot(inward.shadingNormal(0, 0.3, 0.3), Vec3(0, 0, 1)), 0.0);
  // Normals tilted by 78.7 degrees towards +x: a ray arriving from +x at a grazing angle
  // is in front of the triangle but behind its shading surface: that hit shades flat.
  const TriangleMesh tilted({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {{1, 0, 0.2}},
                            {{0, 0, 0}});
  const Vec3 grazing = glm::normalize(Vec3(1.0, 0.0, -0.1));  // n.d < 0, ns.d > 0
  const std::optional<SurfaceInteraction> si =
      tilted.closestHit(Ray::make(Point3(0.25, 0.25, 0.0) - 2.0 * grazing, grazing));
  ASSERT_TRUE(si);
  EXPECT_TRUE(si->frontFace);
  EXPECT_TRUE(isZero(si->ns));
  // Seen from above, the same surface keeps its tilted normal.
  const std::optional<SurfaceInteraction> above =
      tilted.closestHit(Ray::make({0.25, 0.25, 2.0}, {0.0, 0.0, -1.0}));
  ASSERT_TRUE(above);
  expectNear(above->ns, glm::normalize(Vec3(1, 0, 0.2)), 1e-15);
  // sidesAgree: directions in the wedge between the surfaces disagree.
  EXPECT_FALSE(above->sidesAgree(grazing));
  EXPECT_TRUE(above->sidesAgree(Vec3(0, 0, 1)));
  EXPECT_TRUE(above->sidesAgree(Vec3(0, 0, -1)));
  EXPECT_TRUE(si->sidesAgree(grazing));  // a flat hit agrees everywhere
}

TEST(SmoothTriangles, 04_ApplyTurnsTheNormalsWithTheMesh) {
  TriangleMesh mesh = tiltedTriangle();
  // A quarter turn about z: (x, y, z) -> (-y, x, z); n1 = (1,0,1)/sqrt2 -> (0,1,1)/sqrt2.
  mesh.apply(glm::dmat4(glm::dvec4(0, 1, 0, 0), glm::dvec4(-1, 0, 0, 0), glm::dvec4(0, 0, 1, 0),
                        glm::dvec4(0, 0, 0, 1)));
  expectNear(mesh.shadingNormal(0, 1.0, 0.0), {0.0, std::sqrt(0.5), std::sqrt(0.5)}, 1e-15);
  // A mirror x -> -x swaps two corners; corner normals follow (still outward, +z side):
  // the corner at (0, 1, 0) had (0,1,1)/sqrt2 turned to (-1,0,1)/sqrt2, mirrored to (1,0,1).
  mesh.apply(glm::dmat4(glm::dvec4(-1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 1, 0),
                        glm::dvec4(0, 0, 0, 1)));
  const std::optional<SurfaceInteraction> si =
      mesh.closestHit(Ray::make({0.999998, 0.000001, 1.0}, {0.0, 0.0, -1.0}));
  ASSERT_TRUE(si);
  EXPECT_EQ(si->n, Normal3(0, 0, 1));
  expectNear(si->ns, {std::sqrt(0.5), 0.0, std::sqrt(0.5)}, 1e-5);
}

TEST(SmoothTriangles, 05_BadNormalsAreRefused) {
  const auto message = [](auto make) {
    try {
      make();
    } catch (const Shape::InvalidGeometry& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::vector<Point3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(contains(message([&] {
                         TriangleMesh(v, {{0, 1, 2}}, {{0, 0, 1}}, {{0, 0, 3}});
                       }),
                       "triangle 0 has normal index 3 out of range [0, 1)"));
  EXPECT_TRUE(contains(message([&] {
                         TriangleMesh(v, {{0, 1, 2}}, {{0, 0, 1}, {0, 0, 0}}, {{0, 0, 1}});
                       }),
                       "normal 1 (0, 0, 0) has zero length"));
  EXPECT_TRUE(contains(message([&] {
                         TriangleMesh(v, {{0, 1, 2}}, {{0, 0, 1}}, {});
                       }),
                       "0 normal index triples for 1 triangles"));
  EXPECT_TRUE(contains(message([&] {
                         TriangleMesh(v, {{0, 1, 2}}).computeCreaseNormals(4.0);
                       }),
                       "crease angle 4.000000 rad is outside [0, pi]"));
}

TEST(SmoothTriangles, 06_CubeAt30DegreesKeepsFlatFaces) {
  // The faces of a cube meet at 90 degrees, more than 30: every corner keeps its face's
  // normal. Each of the 8 vertices has 3 faces around it: 24 normals.
  TriangleMesh cube = MeshFactory::makeSubdividedCube(Point3(0.0), 2.0, 1);
  cube.computeCreaseNormals(radians(30.0));
  ASSERT_TRUE(cube.hasNormals());
  EXPECT_EQ(cube.normals().size(), 24u);
  for (std::size_t t = 0; t < cube.triangleCount(); ++t) {
    const auto& tri = cube.triangles()[t];
    const Vec3 face = glm::normalize(glm::cross(cube.vertices()[tri[1]] - cube.vertices()[tri[0]],
                                                cube.vertices()[tri[2]] - cube.vertices()[tri[0]]));
    for (int k = 0; k < 3; ++k) expectNear(cube.normals()[cube.normalIndices()[t][k]], face, 1e-15);
    expectNear(cube.shadingNormal(int(t), 0.2, 0.3), face, 1e-15);
  }
  // At 100 degrees the cube's edges are smoothed: a corner normal is the diagonal.
  cube.computeCreaseNormals(radians(100.0));
  EXPECT_EQ(cube.normals().size(), 8u);
  for (std::size_t t = 0; t < cube.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Point3& p = cube.vertices()[cube.triangles()[t][k]];
      expectNear(cube.normals()[cube.normalIndices()[t][k]], glm::normalize(p), 1e-15);
    }
}

TEST(SmoothTriangles, 07_IcosphereAt60DegreesMatchesTheSphereNormal) {
  // An icosphere subdivided 3 times (1280 triangles; neighbouring faces meet at about
  // 10 degrees): at 60 degrees every vertex is smooth. Measured: the angle-weighted vertex
  // normals are within 0.30 degrees of the radial direction (exact at the 12 original
  // vertices, by symmetry; the triangles around the others are not all alike); the
  // interpolated normal at the points tried is within 0.29 degrees of the sphere's normal
  // at the point's radial projection, where the flat triangle's is off by up to 4.6.
  TriangleMesh sphere = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 3);
  sphere.computeCreaseNormals(radians(60.0));
  EXPECT_EQ(sphere.normals().size(), sphere.vertices().size());
  double worstVertex = 0.0;
  for (std::size_t t = 0; t < sphere.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      worstVertex =
          std::max(worstVertex, angleBetween(sphere.normals()[sphere.normalIndices()[t][k]],
                                             sphere.vertices()[sphere.triangles()[t][k]]));
  double worstSmooth = 0.0, worstFlat = 0.0;
  const double bs[][2] = {{1.0 / 3, 1.0 / 3}, {0.1, 0.2}, {0.5, 0.5}, {0.7, 0.1}, {0.05, 0.9}};
  for (std::size_t t = 0; t < sphere.triangleCount(); ++t) {
    const auto& tri = sphere.triangles()[t];
    const Point3 p0 = sphere.vertices()[tri[0]], p1 = sphere.vertices()[tri[1]],
                 p2 = sphere.vertices()[tri[2]];
    const Vec3 face = glm::cross(p1 - p0, p2 - p0);
    for (const auto& b : bs) {
      const Point3 p = (1.0 - b[0] - b[1]) * p0 + b[0] * p1 + b[1] * p2;
      worstSmooth =
          std::max(worstSmooth, angleBetween(sphere.shadingNormal(int(t), b[0], b[1]), p));
      worstFlat = std::max(worstFlat, angleBetween(face, p));
    }
  }
  std::printf(
      "icosphere(3) at 60 deg: vertex normals within %.4f deg of radial; interpolated "
      "within %.4f deg of the sphere's normal, flat within %.4f deg\n",
      worstVertex * 180.0 / kPi, worstSmooth * 180.0 / kPi, worstFlat * 180.0 / kPi);
  EXPECT_LT(worstVertex, radians(0.35));
  EXPECT_LT(worstSmooth, radians(0.35));
  EXPECT_GT(worstFlat, 10.0 * worstSmooth);
}

// ---------------------------------------------------------------------------------------
// Files

/// The corner normal of `mesh` at position p, looked up over every triangle (the first).
std::vector<Normal3> cornerNormalsAt(const TriangleMesh& mesh, const Point3& p) {
  std::vector<Normal3> found;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      if (mesh.vertices()[mesh.triangles()[t][k]] == p)
        found.push_back(mesh.normals()[mesh.normalIndices()[t][k]]);
  return found;
}

TEST(SmoothTriangles, 08_ObjNormalsAreReadBack) {
  // A quad with v/vt/vn corners (triangulated by MeshIO) and a triangle with v//vn.
  const std::string path = writeText("quad_normals.obj",
                                     "# a quad and a triangle with vertex normals\n"
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
                                     "vt 0 0\n"
                                     "vn 0 0 1\nvn 1 0 1\nvn 1 1 1\nvn 0 1 1\nvn 0 -1 1\n"
                                     "f 1/1/1 2/1/2 3/1/3 4/1/4\n"
                                     "f 2//5 5//5 3//3\n");
  const TriangleMesh mesh = MeshIO::load(path);
  ASSERT_TRUE(mesh.hasNormals());
  EXPECT_EQ(mesh.triangleCount(), 3u);
  const std::map<std::vector<double>, Vec3> quadNormals = {{{0, 0, 0}, {0, 0, 1}},
                                                           {{0, 1, 0}, {0, 1, 1}}};
  for (const auto& [p, n] : quadNormals)
    for (const Normal3& got : cornerNormalsAt(mesh, Point3(p[0], p[1], p[2])))
      expectNear(got, glm::normalize(n), 1e-15);
  // (1, 0, 0) is in the quad (normal 2) and the triangle (normal 5): both kept.
  const std::vector<Normal3> shared = cornerNormalsAt(mesh, Point3(1, 0, 0));
  ASSERT_GE(shared.size(), 2u);  // one or two of the quad's triangles, and the triangle
  int quadCorners = 0, triangleCorners = 0;
  for (const Normal3& n : shared) {
    if (glm::length(n - glm::normalize(Vec3(1, 0, 1))) < 1e-15) ++quadCorners;
    if (glm::length(n - glm::normalize(Vec3(0, -1, 1))) < 1e-15) ++triangleCorners;
  }
  EXPECT_EQ(std::size_t(quadCorners + triangleCorners), shared.size());
  EXPECT_EQ(triangleCorners, 1);
  for (const Normal3& n : cornerNormalsAt(mesh, Point3(2, 0, 0)))
    expectNear(n, glm::normalize(Vec3(0, -1, 1)), 1e-15);

  // A face without normal indices shades flat; a file without any stays flat.
  const TriangleMesh mixed = MeshIO::load(writeText(
      "mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvn 1 1 1\nf 1//1 2//1 3//1\nf 2 4 3\n"));
  ASSERT_TRUE(mixed.hasNormals());
  for (std::size_t t = 0; t < mixed.triangleCount(); ++t) {
    const auto& tri = mixed.triangles()[t];
    const Point3 apex(1, 1, 1);  // only the second face has it
    const bool second = mixed.vertices()[tri[0]] == apex || mixed.vertices()[tri[1]] == apex ||
                        mixed.vertices()[tri[2]] == apex;
    const Vec3 face =
        glm::normalize(glm::cross(mixed.vertices()[tri[1]] - mixed.vertices()[tri[0]],
                                  mixed.vertices()[tri[2]] - mixed.vertices()[tri[0]]));
    for (int k = 0; k < 3; ++k)
      expectNear(mixed.normals()[mixed.normalIndices()[t][k]],
                 second ? face : glm::normalize(Vec3(1, 1, 1)), 1e-15);
  }
  EXPECT_FALSE(MeshIO::load(writeText("plain.obj",
                                      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n"
                                      "f 1 2 3\n"))
                   .hasNormals());
}

const char* const kPlyHeader =
    "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n";

/// Vertex positions and normals of the PLY tests (all exact in float).
const float kPlyVertices[4][6] = {
    {0, 0, 0, 0, 0, 1}, {1, 0, 0, 0.5f, 0, 1}, {1, 1, 0, 0.5f, 0.5f, 1}, {0, 1, 0, 0, 0.5f, 1}};

void expectPlyNormals(const TriangleMesh& mesh) {
  ASSERT_TRUE(mesh.hasNormals());
  EXPECT_EQ(mesh.triangleCount(), 2u);
  for (const auto& v : kPlyVertices) {
    const std::vector<Normal3> found = cornerNormalsAt(mesh, Point3(v[0], v[1], v[2]));
    EXPECT_FALSE(found.empty());
    for (const Normal3& n : found) expectNear(n, glm::normalize(Vec3(v[3], v[4], v[5])), 1e-15);
  }
}

TEST(SmoothTriangles, 09_PlyNormalsAreReadBack) {
  std::string ascii = std::string("ply\nformat ascii 1.0\n") + kPlyHeader;
  for (const auto& v : kPlyVertices) {
    for (float x : v) ascii += std::to_string(x) + " ";
    ascii += "\n";
  }
  ascii += "3 0 1 2\n3 0 2 3\n";
  expectPlyNormals(MeshIO::load(writeText("quad_ascii.ply", ascii)));

  std::string binary = std::string("ply\nformat binary_little_endian 1.0\n") + kPlyHeader;
  const auto put = [&binary](const void* data, std::size_t size) {
    binary.append(static_cast<const char*>(data), size);  // the test machines are little-endian
  };
  for (const auto& v : kPlyVertices) put(v, sizeof v);
  const std::int32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& face : faces) {
    const unsigned char three = 3;
    put(&three, 1);
    put(face, sizeof face);
  }
  expectPlyNormals(MeshIO::load(writeText("quad_binary.ply", binary)));
}

TEST(SmoothTriangles, 10_BadNormalsInFilesNameTheFileAndLine) {
  // An OBJ face whose normal index refers to no vn: file:line.
  const std::string badIndex =
      writeText("bad_normal_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n");
  std::string e = readError(badIndex);
  EXPECT_TRUE(contains(e, badIndex + ":5: ")) << e;
  EXPECT_TRUE(contains(e, "face normal index 7 refers to no normal (1 defined so far)")) << e;
  // A zero-length vn: file:line.
  const std::string zero =
      writeText("zero_normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
  e = readError(zero);
  EXPECT_TRUE(contains(e, zero + ":4: ")) << e;
  EXPECT_TRUE(contains(e, "normal 1 has zero length")) << e;
  // A PLY file with nx and ny but no nz.
  std::string partial =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nproperty float ny\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0 0 0\n1 0 0 0 0\n0 1 0 0 0\n"
      "3 0 1 2\n";
  e = readError(writeText("partial.ply", partial));
  EXPECT_TRUE(contains(e, "need the properties nx, ny and nz; the header has only nx, ny")) << e;
  // A zero normal in an ASCII PLY file: the line of its vertex (the header has 12 lines).
  std::string zeroPly = std::string("ply\nformat ascii 1.0\n") + kPlyHeader +
                        "0 0 0 0 0 1\n1 0 0 0 0 0\n1 1 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n3 0 2 3\n";
  const std::string zeroPlyPath = writeText("zero_normal.ply", zeroPly);
  e = readError(zeroPlyPath);
  EXPECT_TRUE(contains(e, zeroPlyPath + ":14: ")) << e;
  EXPECT_TRUE(contains(e, "the normal of vertex 1 has zero length")) << e;
}

// ---------------------------------------------------------------------------------------
// Scene files

std::string meshScene(const std::string& shapeExtra) {
  return R"({"raylab_scene": 1, "name": "smooth",
  "materials": [{"name": "white", "type": "diffuse", "colour": [0.8, 0.8, 0.8]}],
  "objects": [{"name": "ball", "material": "white",
               "shape": {"type": "mesh", "file": "ball.obj")" +
         shapeExtra + R"(}}]})";
}

TEST(SmoothTriangles, 11_SceneKeysNormalsAndCreaseAngle) {
  // An octahedron: faces meet at 109.5 degrees (normals 70.5 degrees apart).
  writeText("ball.obj",
            "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
            "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
  const auto meshOf = [](const Scene& s) -> const TriangleMesh& {
    return static_cast<const TriangleMesh&>(*s.objects.at(0).shape);
  };
  const Scene plain = SceneIO::load(writeText("plain.json", meshScene("")));
  EXPECT_EQ(plain.objects[0].meshNormals, MeshNormals::File);
  EXPECT_FALSE(meshOf(plain).hasNormals());
  // Smooth at 120 degrees: every vertex averages its 4 faces (opposite ones are 109.5
  // degrees apart), the normal is radial.
  const Scene smooth = SceneIO::load(
      writeText("smooth.json", meshScene(R"(, "normals": "smooth", "crease_angle": 120)")));
  ASSERT_TRUE(meshOf(smooth).hasNormals());
  EXPECT_EQ(meshOf(smooth).normals().size(), 6u);
  expectNear(meshOf(smooth).shadingNormal(0, 0.0, 0.0), {1, 0, 0}, 1e-15);
  // At the default 60 degrees the octahedron's edges stay sharp.
  const Scene sharp = SceneIO::load(writeText("sharp.json", meshScene(R"(, "normals": "smooth")")));
  EXPECT_EQ(meshOf(sharp).normals().size(), 24u);
  // Saved and read again: the keys survive, the default is not written.
  const std::string text = SceneIO::serialize(smooth, tempPath(""));
  EXPECT_TRUE(contains(text, "\"normals\": \"smooth\"")) << text;
  EXPECT_TRUE(contains(text, "\"crease_angle\": 120")) << text;
  EXPECT_FALSE(contains(SceneIO::serialize(plain, tempPath("")), "normals"));
  const Scene again = SceneIO::parse(text, tempPath("again.json"));
  EXPECT_EQ(again.objects[0].meshNormals, MeshNormals::Smooth);
  EXPECT_EQ(again.objects[0].creaseAngle, 120.0);
  // "flat" drops a file's normals.
  writeText("ball.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1 1\nf 1//1 2//1 3//1\n");
  EXPECT_TRUE(meshOf(SceneIO::load(writeText("file.json", meshScene("")))).hasNormals());
  EXPECT_FALSE(meshOf(SceneIO::load(writeText("flat.json", meshScene(R"(, "normals": "flat")"))))
                   .hasNormals());
}

TEST(SmoothTriangles, 12_BadSceneKeysNameTheJsonPath) {
  writeText("ball.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string wide = writeText("wide.json", meshScene(R"(, "crease_angle": 200)"));
  std::string e = loadError(wide);
  EXPECT_TRUE(contains(e, wide + ": at /objects/0/shape/crease_angle: crease angle 200 must be "
                                 "in [0, 180] degrees"))
      << e;
  e = loadError(writeText("negative.json", meshScene(R"(, "crease_angle": -1)")));
  EXPECT_TRUE(contains(e, "/objects/0/shape/crease_angle")) << e;
  e = loadError(writeText("text.json", meshScene(R"(, "crease_angle": "30")")));
  EXPECT_TRUE(contains(e, "/objects/0/shape/crease_angle")) << e;
  e = loadError(writeText("bumpy.json", meshScene(R"(, "normals": "bumpy")")));
  EXPECT_TRUE(contains(e,
                       "at /objects/0/shape/normals: unknown normals \"bumpy\" (expected "
                       "file, flat or smooth)"))
      << e;
  // A mesh file with a bad normal: the JSON path and the mesh file's line.
  const std::string obj = writeText("ball.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n");
  e = loadError(writeText("badmesh.json", meshScene("")));
  EXPECT_TRUE(contains(e, "at /objects/0/shape/file")) << e;
  EXPECT_TRUE(contains(e, obj + ":4: ")) << e;
  EXPECT_TRUE(contains(e, "face normal index 1 refers to no normal (0 defined so far)")) << e;
}

// ---------------------------------------------------------------------------------------
// Light transport

/// A 20 x 20 square in the plane z = 0 (geometric normal +z) whose corner normals all lean
/// towards +x by 78.7 degrees: (1, 0, 0.2) normalised. A camera above looks straight down
/// at its centre through a 1 x 1 image.
Scene tiltedFloorScene(const Material& floorMaterial) {
  Scene scene;
  scene.name = "tilted floor";
  const int m = addMaterial(scene, floorMaterial);
  auto floor = std::make_unique<TriangleMesh>(
      std::vector<Point3>{{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}},
      std::vector<TriangleMesh::Index3>{{0, 1, 2}, {0, 2, 3}}, std::vector<Normal3>{{1, 0, 0.2}},
      std::vector<TriangleMesh::Index3>{{0, 0, 0}, {0, 0, 0}});
  addObject(scene, "floor", std::move(floor), m);
  scene.camera.position = Point3(0.0, 0.0, 5.0);
  scene.camera.lookAt = Point3(0.0);
  scene.camera.width = 1;
  scene.camera.height = 1;
  scene.camera.verticalFov = 1.0;
  scene.render.background = Vec3(0.0);
  return scene;
}

Vec3 renderCentre(const Scene& scene, Algorithm algorithm, int spp = 1) {
  RenderSettings settings = scene.render;
  settings.algorithm = algorithm;
  settings.samplesPerPixel = spp;
  settings.shadowSamples = 4;
  settings.glossySamples = 4;
  const Tracer tracer(scene, settings);
  Vec3 sum(0.0);
  for (int s = 0; s < spp; ++s) sum += tracer.trace(0, 0, s);
  return sum / double(spp);
}

TEST(SmoothTriangles, 13_NoLightLeaksThroughTheShadingNormal) {
  // A point light below the floor, in the wedge between the two surfaces: the direction to
  // it, (1, 0, -0.1) normalised, is above the shading surface (dot with (1, 0, 0.2) is
  // 0.98 > 0) but below the geometric one. Lambert shading with the shading normal would
  // give it cos = 0.96; the rule gives it nothing, in every algorithm.
  Scene below = tiltedFloorScene(makeMaterial("white", MaterialType::Diffuse, Vec3(0.8)));
  below.pointLights.push_back({"under", Point3(5.0, 0.0, -0.5), Vec3(50.0)});
  Scene above = below;
  above.pointLights[0].position = Point3(5.0, 0.0, 0.5);  // the control: above both
  for (Algorithm a : kAllAlgorithms) {
    EXPECT_EQ(renderCentre(below, a, 4), Vec3(0.0)) << toString(a);
    EXPECT_GT(renderCentre(above, a, 4).x, 0.1) << toString(a);
  }

  // A mirror floor: the shading normal reflects the camera ray (0, 0, -1) to
  // (0.38, 0, -0.92), below the geometric surface, where a light faces up. The reflected
  // ray would find it; the rule absorbs it.
  Material mirror = makeMaterial("mirror", MaterialType::Mirror, Vec3(1.0));
  mirror.reflectionRate = 1.0;
  mirror.refractionRate = 0.0;
  Scene mirrorScene = tiltedFloorScene(mirror);
  const int light =
      addMaterial(mirrorScene, makeMaterial("light", MaterialType::Diffuse, Vec3(0.0), Vec3(5.0)));
  addObject(mirrorScene, "light below",
            std::make_unique<Quad>(Point3(-50, -50, -1), Vec3(100, 0, 0), Vec3(0, 100, 0)), light);
  // The premise: the specular lobe leaves below the geometric surface.
  const std::optional<SurfaceInteraction> si =
      mirrorScene.objects[0].shape->closestHit(Ray::make({0, 0, 5}, {0, 0, -1}));
  ASSERT_TRUE(si);
  const SpecularLobes lobes = bsdf::specularLobes(mirror, *si, Vec3(0, 0, 1));
  ASSERT_EQ(lobes.count, 1);
  EXPECT_LT(glm::dot(lobes.lobe[0].wi, si->n), -0.9);
  for (Algorithm a : kAllAlgorithms)
    EXPECT_EQ(renderCentre(mirrorScene, a, 4), Vec3(0.0)) << toString(a);
}

TEST(SmoothTriangles, 15_TheRayTreeAndInspectorShowTheInterpolatedNormal) {
  // The camera ray onto the tilted floor records both normals; the inspector shows the
  // shading normal as interpolated, and a ray tree dump keeps it.
  Scene scene = tiltedFloorScene(makeMaterial("white", MaterialType::Diffuse, Vec3(0.8)));
  scene.pointLights.push_back({"lamp", Point3(5.0, 0.0, 0.5), Vec3(50.0)});
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  settings.samplesPerPixel = 1;
  const PixelTrace trace = tracePixel(scene, settings, 0, 0);
  ASSERT_GE(trace.tree.segments.size(), 1u);
  const RaySegment& camera = trace.tree.segments[0];
  EXPECT_EQ(camera.normal, Normal3(0, 0, 1));
  expectNear(camera.shadingNormal, glm::normalize(Vec3(1, 0, 0.2)), 1e-15);
  const std::string text =
      rayText(RayInspector::inspect(scene, trace.tree, 0, false), Language::English);
  EXPECT_TRUE(contains(text, "  shading     (0.9806, 0, 0.1961) interpolated")) << text;
  const RayTree back = RayTreeJson::parse(RayTreeJson::serialize(trace.tree, scene, settings), "t");
  EXPECT_EQ(back.segments[0].shadingNormal, camera.shadingNormal);
  // A flat surface shows one normal only.
  Scene flat = scene;
  static_cast<TriangleMesh&>(*flat.objects[0].shape).clearNormals();
  const PixelTrace flatTrace = tracePixel(flat, settings, 0, 0);
  EXPECT_TRUE(isZero(flatTrace.tree.segments[0].shadingNormal));
  EXPECT_FALSE(
      contains(rayText(RayInspector::inspect(flat, flatTrace.tree, 0, false), Language::English),
               "interpolated"));
}

/// The camera of the ball pictures: 64 x 64 from (0, 0, 4).
CameraSpec ballCamera() {
  CameraSpec camera;
  camera.position = Point3(0.0, 0.0, 4.0);
  camera.lookAt = Point3(0.0);
  camera.verticalFov = 35.0;
  camera.width = 64;
  camera.height = 64;
  return camera;
}

/// A white Lambert ball of radius 1 at the origin lit by a point light, 64 x 64, ray
/// casting (deterministic): the analytic sphere, or an icosphere mesh.
std::vector<Vec3> renderBall(std::unique_ptr<Shape> ball) {
  Scene scene;
  const int m = addMaterial(scene, makeMaterial("white", MaterialType::Diffuse, Vec3(0.8)));
  addObject(scene, "ball", std::move(ball), m);
  scene.pointLights.push_back({"lamp", Point3(3.0, 4.0, 5.0), Vec3(60.0)});
  scene.camera = ballCamera();
  RenderSettings settings;
  settings.algorithm = Algorithm::RayCasting;
  settings.samplesPerPixel = 1;
  const Tracer tracer(scene, settings);
  std::vector<Vec3> image;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) image.push_back(tracer.trace(x, y, 0));
  return image;
}

/// RMS difference per channel over the pixels where `mask` is true (all when empty).
double rms(const std::vector<Vec3>& a, const std::vector<Vec3>& b,
           const std::vector<bool>& mask = {}) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!mask.empty() && !mask[i]) continue;
    const Vec3 d = a[i] - b[i];
    sum += glm::dot(d, d) / 3.0;
    ++count;
  }
  return std::sqrt(sum / double(count));
}

TEST(SmoothTriangles, 14_SmoothSphereIsCloserToTheAnalyticSphere) {
  // Measured (64 x 64, icosphere subdivided twice: 320 triangles, crease 60 degrees), RMS
  // per channel against the analytic sphere's picture: whole picture 0.0206 flat, 0.0172
  // smooth (most of what is left is the polygonal outline, which shading cannot change);
  // inside both outlines (the pixels whose camera ray hits the sphere and the mesh)
  // 0.0163 flat, 0.0045 smooth.
  const Sphere sphere(Point3(0.0), 1.0);
  const TriangleMesh flatMesh = MeshFactory::makeIcosphere(Point3(0.0), 1.0, 2);
  TriangleMesh smoothMesh = flatMesh;
  smoothMesh.computeCreaseNormals(radians(60.0));
  std::vector<bool> inside;
  const Camera camera(ballCamera());
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const Ray ray = camera.generateRay(Vec2(x + 0.5, y + 0.5), Vec2(0.5), 0.0);
      inside.push_back(sphere.intersect(ray) && flatMesh.intersect(ray));
    }
  const std::vector<Vec3> analytic = renderBall(sphere.clone());
  const std::vector<Vec3> flat = renderBall(flatMesh.clone());
  const std::vector<Vec3> smooth = renderBall(smoothMesh.clone());
  const double flatAll = rms(flat, analytic), smoothAll = rms(smooth, analytic);
  const double flatInside = rms(flat, analytic, inside),
               smoothInside = rms(smooth, analytic, inside);
  std::printf(
      "RMS against the analytic sphere: whole picture flat %.4f, smooth %.4f; inside "
      "both outlines flat %.4f, smooth %.4f\n",
      flatAll, smoothAll, flatInside, smoothInside);
  EXPECT_LT(smoothAll, flatAll);
  EXPECT_LT(smoothInside, flatInside);
  EXPECT_LT(smoothInside, 0.5 * flatInside);
}

}  // namespace
}  // namespace raylab
