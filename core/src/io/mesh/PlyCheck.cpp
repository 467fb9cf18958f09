// PLY: the header's elements and every record walked before CGAL reads the file.
#include "io/mesh/MeshReaders.h"

#include "io/mesh/MeshNormals.h"

#include <algorithm>
#include <cmath>
#include <istream>

namespace raylab::meshio {

namespace {

using meshnormals::plySize;
using meshnormals::PlyType;

/// The name a PLY header gives a type, for messages.
const char* plyTypeName(PlyType type) {
  static const char* const kNames[] = {"char", "uchar", "short",  "ushort", "int",
                                       "uint", "float", "double", "unknown"};
  return kNames[static_cast<int>(type)];
}

/// The vertex and face elements as CGAL reads them: a vertex's x, y and z as float or double
/// only, a face's vertex_indices (or vertex_index) as a list of int or uint only.
SizeProblem checkPlyTypes(const meshnormals::PlyHeader& header) {
  // CGAL reads a vertex's x, y and z as float or double only: another type (a `uint16 z`)
  // made its reader call through a null pointer (found by Fuzzply, issue 14).
  for (const meshnormals::PlyElement& e : header.elements) {
    if (e.name != "vertex" && e.name != "vertices") continue;
    // A vertex without coordinates: 425k of them, announced by a 2.7 KB file, took CGAL's
    // reader a second each time (found by Fuzzply, issue 14).
    for (const char* axis : {"x", "y", "z"})
      if (std::none_of(e.properties.begin(), e.properties.end(),
                       [&](const meshnormals::PlyProperty& p) { return p.name == axis; }))
        return Located{e.line, "the " + e.name + " element has no " + axis +
                                   " property (a vertex needs x, y and z)"};
    for (const meshnormals::PlyProperty& p : e.properties) {
      const bool coordinate = p.name == "x" || p.name == "y" || p.name == "z";
      const bool real = !p.isList() && (p.type == meshnormals::PlyType::Float32 ||
                                        p.type == meshnormals::PlyType::Float64);
      if (coordinate && !real)
        return Located{p.line, "the vertex coordinate " + p.name +
                                   " must be a float or double property, not a list or "
                                   "an integer"};
    }
  }
  for (const meshnormals::PlyElement& e : header.elements) {
    if (e.name != "face" && e.name != "faces") continue;
    // CGAL's reader finds no indices of another type ("can't find vertex indices", issue 38).
    for (const meshnormals::PlyProperty& p : e.properties)
      if ((p.name == "vertex_indices" || p.name == "vertex_index") &&
          (!p.isList() || (p.type != PlyType::Int32 && p.type != PlyType::UInt32)))
        return Located{p.line, "the face's " + p.name + " are " +
                                   (p.isList() ? std::string("a list of ") + plyTypeName(p.type)
                                               : std::string("not a list")) +
                                   "; RayLab reads vertex indices stored as a list of int or "
                                   "uint (convert the file, e.g. in MeshLab)"};
  }
  return std::nullopt;
}

/// Walks every record of a PLY file's elements, as CGAL's reader will, to check that each
/// value reads and each list fits in what is left of the file.
class PlyWalker {
 public:
  PlyWalker(std::istream& stream, const meshnormals::PlyHeader& header, std::uintmax_t size)
      : in(stream),
        m_header(header),
        m_size(size),
        ascii(header.ascii()),
        bigEndian(header.bigEndian()),
        kind(ascii ? "ASCII PLY" : "binary PLY") {}

  SizeProblem walk() {
    for (const meshnormals::PlyElement& e : m_header.elements) {
      // CGAL's reader walks every element's records, even records of nothing: 4.3e15 of them
      // (an element without properties, announced in a 2 KB file) ran for ever (found by
      // Fuzzply, issue 14).
      if (e.count > static_cast<long long>(limits::kMaxMeshTriangles))
        return Located{e.line, "the element " + e.name + " announces " + std::to_string(e.count) +
                                   " records; RayLab reads meshes of at most " +
                                   std::to_string(limits::kMaxMeshTriangles) + " of each"};
      if (e.properties.empty()) {
        if (e.count == 0) continue;
        return Located{e.line, "the element " + e.name + " announces " + std::to_string(e.count) +
                                   " records but has no property"};
      }
      if (auto problem = walkRecords(e)) return problem;
    }
    return std::nullopt;
  }

 private:
  std::istream& in;
  const meshnormals::PlyHeader& m_header;
  std::uintmax_t m_size;
  bool ascii;
  bool bigEndian;
  std::string kind;
  static constexpr std::int64_t kLongest = std::int64_t(1) << 53;
  const long long vertices = m_header.count("vertex"), faces = m_header.count("face");

  std::int64_t remaining() const { return std::int64_t(m_size) - std::int64_t(in.tellg()); }

  SizeProblem walkRecords(const meshnormals::PlyElement& e) {
    for (long long r = 0; r < e.count; ++r) {
      // The record's name is built only for a message: per record it made a 2.7 KB file
      // announcing 425k vertices take a second (found by Fuzzply, issue 14).
      const auto where = [&] {
        return "element " + e.name + " " + std::to_string(r) + " of " + std::to_string(e.count);
      };
      for (const meshnormals::PlyProperty& p : e.properties) {
        std::int64_t items = 1;
        if (p.isList()) {
          if (!readCount(p.countType, items))
            return Located{0, (ascii ? "unreadable or truncated " : "truncated ") + kind + ": " +
                                  where() +
                                  (ascii ? ": the length of the list " + p.name +
                                               " is not a whole number its "
                                               "type holds, or is missing"
                                         : " is cut off")};
          // An ASCII item takes at least two characters, a binary one its size.
          if (items * (ascii ? 2 : plySize(p.type)) > remaining())
            return Located{0, "truncated or corrupt " + kind + ": " + where() +
                                  " announces a list of " +
                                  (items == kLongest ? "2^53 or more" : std::to_string(items)) +
                                  " values, more than the file holds"};
        }
        if (!skip(items, p.type))
          return Located{0, (ascii ? "unreadable or truncated " : "truncated ") + kind + ": " +
                                where() +
                                (ascii ? ": a value of " + p.name +
                                             " is not a number its type holds, or is missing"
                                       : std::string(" is cut off")) +
                                " (the header announces " + std::to_string(vertices) +
                                " vertices and " + std::to_string(faces) + " faces)"};
      }
    }
    return std::nullopt;
  }

  // One ASCII value read as CGAL's reader reads it: `>>` into the property's own C++ type
  // (short for int8, unsigned short for uint8), so that both consume the same characters and
  // fail on the same token. Once one of CGAL's reads fails, the lengths it reads after it are
  // uninitialised, and a length that overflows its type reads as the type's largest value:
  // a file both walks read differently once had CGAL allocate 7.6 GB (found by Fuzzply,
  // issue 14). Any value that does not read is refused here.
  bool readAscii(meshnormals::PlyType type, double& value) {
    using meshnormals::PlyType;
    const auto take = [&](auto t) {
      if (!(in >> t)) return false;
      value = double(t);
      return true;
    };
    switch (type) {
      case PlyType::Int8:
        return take(short()) && value >= -128 && value <= 127;
      case PlyType::UInt8:
        return take((unsigned short)0) && value <= 255;
      case PlyType::Int16:
        return take(std::int16_t());
      case PlyType::UInt16:
        return take(std::uint16_t());
      case PlyType::Int32:
        return take(std::int32_t());
      case PlyType::UInt32:
        return take(std::uint32_t());
      case PlyType::Float32:
        return take(float());
      case PlyType::Float64:
        return take(double());
      case PlyType::Unknown:
        break;
    }
    return false;
  }

  // A list's length, at most 2^53 (more than any file holds, and no product with an item's
  // size overflows): 1.3e128 in an ASCII list was cast to an integer (undefined behaviour,
  // found by Fuzzply, issue 14), and 8 bytes read as a length could be negative.
  bool readCount(meshnormals::PlyType type, std::int64_t& value) {
    if (ascii) {
      double v;
      if (!readAscii(type, v) || v < 0 || v != std::floor(v)) return false;
      value = v < double(kLongest) ? std::int64_t(v) : kLongest;
      return true;
    }
    const int bytes = meshnormals::plySize(type);
    unsigned char b[8] = {};
    if (!in.read(reinterpret_cast<char*>(b), bytes)) return false;
    std::uint64_t v = 0;
    for (int k = 0; k < bytes; ++k) v |= std::uint64_t(b[bigEndian ? bytes - 1 - k : k]) << 8 * k;
    value = v < std::uint64_t(kLongest) ? std::int64_t(v) : kLongest;
    return true;
  }

  bool skip(std::int64_t items, meshnormals::PlyType type) {
    if (!ascii) {
      in.seekg(items * meshnormals::plySize(type), std::ios::cur);
      return bool(in) && remaining() >= 0;
    }
    double value;
    for (std::int64_t k = 0; k < items; ++k)
      if (!readAscii(type, value)) return false;
    return true;
  }
};

}  // namespace

SizeProblem checkPly(std::istream& in, const meshnormals::PlyHeader& header, std::uintmax_t size) {
  const std::string& format = header.format;
  if (auto problem = checkCounts(header.count("vertex"), header.count("face"), header.lines))
    return problem;
  if (auto problem = checkPlyTypes(header)) return problem;
  if (!header.ascii() && !header.bigEndian() && format != "binary_little_endian")
    return std::nullopt;
  return PlyWalker(in, header, size).walk();
}

}  // namespace raylab::meshio
