// OBJ: the checks before CGAL reads a file, and the line it refuses.
#include "io/mesh/MeshReaders.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace raylab::meshio {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

SizeProblem checkCounts(long long vertices, long long faces, int line) {
  const long long limit = static_cast<long long>(limits::kMaxMeshTriangles);
  if (vertices > limit || faces > limit)
    return Located{line, "the file announces " + std::to_string(vertices) + " vertices and " +
                             std::to_string(faces) + " faces; RayLab reads meshes of at most " +
                             std::to_string(limit) + " of each"};
  return std::nullopt;
}

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

namespace {

/// A face's corner as CGAL reads it (v, v/vt, v//vn or v/vt/vn): false when one of its
/// numbers is written with a fraction or an exponent ("1.5", "2e1"). CGAL reads the integer
/// in front and drops the rest, so "f 1.5 2 3" was read as "f 1 2 3", silently (issue 38).
/// Other characters after a number are CGAL's to refuse or skip, as before.
bool wholeCorner(const std::string& token) {
  for (std::size_t start = 0; start < token.size();) {
    const char* part = token.c_str() + start;
    char* endInteger = nullptr;
    char* endReal = nullptr;
    std::strtoll(part, &endInteger, 10);
    std::strtod(part, &endReal);
    if (endReal > endInteger) return false;
    const std::size_t slash = token.find('/', start);
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return true;
}

}  // namespace

SizeProblem checkObj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long vertices = 0, faces = 0;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::size_t b = line.find_first_not_of(" \t");
    if (b == std::string::npos || b + 1 >= line.size() || !std::isspace((unsigned char)line[b + 1]))
      continue;
    if (line[b] == 'v') ++vertices;
    if (line[b] != 'f') continue;
    ++faces;
    std::istringstream corners(line.substr(b + 1));
    std::string token;
    while (corners >> token)
      if (!wholeCorner(token))
        return Located{lineNo, "face corner '" + token +
                                   "' is not a vertex index (a whole number, as v, v/vt, "
                                   "v//vn or v/vt/vn): '" +
                                   trimmed(line) + "'"};
  }
  return checkCounts(vertices, faces, 0);
}

int objFaceLine(const std::string& path, std::size_t face) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t faces = 0;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    std::istringstream words(line);
    std::string key;
    if (words >> key && key == "f" && faces++ == face) return lineNo;
  }
  return 0;
}

bool endsLinesWithCrOnly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  for (int c = in.get(), read = 0; c != EOF && read < (1 << 20); c = in.get(), ++read) {
    if (c == '\n') return false;
    if (c == '\r') return in.peek() != '\n' && in.peek() != EOF;
  }
  return false;
}

}  // namespace raylab::meshio
