// The checker texture (Texture.h): its cells, the texel every algorithm shades with, the
// scene file's "texture" read, written and checked like every other value.
#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Texture.h"
#include "raylab/core/Tracer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace raylab {
namespace {

using ::testing::HasSubstr;

const Vec3 kWhite(0.8, 0.8, 0.8);
const Vec3 kRed(0.8, 0.1, 0.1);

/// A checker floor (y = 0, cubes of side 1, white and red) under a point light, seen from
/// straight above: the image's left half shows x in (0.74, 1) (cube (0, -1, 0), odd: red),
/// its right half x in (1, 1.26) (cube (1, -1, 0), even: white). Nothing else is in the
/// scene and escaped rays find black, so every algorithm returns the same direct light,
/// texel / pi * I cos / d^2.
std::string floorScene(const std::string& texture) {
  return R"({"raylab_scene": 2,
  "materials": [{"name": "floor", "type": "diffuse", "colour": [0.8, 0.8, 0.8])" +
         (texture.empty() ? std::string() : ", \"texture\": " + texture) + R"(}],
  "objects": [{"name": "floor", "material": "floor",
               "shape": {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}}],
  "point_lights": [{"name": "lamp", "position": [1, 3, 0.5], "intensity": [10, 10, 10]}],
  "camera": {"position": [1, 3, 0.5], "look_at": [1, 0, 0.5], "up": [0, 0, -1],
             "vertical_fov": 10, "width": 8, "height": 8},
  "render": {"background": [0, 0, 0]}})";
}

const char* kChecker = R"({"type": "checker", "scale": 1, "colour2": [0.8, 0.1, 0.1]})";

std::string loadError(const std::string& text) {
  try {
    SceneIO::parse(text, "floor.json");
  } catch (const SceneIO::LoadError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Texture, 01_CheckerCellsAlternateInAllThreeAxes) {
  Texture t;
  t.type = TextureType::Checker;
  t.scale = 0.5;
  t.colour2 = kRed;
  const Normal3 up(0, 1, 0);
  // Cube (0, 0, 0) is even; one step along any axis (either way) is odd; two are even.
  EXPECT_EQ(t.eval(kWhite, Point3(0.25, 0.25, 0.25), up), kWhite);
  EXPECT_EQ(t.eval(kWhite, Point3(0.75, 0.25, 0.25), up), kRed);
  EXPECT_EQ(t.eval(kWhite, Point3(0.25, 0.75, 0.25), up), kRed);
  EXPECT_EQ(t.eval(kWhite, Point3(0.25, 0.25, -0.25), up), kRed);
  EXPECT_EQ(t.eval(kWhite, Point3(-0.25, -0.25, 0.25), up), kWhite);
  EXPECT_EQ(t.eval(kWhite, Point3(1.25, 0.25, 0.25), up), kWhite);
  // No texture: the material's colour everywhere.
  EXPECT_EQ(Texture().eval(kWhite, Point3(0.75, 0.25, 0.25), up), kWhite);
}

TEST(Texture, 02_AFaceOnACubeBoundaryTakesOneColour) {
  // A floor at y = 0 lies on a boundary: hit points a rounding error above or below it
  // must not flip between the cubes above and below (the texel is looked up just below).
  Texture t;
  t.type = TextureType::Checker;
  t.colour2 = kRed;
  const Normal3 up(0, 1, 0);
  for (double y : {0.0, 1e-15, -1e-15, 1e-12, -1e-12})
    EXPECT_EQ(t.eval(kWhite, Point3(0.5, y, 0.5), up), kRed) << "y = " << y;
  // The same point seen as the top of a box (normal up) and as a ceiling (normal down).
  EXPECT_EQ(t.eval(kWhite, Point3(0.5, 1e-15, 0.5), -up), kWhite);
}

TEST(Texture, 03_EveryAlgorithmShadesAKnownPixelWithTheSameTexel) {
  const Scene scene = SceneIO::parse(floorScene(kChecker), "floor.json");
  // Pixel (1, 4) sees x about 0.84 (red cube), pixel (6, 4) x about 1.16 (white cube).
  // Expected value: texel / pi * 10 * cos / d^2 with d about 3 and cos about 1.
  const double direct = 10.0 / (kPi * 9.0);
  for (Algorithm a : kAllAlgorithms) {
    RenderSettings settings = scene.render;
    settings.algorithm = a;
    settings.samplesPerPixel = 1;
    const Tracer tracer(scene, settings);
    const Vec3 red = tracer.trace(1, 4, 0), white = tracer.trace(6, 4, 0);
    const char* name = algorithmInfo(a).word;
    // The hue is the texel's: red channel 8 times the green one, white grey.
    EXPECT_NEAR(red.r / red.g, 8.0, 1e-9) << name;
    EXPECT_NEAR(red.g / red.b, 1.0, 1e-9) << name;
    EXPECT_NEAR(white.r / white.g, 1.0, 1e-9) << name;
    // The brightness is the direct light of that texel, within the geometry's spread.
    EXPECT_NEAR(red.r, 0.8 * direct, 0.02 * direct) << name;
    EXPECT_NEAR(red.g, 0.1 * direct, 0.01 * direct) << name;
    EXPECT_NEAR(white.g, 0.8 * direct, 0.02 * direct) << name;
  }
}

TEST(Texture, 03b_TheTexturedImageIsTheSameWhateverTheThreadCount) {
  // Each thread shades with its own copy of the textured material: same pixels with 1 and 4.
  const Scene scene = SceneIO::parse(floorScene(kChecker), "floor.json");
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::PathTracing;
  settings.samplesPerPixel = 4;
  Renderer one(scene, settings), four(scene, settings);
  one.setThreads(1);
  four.setThreads(4);
  const FloatImage a = one.render(), b = four.render();
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  for (std::size_t i = 0; i < a.pixels.size(); ++i) EXPECT_EQ(a.pixels[i], b.pixels[i]) << i;
  // And the image holds both colours: red pixels on the left, grey ones on the right.
  const glm::vec3 left = a.pixels[4 * 8 + 1], right = a.pixels[4 * 8 + 6];
  EXPECT_GT(left.r, 4.0f * left.g);
  EXPECT_NEAR(right.r, right.g, 1e-6f);
}

TEST(Texture, 04_TheInspectorNamesTheTextureAndTheTexelAtTheHit) {
  const Scene scene = SceneIO::parse(floorScene(kChecker), "floor.json");
  RenderSettings settings = scene.render;
  settings.algorithm = Algorithm::Whitted;
  const PixelTrace red = tracePixel(scene, settings, 1, 4);
  const RayInspection r = RayInspector::inspect(scene, red.tree, 0);
  ASSERT_TRUE(r.material.has_value());
  const std::string text = rayText(r, Language::English);
  EXPECT_THAT(text, HasSubstr("checker texture (cubes of side 1, second colour (0.8, 0.1, 0.1))"));
  EXPECT_THAT(text, HasSubstr("colour here (0.8, 0.1, 0.1)"));
  EXPECT_THAT(rayText(r, Language::Chinese), HasSubstr("棋盘格纹理"));
  const PixelTrace white = tracePixel(scene, settings, 6, 4);
  EXPECT_THAT(rayText(RayInspector::inspect(scene, white.tree, 0), Language::English),
              HasSubstr("colour here (0.8, 0.8, 0.8)"));
}

TEST(Texture, 05_TheTextureRoundTripsThroughTheSceneFile) {
  const Scene scene = SceneIO::parse(
      floorScene(R"({"type": "checker", "scale": 0.25, "colour2": [0.1, 0.2, 0.3]})"),
      "floor.json");
  const Texture& t = scene.materials[0].texture;
  EXPECT_EQ(t.type, TextureType::Checker);
  EXPECT_EQ(t.scale, 0.25);
  EXPECT_EQ(t.colour2, Vec3(0.1, 0.2, 0.3));
  const std::string text = SceneIO::serialize(scene);
  EXPECT_THAT(text, HasSubstr("\"texture\""));
  const Scene back = SceneIO::parse(text, "floor.json");
  EXPECT_EQ(back.materials[0].texture, t);
  EXPECT_EQ(SceneIO::serialize(back), text);
  // Without a texture nothing is written, and the defaults fill a short form.
  EXPECT_THAT(SceneIO::serialize(SceneIO::parse(floorScene(""), "floor.json")),
              ::testing::Not(HasSubstr("texture")));
  const Scene short_ = SceneIO::parse(floorScene(R"({"type": "checker"})"), "floor.json");
  EXPECT_EQ(short_.materials[0].texture.scale, 1.0);
  EXPECT_EQ(short_.materials[0].texture.colour2, Vec3(0.1));
}

TEST(Texture, 06_BadValuesAreRefusedWithTheFileThePlaceAndTheProblem) {
  struct Case {
    const char* texture;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"type": "checker", "scale": 0})",
       "floor.json: at /materials/0/texture/scale: scale (a checker cube's side) must be "
       "positive, got 0"},
      {R"({"type": "checker", "scale": -2})",
       "at /materials/0/texture/scale: scale (a checker cube's side) must be positive, got -2"},
      {R"({"type": "checker", "scale": 1e-12})",
       "at /materials/0/texture/scale: scale (a checker cube's side) 1e-12 is below"},
      {R"({"type": "checker", "scale": "NaN"})",
       "at /materials/0/texture/scale: expected a number, got \"NaN\""},
      {R"({"type": "checker", "colour2": [0.5, 1.5, 0]})",
       "at /materials/0/texture/colour2: colour components must be in [0, 1]"},
      {R"({"type": "checker", "colour2": [0.5, -0.1, 0]})",
       "at /materials/0/texture/colour2: colour components must be in [0, 1]"},
      {R"({"type": "checker", "colour2": [0.5, 0.5]})",
       "at /materials/0/texture/colour2: expected [x, y, z]"},
      {R"({"type": "checker", "size": 1})",
       "at /materials/0/texture/size: unknown key \"size\" (expected one of type, scale, "
       "colour2)"},
      {R"({"type": "marble"})",
       "at /materials/0/texture/type: unknown texture type \"marble\" (expected checker)"},
      {R"({"scale": 1})", "at /materials/0/texture: missing \"type\""},
      {R"("checker")", "at /materials/0/texture: expected {\"type\": \"checker\""},
  };
  for (const Case& c : cases) {
    const std::string message = loadError(floorScene(c.texture));
    EXPECT_THAT(message, HasSubstr("floor.json: at /materials/0/texture")) << c.texture;
    EXPECT_THAT(message, HasSubstr(c.expected)) << c.texture;
  }
  // JSON has no NaN: the literal is refused where it stands, as everywhere in a scene file.
  EXPECT_THAT(loadError(floorScene(R"({"type": "checker", "scale": NaN})")),
              HasSubstr("JSON has no NaN or Infinity"));
}

TEST(Texture, 07_EditsSetTheTextureAndRefuseBadValues) {
  // The window and Python edit through edit::setValue: the loader's checks apply.
  const Scene plain = SceneIO::parse(floorScene(""), "floor.json");
  const Scene textured = edit::setValue(plain, "/materials/0/texture", kChecker, "floor.json");
  EXPECT_EQ(textured.materials[0].texture.colour2, kRed);
  const Scene finer = edit::setValue(textured, "/materials/0/texture/scale", "0.5", "floor.json");
  EXPECT_EQ(finer.materials[0].texture.scale, 0.5);
  try {
    edit::setValue(textured, "/materials/0/texture/scale", "-1", "floor.json");
    FAIL() << "a negative scale was taken";
  } catch (const SceneIO::LoadError& e) {
    EXPECT_THAT(e.what(), HasSubstr("floor.json: at /materials/0/texture/scale: scale"));
  }
  EXPECT_EQ(textured.materials[0].texture.scale, 1.0);
}

}  // namespace
}  // namespace raylab
