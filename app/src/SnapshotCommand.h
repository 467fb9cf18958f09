#pragma once

#include <string>

namespace raylab::app {

/// Options of `raylab snapshot`.
struct SnapshotOptions {
  std::string out;    ///< PNG file to write (required).
  std::string scene;  ///< Scene file; empty for the built-in default scene.
  int width = 300;    ///< Picture width, pixels.
  int height = 300;   ///< Picture height, pixels.
};

/**
 * \brief `raylab snapshot`: renders the window's default 3D view of the scene offscreen
 * (same SceneView, same camera) into a PNG and prints the path written on stdout.
 * \return kExitOk; errors are thrown (raylab::Exception subtypes naming the file).
 */
int runSnapshot(const SnapshotOptions& options);

}  // namespace raylab::app
