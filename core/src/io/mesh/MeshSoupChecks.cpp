// Linear-time checks of a mesh file's soup: see MeshSoupChecks.h.
#include "io/mesh/MeshSoupChecks.h"

#include "raylab/core/Limits.h"

#include <algorithm>
#include <cstdint>

namespace raylab::meshsoup {

std::optional<std::string> checkFaces(const std::vector<std::vector<std::size_t>>& polygons) {
  std::uint64_t corners = 0, checkWork = 0;
  std::vector<std::size_t> sorted;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const std::vector<std::size_t>& face = polygons[f];
    const std::string which = "face " + std::to_string(f + 1);
    if (face.size() > limits::kMaxFaceCorners)
      return "cannot triangulate a face of " + std::to_string(face.size()) +
             " corners: RayLab triangulates faces of at most " +
             std::to_string(limits::kMaxFaceCorners) + " corners";
    corners += face.size();
    if (corners > limits::kMaxMeshCorners)
      return "the faces have more than " + std::to_string(limits::kMaxMeshCorners) +
             " corners together (at " + which + "); RayLab reads meshes of at most that many";
    // A vertex named twice: sorted in O(n log n), instead of CGAL's repair in O(n^2).
    sorted.assign(face.begin(), face.end());
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    // (A triangle or quad naming a vertex twice is degenerate, and cheap: CGAL's repair
    // drops or mends it, as before.)
    if (twice != sorted.end() && face.size() > 4)
      return which + " names vertex " + std::to_string(*twice + 1) +
             " twice; a polygonal face must be a simple polygon";
    if (face.size() > 4) {
      checkWork += std::uint64_t(face.size()) * face.size();
      if (checkWork > limits::kMaxFaceCheckWork)
        return "the polygonal faces are too large together to check (at " + which +
               "; RayLab checks polygons whose corners squared sum to at most " +
               std::to_string(limits::kMaxFaceCheckWork) + ": triangulate them first)";
    }
  }
  return std::nullopt;
}

}  // namespace raylab::meshsoup
