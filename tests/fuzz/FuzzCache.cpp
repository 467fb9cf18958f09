// libFuzzer target: the reference cache's reader (issue 38). An input is a sidecar's text
// and a PFM's bytes, split at the first NUL byte (no NUL: the whole input is the PFM). The
// PFM alone goes through imageio::decodePfm (refused with a ReadError or decoded within
// the image limit); then both are written as the cache entry of a small fixed scene (the
// sidecar's "@KEY@" replaced by the entry's key, so the fuzzer gets past the key check)
// and ReferenceCache::load must ignore them with a reason or return a verified reference:
// never throw, hang or allocate past -rss_limit_mb.
#include "raylab/core/Image.h"
#include "raylab/core/ReferenceCache.h"
#include "raylab/core/SceneIO.h"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace raylab;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = input.find('\0');
  std::string sidecar = nul == std::string::npos ? std::string() : input.substr(0, nul);
  const std::string pfm = nul == std::string::npos ? input : input.substr(nul + 1);
  try {
    imageio::decodePfm(pfm, "fuzz.pfm");
  } catch (const imageio::ReadError&) {
  }

  static const Scene scene = [] {
    Scene s = SceneIO::parse(R"({"raylab_scene": 2,
      "materials": [{"name": "lamp", "emission": [1, 1, 1]}],
      "objects": [{"name": "l", "material": "lamp",
                   "shape": {"type": "sphere", "centre": [0, 0, -3], "radius": 1}}],
      "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "width": 4, "height": 3},
      "render": {"algorithm": "path", "spp": 1, "max_depth": 2}})",
                             "fuzz.json");
    return s;
  }();
  static const std::string dir =
      std::string(RAYLAB_FUZZ_TEMP_DIR) + "/cache-" + std::to_string(::getpid());
  static const ReferenceCache cache(dir);
  const std::string key = ReferenceCache::key(scene, scene.render);
  for (std::size_t at = sidecar.find("@KEY@"); at != std::string::npos;
       at = sidecar.find("@KEY@", at + key.size()))
    sidecar.replace(at, 5, key);
  ::mkdir(dir.c_str(), 0755);
  std::ofstream(cache.sidecarPath(key), std::ios::binary) << sidecar;
  std::ofstream(cache.imagePath(key), std::ios::binary) << pfm;
  cache.load(scene, scene.render);
  return 0;
}
