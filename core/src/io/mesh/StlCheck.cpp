// STL: a binary file's size against its count; an ASCII file's triangles counted.
#include "io/mesh/MeshReaders.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace raylab::meshio {

namespace {

/// An ASCII STL file in one pass: its triangles (lines starting with "facet") counted, to
/// stop past limits::kMaxMeshTriangles before CGAL reads the whole file (4.5M triangles took
/// it 2.4 GB and 30 s), and each vertex's three coordinates finite numbers (CGAL's reader
/// called "nan" and "1e400" a "premature end of file", issue 38).
SizeProblem checkAsciiStl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t facets = 0;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    const std::size_t b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos) continue;
    if (line.compare(b, 5, "facet") == 0 && ++facets > limits::kMaxMeshTriangles)
      return Located{0, "the ASCII STL file has more than " +
                            std::to_string(limits::kMaxMeshTriangles) +
                            " triangles; RayLab reads meshes of at most that many"};
    if (line.compare(b, 7, "vertex ") != 0 && line.compare(b, 7, "vertex\t") != 0) continue;
    std::istringstream words(line.substr(b + 7));
    std::string word;
    for (int k = 0; k < 3; ++k) {
      if (!(words >> word))
        return Located{lineNo, "vertex needs three numbers: '" + trimmed(line) + "'"};
      char* end = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (*end != '\0' || !std::isfinite(value))
        return Located{lineNo,
                       "vertex coordinate '" + word + "' is not a finite number RayLab can read"};
    }
  }
  return std::nullopt;
}

}  // namespace

SizeProblem checkStl(const std::string& path, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string start(5, '\0');
  in >> std::ws;
  in.read(&start[0], 5);
  const bool looksAscii = in && start == "solid";
  if (size < 84) {
    if (looksAscii) return checkAsciiStl(path);
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
    if (auto problem = checkAsciiStl(path)) return problem;
    return std::nullopt;
  }
  if (auto problem = checkCounts(0, static_cast<long long>(count), 0)) return problem;
  if (expected > size)
    return Located{0, "truncated binary STL: the header announces " + std::to_string(count) +
                          " triangles (" + std::to_string(expected) + " bytes) but the file has " +
                          std::to_string(size) + " bytes"};
  return std::nullopt;
}

}  // namespace raylab::meshio
