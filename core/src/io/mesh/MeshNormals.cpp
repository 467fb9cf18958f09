#include "io/mesh/MeshNormals.h"

#include "raylab/core/Limits.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <unordered_map>

namespace raylab::meshnormals {

namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

/// A file's normal must give a direction: finite and not zero.
void checkNormal(const Normal3& n, int line, const std::string& where) {
  if (!isFinite(n)) throw Problem(line, where + " is not finite: " + toString(n));
  // A component past RayLab's largest coordinate: its length overflows, and the normal
  // normalised later had zero length, named without its line (issue 38).
  for (int k = 0; k < 3; ++k)
    if (std::abs(n[k]) > limits::kMaxCoordinate)
      throw Problem(line, where + " has a component beyond RayLab's largest coordinate, 1e12: " +
                              toString(n));
  if (!(glm::length(n) > 0.0))
    throw Problem(line, where + " has zero length: " + toString(n) + " gives no direction");
}

PlyType plyType(const std::string& t) {
  if (t == "char" || t == "int8") return PlyType::Int8;
  if (t == "uchar" || t == "uint8") return PlyType::UInt8;
  if (t == "short" || t == "int16") return PlyType::Int16;
  if (t == "ushort" || t == "uint16") return PlyType::UInt16;
  if (t == "int" || t == "int32") return PlyType::Int32;
  if (t == "uint" || t == "uint32") return PlyType::UInt32;
  if (t == "float" || t == "float32") return PlyType::Float32;
  if (t == "double" || t == "float64") return PlyType::Float64;
  return PlyType::Unknown;
}

/// One binary PLY scalar as a double.
bool readBinary(std::istream& in, PlyType type, bool bigEndian, double& value) {
  const int size = plySize(type);
  unsigned char b[8] = {};
  if (size == 0 || !in.read(reinterpret_cast<char*>(b), size)) return false;
  std::uint64_t bits = 0;
  for (int k = 0; k < size; ++k) bits |= std::uint64_t(b[bigEndian ? size - 1 - k : k]) << 8 * k;
  switch (type) {
    case PlyType::Int8:
      value = double(std::int8_t(bits));
      break;
    case PlyType::UInt8:
      value = double(std::uint8_t(bits));
      break;
    case PlyType::Int16:
      value = double(std::int16_t(bits));
      break;
    case PlyType::UInt16:
      value = double(std::uint16_t(bits));
      break;
    case PlyType::Int32:
      value = double(std::int32_t(bits));
      break;
    case PlyType::UInt32:
      value = double(std::uint32_t(bits));
      break;
    case PlyType::Float32: {
      const std::uint32_t u = std::uint32_t(bits);
      float f;
      std::memcpy(&f, &u, 4);
      value = double(f);
      break;
    }
    case PlyType::Float64:
      std::memcpy(&value, &bits, 8);
      break;
    case PlyType::Unknown:
      return false;
  }
  return true;
}

using PositionKey = std::array<double, 3>;

struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    std::size_t h = 0;
    for (double v : k) h = h * 1000003u ^ std::hash<double>()(v);
    return h;
  }
};

PositionKey keyOf(const Point3& p) { return {p.x, p.y, p.z}; }

}  // namespace

std::optional<FileNormals> readObj(const std::string& path) {
  std::ifstream in(path);
  FileNormals out;
  std::string line;
  int lineNo = 0;
  bool referenced = false;
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream iss(line);
    std::string key;
    if (!(iss >> key)) continue;
    if (key == "vn") {
      // A normal: three numbers giving a direction.
      double x, y, z;
      if (!(iss >> x >> y >> z))
        throw Problem(lineNo, "normal needs three numbers: '" + trimmed(line) + "'");
      checkNormal(Normal3(x, y, z), lineNo, "normal " + std::to_string(out.normals.size() + 1));
      out.normals.emplace_back(x, y, z);
    } else if (key == "f") {
      // A face: each corner v, v/vt, v//vn or v/vt/vn; the third part is the normal.
      std::vector<int> corners;
      std::string token;
      while (iss >> token) {
        const std::size_t first = token.find('/');
        const std::size_t second =
            first == std::string::npos ? std::string::npos : token.find('/', first + 1);
        if (second == std::string::npos || second + 1 >= token.size()) {
          corners.push_back(-1);
          continue;
        }
        std::istringstream ts(token.substr(second + 1));
        long long i;
        if (!(ts >> i) || !ts.eof())
          throw Problem(lineNo, "face normal index in '" + token + "' is not a number");
        const long long count = static_cast<long long>(out.normals.size());
        const long long resolved = i < 0 ? count + i : i - 1;
        if (i == 0 || resolved < 0 || resolved >= count)
          throw Problem(lineNo, "face normal index " + std::to_string(i) +
                                    " refers to no normal (" + std::to_string(count) +
                                    " defined so far)");
        corners.push_back(int(resolved));
        referenced = true;
      }
      out.corners.push_back(std::move(corners));
    }
  }
  if (!referenced) return std::nullopt;
  return out;
}

int plySize(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
    case PlyType::Unknown:
      return 0;
  }
  return 0;
}

long long PlyHeader::count(const std::string& name) const {
  for (const PlyElement& e : elements)
    if (e.name == name) return e.count;
  return 0;
}

PlyHeader readPlyHeader(std::istream& in) {
  PlyHeader header;
  std::string line;
  while (std::getline(in, line)) {
    ++header.lines;
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "end_header") break;
    // CGAL's reader takes the format from the second word of line 2, whatever the first
    // ("form&at binary_little_endian" too), and no other line: a file whose format this
    // reader had missed was walked by nobody before CGAL read a list of 3.6e9 indices
    // (found by Fuzzply, issue 14).
    if (header.lines == 2) {
      std::string format, version;
      words >> format >> version;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        throw Problem(2,
                      "the second line must give the format (format ascii 1.0, or "
                      "binary_little_endian or binary_big_endian), found '" +
                          trimmed(line) + "'");
      header.format = format;
      continue;
    }
    if (key == "element") {
      PlyElement e;
      e.line = header.lines;
      if (!(words >> e.name >> e.count) || e.count < 0)
        throw Problem(header.lines,
                      "element line needs a name and a count: '" + trimmed(line) + "'");
      header.elements.push_back(e);
    }
    // CGAL's reader adds a property to the last element, even when there is none.
    if (key == "property" && header.elements.empty())
      throw Problem(header.lines, "property line before any element: '" + trimmed(line) + "'");
    if (key == "property") {
      PlyProperty p;
      p.line = header.lines;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType >> p.name;
        p.countType = plyType(countType);
        p.type = plyType(itemType);
        if (p.countType == PlyType::Unknown)
          throw Problem(header.lines, "unknown property type in '" + trimmed(line) + "'");
      } else {
        p.type = plyType(type);
        words >> p.name;
      }
      if (p.type == PlyType::Unknown)
        throw Problem(header.lines, "unknown property type in '" + trimmed(line) + "'");
      header.elements.back().properties.push_back(p);
    }
  }
  header.records = in.tellg();
  return header;
}

namespace {

/// One record of `element` into `values` (a list property: its length): an ASCII record is
/// one line (blank lines skipped; `lineNo` counts them, `recordLine` is the record's), a
/// binary one its bytes. False when the file is cut off or malformed there.
bool readPlyRecord(std::istream& in, const PlyElement& element, const PlyHeader& header,
                   int& lineNo, int& recordLine, std::vector<double>& values) {
  if (header.ascii()) {
    std::string record;
    do {
      if (!std::getline(in, record)) return false;
      ++lineNo;
    } while (trimmed(record).empty());
    recordLine = lineNo;
    std::istringstream tokens(record);
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
      double v = 0.0;
      if (!(tokens >> v)) return false;
      if (element.properties[i].isList()) {
        for (long long k = 0; k < static_cast<long long>(v); ++k) {
          double item;
          if (!(tokens >> item)) return false;
        }
      }
      values[i] = v;
    }
    return true;
  }
  const bool bigEndian = header.bigEndian();
  for (std::size_t i = 0; i < element.properties.size(); ++i) {
    const PlyProperty& p = element.properties[i];
    double v = 0.0;
    if (!p.isList()) {
      if (!readBinary(in, p.type, bigEndian, v)) return false;
    } else {
      if (!readBinary(in, p.countType, bigEndian, v) || v < 0) return false;
      in.seekg(static_cast<std::streamoff>(v) * plySize(p.type), std::ios::cur);
      if (!in) return false;
    }
    values[i] = v;
  }
  return true;
}

}  // namespace

std::optional<FileNormals> readPly(const std::string& path, const PlyHeader& header) {
  static const char* const kAxisNames[3] = {"nx", "ny", "nz"};
  const std::vector<PlyElement>& elements = header.elements;
  // Which of the vertex's properties are nx, ny, nz.
  std::size_t vertexElement = elements.size();
  int axis[3] = {-1, -1, -1};
  for (std::size_t e = 0; e < elements.size() && vertexElement == elements.size(); ++e) {
    if (elements[e].name != "vertex") continue;
    vertexElement = e;
    for (std::size_t i = 0; i < elements[e].properties.size(); ++i) {
      const PlyProperty& p = elements[e].properties[i];
      for (int a = 0; a < 3; ++a)
        if (p.name == kAxisNames[a] && !p.isList()) axis[a] = int(i);
    }
  }
  const int found = (axis[0] >= 0) + (axis[1] >= 0) + (axis[2] >= 0);
  if (found == 0) return std::nullopt;
  if (found < 3) {
    std::string have;
    for (int a = 0; a < 3; ++a)
      if (axis[a] >= 0) have += std::string(have.empty() ? "" : ", ") + kAxisNames[a];
    throw Problem(0,
                  "vertex normals need the properties nx, ny and nz; the header has only " + have);
  }

  // The records up to the end of the vertex element, the vertices' normals kept.
  const bool ascii = header.ascii();
  std::ifstream in(path, std::ios::binary);
  in.seekg(header.records);
  int lineNo = header.lines;
  FileNormals out;
  out.perVertex = true;
  out.normals.reserve(std::size_t(elements[vertexElement].count));
  const auto fail = [&](long long record, int atLine) {
    throw Problem(atLine, "cannot read the normal of vertex " + std::to_string(record) +
                              " (the file is cut off or malformed)");
  };
  for (std::size_t e = 0; e <= vertexElement; ++e) {
    const PlyElement& element = elements[e];
    for (long long r = 0; r < element.count; ++r) {
      std::vector<double> values(element.properties.size(), 0.0);
      int recordLine = 0;
      if (!readPlyRecord(in, element, header, lineNo, recordLine, values))
        fail(r, ascii ? (recordLine > 0 ? recordLine : lineNo) : 0);
      if (e != vertexElement) continue;
      const Normal3 n(values[std::size_t(axis[0])], values[std::size_t(axis[1])],
                      values[std::size_t(axis[2])]);
      checkNormal(n, recordLine, "the normal of vertex " + std::to_string(r));
      out.normals.push_back(n);
    }
  }
  return out;
}

void attach(const FileNormals& file, const std::vector<Point3>& soupPoints,
            const std::vector<std::vector<std::size_t>>& soupPolygons,
            const std::vector<Point3>& vertices, const std::vector<TriangleMesh::Index3>& triangles,
            std::vector<Normal3>& normals, std::vector<TriangleMesh::Index3>& normalIndices) {
  // Where each position occurs in the original faces: (face, corner), faces in order.
  std::unordered_map<PositionKey, std::vector<std::pair<int, int>>, PositionHash> at;
  for (std::size_t f = 0; f < soupPolygons.size(); ++f)
    for (std::size_t k = 0; k < soupPolygons[f].size(); ++k)
      at[keyOf(soupPoints[soupPolygons[f][k]])].push_back({int(f), int(k)});
  // The file's normal at corner k of face f, or -1.
  const auto fileNormal = [&](int f, int k) -> int {
    if (file.perVertex) return int(soupPolygons[std::size_t(f)][std::size_t(k)]);
    const std::vector<int>& corners = file.corners[std::size_t(f)];
    return std::size_t(k) < corners.size() ? corners[std::size_t(k)] : -1;
  };
  static const std::vector<std::pair<int, int>> kNone;
  const auto cornersAt = [&](const Point3& p) -> const std::vector<std::pair<int, int>>& {
    const auto it = at.find(keyOf(p));
    return it == at.end() ? kNone : it->second;
  };

  normals = file.normals;
  normalIndices.assign(triangles.size(), TriangleMesh::Index3{0, 0, 0});
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const TriangleMesh::Index3& tri = triangles[t];
    const std::vector<std::pair<int, int>>* lists[3] = {&cornersAt(vertices[std::size_t(tri[0])]),
                                                        &cornersAt(vertices[std::size_t(tri[1])]),
                                                        &cornersAt(vertices[std::size_t(tri[2])])};
    // The first original face that has all three positions, and each one's corner in it.
    int corner[3] = {-1, -1, -1};
    int face = -1;
    for (const auto& [f0, k0] : *lists[0]) {
      corner[0] = k0;
      bool all = true;
      for (int c = 1; c < 3 && all; ++c) {
        corner[c] = -1;
        for (const auto& [f, k] : *lists[c])
          if (f == f0) {
            corner[c] = k;
            break;
          }
        all = corner[c] >= 0;
      }
      if (all) {
        face = f0;
        break;
      }
    }
    // The triangle's own normal for corners without one (appended once, when needed).
    int flat = -1;
    for (int c = 0; c < 3; ++c) {
      int index = face >= 0 ? fileNormal(face, corner[c]) : -1;
      if (index < 0) {
        if (flat < 0) {
          const Point3& p0 = vertices[std::size_t(tri[0])];
          const Vec3 cross =
              glm::cross(vertices[std::size_t(tri[1])] - p0, vertices[std::size_t(tri[2])] - p0);
          const double length = glm::length(cross);
          flat = int(normals.size());
          normals.push_back(length > 0.0 ? cross / length : Normal3(0.0, 0.0, 1.0));
        }
        index = flat;
      }
      normalIndices[t][std::size_t(c)] = index;
    }
  }
}

}  // namespace raylab::meshnormals
