#include "raylab/core/MeshIO.h"

#include "io/MeshNormals.h"
#include "io/MeshSoupChecks.h"
#include "raylab/core/FilePaths.h"
#include "raylab/core/Limits.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

namespace raylab {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;

/// Redirects std::cerr and std::cout into a string while alive, to collect what CGAL's
/// readers report (they print their errors instead of returning them).
class CaptureStreams {
 public:
  CaptureStreams()
      : m_err(std::cerr.rdbuf(m_buffer.rdbuf())), m_out(std::cout.rdbuf(m_sink.rdbuf())) {}
  ~CaptureStreams() {
    std::cerr.rdbuf(m_err);
    std::cout.rdbuf(m_out);
  }
  CaptureStreams(const CaptureStreams&) = delete;
  CaptureStreams& operator=(const CaptureStreams&) = delete;

  /// The captured error lines, repeated lines dropped, joined with "; ".
  std::string errors() const {
    std::istringstream in(m_buffer.str());
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) {
      while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back())))
        line.pop_back();
      if (!line.empty() && std::find(lines.begin(), lines.end(), line) == lines.end())
        lines.push_back(line);
    }
    std::string joined;
    for (const std::string& l : lines) joined += (joined.empty() ? "" : "; ") + l;
    return joined;
  }

 private:
  std::ostringstream m_buffer;
  std::ostringstream m_sink;
  std::streambuf* m_err;
  std::streambuf* m_out;
};

/// A problem located in a text file: 1-based line and description.
struct Located {
  int line;
  std::string what;
};

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

/// Finds the first line of an OBJ file that CGAL's reader rejects: an unknown statement,
/// a vertex without three numbers, or a face index that is not an existing vertex.
std::optional<Located> locateObjError(const std::string& path) {
  static const char* const kKnown[] = {
      "v",        "vt",       "vn",     "f",     "vp",       "bevel",    "lod",        "ctech",
      "c_interp", "usemap",   "usemtl", "stech", "d_interp", "mtllib",   "shadow_obj", "trace_obj",
      "o",        "g",        "s",      "p",     "cstype",   "deg",      "step",       "bmat",
      "con",      "curv",     "curv2",  "surf",  "parm",     "trim",     "hole",       "scrv",
      "sp",       "end",      "surf_1", "q0_1",  "q1_1",     "curv2d_1", "surf_2",     "q0_2",
      "q1_2",     "curv2d_2", "bsp",    "bzp",   "cdc",      "cdp",      "res"};
  std::ifstream in(path);
  std::string line;
  int lineNo = 0;
  long long vertexCount = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream iss(line);
    std::string key;
    if (!(iss >> key) || key[0] == '#') continue;
    if (std::find(std::begin(kKnown), std::end(kKnown), key) == std::end(kKnown))
      return Located{lineNo, "unrecognised statement '" + trimmed(line) + "'"};
    if (key == "v") {
      double x, y, z;
      if (!(iss >> x >> y >> z))
        return Located{lineNo, "vertex needs three numbers: '" + trimmed(line) + "'"};
      ++vertexCount;
    } else if (key == "f") {
      std::string token;
      int corners = 0;
      while (iss >> token) {
        std::istringstream ts(token);
        long long i;
        if (!(ts >> i)) return Located{lineNo, "face index '" + token + "' is not a number"};
        const long long resolved = i < 0 ? vertexCount + i : i - 1;
        if (i == 0 || resolved < 0 || resolved >= vertexCount)
          return Located{lineNo, "face index " + std::to_string(i) + " refers to no vertex (" +
                                     std::to_string(vertexCount) + " defined so far)"};
        ++corners;
      }
      if (corners < 3)
        return Located{lineNo, "face needs at least three vertices: '" + trimmed(line) + "'"};
    }
  }
  return std::nullopt;
}

/// The problem with counts a mesh file announces, found before CGAL reads it: CGAL trusts
/// them (a 50-byte OFF file announcing a face of 300,000,000 corners made it allocate
/// 2.4 GB), and a truncated binary file used to be reported as an empty mesh.
using SizeProblem = std::optional<Located>;

/// At most limits::kMaxMeshTriangles vertices and faces.
SizeProblem checkCounts(long long vertices, long long faces, int line) {
  const long long limit = static_cast<long long>(limits::kMaxMeshTriangles);
  if (vertices > limit || faces > limit)
    return Located{line, "the file announces " + std::to_string(vertices) + " vertices and " +
                             std::to_string(faces) + " faces; RayLab reads meshes of at most " +
                             std::to_string(limit) + " of each"};
  return std::nullopt;
}

/// An OFF file's vertices and faces, read by RayLab (colours, normals and texture
/// coordinates ignored): CGAL's OFF reader cast colours to integers unchecked (a colour-map
/// index of -4 read outside its table, found by Fuzzoff, issue 14), and RayLab needs none.
struct OffSoup {
  std::vector<CgalPoint> points;
  std::vector<Polygon> polygons;
};

/// Binary OFF (after the "OFF BINARY" line): big-endian int32 counts, 3 float32 per
/// vertex, then per face its corner count, the corners and a colour count with its floats.
SizeProblem readBinaryOff(std::istream& in, std::uintmax_t size, OffSoup& soup) {
  const auto readWord = [&](std::uint32_t& value) {
    unsigned char b[4];
    if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
    value = std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 |
            std::uint32_t(b[3]);
    return true;
  };
  const auto readInt = [&](std::int64_t& value) {
    std::uint32_t word = 0;
    if (!readWord(word)) return false;
    value = std::int32_t(word);
    return true;
  };
  std::int64_t nv = 0, nf = 0, ne = 0;
  if (!readInt(nv) || !readInt(nf) || !readInt(ne) || nv < 0 || nf < 0)
    return Located{0, "binary OFF header has no vertex and face counts"};
  if (auto problem = checkCounts(nv, nf, 0)) return problem;
  const auto remaining = [&] { return std::int64_t(size) - std::int64_t(in.tellg()); };
  if (12 * nv > remaining())
    return Located{0, "truncated binary OFF: " + std::to_string(nv) +
                          " vertices announced, the file ends before them"};
  soup.points.reserve(std::size_t(nv));
  for (std::int64_t v = 0; v < nv; ++v) {
    float xyz[3];
    for (float& c : xyz) {
      std::uint32_t word = 0;
      readWord(word);
      std::memcpy(&c, &word, sizeof c);
    }
    soup.points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  for (std::int64_t f = 0; f < nf; ++f) {
    std::int64_t corners = 0, colours = 0;
    if (!readInt(corners) || corners < 1 || 4 * corners > remaining())
      return Located{0, "truncated or corrupt binary OFF: face " + std::to_string(f) + " of " +
                            std::to_string(nf) + " announces more corners than the " +
                            "file holds"};
    if (corners > std::int64_t(limits::kMaxFaceCorners))
      return Located{0, "binary OFF: face " + std::to_string(f) + " has " +
                            std::to_string(corners) +
                            " corners; RayLab triangulates faces of "
                            "at most " +
                            std::to_string(limits::kMaxFaceCorners) + " corners"};
    Polygon polygon(static_cast<std::size_t>(corners));
    for (std::size_t& index : polygon) {
      std::int64_t i = 0;
      readInt(i);
      if (i < 0 || i >= nv)
        return Located{0, "corrupt binary OFF: face " + std::to_string(f) + " refers to vertex " +
                              std::to_string(i) + ", out of range [0, " + std::to_string(nv) + ")"};
      index = static_cast<std::size_t>(i);
    }
    soup.polygons.push_back(std::move(polygon));
    if (!readInt(colours) || colours < 0 || 4 * colours > remaining())
      return Located{0, "truncated or corrupt binary OFF: face " + std::to_string(f) + " of " +
                            std::to_string(nf) + " is cut off"};
    in.seekg(4 * colours, std::ios::cur);
  }
  return std::nullopt;
}

/// PLY: the header's elements (`header`, read from `in`, which is left at the first
/// record), then every record walked (ASCII tokens or binary bytes), each list's announced
/// length checked against what is left of the file.
SizeProblem checkPly(std::istream& in, const meshnormals::PlyHeader& header, std::uintmax_t size) {
  using meshnormals::plySize;
  const std::string& format = header.format;
  const long long vertices = header.count("vertex"), faces = header.count("face");
  if (auto problem = checkCounts(vertices, faces, header.lines)) return problem;
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
  const bool ascii = header.ascii();
  const bool bigEndian = header.bigEndian();
  if (!ascii && !bigEndian && format != "binary_little_endian") return std::nullopt;
  const auto remaining = [&] { return std::int64_t(size) - std::int64_t(in.tellg()); };
  // One ASCII value read as CGAL's reader reads it: `>>` into the property's own C++ type
  // (short for int8, unsigned short for uint8), so that both consume the same characters and
  // fail on the same token. Once one of CGAL's reads fails, the lengths it reads after it are
  // uninitialised, and a length that overflows its type reads as the type's largest value:
  // a file both walks read differently once had CGAL allocate 7.6 GB (found by Fuzzply,
  // issue 14). Any value that does not read is refused here.
  const auto readAscii = [&](meshnormals::PlyType type, double& value) {
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
  };
  // A list's length, at most 2^53 (more than any file holds, and no product with an item's
  // size overflows): 1.3e128 in an ASCII list was cast to an integer (undefined behaviour,
  // found by Fuzzply, issue 14), and 8 bytes read as a length could be negative.
  constexpr std::int64_t kLongest = std::int64_t(1) << 53;
  const auto readCount = [&](meshnormals::PlyType type, std::int64_t& value) {
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
  };
  const auto skip = [&](std::int64_t items, meshnormals::PlyType type) {
    if (!ascii) {
      in.seekg(items * meshnormals::plySize(type), std::ios::cur);
      return bool(in) && remaining() >= 0;
    }
    double value;
    for (std::int64_t k = 0; k < items; ++k)
      if (!readAscii(type, value)) return false;
    return true;
  };
  const std::string kind = ascii ? "ASCII PLY" : "binary PLY";
  for (const meshnormals::PlyElement& e : header.elements) {
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
  }
  return std::nullopt;
}

/// STL: a binary file holds exactly 84 + 50 n bytes for the n triangles of its header.
SizeProblem checkStl(const std::string& path, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string start(5, '\0');
  in >> std::ws;
  in.read(&start[0], 5);
  const bool looksAscii = in && start == "solid";
  if (size < 84) {
    if (looksAscii) return std::nullopt;
    return Located{0, "truncated binary STL: " + std::to_string(size) +
                          " bytes, less than its 84-byte header"};
  }
  unsigned char b[4];
  in.clear();
  in.seekg(80);
  in.read(reinterpret_cast<char*>(b), 4);
  const std::uint64_t count = std::uint64_t(b[0]) | std::uint64_t(b[1]) << 8 |
                              std::uint64_t(b[2]) << 16 | std::uint64_t(b[3]) << 24;
  const std::uint64_t expected = 84 + 50 * count;
  if (looksAscii && expected != size) {  // an ASCII STL file: its triangles counted first
    if (auto problem = meshsoup::checkAsciiStlCount(path)) return Located{0, *problem};
    return std::nullopt;
  }
  if (auto problem = checkCounts(0, static_cast<long long>(count), 0)) return problem;
  if (expected > size)
    return Located{0, "truncated binary STL: the header announces " + std::to_string(count) +
                          " triangles (" + std::to_string(expected) + " bytes) but the file has " +
                          std::to_string(size) + " bytes"};
  return std::nullopt;
}

/// OBJ has no counts: its faces are counted, for the limit.
SizeProblem checkObj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long vertices = 0, faces = 0;
  while (std::getline(in, line)) {
    const std::size_t b = line.find_first_not_of(" \t");
    if (b == std::string::npos || b + 1 >= line.size() || !std::isspace((unsigned char)line[b + 1]))
      continue;
    if (line[b] == 'v') ++vertices;
    if (line[b] == 'f') ++faces;
  }
  return checkCounts(vertices, faces, 0);
}
/// Reads an OFF file (ASCII or binary) into `soup`, or says where and why it cannot: the
/// first malformed line (header, counts, vertex or face) of an ASCII file; for a binary file,
/// its counts against its `size`.
SizeProblem readOff(const std::string& path, std::uintmax_t size, OffSoup& soup) {
  // The text is read as CGAL's reader read it (the files it read are read the same): the
  // counts are numbers read across lines (a header "OFF 3" followed by "1 0" announces 3
  // vertices and 1 face: read line by line, that file once passed RayLab's check as one vertex
  // and no face while CGAL allocated a face of 3,000,000,000 corners, found by Fuzzoff,
  // issue 14); a vertex or a face is the rest of a line, from the next character that is
  // not blank or in a `#` comment. A vertex is its first three numbers (four with the `4`
  // prefix: x, y, z, w), a face its count and corners; colours, normals and texture
  // coordinates after them are not read.
  std::ifstream in(path, std::ios::binary);
  int lineNo = 1;
  // Blanks, newlines and `#` comments up to the next character (CGAL's skip_comment_OFF).
  const auto skipBlanksAndComments = [&](bool comments) {
    for (int c = in.peek(); c != EOF; c = in.peek()) {
      if (c == '#' && comments) {
        std::string rest;
        std::getline(in, rest);
        ++lineNo;
      } else if (std::isspace(c)) {
        in.get();
        if (c == '\n') ++lineNo;
      } else {
        return true;
      }
    }
    return false;
  };
  // The next vertex or face: the rest of its line, without its comment.
  std::string s;
  const auto nextRecord = [&]() {
    if (!skipBlanksAndComments(true)) return false;
    std::getline(in, s);
    s = trimmed(s.substr(0, s.find('#')));
    ++lineNo;
    return true;
  };
  if (!skipBlanksAndComments(true)) return Located{lineNo, "no OFF header"};
  std::string keyword;
  in >> keyword;
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    return Located{lineNo, "header must start with OFF, found '" + keyword + "'"};
  // A count, as CGAL reads it: an int after blanks (and comments before the first).
  const auto readCount = [&](long long& value, bool comments) {
    if (!skipBlanksAndComments(comments)) return false;
    int n = 0;
    if (!(in >> n)) return false;
    value = n;
    return true;
  };
  {
    skipBlanksAndComments(true);
    const std::streampos before = in.tellg();
    std::string word;
    if (in >> word && word == "BINARY") {
      if (keyword != "OFF")
        return Located{lineNo, "binary " + keyword +
                                   " is not read: RayLab reads binary OFF files without "
                                   "colours, normals or texture coordinates (OFF BINARY)"};
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      return readBinaryOff(in, size, soup);
    }
    in.clear();
    in.seekg(before);
  }
  const int countsLine = lineNo;
  long long dimension = 0, nv = -1, nf = -1, ne = -1;
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  const bool dimensional = prefix.find('n') != std::string::npos;
  const bool homogeneous = prefix.find('4') != std::string::npos;
  if ((dimensional && !readCount(dimension, true)) || !readCount(nv, !dimensional) ||
      !readCount(nf, false) || !readCount(ne, false) || nv < 0 || nf < 0)
    return Located{countsLine, "expected the vertex, face and edge counts after " + keyword +
                                   " (three whole numbers)"};
  if (dimensional && dimension != 3)
    return Located{countsLine, "the file's vertices have " + std::to_string(dimension) +
                                   " coordinates; RayLab reads 3D meshes"};
  if (auto problem = checkCounts(nv, nf, lineNo)) return problem;
  // The rest of the counts' line, if anything but blanks, is CGAL's first vertex.
  for (int c = in.peek(); c != EOF && c != '\n' && std::isspace(c); c = in.peek()) in.get();
  if (in.peek() == '\n') {
    in.get();
    ++lineNo;
  }
  for (long long i = 0; i < nv; ++i) {
    if (!nextRecord())
      return Located{lineNo, "file ends after " + std::to_string(i) + " of " + std::to_string(nv) +
                                 " vertices"};
    std::istringstream v(s);
    double x, y, z, w = 1.0;
    if (!(v >> x >> y >> z) || (homogeneous && !(v >> w)))
      return Located{lineNo - 1, std::string("vertex needs ") + (homogeneous ? "four" : "three") +
                                     " numbers: '" + s + "'"};
    if (homogeneous && !(std::abs(w) > 0.0))
      return Located{lineNo - 1, "vertex has the weight w = 0 (a point at infinity): '" + s + "'"};
    soup.points.emplace_back(x / w, y / w, z / w);
  }
  for (long long i = 0; i < nf; ++i) {
    if (!nextRecord())
      return Located{
          lineNo, "file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces"};
    std::istringstream f(s);
    long long k;
    if (!(f >> k) || k < 1)
      return Located{lineNo - 1, "face must start with its vertex count: '" + s + "'"};
    Polygon polygon;
    for (long long j = 0; j < k; ++j) {
      long long index;
      if (!(f >> index))
        return Located{lineNo - 1,
                       "face lists fewer than " + std::to_string(k) + " indices: '" + s + "'"};
      if (index < 0 || index >= nv)
        return Located{lineNo - 1, "face index " + std::to_string(index) + " out of range [0, " +
                                       std::to_string(nv) + ")"};
      polygon.push_back(static_cast<std::size_t>(index));
    }
    soup.polygons.push_back(std::move(polygon));
  }
  return std::nullopt;
}

/// A closed mesh (every edge shared by exactly two triangles) whose signed volume is
/// negative has its normals pointing inward: flip every triangle. Open meshes are left as
/// orient_polygon_soup made them.
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

/// Why the face `f` of `mesh` cannot be triangulated as a polygon seen along its normal, or
/// nothing: too many corners, two corners that coincide, an edge that doubles back on the one
/// before it, or two edges that cross or touch. Exact predicates of CGAL's projection.
std::optional<std::string> checkSimplePolygon(const CGAL::Surface_mesh<CgalPoint>& mesh,
                                              CGAL::Surface_mesh<CgalPoint>::Face_index f) {
  std::vector<CgalPoint> c;
  for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) c.push_back(mesh.point(v));
  const std::size_t n = c.size();
  const std::string face = "cannot triangulate a face of " + std::to_string(n) + " corners: ";
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

}  // namespace

std::vector<std::string> MeshIO::supportedExtensions() { return {".obj", ".off", ".ply", ".stl"}; }

TriangleMesh MeshIO::load(const std::string& path, const Options& options) {
  auto fail = [&path](const std::string& what, int line = 0) -> ReadError {
    return ReadError(path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what);
  };

  // Step 1: the file must exist, be readable and have a known extension.
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw fail("file not found");
  if (!std::filesystem::is_regular_file(path, ec)) throw fail("not a regular file");
  const std::string ext = lowerExtension(path);
  const auto known = supportedExtensions();
  if (std::find(known.begin(), known.end(), ext) == known.end())
    throw fail("unknown mesh extension '" + ext + "' (supported: .obj, .off, .ply, .stl)");
  if (!std::ifstream(path).good()) throw fail("cannot open the file for reading");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (size == 0) throw fail("file is empty (no faces)");
  if (size > limits::kMaxMeshFileBytes)
    throw fail("file is " + std::to_string(size >> 20) + " MiB; RayLab reads meshes of at most " +
               std::to_string(limits::kMaxMeshFileBytes >> 20) + " MiB");
  const std::string format = ext.substr(1);
  std::string upperFormat = format;
  std::transform(upperFormat.begin(), upperFormat.end(), upperFormat.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });

  // Step 1b: what the file announces must fit in it and in the limits (CGAL trusts it).
  // A PLY header is read once, here: for this check and for the normals (step 3b).
  std::optional<meshnormals::PlyHeader> plyHeader;
  OffSoup offSoup;  // An OFF file is read here, by RayLab, whole.
  SizeProblem announced;
  if (ext == ".ply") {
    std::ifstream in(path, std::ios::binary);
    try {
      plyHeader = meshnormals::readPlyHeader(in);
      announced = checkPly(in, *plyHeader, size);
    } catch (const meshnormals::Problem& problem) {
      announced = Located{problem.line(), problem.what()};
    }
  } else {
    announced = ext == ".off"   ? readOff(path, size, offSoup)
                : ext == ".stl" ? checkStl(path, size)
                                : checkObj(path);
  }
  if (announced)
    throw fail("cannot parse " + upperFormat + " file: " + announced->what, announced->line);

  // Step 2: read the polygon soup with CGAL, collecting what it reports (OFF: read above).
  std::vector<CgalPoint> points;
  std::vector<Polygon> polygons;
  bool ok = false;
  std::string report;
  if (ext == ".off") {
    points = std::move(offSoup.points);
    polygons = std::move(offSoup.polygons);
    ok = true;
  } else {
    CaptureStreams capture;
    try {
      ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(true));
    } catch (const std::exception& e) {
      ok = false;
      report = e.what();
    }
    const std::string printed = capture.errors();
    report = report.empty() ? printed : report + " " + printed;
  }
  // Step 3: classify failures: locate the bad line in text formats, else say "no faces"
  // when nothing was wrong but faces are missing.
  auto locate = [&]() -> std::optional<Located> {
    if (ext == ".obj") return locateObjError(path);
    return std::nullopt;
  };
  auto throwLocated = [&](const std::optional<Located>& located) {
    if (located)
      throw fail("cannot parse " + upperFormat + " file: " + located->what +
                     (report.empty() ? std::string() : " (CGAL: " + report + ")"),
                 located->line);
  };
  if (!ok) {
    throwLocated(locate());
    if (polygons.empty() && (report.empty() || report.find("empty") != std::string::npos))
      throw fail("no faces in the file (empty mesh)");
    throw fail("cannot parse " + upperFormat + " file" +
               (report.empty() ? std::string(": the reader gave no reason") : ": " + report));
  }
  if (polygons.empty()) throw fail("no faces in the file (empty mesh)");
  // Corners counted and repeated vertices found in linear time, before CGAL's repair
  // (quadratic in a face repeating its vertices) and the polygon checks (issue 38).
  if (auto problem = meshsoup::checkFaces(polygons)) throw fail(*problem);
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const bool bad =
        polygons[f].size() < 3 || std::any_of(polygons[f].begin(), polygons[f].end(),
                                              [&](std::size_t i) { return i >= points.size(); });
    if (bad) throwLocated(locate());
    for (std::size_t index : polygons[f])
      if (index >= points.size())
        throw fail("corrupt " + upperFormat + " file: face " + std::to_string(f) +
                   " refers to vertex " + std::to_string(index) + " but there are only " +
                   std::to_string(points.size()) + " vertices");
    if (polygons[f].size() < 3)
      throw fail("corrupt " + upperFormat + " file: face " + std::to_string(f) + " has only " +
                 std::to_string(polygons[f].size()) + " vertices");
  }

  // Every coordinate finite and within RayLab's largest coordinate, as in a scene file: a
  // vertex at 1e300 overflowed the BVH build's bin index (found by Fuzzply, issue 14).
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const double c : {points[i].x(), points[i].y(), points[i].z()}) {
      if (std::abs(c) <= limits::kMaxCoordinate) continue;
      std::ostringstream value;
      value << c;
      throw fail("vertex " + std::to_string(i + 1) + " has the coordinate " + value.str() +
                 ", beyond RayLab's largest coordinate, 1e12 (or not a number)");
    }
  }

  // Step 3b: the file's vertex normals, if it has any, beside the soup as it was read.
  std::optional<meshnormals::FileNormals> fileNormals;
  std::vector<Point3> soupPoints;
  std::vector<Polygon> soupPolygons;
  try {
    if (ext == ".obj") fileNormals = meshnormals::readObj(path);
    if (ext == ".ply") fileNormals = meshnormals::readPly(path, *plyHeader);
  } catch (const meshnormals::Problem& problem) {
    throw fail("cannot read the normals of the " + upperFormat + " file: " + problem.what(),
               problem.line());
  }
  if (fileNormals) {
    if (fileNormals->perVertex ? fileNormals->normals.size() != points.size()
                               : fileNormals->corners.size() != polygons.size())
      throw fail("the file's normals do not match its " +
                 std::string(fileNormals->perVertex ? "vertices" : "faces") + " (" +
                 std::to_string(fileNormals->perVertex ? fileNormals->normals.size()
                                                       : fileNormals->corners.size()) +
                 " for " +
                 std::to_string(fileNormals->perVertex ? points.size() : polygons.size()) + ")");
    soupPoints.reserve(points.size());
    for (const CgalPoint& p : points) soupPoints.emplace_back(p.x(), p.y(), p.z());
    soupPolygons = polygons;
  }

  // Step 4: repair (merge duplicate points, drop degenerate / duplicate faces), orient.
  PMP::repair_polygon_soup(points, polygons);
  if (polygons.empty()) throw fail("no faces left after removing degenerate faces");
  const std::size_t pointsBefore = points.size();
  const bool oriented = PMP::orient_polygon_soup(points, polygons);
  if (!options.allowNonManifold && !oriented)
    throw fail("non-manifold mesh beyond repair: orienting it needed " +
               std::to_string(points.size() - pointsBefore) +
               " duplicated vertices (an edge shared by more than two faces, faces touching "
               "only at a vertex, or a non-orientable surface)");
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw fail("non-manifold mesh beyond repair: not a polygon mesh after repair and orientation");

  // Step 5: triangulate faces with more than three vertices, then copy out.
  std::vector<Point3> vertices;
  std::vector<TriangleMesh::Index3> triangles;
  const bool allTriangles =
      std::all_of(polygons.begin(), polygons.end(), [](const Polygon& p) { return p.size() == 3; });
  if (allTriangles) {
    vertices.reserve(points.size());
    for (const CgalPoint& p : points) vertices.emplace_back(p.x(), p.y(), p.z());
    triangles.reserve(polygons.size());
    for (const Polygon& p : polygons)
      triangles.push_back({static_cast<int>(p[0]), static_cast<int>(p[1]), static_cast<int>(p[2])});
  } else {
    CGAL::Surface_mesh<CgalPoint> mesh;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    // CGAL triangulates a face of more than four corners in its projection along the face's
    // normal, with a constrained Delaunay triangulation: two corners that coincide there
    // made it join a vertex to itself (a null pointer), and edges that cross there made it
    // insert constraints for ever (both found by Fuzzobj, issue 14). Such a face is
    // refused first, with the same normal and the exact predicates of that projection.
    for (auto f : mesh.faces()) {
      if (mesh.degree(f) <= 4) continue;
      if (auto problem = checkSimplePolygon(mesh, f)) throw fail(*problem);
    }
    if (!PMP::triangulate_faces(mesh)) throw fail("could not triangulate a polygonal face");
    vertices.reserve(mesh.number_of_vertices());
    for (auto v : mesh.vertices()) {
      const CgalPoint& p = mesh.point(v);
      vertices.emplace_back(p.x(), p.y(), p.z());
    }
    for (auto f : mesh.faces()) {
      TriangleMesh::Index3 tri{};
      int k = 0;
      for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
        if (k < 3) tri[k] = static_cast<int>(static_cast<std::size_t>(v));
        // A face cycle broken by a bad soup would never close (found by fuzzing).
        if (++k > 3) break;
      }
      if (k != 3) throw fail("could not triangulate a polygonal face");
      triangles.push_back(tri);
    }
  }
  if (triangles.size() > limits::kMaxMeshTriangles)
    throw fail("the mesh has " + std::to_string(triangles.size()) +
               " triangles once its faces are triangulated; RayLab reads meshes of at most " +
               std::to_string(limits::kMaxMeshTriangles));
  orientOutward(vertices, triangles);
  // Step 6: the file's normals at the corners of the final triangles.
  std::vector<Normal3> normals;
  std::vector<TriangleMesh::Index3> normalIndices;
  if (fileNormals)
    meshnormals::attach(*fileNormals, soupPoints, soupPolygons, vertices, triangles, normals,
                        normalIndices);
  try {
    if (fileNormals)
      return TriangleMesh(std::move(vertices), std::move(triangles), std::move(normals),
                          std::move(normalIndices));
    return TriangleMesh(std::move(vertices), std::move(triangles));
  } catch (const Exception& e) {
    throw fail(e.what());
  }
}

}  // namespace raylab
