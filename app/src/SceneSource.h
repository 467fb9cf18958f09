#pragma once

#include "raylab/core/Scene.h"

#include <string>

namespace raylab::app {

/// The scene a command works on: the file at `path` (through SceneIO::load, which throws
/// SceneIO::LoadError naming the file and the place), or the built-in default scene when
/// `path` is empty.
Scene loadSceneOrDefault(const std::string& path);

}  // namespace raylab::app
