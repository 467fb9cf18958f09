// libFuzzer target: the scene loader (SceneIO::parse). An input is either refused with a
// SceneIO::LoadError or loads into a scene the core accepts: its camera ray and a short
// trace of the centre pixel with every algorithm must not abort (the loader must catch
// every value the core would refuse, issue 14). Any other exception, a sanitizer report,
// a timeout or an allocation past -rss_limit_mb is a finding.
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"

#include <algorithm>
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
  // Keep a trace short whatever the file asks: the point is the values, not the work.
  RenderSettings settings = scene.render;
  settings.maxDepth = std::min(settings.maxDepth, 3);
  settings.shadowSamples = std::min(settings.shadowSamples, 2);
  settings.glossySamples = std::min(settings.glossySamples, 2);
  for (Algorithm algorithm : {Algorithm::RayCasting, Algorithm::Whitted, Algorithm::Distributed,
                              Algorithm::PathTracing}) {
    settings.algorithm = algorithm;
    const Tracer tracer(scene, settings);
    tracer.trace(scene.camera.width / 2, scene.camera.height / 2, 0);
  }
  return 0;
}
