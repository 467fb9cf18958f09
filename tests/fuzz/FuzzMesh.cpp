// libFuzzer target: one mesh reader (MeshIO::load), built once per format with
// RAYLAB_FUZZ_EXT ".obj", ".off", ".ply" or ".stl". The input is written to a file of that
// extension (MeshIO reads files: CGAL's readers take a path); it is either refused with a
// MeshIO::ReadError or loads into a mesh. A file asking for more than it holds must be
// refused before CGAL allocates it (issue 14: -rss_limit_mb catches the allocation).
#include "raylab/core/MeshIO.h"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path =
      std::string(RAYLAB_FUZZ_TEMP_DIR) + "/fuzz-" + std::to_string(::getpid()) + RAYLAB_FUZZ_EXT;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try {
    raylab::MeshIO::load(path);
  } catch (const raylab::MeshIO::ReadError&) {
  }
  return 0;
}
