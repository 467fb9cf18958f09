// libFuzzer target: the ray-tree dump reader (RayTreeJson::parse), then what a reader of a
// tree does with it: propagate the energy, take the estimate, describe every ray. An input
// is refused with a RayTreeJson::Error or read as a tree the engine could have made;
// anything else (another exception, a sanitizer report, a timeout, a huge allocation) is a
// finding.
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/RayWords.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    raylab::RayTreeJson::Info info;
    raylab::RayTree tree = raylab::RayTreeJson::parse(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.json", &info);
    tree.propagate();
    (void)tree.estimate();
    (void)tree.toString();
    const raylab::SceneNames names{info.objectNames, {}};
    for (const raylab::RaySegment& s : tree.segments)
      (void)raylab::narrateRay(tree, s.id, names, raylab::Language::English);
  } catch (const raylab::RayTreeJson::Error&) {
  }
  return 0;
}
