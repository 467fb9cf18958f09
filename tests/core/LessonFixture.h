#pragma once

// The small scene the lesson suites (TestLesson, TestLessonQuiz) write their lessons over:
// a glass ball on a floor under a quad light, 320x240, 4 spp, in a folder of its own per
// test (CTest runs tests side by side: a test rewriting a shared scene.json made another read
// it empty).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace raylab::testing {

/// What differs between the suites' scenes.
struct LessonSceneOptions {
  std::string folderPrefix;  ///< "lesson-" or "quiz-": the folder is prefix + the test's name.
  std::string name;          ///< The scene's name.
  std::string algorithm;     ///< Its render algorithm.
  bool pointLight = false;   ///< Also a point light "key" at (2, 5, 2), intensity 20.
};

/// Writes the scene as `scene.json` in the current test's own folder, which it returns.
inline std::filesystem::path writeLessonScene(const LessonSceneOptions& o) {
  const std::filesystem::path dir =
      std::filesystem::path(RAYLAB_TEMP_DIR) /
      (o.folderPrefix + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(dir);
  const std::string pointLights =
      o.pointLight
          ? R"("point_lights": [{"name": "key", "position": [2, 5, 2], "intensity": [20, 20, 20]}],)"
          : "";
  std::ofstream(dir / "scene.json") << R"({
    "raylab_scene": 2,
    "name": ")" + o.name + R"(",
    "materials": [
      {"name": "glass", "type": "dielectric", "ior": 1.5},
      {"name": "white", "colour": [0.7, 0.7, 0.7]},
      {"name": "lamp", "emission": [10, 10, 10]}],
    "objects": [
      {"name": "ball", "material": "glass",
       "shape": {"type": "sphere", "centre": [0, 1, 0], "radius": 1}},
      {"name": "floor", "material": "white",
       "shape": {"type": "quad", "corner": [-5, 0, 5], "u": [10, 0, 0], "v": [0, 0, -10]}},
      {"name": "light", "material": "lamp",
       "shape": {"type": "quad", "corner": [-1, 4, 1], "u": [2, 0, 0], "v": [0, 0, -2]}}],
    )" + pointLights + R"(
    "camera": {"position": [0, 1.5, 5], "look_at": [0, 1, 0], "width": 320, "height": 240},
    "render": {"algorithm": ")" + o.algorithm +
                                           R"(", "spp": 4, "max_depth": 5}
  })";
  return dir;
}

}  // namespace raylab::testing
