#include "SceneSource.h"

#include "Subcommand.h"

#include "raylab/core/SceneIO.h"

#include <iostream>

namespace raylab::app {

namespace {

/// True when something in `scene` gives light: a point light, an object with an emissive
/// material, a classic material's ambient term, or a background that is not black.
bool hasLight(const Scene& scene) {
  if (!scene.pointLights.empty()) return true;
  if (scene.render.background != Vec3(0.0)) return true;
  for (const SceneObject& object : scene.objects) {
    const Material& m = scene.materials[std::size_t(object.material)];
    if (m.isEmitter() || (m.isClassic() && m.ambient != Vec3(0.0))) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> sceneWarnings(const Scene& scene) {
  if (scene.objects.empty()) return {"the scene has no objects: every pixel shows the background"};
  if (!hasLight(scene))
    return {
        "the scene has no light (no point light, no emissive material, no ambient term, "
        "a black background): the image is black"};
  return {};
}

Scene loadSceneOrDefault(const std::string& path) {
  if (path.empty()) return defaultScene();
  Scene scene = SceneIO::load(path);
  for (const std::string& warning : sceneWarnings(scene))
    std::cerr << "raylab: warning: " << printable(path) << ": " << warning << std::endl;
  return scene;
}

}  // namespace raylab::app
