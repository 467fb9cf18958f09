// libFuzzer target: `--set PLACE=VALUE` (edit::setValue) on the shipped default scene, as
// the command line applies it (issue 38): the input is split at its first '=', a place
// without a leading '/' is a key of the render block, and a value that is not JSON is the
// string it spells. A change is refused with an Exception (the loader's checks) or gives a
// scene whose centre pixel every algorithm traces; anything else is a finding.
#include "raylab/core/Exception.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Tracer.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace raylab;
  static const Scene base = SceneIO::load(RAYLAB_FUZZ_SET_SCENE);
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) return 0;
  std::string place = text.substr(0, eq);
  if (place.front() != '/') place = "/render/" + place;
  std::string value = text.substr(eq + 1);
  if (!nlohmann::json::accept(value))
    value = nlohmann::json(value).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  Scene scene;
  try {
    scene = edit::setValue(base, place, value, "fuzz (--set)");
  } catch (const Exception&) {
    return 0;
  }
  RenderSettings settings = scene.render;
  for (Algorithm algorithm : {Algorithm::RayCasting, Algorithm::Whitted, Algorithm::Distributed,
                              Algorithm::PathTracing}) {
    settings.algorithm = algorithm;
    const Tracer tracer(scene, settings);
    tracer.trace(scene.camera.width / 2, scene.camera.height / 2, 0, nullptr, nullptr, 4096);
  }
  return 0;
}
