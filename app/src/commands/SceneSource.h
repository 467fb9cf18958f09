#pragma once

#include "raylab/core/Scene.h"

#include <string>
#include <vector>

namespace raylab::app {

/// The scene a command works on: the file at `path` (through SceneIO::load, which throws
/// SceneIO::LoadError naming the file and the place), or the built-in default scene when
/// `path` is empty. A scene that will render black or empty is loaded all the same, with a
/// warning on stderr naming the file (sceneWarnings).
Scene loadSceneOrDefault(const std::string& path);

}  // namespace raylab::app
