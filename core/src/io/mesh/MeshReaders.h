#pragma once

#include "raylab/core/Limits.h"
#include "raylab/core/TriangleMesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

/// \file MeshReaders.h
/// The parts of MeshIO::load, private to core: each format's check of what a file announces
/// before CGAL reads it (ObjReader.cpp, PlyCheck.cpp, StlCheck.cpp), RayLab's own OFF reader
/// (OffReader.cpp), CGAL's soup reader with its printed errors captured (CgalSoup.cpp), and
/// the repair that orients and triangulates (MeshRepair.cpp).

namespace raylab::meshio {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;
using CgalMesh = CGAL::Surface_mesh<CgalPoint>;

/// A problem located in a text file: 1-based line and description.
struct Located {
  int line;
  std::string what;
};

/// The problem with counts a mesh file announces, found before CGAL reads it: CGAL trusts
/// them (a 50-byte OFF file announcing a face of 300,000,000 corners made it allocate
/// 2.4 GB), and a truncated binary file used to be reported as an empty mesh.
using SizeProblem = std::optional<Located>;

/// `s` without leading and trailing blanks and carriage returns.
std::string trimmed(const std::string& s);

/// At most limits::kMaxMeshTriangles vertices and faces.
SizeProblem checkCounts(long long vertices, long long faces, int line);

/// An OFF file's vertices and faces, read by RayLab (colours, normals and texture
/// coordinates ignored): CGAL's OFF reader cast colours to integers unchecked (a colour-map
/// index of -4 read outside its table, found by Fuzzoff, issue 14), and RayLab needs none.
struct OffSoup {
  std::vector<CgalPoint> points;
  std::vector<Polygon> polygons;
  std::vector<int> faceLines;  ///< An ASCII file's line of each face, for messages.
};

/// Finds the first line of an OBJ file that CGAL's reader rejects: an unknown statement,
/// a vertex without three numbers, or a face index that is not an existing vertex.
std::optional<Located> locateObjError(const std::string& path);
/// OBJ has no counts: its faces are counted, for the limit, and each face's corners must
/// be whole numbers (CGAL reads "f 1.5 2 3" as "f 1 2 3").
SizeProblem checkObj(const std::string& path);
/// The 1-based line of the OBJ file's face `face` (0-based), or 0.
int objFaceLine(const std::string& path, std::size_t face);
/// True when a text file's first line ends in a carriage return alone (classic Mac OS):
/// the readers, which split lines at LF, would read the whole file as one line.
bool endsLinesWithCrOnly(const std::string& path);

/// Reads an OFF file (ASCII or binary) into `soup`, or says where and why it cannot: the
/// first malformed line (header, counts, vertex or face) of an ASCII file; for a binary file,
/// its counts against its `size`.
SizeProblem readOff(const std::string& path, std::uintmax_t size, OffSoup& soup);

}  // namespace raylab::meshio

namespace raylab::meshnormals {
struct PlyHeader;
}

namespace raylab::meshio {

/// PLY: the header's elements (`header`, read from `in`, which is left at the first
/// record), then every record walked (ASCII tokens or binary bytes), each list's announced
/// length checked against what is left of the file.
SizeProblem checkPly(std::istream& in, const meshnormals::PlyHeader& header, std::uintmax_t size);

/// STL: a binary file holds exactly 84 + 50 n bytes for the n triangles of its header.
SizeProblem checkStl(const std::string& path, std::uintmax_t size);

/// Reads an OBJ, PLY or STL file's polygon soup with CGAL. False when CGAL refuses the file;
/// `report` then holds what it printed (or threw).
bool readCgalSoup(const std::string& path, std::vector<CgalPoint>& points,
                  std::vector<Polygon>& polygons, std::string& report);

/// A closed mesh (every edge shared by exactly two triangles) whose signed volume is
/// negative has its normals pointing inward: flip every triangle. Open meshes are left as
/// orient_polygon_soup made them.
void orientOutward(const std::vector<Point3>& vertices,
                   std::vector<TriangleMesh::Index3>& triangles);

/// Why the face `f` of `mesh` cannot be triangulated as a polygon seen along its normal (the
/// reason alone: the caller names the face), or nothing: too many corners, two corners that
/// coincide, an edge that doubles back on the one before it, or two edges that cross or touch.
/// Exact predicates of CGAL's projection.
std::optional<std::string> checkSimplePolygon(const CgalMesh& mesh, CgalMesh::Face_index f);

}  // namespace raylab::meshio
