// CGAL's polygon-soup readers (OBJ, PLY, STL), with what they print captured.
#include "io/mesh/MeshReaders.h"

#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <sstream>

namespace raylab::meshio {

namespace {

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

}  // namespace

bool readCgalSoup(const std::string& path, std::vector<CgalPoint>& points,
                  std::vector<Polygon>& polygons, std::string& report) {
  bool ok = false;
  CaptureStreams capture;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(true));
  } catch (const std::exception& e) {
    ok = false;
    report = e.what();
  }
  const std::string printed = capture.errors();
  report = report.empty() ? printed : report + " " + printed;
  return ok;
}

}  // namespace raylab::meshio
