#include "raylab/core/MeshFactory.h"

#include "raylab/core/Check.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace raylab {
namespace MeshFactory {

TriangleMesh makeIcosphere(const Point3& centre, double radius, int subdivisions) {
  RAYLAB_CHECK(subdivisions >= 0 && subdivisions <= 10);
  RAYLAB_CHECK(radius > 0.0);
  // Step 1: the icosahedron, vertices on the unit sphere (golden-ratio rectangles).
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point3> unit = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                              {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                              {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  for (Point3& p : unit) p = glm::normalize(p);
  std::vector<TriangleMesh::Index3> tris = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};

  // Step 2: split every triangle into four; each edge's midpoint is made once and shared.
  for (int s = 0; s < subdivisions; ++s) {
    std::unordered_map<std::uint64_t, int> midpoints;
    midpoints.reserve(tris.size() * 2);
    auto midpoint = [&](int a, int b) {
      const std::uint64_t key =
          (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b));
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      unit.push_back(glm::normalize(unit[a] + unit[b]));
      const int index = static_cast<int>(unit.size()) - 1;
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<TriangleMesh::Index3> finer;
    finer.reserve(tris.size() * 4);
    for (const auto& t : tris) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    tris.swap(finer);
  }

  // Step 3: scale and move onto the requested sphere.
  for (Point3& p : unit) p = centre + radius * p;
  return TriangleMesh(std::move(unit), std::move(tris));
}

TriangleMesh makeUvSphere(const Point3& centre, double radius, int stacks, int slices) {
  RAYLAB_CHECK(stacks >= 2 && slices >= 3);
  RAYLAB_CHECK(radius > 0.0);
  // Vertices: the two poles (on +y and -y) and (stacks - 1) rings of `slices` points.
  std::vector<Point3> vertices;
  vertices.reserve(2 + static_cast<std::size_t>(stacks - 1) * slices);
  vertices.push_back(centre + Vec3(0.0, radius, 0.0));
  for (int i = 1; i < stacks; ++i) {
    const double theta = kPi * i / stacks;  // polar angle from +y
    for (int j = 0; j < slices; ++j) {
      const double phi = 2.0 * kPi * j / slices;
      vertices.push_back(centre + radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                -std::sin(theta) * std::sin(phi)));
    }
  }
  const int south = static_cast<int>(vertices.size());
  vertices.push_back(centre + Vec3(0.0, -radius, 0.0));

  // Triangles, counter-clockwise seen from outside: caps as fans, bands as split quads.
  auto ring = [slices](int i, int j) { return 1 + (i - 1) * slices + (j % slices); };
  std::vector<TriangleMesh::Index3> tris;
  tris.reserve(static_cast<std::size_t>(2) * slices * (stacks - 1));
  for (int j = 0; j < slices; ++j) tris.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const int a = ring(i, j), b = ring(i + 1, j), c = ring(i + 1, j + 1), d = ring(i, j + 1);
      tris.push_back({a, b, c});
      tris.push_back({a, c, d});
    }
  }
  for (int j = 0; j < slices; ++j)
    tris.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
  return TriangleMesh(std::move(vertices), std::move(tris));
}

TriangleMesh makeSubdividedCube(const Point3& centre, double size, int n) {
  RAYLAB_CHECK(n >= 1);
  RAYLAB_CHECK(size > 0.0);
  // Vertices on the (n + 1)^3 lattice that lie on the surface, indexed once each so that
  // faces share their border vertices.
  const int m = n + 1;
  std::vector<int> index(static_cast<std::size_t>(m) * m * m, -1);
  std::vector<Point3> vertices;
  auto vertex = [&](int i, int j, int k) {
    int& slot = index[(static_cast<std::size_t>(i) * m + j) * m + k];
    if (slot < 0) {
      slot = static_cast<int>(vertices.size());
      vertices.push_back(centre + size * (Vec3(i, j, k) / double(n) - 0.5));
    }
    return slot;
  };
  std::vector<TriangleMesh::Index3> tris;
  tris.reserve(static_cast<std::size_t>(12) * n * n);
  // For each axis and side, walk the face grid; (u, v) are the other two axes in
  // right-handed order so that u x v points along +axis, and the + side keeps that
  // winding while the - side reverses it.
  for (int axis = 0; axis < 3; ++axis) {
    const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int a = 0; a < n; ++a) {
        for (int b = 0; b < n; ++b) {
          int corner[4];
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int q = 0; q < 4; ++q) {
            int ijk[3];
            ijk[axis] = side * n;
            ijk[ua] = a + du[q];
            ijk[va] = b + dv[q];
            corner[q] = vertex(ijk[0], ijk[1], ijk[2]);
          }
          if (side == 1) {
            tris.push_back({corner[0], corner[1], corner[2]});
            tris.push_back({corner[0], corner[2], corner[3]});
          } else {
            tris.push_back({corner[0], corner[2], corner[1]});
            tris.push_back({corner[0], corner[3], corner[2]});
          }
        }
      }
    }
  }
  return TriangleMesh(std::move(vertices), std::move(tris));
}

}  // namespace MeshFactory
}  // namespace raylab
