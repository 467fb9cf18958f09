// libFuzzer target: the scene loader (SceneIO::parse). An input is either refused with a
// SceneIO::LoadError or loads into a scene the core accepts: nine pixels spread over its
// image are traced with every algorithm at the file's own depth, shadow and glossy samples
// (so a value that reaches the shading code, an ior of 1e20 on a mirror or a bushy glossy
// room, issue 38, is exercised), each sample within a ray cap of 4,096 rays (the image
// renderer's cap is 65,536: past the cap a sample must stay cheap). Any other exception,
// a sanitizer report, a timeout or an allocation past -rss_limit_mb is a finding.
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace raylab;
  Scene scene;
  try {
    scene = SceneIO::parse(std::string(reinterpret_cast<const char*>(data), size),
                           RAYLAB_FUZZ_SCENE_ORIGIN);
  } catch (const SceneIO::LoadError&) {
    return 0;
  }
  RenderSettings settings = scene.render;
  for (Algorithm algorithm : {Algorithm::RayCasting, Algorithm::Whitted, Algorithm::Distributed,
                              Algorithm::PathTracing}) {
    settings.algorithm = algorithm;
    const Tracer tracer(scene, settings);
    for (int i = 1; i <= 3; ++i)
      for (int j = 1; j <= 3; ++j)
        tracer.trace(scene.camera.width * i / 4, scene.camera.height * j / 4, 0, nullptr, nullptr,
                     4096);
  }
  return 0;
}
