#pragma once

#include "raylab/core/TriangleMesh.h"
#include "raylab/core/Types.h"

namespace raylab {

/**
 * \brief Closed triangle meshes made in code, for tests, benchmarks and lessons.
 *
 * Every mesh is closed and consistently oriented (counter-clockwise seen from outside,
 * so normals point outward), with shared vertices: neighbouring triangles use the same
 * vertex indices, which is what the watertightness tests need. Positions are world space.
 */
namespace MeshFactory {

/// Icosahedron subdivided `subdivisions` times (each step splits every triangle into 4),
/// vertices pushed onto the sphere: 20 * 4^subdivisions triangles (6 -> 81,920;
/// 8 -> 1,310,720). subdivisions must be in [0, 10].
TriangleMesh makeIcosphere(const Point3& centre, double radius, int subdivisions);

/// Latitude/longitude sphere with `stacks` bands from pole to pole (>= 2) and `slices`
/// around the y axis (>= 3): 2 * slices * (stacks - 1) triangles (501 x 1000 -> 1,000,000).
TriangleMesh makeUvSphere(const Point3& centre, double radius, int stacks, int slices);

/// Axis-aligned cube of edge length `size`, each face split into n x n squares of two
/// triangles: 12 * n^2 triangles. n must be >= 1.
TriangleMesh makeSubdividedCube(const Point3& centre, double size, int n);

}  // namespace MeshFactory

}  // namespace raylab
