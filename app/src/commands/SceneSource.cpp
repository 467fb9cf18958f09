#include "commands/SceneSource.h"

#include "commands/Subcommand.h"

#include "raylab/core/SceneIO.h"

#include <iostream>

namespace raylab::app {

Scene loadSceneOrDefault(const std::string& path) {
  if (path.empty()) return defaultScene();
  Scene scene = SceneIO::load(path);
  for (const std::string& warning : sceneWarnings(scene))
    std::cerr << "raylab: warning: " << printable(path) << ": " << warning << std::endl;
  return scene;
}

}  // namespace raylab::app
