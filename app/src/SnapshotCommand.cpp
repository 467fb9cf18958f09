#include "SnapshotCommand.h"

#include "ExitCodes.h"
#include "SceneSource.h"

#include "raylab/vis/SceneView.h"

#include <iostream>

namespace raylab::app {

int runSnapshot(const SnapshotOptions& options) {
  const Scene scene = loadSceneOrDefault(options.scene);
  SceneView view(scene);
  view.resetViewCamera(static_cast<double>(options.width) / options.height);
  view.renderToPng(options.out, options.width, options.height);
  std::cout << options.out << std::endl;
  return kExitOk;
}

}  // namespace raylab::app
