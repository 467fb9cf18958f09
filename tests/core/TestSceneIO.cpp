// Scene files: the default scene, round trips, and error messages that name the place.
#include "raylab/core/Box.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace raylab {
namespace {

using ::testing::HasSubstr;

std::string loadError(const std::string& text) {
  try {
    SceneIO::parse(text, "test.json");
  } catch (const SceneIO::LoadError& e) {
    return e.what();
  }
  return "no error";
}

const char* kMinimal = R"({
  "raylab_scene": 1,
  "materials": [{"name": "red", "colour": [0.8, 0.1, 0.1]}],
  "objects": [{"name": "ball", "material": "red",
               "shape": {"type": "sphere", "centre": [0, 0, 0], "radius": 1}}]
})";

TEST(DefaultScene, 01_HasTheSeedObjectsInARoom) {
  const Scene s = defaultScene();
  for (const char* name : {"red sphere", "blue cube", "light", "floor", "back wall"})
    EXPECT_GE(s.findObject(name), 0) << name;
  const SceneObject& light = s.objects[s.findObject("light")];
  EXPECT_TRUE(s.materials[light.material].isEmitter());
  EXPECT_EQ(light.shape->kind(), ShapeKind::Box);
  EXPECT_EQ(s.objects[s.findObject("blue cube")].shape->kind(), ShapeKind::Box);
  // The camera looks at the red sphere's side of the room: a ray from the camera to the
  // sphere's centre hits the sphere first, not a wall.
  const auto& sphere = static_cast<const Sphere&>(*s.objects[s.findObject("red sphere")].shape);
  const Ray r = Ray::make(s.camera.position, sphere.centre() - s.camera.position);
  double nearest = kInfinity;
  int nearestObject = -1;
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    if (const auto hit = s.objects[i].shape->intersect(r); hit && hit->t < nearest) {
      nearest = hit->t;
      nearestObject = static_cast<int>(i);
    }
  }
  EXPECT_EQ(nearestObject, s.findObject("red sphere"));
}

TEST(SceneIO, 01_RoundTripIsExact) {
  Scene s = defaultScene();
  // Add shapes whose parameters are not short decimals.
  auto ellipsoid = std::make_unique<Sphere>(Point3(0.1, 0.2, 0.3), 0.7);
  ellipsoid->apply(Transform::scale({1.3, 1.0 / 3.0, 1.0}).matrix());
  s.objects.emplace_back("ellipsoid", std::move(ellipsoid), 0);
  auto sheared = std::make_unique<Box>(Point3(0.0), Vec3(1.0));
  sheared->apply((Transform::scale({2, 1, 1}) * Transform::rotate(0.3, {0, 0, 1})).matrix());
  s.objects.emplace_back("sheared", std::move(sheared), 1);

  const std::string text = SceneIO::serialize(s);
  const Scene back = SceneIO::parse(text, "roundtrip");
  EXPECT_EQ(SceneIO::serialize(back), text);
  ASSERT_EQ(back.objects.size(), s.objects.size());
  // Same geometry bit for bit: the same rays give the same t.
  const Ray r = Ray::make({0.3, 1.1, 3.0}, {-0.1, -0.05, -1.0});
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const auto a = s.objects[i].shape->intersect(r);
    const auto b = back.objects[i].shape->intersect(r);
    ASSERT_EQ(bool(a), bool(b)) << s.objects[i].name;
    if (a) {
      EXPECT_EQ(a->t, b->t) << s.objects[i].name;
    }
  }
}

TEST(SceneIO, 02_TransformStepsApplyInListedOrder) {
  const Scene s = SceneIO::parse(R"({"raylab_scene": 1,
    "materials": [{"name": "m"}],
    "objects": [{"name": "b", "material": "m",
      "shape": {"type": "sphere", "centre": [1, 0, 0], "radius": 1},
      "transform": [{"scale": [2, 2, 2]}, {"translate": [0, 0, 5]}]}]})",
                                 "order");
  // Scale first: centre (2, 0, 0), radius 2; then translate: centre (2, 0, 5).
  const auto& sphere = static_cast<const Sphere&>(*s.objects[0].shape);
  EXPECT_EQ(sphere.centre(), Point3(2, 0, 5));
  EXPECT_EQ(sphere.radius(), 2.0);
}

struct ErrorCase {
  const char* name;
  std::string text;
  const char* expected;
};

TEST(SceneIO, 03_ErrorsNameThePlaceAndTheProblem) {
  const std::string head = R"({"raylab_scene": 1, "materials": [{"name": "m"}], "objects": [)";
  const ErrorCase cases[] = {
      {"syntax", "{\n  \"raylab_scene\": 1,\n  \"materials\": [,]\n}", "test.json:3:"},
      {"version", R"({"raylab_scene": 7, "materials": [], "objects": []})",
       "unsupported version 7"},
      {"no version", R"({"materials": [], "objects": []})", "raylab_scene"},
      {"negative radius",
       head +
           R"({"name": "b", "material": "m", "shape": {"type": "sphere", "centre": [0,0,0], "radius": -1}}]})",
       "/objects/0/shape/radius: radius must be positive"},
      {"unknown material",
       head +
           R"({"name": "b", "material": "gold", "shape": {"type": "sphere", "centre": [0,0,0], "radius": 1}}]})",
       "/objects/0/material: unknown material \"gold\""},
      {"zero axis",
       head +
           R"({"name": "b", "material": "m", "shape": {"type": "box", "centre": [0,0,0], "size": [1,1,1], "axes": [[1,0,0],[0,0,0],[0,0,1]]}}]})",
       "/objects/0/shape/axes/1: vector must not be zero"},
      {"nan-like string",
       head +
           R"({"name": "b", "material": "m", "shape": {"type": "sphere", "centre": [0,"NaN",0], "radius": 1}}]})",
       "/objects/0/shape/centre/1: expected a number"},
      {"unknown shape", head + R"({"name": "b", "material": "m", "shape": {"type": "torus"}}]})",
       "unknown shape type \"torus\""},
      {"duplicate",
       head +
           R"({"name": "b", "material": "m", "shape": {"type": "plane", "point": [0,0,0], "normal": [0,1,0]}},
                 {"name": "b", "material": "m", "shape": {"type": "plane", "point": [0,0,0], "normal": [0,1,0]}}]})",
       "/objects/1/name: duplicate object \"b\""},
      {"degenerate triangle",
       head +
           R"({"name": "t", "material": "m", "shape": {"type": "triangle", "vertices": [[0,0,0],[1,1,1],[2,2,2]]}}]})",
       "/objects/0/shape: triangle is degenerate"},
  };
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string message = loadError(c.text);
    EXPECT_THAT(message, HasSubstr("test.json")) << message;
    EXPECT_THAT(message, HasSubstr(c.expected)) << message;
  }
}

TEST(SceneIO, 04_MissingFileIsNamed) {
  try {
    SceneIO::load("/nonexistent/dir/scene.json");
    FAIL() << "no error";
  } catch (const SceneIO::LoadError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent/dir/scene.json"));
    EXPECT_THAT(e.what(), HasSubstr("cannot open"));
  }
}

TEST(SceneIO, 05_SaveReplacesAtomicallyAndFailureKeepsTheOldFile) {
  const std::filesystem::path dir = std::filesystem::path(RAYLAB_TEMP_DIR) / "sceneio";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "scene.json").string();
  SceneIO::save(defaultScene(), path);
  const Scene back = SceneIO::load(path);
  EXPECT_EQ(back.objects.size(), defaultScene().objects.size());
  // No temporary files are left beside it.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  // Saving into a missing directory fails with the path in the message.
  EXPECT_THROW(SceneIO::save(defaultScene(), (dir / "missing" / "x.json").string()),
               SceneIO::SaveError);
  EXPECT_EQ(SceneIO::load(path).objects.size(), back.objects.size());
}

TEST(SceneIO, 06_LoadMinimal) {
  const Scene s = SceneIO::parse(kMinimal, "minimal");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].shape->kind(), ShapeKind::Sphere);
  EXPECT_EQ(s.materials[0].colour, Vec3(0.8, 0.1, 0.1));
}

}  // namespace
}  // namespace raylab

namespace raylab {
namespace {

TEST(SceneIO, 07_ShippedDefaultSceneFileMatchesTheBuiltIn) {
  // lessons/scenes/default.json is the built-in scene as a file; regenerate it with
  // SceneIO::serialize(defaultScene()) when the built-in scene changes.
  const std::string path = std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/default.json";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), SceneIO::serialize(defaultScene()));
}

}  // namespace
}  // namespace raylab
