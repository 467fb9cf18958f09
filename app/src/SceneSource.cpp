#include "SceneSource.h"

#include "raylab/core/SceneIO.h"

namespace raylab::app {

Scene loadSceneOrDefault(const std::string& path) {
  if (path.empty()) return defaultScene();
  return SceneIO::load(path);
}

}  // namespace raylab::app
