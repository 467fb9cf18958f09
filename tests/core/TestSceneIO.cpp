// Scene files: the default scene, round trips, and error messages that name the place.
#include "raylab/core/Box.h"
#include "raylab/core/Camera.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Transform.h"
#include "raylab/core/TriangleMesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// A file's readable transform steps are saved as written while the object is unchanged,
// and only then: a moved object is saved as it now is (its steps baked into the shape).
TEST(SceneIO, 02b_AnUnchangedObjectKeepsItsStepsAndAChangedOneIsBaked) {
  const std::string text = R"({"raylab_scene": 2,
    "materials": [{"name": "m"}],
    "objects": [{"name": "b", "material": "m",
      "shape": {"type": "box", "size": [1, 2, 1], "centre": [0, 0, 0]},
      "transform": [{"rotate": {"degrees": 35, "axis": [0, 1, 0]}}, {"translate": [0.3, 0.6, 0.6]}]}]})";
  const Scene s = SceneIO::parse(text, "steps.json");
  const std::string saved = SceneIO::serialize(s);
  std::string compact;  // the text without its layout
  for (const char c : saved)
    if (c != ' ' && c != '\n') compact += c;
  // The entry as written, in the writer's key order (name, material, shape, transform).
  EXPECT_NE(compact.find(R"("shape":{"type":"box","centre":[0,0,0],"size":[1,2,1]})"),
            std::string::npos)
      << saved;
  EXPECT_NE(compact.find(R"({"rotate":{"axis":[0,1,0],"degrees":35}})"), std::string::npos)
      << saved;
  EXPECT_EQ(saved.find("matrix"), std::string::npos) << saved;
  // Read back: the same box, bit for bit.
  const Scene again = SceneIO::parse(saved, "steps.json");
  EXPECT_EQ(static_cast<const Box&>(*again.objects[0].shape).worldFromBox().matrix(),
            static_cast<const Box&>(*s.objects[0].shape).worldFromBox().matrix());
  // Moved in code: the steps no longer describe it; the box is saved as it now is.
  Scene moved = s;
  moved.objects[0].apply(Transform::translate(Vec3(1, 0, 0)).matrix());
  const std::string movedText = SceneIO::serialize(moved);
  EXPECT_EQ(movedText.find("rotate"), std::string::npos) << movedText;
  const Scene movedBack = SceneIO::parse(movedText, "moved.json");
  EXPECT_NEAR(glm::length(static_cast<const Box&>(*movedBack.objects[0].shape).centre() -
                          Point3(1.3, 0.6, 0.6)),
              0.0, 1e-12);
}

/// "1,1,...,1" with `n` ones: a large JSON array's contents.
std::string manyOnes(int n) {
  std::string text = "1";
  for (int i = 1; i < n; ++i) text += ",1";
  return text;
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
      {"integer out of range (issue 14: 4294967298 read as 2)",
       R"({"raylab_scene": 4294967298, "materials": [], "objects": []})",
       "/raylab_scene: integer 4294967298 is out of range"},
      {"width out of range",
       R"({"raylab_scene": 2, "materials": [], "objects": [], "camera": {"width": -4294967296}})",
       "/camera/width: integer -4294967296 is out of range"},
      {"number too large for a double",
       R"({"raylab_scene": 2, "materials": [], "objects": [], "camera": {"vertical_fov": 1e999}})",
       "test.json:1:80: number '1e999' is too large for a double"},
      {"huge array quoted by its size",
       head +
           R"({"name": "b", "material": "m", "shape": {"type": "sphere", "centre": [0,0,0], "radius": [)" +
           manyOnes(100000) + R"(]}}]})",
       "/objects/0/shape/radius: expected a number, got an array of 100000 values"},
      {"repeated key (the second would silently win)",
       "{\"raylab_scene\": 2, \"materials\": [{\"name\": \"m\"}], \"objects\": [\n"
       "  {\"name\": \"b\", \"material\": \"m\", \"shape\": {\"type\": \"sphere\", "
       "\"radius\": 1, \"radius\": 2, \"centre\": [0,0,0]}}]}",
       "test.json:2:75: the key \"radius\" appears twice in one object (JSON would silently keep "
       "the last: remove one)"},
      {"degenerate triangle",
       head +
           R"({"name": "t", "material": "m", "shape": {"type": "triangle", "vertices": [[0,0,0],[1,1,1],[2,2,2]]}}]})",
       "/objects/0/shape: triangle is degenerate"},
  };
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string message = loadError(c.text);
    EXPECT_THAT(message, HasSubstr("test.json")) << message.substr(0, 300);
    EXPECT_THAT(message, HasSubstr(c.expected)) << message.substr(0, 300);
    EXPECT_LT(message.size(), 400u) << "messages quote a bounded excerpt";
  }
}

// A value nested 100,000 levels deep: refused before parsing at the place it passes
// RayLab's nesting limit (it used to be dumped recursively into the message, which
// overflowed the stack; issue 14).
TEST(SceneIO, 03b_DeeplyNestedValuesAreRefusedAtTheirPlace) {
  const int depth = 100000;
  const std::string nested = std::string(depth, '[') + std::string(depth, ']');
  const std::string text =
      R"({"raylab_scene": 2, "materials": [], "objects": [], "camera": {"vertical_fov": )" +
      nested + "}}";
  const std::string message = loadError(text);
  // The 65th opening bracket: the root object and the camera are levels 1 and 2.
  EXPECT_EQ(message, "test.json:1:" + std::to_string(text.find("[[") + 63) +
                         ": JSON nested deeper than 64 levels (RayLab's limit)");
  // 64 levels are fine (then the value is the wrong type).
  const std::string deep = std::string(62, '[') + std::string(62, ']');
  EXPECT_THAT(loadError(R"({"raylab_scene": 2, "materials": [], "objects": [], "camera": )"
                        R"({"vertical_fov": )" +
                        deep + "}}"),
              HasSubstr("/camera/vertical_fov: expected a number, got an array of 1 values"));
}

// Issue 14: every value the core would refuse, or that would ask for an allocation or a
// computation without end, is refused by the loader with the file, the JSON path and the
// limit (core/include/raylab/core/Limits.h; README "Limits").
TEST(SceneIO, 03c_LimitsAreRefusedWithTheirPlace) {
  const std::string head = R"({"raylab_scene": 2, "materials": [{"name": "m"}], "objects": [)";
  // One sphere with `fields`, object keys `extra` and top-level keys `root`.
  const auto sphere = [&](const std::string& fields, const std::string& extra = "",
                          const std::string& root = "") {
    return head + R"({"name": "b", "material": "m", "shape": {"type": "sphere", )" + fields + "}" +
           extra + "}]" + root + "}";
  };
  const std::string ball = R"("centre": [0, 0, 0], "radius": 1)";
  const auto withRender = [&](const std::string& render) {
    return sphere(ball, "", R"(, "render": {)" + render + "}");
  };
  const auto withCamera = [&](const std::string& camera) {
    return sphere(ball, "", R"(, "camera": {)" + camera + "}");
  };
  std::string scales;
  for (int i = 0; i < 13; ++i)
    scales += std::string(i ? ", " : "") + R"({"scale": [1e12, 1e12, 1e12]})";
  const ErrorCase cases[] = {
      {"radius whose square overflows (was an abort in Ray.cpp)",
       sphere(R"("centre": [0, 0, 0], "radius": 1e155)"),
       "/objects/0/shape/radius: 1e+155 is beyond RayLab's largest coordinate, 1e12"},
      {"radius whose square underflows", sphere(R"("centre": [0, 0, 0], "radius": 1e-300)"),
       "/objects/0/shape/radius: radius 1e-300 is below RayLab's smallest size, 1e-9"},
      {"rotation axis whose length underflows (was an abort in Transform.cpp)",
       sphere(ball, R"(, "transform": [{"rotate": {"axis": [0, 1e-300, 0], "degrees": 30}}])"),
       "/objects/0/transform/0/rotate/axis: vector is too short to give a direction"},
      {"scales that compose to an overflow", sphere(ball, R"(, "transform": [)" + scales + "]"),
       "/objects/0/transform/5: the steps so far make a transform too large or too degenerate"},
      {"tiny scale factor", sphere(ball, R"(, "transform": [{"scale": [1, 1e-12, 1]}])"),
       "/objects/0/transform/0/scale/1: scale factor 1e-12 is below 1e-9 in magnitude"},
      {"centre beyond the largest coordinate", sphere(R"("centre": [0, -3e15, 0], "radius": 1)"),
       "/objects/0/shape/centre/1: -3e+15 is beyond RayLab's largest coordinate"},
      {"tessellation too fine", sphere(ball + R"(, "m": 100000)"),
       "/objects/0/shape/m: m and n (sphere slices) must be at most 1024"},
      {"box side too large",
       head +
           R"({"name": "b", "material": "m", "shape": {"type": "box", "centre": [0,0,0], "size": [1, 1, 2e20]}}]})",
       "/objects/0/shape/size/2: 2e+20 is beyond RayLab's largest coordinate"},
      {"camera with overflowing coordinates (had no file or place)",
       withCamera(R"("position": [1e300, 0, 0])"),
       "/camera/position/0: 1e+300 is beyond RayLab's largest coordinate"},
      {"camera aperture beyond the largest coordinate", withCamera(R"("aperture": 2e20)"),
       "/camera/aperture: 2e+20 is beyond"},
      {"image side too large", withCamera(R"("width": 16384, "height": 16384)"),
       "/camera: width and height must be in [1, 8192], got 16384 x 16384"},
      {"image too large", withCamera(R"("width": 8192, "height": 4096)"),
       "/camera: width x height must be at most 4096 x 4096 = 16777216 pixels, got 8192 x 4096"},
      {"spp", withRender(R"("spp": 1000000000)"),
       "/render/spp: must be at most 1048576, got 1000000000"},
      {"max depth", withRender(R"("max_depth": 1000000)"),
       "/render/max_depth: must be at most 64, got 1000000"},
      {"shadow samples", withRender(R"("shadow_samples": 1000000000)"),
       "/render/shadow_samples: must be at most 256, got 1000000000"},
      {"glossy samples", withRender(R"("glossy_samples": 257)"),
       "/render/glossy_samples: must be at most 256, got 257"},
      {"roulette depth", withRender(R"("russian_roulette_depth": 65)"),
       "/render/russian_roulette_depth: must be at most 64, got 65"},
  };
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string message = loadError(c.text);
    EXPECT_THAT(message, HasSubstr("test.json: at ")) << message;
    EXPECT_THAT(message, HasSubstr(c.expected)) << message;
  }
  // The limits themselves are accepted.
  EXPECT_NO_THROW(SceneIO::parse(withRender(R"("spp": 1048576, "max_depth": 64, )"
                                            R"("shadow_samples": 256, "glossy_samples": 256)"),
                                 "test.json"));
  EXPECT_NO_THROW(SceneIO::parse(
      sphere(R"("centre": [0, 0, 0], "radius": 1e12, "m": 1024, "n": 1024)", "",
             R"(, "camera": {"position": [0, 0, 1e12], "width": 4096, "height": 4096})"),
      "test.json"));
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

// A device, a folder or a file over the size limit is refused before reading (/dev/zero
// used to be read without end).
TEST(SceneIO, 04b_OnlyRegularFilesOfBoundedSizeAreRead) {
  const auto message = [](const std::string& path) -> std::string {
    try {
      SceneIO::load(path);
    } catch (const SceneIO::LoadError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message("/dev/zero"),
            "/dev/zero: cannot read scene file: not a regular file (a folder or a device?)");
  EXPECT_EQ(message(RAYLAB_TEMP_DIR),
            std::string(RAYLAB_TEMP_DIR) +
                ": cannot read scene file: not a regular file (a folder or a device?)");
  // A sparse 65 MiB file: no disk space used.
  const std::string big = std::string(RAYLAB_TEMP_DIR) + "/sceneio-65MiB.json";
  { std::ofstream(big) << "{"; }
  std::filesystem::resize_file(big, std::uintmax_t(65) << 20);
  EXPECT_EQ(message(big),
            big + ": scene file is 65 MiB; RayLab reads scene files of at most 64 MiB");
  std::filesystem::remove(big);
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

namespace raylab {
namespace {

const char* kEverything = R"({
  "raylab_scene": 2,
  "name": "everything",
  "materials": [
    {"name": "white", "type": "diffuse", "colour": [0.7, 0.7, 0.7]},
    {"name": "chrome", "type": "mirror", "colour": [0.9, 0.9, 0.9],
     "reflection_rate": 0.6, "refraction_rate": 0.3, "ior": 1.33},
    {"name": "glass", "type": "dielectric", "colour": [1, 1, 1], "ior": 1.5},
    {"name": "plastic", "type": "glossy", "colour": [0.2, 0.5, 0.2],
     "exponent": 200, "specular": 0.25},
    {"name": "lamp", "emission": [4, 4, 3]}
  ],
  "objects": [
    {"name": "ball", "material": "chrome",
     "shape": {"type": "sphere", "centre": [0, 1, 0], "radius": 1}, "velocity": [0, 0.5, 0]},
    {"name": "panel", "material": "lamp",
     "shape": {"type": "quad", "corner": [-1, 3, -1], "u": [2, 0, 0], "v": [0, 0, 2]}}
  ],
  "point_lights": [{"name": "key", "position": [2, 5, 2], "intensity": [20, 10, 5]}],
  "camera": {"position": [0, 2, 5], "look_at": [0, 1, 0], "up": [0, 1, 0],
             "vertical_fov": 45, "width": 64, "height": 48,
             "aperture": 0.1, "focus_distance": 4.5},
  "render": {"algorithm": "distributed", "spp": 9, "max_depth": 7, "seed": 12345678901234,
             "shadow_samples": 3, "glossy_samples": 5, "russian_roulette_depth": 2,
             "next_event_estimation": false, "multiple_importance": false,
             "background": [0.1, 0.2, 0.3]}
})";

TEST(SceneIO, 08_ReadsMaterialsLightsCameraAndRenderSettings) {
  const Scene s = SceneIO::parse(kEverything, "everything.json");
  ASSERT_EQ(s.materials.size(), 5u);
  const Material& chrome = s.materials[s.findMaterial("chrome")];
  EXPECT_EQ(chrome.type, MaterialType::Mirror);
  EXPECT_EQ(chrome.reflectionRate, 0.6);
  EXPECT_EQ(chrome.refractionRate, 0.3);
  EXPECT_EQ(chrome.ior, 1.33);
  EXPECT_EQ(s.materials[s.findMaterial("glass")].type, MaterialType::Dielectric);
  const Material& plastic = s.materials[s.findMaterial("plastic")];
  EXPECT_EQ(plastic.type, MaterialType::Glossy);
  EXPECT_EQ(plastic.exponent, 200.0);
  EXPECT_EQ(plastic.specular, 0.25);
  // No "type": diffuse, as in version 1.
  EXPECT_EQ(s.materials[s.findMaterial("lamp")].type, MaterialType::Diffuse);
  EXPECT_TRUE(s.materials[s.findMaterial("lamp")].isEmitter());

  EXPECT_EQ(s.objects[0].velocity, Vec3(0, 0.5, 0));
  EXPECT_EQ(s.objects[1].velocity, Vec3(0.0));
  ASSERT_EQ(s.pointLights.size(), 1u);
  EXPECT_EQ(s.pointLights[0].name, "key");
  EXPECT_EQ(s.pointLights[0].position, Point3(2, 5, 2));
  EXPECT_EQ(s.pointLights[0].intensity, Vec3(20, 10, 5));
  EXPECT_EQ(s.camera.aperture, 0.1);
  EXPECT_EQ(s.camera.focusDistance, 4.5);

  const RenderSettings& r = s.render;
  EXPECT_EQ(r.algorithm, Algorithm::Distributed);
  EXPECT_EQ(r.samplesPerPixel, 9);
  EXPECT_EQ(r.maxDepth, 7);
  EXPECT_EQ(r.seed, 12345678901234u);
  EXPECT_EQ(r.shadowSamples, 3);
  EXPECT_EQ(r.glossySamples, 5);
  EXPECT_EQ(r.russianRouletteDepth, 2);
  EXPECT_FALSE(r.nextEventEstimation);
  EXPECT_FALSE(r.multipleImportance);
  EXPECT_EQ(r.background, Vec3(0.1, 0.2, 0.3));
}

TEST(SceneIO, 09_NewFieldsRoundTripExactly) {
  Scene s = SceneIO::parse(kEverything, "everything.json");
  // Parameters a type does not use, and values with long expansions, survive too.
  s.materials[0].ior = 1.0 / 3.0;
  s.materials[3].exponent = std::sqrt(2.0) * 100.0;
  s.pointLights.push_back({"fill", Point3(-1.0 / 7.0, 2, 3), Vec3(0.1, 0.2, 0.3)});
  s.objects[1].velocity = Vec3(1e-17, -3.25, 0.0);
  s.render.seed = 18446744073709551615u;  // the largest seed
  s.render.algorithm = Algorithm::RayCasting;

  const std::string text = SceneIO::serialize(s);
  const Scene back = SceneIO::parse(text, "roundtrip");
  EXPECT_EQ(SceneIO::serialize(back), text);
  ASSERT_EQ(back.materials.size(), s.materials.size());
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    SCOPED_TRACE(s.materials[i].name);
    EXPECT_EQ(back.materials[i].type, s.materials[i].type);
    EXPECT_EQ(back.materials[i].colour, s.materials[i].colour);
    EXPECT_EQ(back.materials[i].emission, s.materials[i].emission);
    EXPECT_EQ(back.materials[i].reflectionRate, s.materials[i].reflectionRate);
    EXPECT_EQ(back.materials[i].refractionRate, s.materials[i].refractionRate);
    EXPECT_EQ(back.materials[i].ior, s.materials[i].ior);
    EXPECT_EQ(back.materials[i].exponent, s.materials[i].exponent);
    EXPECT_EQ(back.materials[i].specular, s.materials[i].specular);
  }
  EXPECT_EQ(back.objects[1].velocity, s.objects[1].velocity);
  ASSERT_EQ(back.pointLights.size(), 2u);
  EXPECT_EQ(back.pointLights[1].position, s.pointLights[1].position);
  EXPECT_EQ(back.render.seed, s.render.seed);
  EXPECT_EQ(back.render.algorithm, Algorithm::RayCasting);
  EXPECT_EQ(back.render.toString(), s.render.toString());
  EXPECT_EQ(back.camera.aperture, s.camera.aperture);
  EXPECT_EQ(back.camera.focusDistance, s.camera.focusDistance);
  Scene clipped = s;
  clipped.camera.nearClip = 0.1;
  EXPECT_EQ(SceneIO::parse(SceneIO::serialize(clipped), "clipped").camera.nearClip, 0.1);
  // The file says which version it is.
  EXPECT_THAT(text, HasSubstr("\"raylab_scene\": " + std::to_string(SceneIO::kVersion)));
}

TEST(SceneIO, 10_Version1FilesLoadWithDefaults) {
  // kMinimal is a version-1 file: nothing of version 2 in it.
  const Scene s = SceneIO::parse(kMinimal, "minimal");
  const RenderSettings defaults;
  EXPECT_EQ(s.materials[0].type, MaterialType::Diffuse);
  EXPECT_TRUE(s.pointLights.empty());
  EXPECT_EQ(s.objects[0].velocity, Vec3(0.0));
  EXPECT_EQ(s.camera.aperture, 0.0);
  EXPECT_EQ(s.render.toString(), defaults.toString());
}

TEST(SceneIO, 11_NewErrorsNameThePlaceAndTheProblem) {
  const auto withMaterial = [](const std::string& material) {
    return R"({"raylab_scene": 2, "materials": [)" + material + R"(], "objects": []})";
  };
  const std::string one = R"({"raylab_scene": 2, "materials": [{"name": "m"}], "objects": [)";
  const std::string ball =
      R"({"name": "b", "material": "m", "shape": {"type": "sphere", "centre": [0,0,0], "radius": 1}})";
  const ErrorCase cases[] = {
      {"unknown material type", withMaterial(R"({"name": "x", "type": "velvet"})"),
       "/materials/0/type: unknown material type \"velvet\" (expected diffuse, mirror"},
      {"box matrix and size",
       one + R"({"name": "c", "material": "m", "shape": {"type": "box", "size": [1, 1, 1],
           "matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}}]})",
       "/objects/0/shape/size: a box is given either by \"matrix\" or by centre, size and axes, "
       "not both"},
      {"ior zero", withMaterial(R"({"name": "x", "type": "dielectric", "ior": 0})"),
       "/materials/0/ior: ior (index of refraction) must be positive"},
      {"ior negative", withMaterial(R"({"name": "x", "type": "mirror", "ior": -1.5})"),
       "/materials/0/ior: ior"},
      {"negative reflection rate",
       withMaterial(R"({"name": "x", "type": "mirror", "reflection_rate": -0.1})"),
       "/materials/0/reflection_rate: reflection_rate must be in [0, 1]"},
      {"negative refraction rate",
       withMaterial(R"({"name": "x", "type": "mirror", "refraction_rate": -0.5})"),
       "/materials/0/refraction_rate: refraction_rate must be in [0, 1]"},
      {"rates above one",
       withMaterial(
           R"({"name": "x", "type": "mirror", "reflection_rate": 0.7, "refraction_rate": 0.4})"),
       "/materials/0: reflection_rate + refraction_rate must not exceed 1"},
      {"exponent zero", withMaterial(R"({"name": "x", "type": "glossy", "exponent": 0})"),
       "/materials/0/exponent: exponent (Phong) must be positive"},
      {"specular above one", withMaterial(R"({"name": "x", "type": "glossy", "specular": 1.5})"),
       "/materials/0/specular: specular must be in [0, 1]"},
      {"misspelt key", withMaterial(R"({"name": "x", "refraction_rat": 0.5})"),
       "/materials/0/refraction_rat: unknown key \"refraction_rat\""},
      {"emitter on a plane",
       R"({"raylab_scene": 2, "materials": [{"name": "sun", "emission": [1, 1, 1]}], "objects": [
          {"name": "sky", "material": "sun", "shape": {"type": "plane", "point": [0,9,0], "normal": [0,-1,0]}}]})",
       "/objects/0/material: emitting material \"sun\" on a plane"},
      {"velocity not a vector", one + R"({"name": "b", "material": "m", "velocity": [1, 2],
                 "shape": {"type": "sphere", "centre": [0,0,0], "radius": 1}}]})",
       "/objects/0/velocity: expected [x, y, z]"},
      {"point light without position", one + ball + R"(], "point_lights": [{"name": "p"}]})",
       "/point_lights/0: missing \"position\""},
      {"negative intensity",
       one + ball +
           R"(], "point_lights": [{"name": "p", "position": [0,1,0], "intensity": [1,-1,1]}]})",
       "/point_lights/0/intensity: intensity must not be negative"},
      {"duplicate point light",
       one + ball +
           R"(], "point_lights": [{"name": "p", "position": [0,1,0]}, {"name": "p", "position": [0,2,0]}]})",
       "/point_lights/1/name: duplicate point light \"p\""},
      {"negative aperture", one + ball + R"(], "camera": {"aperture": -1}})",
       "/camera/aperture: aperture (lens radius) must not be negative"},
      {"negative near clip", one + ball + R"(], "camera": {"near_clip": -1}})",
       "/camera/near_clip: near_clip must not be negative"},
      {"negative focus distance", one + ball + R"(], "camera": {"focus_distance": -2}})",
       "/camera/focus_distance: focus_distance must not be negative"},
      {"unknown algorithm", one + ball + R"(], "render": {"algorithm": "photon"}})",
       "/render/algorithm: unknown algorithm \"photon\" (expected raycast, whitted, distributed"},
      {"zero spp", one + ball + R"(], "render": {"spp": 0}})",
       "/render/spp: must be at least 1, got 0"},
      {"negative depth", one + ball + R"(], "render": {"max_depth": -1}})",
       "/render/max_depth: must be at least 0"},
      {"negative seed", one + ball + R"(], "render": {"seed": -3}})",
       "/render/seed: expected a non-negative integer"},
      {"nee not a boolean", one + ball + R"(], "render": {"next_event_estimation": 1}})",
       "/render/next_event_estimation: expected true or false"},
      {"negative background", one + ball + R"(], "render": {"background": [0, -1, 0]}})",
       "/render/background: background radiance must not be negative"},
      {"future version", R"({"raylab_scene": 3, "materials": [], "objects": []})",
       "unsupported version 3 (this RayLab reads versions 1 to 2)"},
  };
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string message = loadError(c.text);
    EXPECT_THAT(message, HasSubstr("test.json: at ")) << message;
    EXPECT_THAT(message, HasSubstr(c.expected)) << message;
  }
}

/// A fresh folder under the build's temporary directory.
std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(RAYLAB_TEMP_DIR) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

const char* kMeshScene = R"({
  "raylab_scene": 2,
  "materials": [{"name": "m"}],
  "objects": [{"name": "cube", "material": "m",
               "shape": {"type": "mesh", "file": "meshes/cube.obj"},
               "transform": [{"scale": [2, 2, 2]}, {"translate": [10, 0, 0]}]}]
})";

TEST(SceneIO, 12_MeshesAreLoadedRelativeToTheSceneFileAndSavedByReference) {
  const std::filesystem::path dir = freshDir("sceneio_mesh");
  std::filesystem::create_directories(dir / "scenes" / "meshes");
  std::filesystem::copy_file(std::string(RAYLAB_TEST_DATA_DIR) + "/meshes/cube.obj",
                             dir / "scenes" / "meshes" / "cube.obj");
  writeText(dir / "scenes" / "mesh.json", kMeshScene);

  // The unit cube [0, 1]^3, scaled by 2, moved by 10 along x.
  const Scene s = SceneIO::load((dir / "scenes" / "mesh.json").string());
  ASSERT_EQ(s.objects.size(), 1u);
  const SceneObject& cube = s.objects[0];
  ASSERT_EQ(cube.shape->kind(), ShapeKind::TriangleMesh);
  EXPECT_EQ(static_cast<const TriangleMesh&>(*cube.shape).triangleCount(), 12u);
  EXPECT_EQ(cube.shape->bounds().lower, Point3(10, 0, 0));
  EXPECT_EQ(cube.shape->bounds().upper, Point3(12, 2, 2));
  EXPECT_EQ(cube.source, (dir / "scenes" / "meshes" / "cube.obj").lexically_normal().string());
  EXPECT_EQ(cube.worldFromSource * glm::dvec4(1, 1, 1, 1), glm::dvec4(12, 2, 2, 1));

  // Saved beside the original: the same relative path, and the transform as a matrix.
  const std::string text = SceneIO::serialize(s, (dir / "scenes").string());
  EXPECT_THAT(text, HasSubstr("\"file\": \"meshes/cube.obj\""));
  EXPECT_THAT(text, HasSubstr("\"matrix\""));
  const Scene back = SceneIO::parse(text, (dir / "scenes" / "copy.json").string());
  EXPECT_EQ(SceneIO::serialize(back, (dir / "scenes").string()), text);
  EXPECT_EQ(back.objects[0].shape->bounds().upper, Point3(12, 2, 2));

  // Saved into another folder: the path is rewritten relative to the new file.
  std::filesystem::create_directories(dir / "elsewhere");
  SceneIO::save(s, (dir / "elsewhere" / "moved.json").string());
  const Scene moved = SceneIO::load((dir / "elsewhere" / "moved.json").string());
  EXPECT_EQ(moved.objects[0].shape->bounds().upper, Point3(12, 2, 2));
  std::ifstream in(dir / "elsewhere" / "moved.json");
  std::ostringstream movedText;
  movedText << in.rdbuf();
  EXPECT_THAT(movedText.str(), HasSubstr("\"file\": \"../scenes/meshes/cube.obj\""));

  // Moving the object keeps the saved transform in step with the vertices.
  Scene turned = s;
  turned.objects[0].apply(Transform::translate({0, 5, 0}).matrix());
  const Scene turnedBack = SceneIO::parse(SceneIO::serialize(turned, (dir / "scenes").string()),
                                          (dir / "scenes" / "x.json").string());
  EXPECT_EQ(turnedBack.objects[0].shape->bounds().lower, Point3(10, 5, 0));
}

TEST(SceneIO, 13_MissingOrBadMeshNamesSceneFilePlaceAndMesh) {
  const std::filesystem::path dir = freshDir("sceneio_missing_mesh");
  const std::string scenePath = (dir / "scene.json").string();
  writeText(dir / "scene.json", kMeshScene);
  try {
    SceneIO::load(scenePath);
    FAIL() << "no error";
  } catch (const SceneIO::LoadError& e) {
    EXPECT_THAT(e.what(), HasSubstr(scenePath));
    EXPECT_THAT(e.what(), HasSubstr("/objects/0/shape/file"));
    EXPECT_THAT(e.what(), HasSubstr("meshes/cube.obj"));
    EXPECT_THAT(e.what(), HasSubstr("not found"));
  }
  // A file that is there but is no mesh: MeshIO's reason is included.
  std::filesystem::create_directories(dir / "meshes");
  std::filesystem::copy_file(std::string(RAYLAB_TEST_DATA_DIR) + "/meshes/empty.obj",
                             dir / "meshes" / "cube.obj");
  try {
    SceneIO::load(scenePath);
    FAIL() << "no error";
  } catch (const SceneIO::LoadError& e) {
    EXPECT_THAT(e.what(), HasSubstr(scenePath + ": at /objects/0/shape/file: cannot load mesh"));
    EXPECT_THAT(e.what(), HasSubstr("no faces"));
  }
  // A mesh object without a file cannot be saved.
  Scene s = defaultScene();
  s.objects.emplace_back(
      "orphan",
      std::make_unique<TriangleMesh>(std::vector<Point3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                     std::vector<TriangleMesh::Index3>{{0, 1, 2}}),
      0);
  EXPECT_THROW(SceneIO::serialize(s), SceneIO::SaveError);
}

TEST(SceneIO, 14_CopiedObjectsKeepVelocityAndSource) {
  SceneObject a("a", std::make_unique<Sphere>(Point3(0.0), 1.0), 0);
  a.velocity = Vec3(1, 2, 3);
  a.source = "meshes/a.obj";
  a.worldFromSource = Transform::translate({4, 5, 6}).matrix();
  const SceneObject b = a;
  EXPECT_EQ(b.velocity, a.velocity);
  EXPECT_EQ(b.source, a.source);
  EXPECT_EQ(b.worldFromSource, a.worldFromSource);
  SceneObject c;
  c = a;
  EXPECT_EQ(c.velocity, a.velocity);
  EXPECT_EQ(c.source, a.source);
}

/// Every scene file shipped in lessons/scenes.
std::vector<std::filesystem::path> shippedScenes() {
  std::vector<std::filesystem::path> files;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ShippedScenes, 01_EveryFileLoadsAndHasALight) {
  const auto files = shippedScenes();
  // default, cornell, smallpt, materials at least.
  EXPECT_GE(files.size(), 4u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const Scene s = SceneIO::load(file.string());
    int lights = static_cast<int>(s.pointLights.size());
    for (const SceneObject& o : s.objects) lights += s.materials[o.material].isEmitter();
    EXPECT_GE(lights, 1);
    // Saving and loading again changes nothing.
    const std::string text = SceneIO::serialize(s, file.parent_path().string());
    EXPECT_EQ(SceneIO::serialize(SceneIO::parse(text, file.string()), file.parent_path().string()),
              text);
  }
}

TEST(ShippedScenes, 02_SmallptIsTheNineSphereCornellBox) {
  const Scene s = SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/smallpt.json");
  ASSERT_EQ(s.objects.size(), 9u);
  for (const SceneObject& o : s.objects) EXPECT_EQ(o.shape->kind(), ShapeKind::Sphere) << o.name;
  // smallpt: d = cx (sx - 0.5) + cy (sy - 0.5) + dir with |cy| = 0.5135 and sx, sy in
  // [0, 1]: the top of the image is 0.5135 / 2 above the axis at unit distance, so the
  // vertical field of view is 2 atan(0.5135 / 2) = 28.79 degrees (cx = w 0.5135 / h keeps
  // the pixels square).
  EXPECT_NEAR(s.camera.verticalFov, 2.0 * std::atan(0.5135 / 2.0) * 180.0 / kPi, 1e-12);
  EXPECT_EQ(s.camera.position, Point3(50, 52, 295.6));
  const Vec3 dir = glm::normalize(s.camera.lookAt - s.camera.position);
  const Vec3 expected = glm::normalize(Vec3(0, -0.042612, -1));
  EXPECT_NEAR(glm::length(dir - expected), 0.0, 1e-12);
  EXPECT_EQ(s.camera.width, 1024);
  EXPECT_EQ(s.camera.height, 768);
  // smallpt starts camera rays 140 units along the normalised pixel direction: inside
  // the box, past the black front wall (z = 170) that the eye at z = 295.6 is behind.
  EXPECT_EQ(s.camera.nearClip, 140.0);
  EXPECT_EQ(s.camera.nearClipShape, NearClipShape::Sphere);
  const Ray centre = Camera(s.camera).generateRay(Vec2(512.0, 384.0), Vec2(0.5), 0.0);
  EXPECT_NEAR(glm::length(centre.origin - (s.camera.position + 140.0 * expected)), 0.0, 1e-9);
  EXPECT_LT(centre.origin.z, 170.0);
  const Ray corner = Camera(s.camera).generateRay(Vec2(0.0), Vec2(0.5), 0.0);
  EXPECT_NEAR(glm::length(corner.origin - s.camera.position), 140.0, 1e-9);

  const auto sphere = [&](const char* name) -> const Sphere& {
    const int i = s.findObject(name);
    EXPECT_GE(i, 0) << name;
    return static_cast<const Sphere&>(*s.objects[std::max(i, 0)].shape);
  };
  const auto material = [&](const char* name) -> const Material& {
    return s.materials[s.objects[std::max(s.findObject(name), 0)].material];
  };
  EXPECT_EQ(sphere("light").radius(), 600.0);
  EXPECT_EQ(sphere("light").centre(), Point3(50, 681.33, 81.6));
  EXPECT_EQ(material("light").emission, Vec3(12.0));
  EXPECT_EQ(sphere("left").centre(), Point3(1e5 + 1, 40.8, 81.6));
  EXPECT_EQ(material("left").colour, Vec3(0.75, 0.25, 0.25));
  EXPECT_EQ(material("right").colour, Vec3(0.25, 0.25, 0.75));
  EXPECT_EQ(material("front").colour, Vec3(0.0));
  EXPECT_EQ(material("mirror").type, MaterialType::Mirror);
  EXPECT_EQ(material("mirror").reflectionRate, 1.0);
  EXPECT_EQ(material("mirror").refractionRate, 0.0);
  EXPECT_EQ(material("mirror").colour, Vec3(0.999));
  EXPECT_EQ(sphere("mirror").centre(), Point3(27, 16.5, 47));
  EXPECT_EQ(material("glass").type, MaterialType::Dielectric);
  EXPECT_EQ(material("glass").ior, 1.5);
  EXPECT_EQ(sphere("glass").radius(), 16.5);
  EXPECT_EQ(sphere("glass").centre(), Point3(73, 16.5, 78));
}

/// smallpt's camera ray through film position (fx, fy) of a w x h image (fy in RayLab's
/// pixels, down from the top), written as smallpt writes it (explicit.cpp, line 79-86):
/// cam(Vec(50,52,295.6), Vec(0,-0.042612,-1).norm()), cx = Vec(w*.5135/h),
/// cy = (cx%cam.d).norm()*.5135, d = cx*(fx/w - .5) + cy*(fy'/h - .5) + cam.d with fy' up
/// from the bottom, and Ray(cam.o+d*140, d.norm()) with d normalised first (g++ evaluates
/// the arguments right to left).
Ray smallptCameraRay(double fx, double fy, int w, int h) {
  const Point3 camO(50, 52, 295.6);
  const Vec3 camD = glm::normalize(Vec3(0, -0.042612, -1));
  const Vec3 cx(w * .5135 / h, 0, 0);
  const Vec3 cy = glm::normalize(glm::cross(cx, camD)) * .5135;
  const Vec3 d = glm::normalize(cx * (fx / w - .5) + cy * ((h - fy) / h - .5) + camD);
  Ray r;
  r.origin = camO + d * 140.0;
  r.direction = d;
  return r;
}

TEST(ShippedScenes, 03_SmallptTopRowsSeeTheCeilingAsSmallptDoes) {
  // The light (a sphere of radius 600 at y = 681.33) pokes 0.27 below the ceiling
  // (y = 81.6). A camera ray that started 140 in front of the eye on the near plane would
  // start above the ceiling in the top rows of the image (52 + 140 tan(14.4 - 2.44 deg)
  // = 81.7 > 81.6 at the top edge), outside the room, and see the light (radiance 12,
  // white) there: RayLab's picture had 4 white rows at 1024 x 768 that smallpt's has not.
  // Started 140 along each ray, as smallpt does, they stay in the room and hit the ceiling.
  const Scene s = SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/smallpt.json");
  const SceneIntersector scene(s);
  const Camera camera(s.camera);
  const int w = s.camera.width, h = s.camera.height;
  const auto objectHit = [&](const Ray& r) {
    const auto hit = scene.intersect(r);
    return hit ? s.objects[hit->object].name : std::string("nothing");
  };
  for (const double fy : {0.0, 0.5, 1.0, 2.5, 3.99})
    for (const double fx : {0.0, 100.5, 512.0, 700.25, 1024.0}) {
      SCOPED_TRACE("film (" + std::to_string(fx) + ", " + std::to_string(fy) + ")");
      const Ray ours = camera.generateRay(Vec2(fx, fy), Vec2(0.5), 0.0);
      const Ray theirs = smallptCameraRay(fx, fy, w, h);
      EXPECT_NEAR(glm::length(ours.origin - theirs.origin), 0.0, 1e-9);
      EXPECT_NEAR(glm::length(ours.direction - theirs.direction), 0.0, 1e-12);
      EXPECT_LT(ours.origin.y, 81.6);
      EXPECT_EQ(objectHit(ours), "top");
    }
  // The near plane (the old smallpt.json) leaves the room at the top edge, 4 rows deep:
  // what this test guards against.
  CameraSpec planeSpec = s.camera;
  planeSpec.nearClipShape = NearClipShape::Plane;
  const Camera plane(planeSpec);
  for (const double fy : {0.0, 3.5}) {
    const Ray r = plane.generateRay(Vec2(512.0, fy), Vec2(0.5), 0.0);
    EXPECT_GT(r.origin.y, 81.6) << fy;
    EXPECT_EQ(objectHit(r), "light") << fy;
  }
  EXPECT_EQ(objectHit(plane.generateRay(Vec2(512.0, 4.5), Vec2(0.5), 0.0)), "top");
}

TEST(ShippedScenes, 04_NearClipShapeRoundTripsAndBadShapesAreRefused) {
  Scene s = defaultScene();
  s.camera.nearClip = 2.0;
  EXPECT_EQ(SceneIO::serialize(s).find("near_clip_shape"), std::string::npos);
  s.camera.nearClipShape = NearClipShape::Sphere;
  const std::string text = SceneIO::serialize(s);
  EXPECT_THAT(text, HasSubstr("\"near_clip_shape\": \"sphere\""));
  EXPECT_EQ(SceneIO::parse(text, "sphere.json").camera.nearClipShape, NearClipShape::Sphere);
  std::string bad = text;
  const std::string key = "\"near_clip_shape\": \"sphere\"";
  bad.replace(bad.find(key), key.size(), "\"near_clip_shape\": \"ball\"");
  try {
    SceneIO::parse(bad, "ball.json");
    FAIL() << "an unknown near clip shape was accepted";
  } catch (const SceneIO::LoadError& e) {
    EXPECT_THAT(e.what(), HasSubstr("ball.json"));
    EXPECT_THAT(e.what(), HasSubstr("/camera/near_clip_shape"));
    EXPECT_THAT(e.what(), HasSubstr("unknown near clip shape \"ball\" (expected plane or sphere)"));
  }
  // On the sphere every camera ray starts exactly nearClip from the eye; on the plane
  // the corner rays start farther (nearClip / cos of their angle to the axis).
  const Camera sphere(s.camera);
  s.camera.nearClipShape = NearClipShape::Plane;
  const Camera planar(s.camera);
  for (const Vec2 film : {Vec2(0.0), Vec2(160.0, 120.0), Vec2(320.0, 17.0)}) {
    const Ray a = sphere.generateRay(film, Vec2(0.5), 0.0);
    const Ray b = planar.generateRay(film, Vec2(0.5), 0.0);
    EXPECT_NEAR(glm::length(a.origin - s.camera.position), 2.0, 1e-12);
    EXPECT_EQ(a.direction, b.direction);
    EXPECT_NEAR(glm::dot(b.origin - s.camera.position, planar.forward()), 2.0, 1e-12);
  }
}

TEST(ShippedScenes, 05_ChineseDisplayNamesLoadSaveAndAreChecked) {
  const std::string file = R"({
  "raylab_scene": 2, "name": "Glass", "display_name": {"zh": "玻璃"},
  "materials": [{"name": "glass", "display_name": {"zh": "玻璃"}, "type": "dielectric"},
                {"name": "wall"}],
  "objects": [{"name": "glass ball", "display_name": {"zh": "玻璃球"}, "material": "glass",
               "shape": {"type": "sphere", "centre": [0, 0, 0], "radius": 1}},
              {"name": "floor", "material": "wall",
               "shape": {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0]}}]})";
  const Scene s = SceneIO::parse(file, "names.json");
  EXPECT_EQ(s.nameZh, "玻璃");
  EXPECT_EQ(s.materials[0].nameZh, "玻璃");
  EXPECT_EQ(s.objects[0].nameZh, "玻璃球");
  // Shown in Chinese where there is one, the English name elsewhere; the name stays.
  EXPECT_EQ(s.objects[0].shownName(true), "玻璃球");
  EXPECT_EQ(s.objects[0].shownName(false), "glass ball");
  EXPECT_EQ(s.objects[1].shownName(true), "floor");
  EXPECT_EQ(s.findObject("glass ball"), 0);
  const Scene shown = sceneAsShown(s, true);
  EXPECT_EQ(shown.name, "玻璃");
  EXPECT_EQ(shown.objects[0].name, "玻璃球");
  EXPECT_EQ(shown.materials[0].name, "玻璃");
  EXPECT_EQ(shown.objects[1].name, "floor");
  EXPECT_EQ(sceneAsShown(s, false).objects[0].name, "glass ball");
  // Saved and read again (a copied object keeps it too).
  const std::string text = SceneIO::serialize(s);
  EXPECT_THAT(text, HasSubstr("\"zh\": \"玻璃球\""));
  const Scene back = SceneIO::parse(text, "again.json");
  EXPECT_EQ(back.nameZh, "玻璃");
  EXPECT_EQ(back.materials[0].nameZh, "玻璃");
  EXPECT_EQ(SceneObject(back.objects[0]).nameZh, "玻璃球");
  EXPECT_EQ(SceneIO::serialize(back), text);
  // Every shipped scene names all its objects and materials in Chinese.
  for (const auto& path : shippedScenes()) {
    SCOPED_TRACE(path.string());
    const Scene shipped = SceneIO::load(path.string());
    EXPECT_FALSE(shipped.nameZh.empty());
    for (const Material& m : shipped.materials) EXPECT_FALSE(m.nameZh.empty()) << m.name;
    for (const SceneObject& o : shipped.objects) EXPECT_FALSE(o.nameZh.empty()) << o.name;
  }
  // A bad display name: the file, the place and the problem.
  const auto objectWith = [](const std::string& displayName) {
    return R"({"raylab_scene": 2, "materials": [{"name": "m"}], "objects": [{"name": "b",
        "display_name": )" +
           displayName + R"(, "material": "m",
        "shape": {"type": "sphere", "centre": [0, 0, 0], "radius": 1}}]})";
  };
  const ErrorCase cases[] = {
      {"not an object", objectWith(R"("玻璃球")"),
       "/objects/0/display_name: expected the names in other languages"},
      {"unknown language", objectWith(R"({"zh": "玻璃球", "fr": "boule"})"),
       "/objects/0/display_name"},
      {"no zh", objectWith("{}"), "/objects/0/display_name"},
      {"not Chinese", objectWith(R"({"zh": "glass ball"})"),
       "/objects/0/display_name/zh: \"glass ball\" has no Chinese character"},
      {"not a string", objectWith(R"({"zh": 3})"), "/objects/0/display_name/zh"},
      {"on a material",
       R"({"raylab_scene": 2, "materials": [{"name": "m", "display_name": {"zh": ""}}],
           "objects": []})",
       "/materials/0/display_name/zh: \"\" has no Chinese character"},
  };
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(c.name);
    try {
      SceneIO::parse(c.text, "names.json");
      FAIL() << "accepted";
    } catch (const SceneIO::LoadError& e) {
      EXPECT_THAT(e.what(), HasSubstr("names.json"));
      EXPECT_THAT(e.what(), HasSubstr(c.expected));
    }
  }
}

}  // namespace
}  // namespace raylab
