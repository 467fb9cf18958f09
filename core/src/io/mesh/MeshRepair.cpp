// Orientation and the polygon checks before CGAL triangulates a face.
#include "io/mesh/MeshReaders.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Projection_traits_3.h>

#include <algorithm>
#include <map>
#include <utility>

namespace raylab::meshio {

namespace PMP = CGAL::Polygon_mesh_processing;

void orientOutward(const std::vector<Point3>& vertices,
                   std::vector<TriangleMesh::Index3>& triangles) {
  std::map<std::pair<int, int>, int> edgeUse;
  double volume6 = 0.0;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      edgeUse[{std::min(a, b), std::max(a, b)}]++;
    }
    volume6 += glm::dot(vertices[t[0]], glm::cross(vertices[t[1]], vertices[t[2]]));
  }
  const bool closed =
      std::all_of(edgeUse.begin(), edgeUse.end(), [](const auto& e) { return e.second == 2; });
  if (closed && volume6 < 0.0)
    for (auto& t : triangles) std::swap(t[1], t[2]);
}

std::optional<std::string> checkSimplePolygon(const CgalMesh& mesh, CgalMesh::Face_index f) {
  std::vector<CgalPoint> c;
  for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) c.push_back(mesh.point(v));
  const std::size_t n = c.size();
  const std::string face;  // the caller names the face
  if (n > limits::kMaxFaceCorners)
    return face + "RayLab triangulates faces of at most " +
           std::to_string(limits::kMaxFaceCorners) + " corners";
  const Kernel::Vector_3 normal = PMP::compute_face_normal(f, mesh);
  if (normal == CGAL::NULL_VECTOR) return std::nullopt;  // triangulate_faces refuses it
  const CGAL::Projection_traits_3<Kernel> projection(normal);
  const auto compareX = projection.compare_x_2_object();
  const auto compareY = projection.compare_y_2_object();
  const auto orientation = projection.orientation_2_object();
  // Lexicographic order of two points in the projection.
  const auto compare = [&](const CgalPoint& a, const CgalPoint& b) {
    const CGAL::Comparison_result x = compareX(a, b);
    return x != CGAL::EQUAL ? x : compareY(a, b);
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (compare(c[i], c[j]) == CGAL::EQUAL)
        return face +
               "two of them coincide seen along the face's normal (a face folded onto "
               "itself)";
  const std::string crossing =
      "its edges cross or touch seen along the face's normal (a "
      "polygon that intersects itself)";
  // Corner i's edges double back when the corners before and after it are on one line with it
  // and on the same side of it.
  for (std::size_t i = 0; i < n; ++i) {
    const CgalPoint& before = c[(i + n - 1) % n];
    const CgalPoint& after = c[(i + 1) % n];
    if (orientation(before, c[i], after) == CGAL::COLLINEAR &&
        compare(before, c[i]) == compare(after, c[i]))
      return face + crossing;
  }
  // Edges (a, b) and (p, q) that share no corner must not meet, not even at an end.
  const auto meet = [&](const CgalPoint& a, const CgalPoint& b, const CgalPoint& p,
                        const CgalPoint& q) {
    const CGAL::Orientation o1 = orientation(a, b, p), o2 = orientation(a, b, q);
    const CGAL::Orientation o3 = orientation(p, q, a), o4 = orientation(p, q, b);
    if (o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) {  // on one line: do they overlap?
      const bool abForward = compare(a, b) == CGAL::SMALLER;
      const CgalPoint& lo1 = abForward ? a : b;
      const CgalPoint& hi1 = abForward ? b : a;
      const bool pqForward = compare(p, q) == CGAL::SMALLER;
      const CgalPoint& lo2 = pqForward ? p : q;
      const CgalPoint& hi2 = pqForward ? q : p;
      return compare(hi1, lo2) != CGAL::SMALLER && compare(hi2, lo1) != CGAL::SMALLER;
    }
    // Otherwise each must have the other's ends on both sides of its line (or one on it).
    return o1 != o2 && o3 != o4;
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the last edge and the first share corner 0
      if (meet(c[i], c[(i + 1) % n], c[j], c[(j + 1) % n])) return face + crossing;
    }
  return std::nullopt;
}

}  // namespace raylab::meshio
