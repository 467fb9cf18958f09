#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

/// \file MeshSoupChecks.h
/// Checks of a mesh file's polygon soup that keep reading it linear in the file's size
/// (issue 38), made before CGAL repairs the soup: CGAL's repair is quadratic in a face
/// that lists the same vertices over and over, and the simple-polygon check of a face is
/// quadratic in its corners. Private to core/src/io.

namespace raylab::meshsoup {

/**
 * \brief Checks every face at most limits::kMaxFaceCorners corners, all faces at most
 * limits::kMaxMeshCorners, no face of more than four corners naming a vertex twice, and the
 * simple-polygon checks of faces of more than four corners within
 * limits::kMaxFaceCheckWork (the sum of their corners squared). The problem (naming the
 * face, counted from 1) when not.
 */
std::optional<std::string> checkFaces(const std::vector<std::vector<std::size_t>>& polygons);

}  // namespace raylab::meshsoup
