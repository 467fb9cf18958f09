#pragma once

#include "raylab/core/TriangleMesh.h"
#include "raylab/core/Types.h"

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

/// \file MeshNormals.h
/// The vertex normals a mesh file gives (OBJ `vn` with `f v//vn` or `v/vt/vn`, PLY vertex
/// properties `nx ny nz`), read beside CGAL's polygon soup, and carried through MeshIO's
/// repair, orientation and triangulation to the corners of the final triangles. Private to
/// MeshIO.cpp; no CGAL here.

namespace raylab::meshnormals {

/// A problem with a file's normals: the 1-based line (0 when the file has no lines, e.g. a
/// binary PLY) and what is wrong.
class Problem : public std::runtime_error {
 public:
  Problem(int line, const std::string& what) : std::runtime_error(what), m_line(line) {}
  int line() const { return m_line; }

 private:
  int m_line;
};

/// The normals of a file, per face corner, in the file's face order (CGAL's soup order).
struct FileNormals {
  std::vector<Normal3> normals;  ///< As the file gives them: finite, never zero length.
  /// OBJ: per face, per corner, the index in `normals` (-1 for a corner without one).
  std::vector<std::vector<int>> corners;
  bool perVertex = false;  ///< PLY: normals[i] belongs to vertex i (corners unused).
};

/// The normals of an OBJ file, or nothing when no face refers to a normal. Throws Problem
/// (with the line) for a `vn` without three numbers, a zero or non-finite normal, or a
/// face's normal index that refers to no normal.
std::optional<FileNormals> readObj(const std::string& path);

/// One scalar type of a PLY property (Unknown: a name PLY does not have).
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64, Unknown };

/// Bytes of one binary value of `type` (0 for Unknown).
int plySize(PlyType type);

/// One property of a PLY element: a scalar, or a list (the type of its length, then of its
/// items).
struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Unknown;       ///< Of the scalar, or of each list item.
  PlyType countType = PlyType::Unknown;  ///< Of a list's length; Unknown for a scalar.
  int line = 0;                          ///< Its line in the header.
  bool isList() const { return countType != PlyType::Unknown; }
};

/// One element of a PLY header: its name, its record count and each record's properties.
struct PlyElement {
  std::string name;
  long long count = 0;
  int line = 0;  ///< Header line of the element.
  std::vector<PlyProperty> properties;
};

/// A PLY file's header, read once for both of MeshIO's uses: the check of what it announces
/// against the file's size, and the vertex normals (readPly).
struct PlyHeader {
  std::string format;  ///< ascii, binary_little_endian or binary_big_endian (as written).
  std::vector<PlyElement> elements;
  int lines = 0;               ///< Lines up to and including end_header.
  std::streamoff records = 0;  ///< Where the first record starts (after end_header).
  bool ascii() const { return format == "ascii"; }
  bool bigEndian() const { return format == "binary_big_endian"; }
  /// The count of the element `name` (0 when there is none).
  long long count(const std::string& name) const;
};

/// Reads the header of the PLY file `in` up to end_header and leaves `in` at the first
/// record. Throws Problem (with the line) for an element line without a name and a count,
/// a property line before any element, or a property of an unknown type.
PlyHeader readPlyHeader(std::istream& in);

/// The per-vertex normals of the PLY file `path` (ASCII or binary) whose header is
/// `header`, or nothing when its vertices have no nx, ny, nz. Throws Problem for only some
/// of the three, or a zero or non-finite normal (with its line in an ASCII file, its vertex
/// number in a binary one).
std::optional<FileNormals> readPly(const std::string& path, const PlyHeader& header);

/**
 * \brief The corner normals of the final triangles: each triangle is matched, by the
 * positions of its corners, to the first face of the original soup (`soupPoints`,
 * `soupPolygons`, before repair) that has all three; each corner takes the file's normal
 * at that position in that face. Corners the file gives no normal (an OBJ face without
 * `vn` indices) take their triangle's geometric normal (they shade flat).
 * Repair only merges equal points, orientation only copies them and triangulation adds
 * none, so every final position is one of the soup's.
 */
void attach(const FileNormals& file, const std::vector<Point3>& soupPoints,
            const std::vector<std::vector<std::size_t>>& soupPolygons,
            const std::vector<Point3>& vertices, const std::vector<TriangleMesh::Index3>& triangles,
            std::vector<Normal3>& normals, std::vector<TriangleMesh::Index3>& normalIndices);

}  // namespace raylab::meshnormals
