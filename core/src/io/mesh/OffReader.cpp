// RayLab's own OFF reader (ASCII and binary), which reads no colours.
#include "io/mesh/MeshReaders.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace raylab::meshio {

namespace {

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

/// An ASCII OFF file read as CGAL's reader reads it, with the line it is at.
struct OffText {
  std::istream& in;
  int lineNo = 1;
  std::string record;  ///< The last vertex or face read: the rest of its line.

  /// Blanks, newlines and `#` comments up to the next character (CGAL's skip_comment_OFF).
  bool skipBlanksAndComments(bool comments) {
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
  }
  /// The next vertex or face: the rest of its line, without its comment.
  bool nextRecord() {
    if (!skipBlanksAndComments(true)) return false;
    std::getline(in, record);
    record = trimmed(record.substr(0, record.find('#')));
    ++lineNo;
    return true;
  }
  /// A count, as CGAL reads it: an int after blanks (and comments before the first).
  bool readCount(long long& value, bool comments) {
    if (!skipBlanksAndComments(comments)) return false;
    int n = 0;
    if (!(in >> n)) return false;
    value = n;
    return true;
  }
};

SizeProblem readOffVertices(OffText& text, long long nv, bool homogeneous, OffSoup& soup) {
  const std::string& s = text.record;
  for (long long i = 0; i < nv; ++i) {
    if (!text.nextRecord())
      return Located{text.lineNo, "file ends after " + std::to_string(i) + " of " +
                                      std::to_string(nv) + " vertices"};
    std::istringstream v(s);
    double x, y, z, w = 1.0;
    if (!(v >> x >> y >> z) || (homogeneous && !(v >> w)))
      return Located{text.lineNo - 1, std::string("vertex needs ") +
                                          (homogeneous ? "four" : "three") + " numbers: '" + s +
                                          "'"};
    if (homogeneous && !(std::abs(w) > 0.0))
      return Located{text.lineNo - 1,
                     "vertex has the weight w = 0 (a point at infinity): '" + s + "'"};
    soup.points.emplace_back(x / w, y / w, z / w);
  }
  return std::nullopt;
}

SizeProblem readOffFaces(OffText& text, long long nv, long long nf, OffSoup& soup) {
  const std::string& s = text.record;
  for (long long i = 0; i < nf; ++i) {
    if (!text.nextRecord())
      return Located{text.lineNo, "file ends after " + std::to_string(i) + " of " +
                                      std::to_string(nf) + " faces"};
    const int line = text.lineNo - 1;
    std::istringstream f(s);
    long long k;
    if (!(f >> k) || k < 1)
      return Located{line, "face must start with its vertex count: '" + s + "'"};
    Polygon polygon;
    for (long long j = 0; j < k; ++j) {
      long long index;
      if (!(f >> index))
        return Located{line,
                       "face lists fewer than " + std::to_string(k) + " indices: '" + s + "'"};
      if (index < 0 || index >= nv)
        return Located{line, "face index " + std::to_string(index) + " out of range [0, " +
                                 std::to_string(nv) + ")"};
      polygon.push_back(static_cast<std::size_t>(index));
    }
    soup.faceLines.push_back(line);
    soup.polygons.push_back(std::move(polygon));
  }
  return std::nullopt;
}

}  // namespace

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
  OffText text{in, 1, {}};
  int& lineNo = text.lineNo;
  if (!text.skipBlanksAndComments(true)) return Located{lineNo, "no OFF header"};
  std::string keyword;
  in >> keyword;
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    return Located{lineNo, "header must start with OFF, found '" + keyword + "'"};
  {
    text.skipBlanksAndComments(true);
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
  if ((dimensional && !text.readCount(dimension, true)) || !text.readCount(nv, !dimensional) ||
      !text.readCount(nf, false) || !text.readCount(ne, false) || nv < 0 || nf < 0)
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
  if (auto problem = readOffVertices(text, nv, homogeneous, soup)) return problem;
  return readOffFaces(text, nv, nf, soup);
}

}  // namespace raylab::meshio
