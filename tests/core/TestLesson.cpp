// Lesson files: the format, error messages that name the file, the step and the place,
// scene changes, and the shipped lessons (they load, both languages, answers computed).
#include "LessonFixture.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/PixelTrace.h"
#include "raylab/core/RayInspector.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/SceneIntersector.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Tracer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace raylab {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

/// A folder with a small scene (glass sphere, floor, quad light, point light; 320x240,
/// 4 spp) for the lessons the tests write; one folder per test, as CTest runs tests side by
/// side (a test rewriting a shared scene.json made another read it empty).
std::string fixtureDir() {
  const fs::path dir = testing::writeLessonScene({"lesson-", "lesson test", "path", true});
  return dir.string();
}

/// A valid two-step lesson on the fixture scene; the error cases break one thing in it.
json baseLesson() {
  return json::parse(R"({
    "raylab_lesson": 1,
    "id": "04-test",
    "title": {"en": "Test lesson", "zh": "测试课"},
    "summary": {"en": "A lesson for the tests.", "zh": "供测试用的一课。"},
    "scene": "scene.json",
    "defaults": {"algorithm": "whitted", "pixel": [160, 100]},
    "steps": [
      {"title": {"en": "The scene", "zh": "场景"},
       "text": {"en": "A glass ball on a floor.", "zh": "地板上有一个玻璃球。"},
       "view": "image"},
      {"title": {"en": "Snell's law", "zh": "斯涅尔定律"},
       "text": {"en": "The ray bends towards the normal.", "zh": "光线向法线方向偏折。"},
       "view": "scene", "colour": "kind", "reveal": {"depth": 2},
       "filters": {"kinds": ["camera", "refraction"], "max_depth": 3},
       "select_ray": 1,
       "scene_changes": [{"material": "glass", "set": {"ior": 1.33}},
                         {"object": "light", "translate": [0, 0.5, 0]},
                         {"render": {"next_event_estimation": false}}],
       "question": {"type": "choice",
                    "prompt": {"en": "Which way does it bend?", "zh": "光线向哪边偏折？"},
                    "choices": [{"en": "towards the normal", "zh": "靠近法线"},
                                {"en": "away from it", "zh": "远离法线"}],
                    "answer": 0,
                    "explanation": {"en": "Glass is denser.", "zh": "玻璃的光密度更大。"}},
       "teacher_notes": {"en": "Ask first.", "zh": "先提问。"}}
    ]
  })");
}

std::string fixtureOrigin() { return fixtureDir() + "/test.json"; }

std::string loadError(const json& lesson) {
  try {
    LessonIO::parse(lesson.dump(), fixtureOrigin());
  } catch (const LessonIO::LoadError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Lesson, 01_ReadsTheFormatAndInheritsTheDefaults) {
  const Lesson lesson = LessonIO::parse(baseLesson().dump(), fixtureOrigin());
  EXPECT_EQ(lesson.id, "04-test");
  EXPECT_EQ(lesson.title.in(Language::Chinese), "测试课");
  ASSERT_EQ(lesson.steps.size(), 2u);
  const LessonStep& first = lesson.steps[0];
  EXPECT_EQ(first.view, LessonView::Image);
  EXPECT_EQ(first.algorithm, Algorithm::Whitted);  // from "defaults"
  ASSERT_TRUE(first.pixelX);
  EXPECT_EQ(*first.pixelX, 160);
  EXPECT_EQ(*first.pixelY, 100);
  EXPECT_FALSE(first.question);
  EXPECT_EQ(first.scene, lesson.scene);  // no changes: the lesson's scene, shared
  const LessonStep& second = lesson.steps[1];
  EXPECT_EQ(second.view, LessonView::Scene);
  EXPECT_EQ(second.colouring, LessonColouring::Kind);
  EXPECT_EQ(second.reveal.by, LessonReveal::By::Depth);
  EXPECT_EQ(second.reveal.value, 2);
  EXPECT_EQ(second.filters.kinds, (std::vector<RayKind>{RayKind::Camera, RayKind::Refraction}));
  EXPECT_EQ(second.filters.maxDepth, 3);
  EXPECT_EQ(second.selectRay, 1);
  ASSERT_TRUE(second.question);
  EXPECT_EQ(second.question->choices.size(), 2u);
  EXPECT_EQ(second.teacherNotes.en, "Ask first.");
  EXPECT_EQ(second.sceneChanges.size(), 3u);
  EXPECT_EQ(lesson.questionCount(), 1);
  EXPECT_TRUE(lesson.requiredFeatures().empty());
}

TEST(Lesson, 02_SceneChangesApplyToTheirStepOnly) {
  const Lesson lesson = LessonIO::parse(baseLesson().dump(), fixtureOrigin());
  const Scene& before = *lesson.scene;
  const Scene& after = lesson.sceneOfStep(1);
  EXPECT_EQ(before.materials[before.findMaterial("glass")].ior, 1.5);
  EXPECT_EQ(after.materials[after.findMaterial("glass")].ior, 1.33);
  const Bounds3 lightBefore = before.objects[before.findObject("light")].shape->bounds();
  const Bounds3 lightAfter = after.objects[after.findObject("light")].shape->bounds();
  EXPECT_DOUBLE_EQ(lightAfter.lower.y - lightBefore.lower.y, 0.5);
  EXPECT_TRUE(before.render.nextEventEstimation);
  EXPECT_FALSE(after.render.nextEventEstimation);
  EXPECT_FALSE(lesson.steps[1].settings().nextEventEstimation);
  EXPECT_EQ(lesson.steps[1].settings().algorithm, Algorithm::Whitted);

  // The other kinds of change, in the scene format's own key names.
  json l = baseLesson();
  l["steps"][1]["scene_changes"] = json::parse(R"([
    {"object": "ball", "set": {"shape": {"radius": 0.5}, "velocity": [1, 0, 0]}},
    {"camera": {"aperture": 0.1, "focus_distance": 4}},
    {"point_light": "key", "translate": [1, 0, 0]},
    {"add_material": {"name": "chrome", "type": "mirror"}},
    {"add_object": {"name": "second", "material": "chrome",
                    "shape": {"type": "sphere", "centre": [2, 1, 0], "radius": 0.5}}},
    {"object": "floor", "remove": true}])");
  const Lesson changed = LessonIO::parse(l.dump(), fixtureOrigin());
  const Scene& s = changed.sceneOfStep(1);
  const auto& ball = static_cast<const Sphere&>(*s.objects[s.findObject("ball")].shape);
  EXPECT_EQ(ball.radius(), 0.5);
  EXPECT_EQ(s.objects[s.findObject("ball")].velocity, Vec3(1, 0, 0));
  EXPECT_EQ(s.camera.aperture, 0.1);
  EXPECT_EQ(s.pointLights[0].position, Point3(3, 5, 2));
  EXPECT_GE(s.findObject("second"), 0);
  EXPECT_EQ(s.findObject("floor"), -1);
  EXPECT_GE(changed.scene->findObject("floor"), 0);
}

struct ErrorCase {
  const char* name;
  std::function<void(json&)> breakIt;
  const char* expected;  ///< Text the message must contain (besides the file name).
};

TEST(Lesson, 03_ErrorsNameTheFileTheStepAndThePlace) {
  const ErrorCase cases[] = {
      {"pixel outside",
       [](json& l) {
         l["steps"][1]["pixel"] = {400, 10};
       },
       "test.json: step 2 (\"Snell's law\"): at /steps/1/pixel: pixel (400, 10) is outside "
       "the 320x240 image"},
      {"default pixel outside",
       [](json& l) {
         l["defaults"]["pixel"] = {10, 240};
       },
       "step 1 (\"The scene\"): at /defaults/pixel: pixel (10, 240) is outside the 320x240"},
      {"pixel outside after a size change",
       [](json& l) {
         l["steps"][1]["scene_changes"] = {{{"camera", {{"width", 100}}}}};
       },
       "step 2 (\"Snell's law\"): at /defaults/pixel: pixel (160, 100) is outside the "
       "100x240 image"},
      {"unknown view", [](json& l) { l["steps"][0]["view"] = "movie"; },
       "step 1 (\"The scene\"): at /steps/0/view: unknown view \"movie\" (expected scene, "
       "image, compare, plot, inspector or samples)"},
      {"unknown algorithm", [](json& l) { l["steps"][1]["algorithm"] = "photon"; },
       "at /steps/1/algorithm: unknown algorithm \"photon\""},
      {"unknown colour", [](json& l) { l["steps"][1]["colour"] = "rainbow"; },
       "at /steps/1/colour: unknown colouring \"rainbow\" (expected energy, kind or depth)"},
      {"unknown ray kind", [](json& l) { l["steps"][1]["filters"]["kinds"][1] = "bounce"; },
       "at /steps/1/filters/kinds/1: unknown ray kind \"bounce\""},
      {"no Chinese text", [](json& l) { l["steps"][1]["text"].erase("zh"); },
       "step 2 (\"Snell's law\"): at /steps/1/text: missing \"zh\" (the Chinese text)"},
      {"no English text", [](json& l) { l["steps"][0]["text"].erase("en"); },
       "at /steps/0/text: missing \"en\" (the English text)"},
      {"Chinese text in English", [](json& l) { l["steps"][0]["text"]["zh"] = "A glass ball."; },
       "at /steps/0/text/zh: the Chinese text has no Chinese characters"},
      {"no title", [](json& l) { l["steps"][0].erase("title"); },
       "step 1: at /steps/0: missing \"title\""},
      {"unknown step key",
       [](json& l) {
         l["steps"][0]["pixels"] = {1, 1};
       },
       "at /steps/0/pixels: unknown key \"pixels\""},
      {"bundle too large", [](json& l) { l["steps"][1]["bundle"] = 300; },
       "step 2 (\"Snell's law\"): at /steps/1/bundle: a bundle draws at most 256 samples of "
       "the pixel (300 asked)"},
      {"bundle in the image view", [](json& l) { l["steps"][0]["bundle"] = 8; },
       "at /steps/0/bundle: bundle and all_hits belong to the scene and inspector views (this "
       "step's view is \"image\")"},
      {"all_hits not a boolean", [](json& l) { l["steps"][1]["all_hits"] = "yes"; },
       "at /steps/1/all_hits: expected true or false"},
      {"unknown lesson key", [](json& l) { l["author"] = "me"; },
       "test.json: at /author: unknown key \"author\""},
      {"answer out of range", [](json& l) { l["steps"][1]["question"]["answer"] = 2; },
       "at /steps/1/question/answer: answer 2 is not one of the 2 choices (0..1)"},
      {"negative tolerance",
       [](json& l) {
         l["steps"][1]["question"] = json::parse(R"({"type": "number",
           "prompt": {"en": "How many?", "zh": "多少条？"}, "answer": 3, "tolerance": -1,
           "explanation": {"en": "Count.", "zh": "数一数。"}})");
       },
       "at /steps/1/question/tolerance: tolerance must not be negative"},
      {"unknown check quantity",
       [](json& l) {
         l["steps"][1]["question"] = json::parse(R"({"type": "number",
           "prompt": {"en": "How many?", "zh": "多少条？"}, "answer": 3,
           "check": {"quantity": "photons"},
           "explanation": {"en": "Count.", "zh": "数一数。"}})");
       },
       "at /steps/1/question/check/quantity: unknown quantity \"photons\""},
      {"missing scene", [](json& l) { l["scene"] = "nowhere.json"; },
       "test.json: at /scene: scene file \"nowhere.json\" not found"},
      {"scene that does not load", [](json& l) { l["scene"] = "test-broken-scene.json"; },
       "at /scene: the scene does not load: "},
      {"unknown material", [](json& l) { l["steps"][1]["scene_changes"][0]["material"] = "gold"; },
       "step 2 (\"Snell's law\"): at /steps/1/scene_changes/0/material: no material named "
       "\"gold\""},
      {"unknown object", [](json& l) { l["steps"][1]["scene_changes"][1]["object"] = "lamp"; },
       "at /steps/1/scene_changes/1/object: no object named \"lamp\""},
      {"invalid value", [](json& l) { l["steps"][1]["scene_changes"][0]["set"]["ior"] = -1; },
       "at /steps/1/scene_changes/0/set/ior: ior (index of refraction) must be positive"},
      {"unknown material key",
       [](json& l) {
         l["steps"][1]["scene_changes"][0]["set"] = {{"sheen", 0.2}};
       },
       "at /steps/1/scene_changes/0/set/sheen: unknown key \"sheen\""},
      {"invalid translate",
       [](json& l) {
         l["steps"][1]["scene_changes"][1]["translate"] = {0, "up", 0};
       },
       "at /steps/1/scene_changes/1/translate/1: expected a number"},
      {"invalid render value",
       [](json& l) {
         l["steps"][1]["scene_changes"][2]["render"] = {{"spp", 0}};
       },
       "at /steps/1/scene_changes/2/render/spp: must be at least 1"},
      {"change naming nothing",
       [](json& l) {
         l["steps"][1]["scene_changes"][2] = {{"x", 1}};
       },
       "at /steps/1/scene_changes/2: a change names what it edits"},
      {"renaming",
       [](json& l) {
         l["steps"][1]["scene_changes"][0]["set"] = {{"name", "g"}};
       },
       "at /steps/1/scene_changes/0/set/name: a step cannot rename"},
      {"ray not in the tree", [](json& l) { l["steps"][1]["select_ray"] = 5000; },
       "at /steps/1/select_ray: ray 5000 is not in the whitted tree of pixel (160, 100) "
       "sample 0"},
      {"sample beyond spp", [](json& l) { l["steps"][1]["sample"] = 4; },
       "at /steps/1/sample: sample 4 is not a sample of the pixel: the scene renders 4 "
       "samples per pixel (0..3)"},
      {"samples outside the samples view",
       [](json& l) {
         l["steps"][0]["samples"] = {{"sampler", "cosine"}};
       },
       "at /steps/0/samples: \"samples\" belongs to the samples view"},
      {"unknown sampler",
       [](json& l) {
         l["steps"][0]["view"] = "samples";
         l["steps"][0]["samples"] = {{"sampler", "gaussian"}};
       },
       "at /steps/0/samples/sampler: unknown sampler \"gaussian\" (expected cosine, uniform, "
       "sphere or phong)"},
      {"measure outside compare and plot", [](json& l) { l["steps"][0]["measure"] = "time"; },
       "at /steps/0/measure: \"measure\" belongs to the compare and plot views"},
      {"unknown measure",
       [](json& l) {
         l["steps"][0]["view"] = "compare";
         l["steps"][0]["measure"] = "money";
       },
       "at /steps/0/measure: unknown measure \"money\" (expected samples or time)"},
      {"inspector without a pixel",
       [](json& l) {
         l.erase("defaults");
         l["steps"][0]["view"] = "inspector";
       },
       "step 1 (\"The scene\"): at /steps/0: the inspector view needs a pixel"},
      {"version", [](json& l) { l["raylab_lesson"] = 2; },
       "at /raylab_lesson: unsupported version 2"},
      {"no version", [](json& l) { l.erase("raylab_lesson"); }, "missing \"raylab_lesson\""},
      {"no steps", [](json& l) { l["steps"] = json::array(); },
       "at /steps: expected a list of steps"},
  };
  std::ofstream(fs::path(fixtureDir()) / "test-broken-scene.json")
      << R"({"raylab_scene": 2, "materials": [], "objects": [{"name": "x"}]})";
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE(c.name);
    json lesson = baseLesson();
    c.breakIt(lesson);
    const std::string message = loadError(lesson);
    EXPECT_THAT(message, HasSubstr("test.json")) << message;
    EXPECT_THAT(message, HasSubstr(c.expected)) << message;
  }
}

TEST(Lesson, 04_SyntaxErrorsAndMissingFilesAreNamed) {
  try {
    LessonIO::parse("{\n  \"raylab_lesson\": 1,\n  \"steps\": [,]\n}", "broken.json");
    FAIL() << "no error";
  } catch (const LessonIO::LoadError& e) {
    EXPECT_THAT(e.what(), HasSubstr("broken.json:3:"));
  }
  try {
    LessonIO::load("/nonexistent/lessons/01-x.json");
    FAIL() << "no error";
  } catch (const LessonIO::LoadError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent/lessons/01-x.json: cannot open"));
  }
  EXPECT_THROW(LessonIO::list("/nonexistent/lessons"), LessonIO::LoadError);
}

TEST(Lesson, 05_RequiresIsAcceptedAndReported) {
  json l = baseLesson();
  l["steps"][0]["requires"] = "schlick-fresnel";
  l["steps"][1]["requires"] = {"bvh-view", "schlick-fresnel"};
  const Lesson lesson = LessonIO::parse(l.dump(), fixtureOrigin());
  EXPECT_EQ(lesson.steps[0].needs, std::vector<std::string>{"schlick-fresnel"});
  EXPECT_EQ(lesson.requiredFeatures(), (std::vector<std::string>{"schlick-fresnel", "bvh-view"}));
}

/// A lesson on the acceleration lesson's scene (a 1280-triangle mesh ball and a sphere)
/// with one scene step that draws BVH boxes.
json bvhLesson() {
  json l = baseLesson();
  l["scene"] = std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/bvh.json";
  l["defaults"] = {{"algorithm", "raycast"}};
  l["steps"][1].erase("scene_changes");
  l["steps"][1].erase("select_ray");
  l["steps"][1].erase("reveal");
  l["steps"][1]["pixel"] = {199, 110};
  l["steps"][1]["bvh"] = {{"levels", {0, 2}}};
  return l;
}

TEST(Lesson, 05b_BvhStepsNameAMeshAndLevelsItHas) {
  json l = bvhLesson();
  Lesson lesson = LessonIO::parse(l.dump(), fixtureOrigin());
  const LessonStep& step = lesson.steps[1];
  ASSERT_TRUE(step.bvh);
  EXPECT_EQ(step.bvh->object, step.scene->findObject("mesh ball"));  // the first mesh
  EXPECT_EQ(step.bvh->firstLevel, 0);
  EXPECT_EQ(step.bvh->lastLevel, 2);
  EXPECT_FALSE(step.bvh->visits);
  // The camera ray of the pixel is the first ray of its tree.
  const auto ray = step.cameraRay();
  ASSERT_TRUE(ray);
  EXPECT_EQ(ray->origin, step.scene->camera.position);
  EXPECT_FALSE(lesson.steps[0].cameraRay()) << "a step without a pixel has no camera ray";

  l["steps"][1]["bvh"] = {{"object", "mesh ball"}, {"level", 3}, {"visits", true}};
  l["steps"][1]["scene_changes"] = {{{"render", {{"bvh_split", "median"}}}}};
  lesson = LessonIO::parse(l.dump(), fixtureOrigin());
  EXPECT_EQ(lesson.steps[1].bvh->firstLevel, 3);
  EXPECT_EQ(lesson.steps[1].bvh->lastLevel, 3);
  EXPECT_TRUE(lesson.steps[1].bvh->visits);
  EXPECT_EQ(lesson.steps[1].settings().bvhSplit, BvhSettings::Split::Median);

  struct Case {
    const char* name;
    std::function<void(json&)> breakIt;
    const char* expected;
  };
  const Case cases[] = {
      {"not a mesh", [](json& s) { s["bvh"]["object"] = "sphere"; },
       "step 2 (\"Snell's law\"): at /steps/1/bvh/object: object \"sphere\" is not a mesh: "
       "only meshes have a BVH"},
      {"no such object", [](json& s) { s["bvh"]["object"] = "teapot"; },
       "at /steps/1/bvh/object: no object named \"teapot\" in the scene"},
      {"too deep",
       [](json& s) {
         s["bvh"]["levels"] = {0, 40};
       },
       "at /steps/1/bvh/levels/1: level 40 is below the deepest level of \"mesh ball\"'s BVH "
       "(sah split: levels 0.."},
      {"backwards",
       [](json& s) {
         s["bvh"]["levels"] = {2, 1};
       },
       "at /steps/1/bvh/levels: the last level (1) comes before the first (2)"},
      {"both", [](json& s) { s["bvh"]["level"] = 1; },
       "at /steps/1/bvh: give \"level\" or \"levels\", not both"},
      {"visits without pixel",
       [](json& s) {
         s.erase("pixel");
         s["bvh"]["visits"] = true;
       },
       "at /steps/1/bvh/visits: visits needs a pixel"},
      {"image view", [](json& s) { s["view"] = "image"; },
       "at /steps/1/bvh: \"bvh\" belongs to the scene view (this step's view is \"image\")"},
      {"unknown key", [](json& s) { s["bvh"]["depth"] = 2; },
       "at /steps/1/bvh/depth: unknown key \"depth\" (expected one of object, level, levels, "
       "visits)"},
      {"check on a sphere",
       [](json& s) {
         s["question"] = {{"type", "number"},
                          {"prompt", {{"en", "How many?"}, {"zh", "多少？"}}},
                          {"answer", 1},
                          {"check", {{"quantity", "bvh_nodes"}, {"object", "sphere"}}},
                          {"explanation", {{"en", "So."}, {"zh", "如此。"}}}};
       },
       "at /steps/1/question/check/object: object \"sphere\" is not a mesh"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    json broken = bvhLesson();
    c.breakIt(broken["steps"][1]);
    EXPECT_THAT(loadError(broken), HasSubstr(c.expected));
  }
  // Without a mesh in the scene there is no BVH to show.
  json noMesh = baseLesson();
  noMesh["steps"][1]["bvh"] = json::object();
  EXPECT_THAT(loadError(noMesh), HasSubstr("at /steps/1/bvh/object: the scene has no mesh object"));
}

/// The shipped lessons: lessons/NN-topic.json in the source tree.
std::vector<std::string> shippedLessons() {
  return LessonIO::list(std::string(RAYLAB_SOURCE_DIR) + "/lessons");
}

TEST(Lesson, 06_EveryShippedLessonLoads) {
  const std::vector<std::string> files = shippedLessons();
  // Issue 32 put the foundations lesson before path tracing: nine lessons.
  EXPECT_EQ(files.size(), 9u);
  std::vector<std::string> ids;
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    Lesson lesson;
    ASSERT_NO_THROW(lesson = LessonIO::load(file));
    // Issue 12: each lesson has 8 to 15 steps and at least 3 questions; issue 32 adds a
    // "change a value" step and a recap to each, and to lesson 6 MIS on and off; issue 35 a
    // bug-hunt step to lessons 4 and 7.
    EXPECT_GE(lesson.steps.size(), 8u);
    EXPECT_LE(lesson.steps.size(), 19u);
    EXPECT_GE(lesson.questionCount(), 3);
    // The id is the file's name, so lists and files agree.
    EXPECT_EQ(lesson.id, fs::path(file).stem().string());
    // Scenes come from lessons/scenes/.
    EXPECT_EQ(fs::path(lesson.scenePath).parent_path().filename(), "scenes");
    ids.push_back(lesson.id);
  }
}

TEST(Lesson, 06b_ReadTitleReadsTheTitleAloneAndNamesProblems) {
  // The title of every shipped lesson, as load() reads it (the window's Lessons menu).
  for (const std::string& file : shippedLessons()) {
    SCOPED_TRACE(file);
    const Lesson lesson = LessonIO::load(file);
    const LocalText title = LessonIO::readTitle(file);
    EXPECT_EQ(title.en, lesson.title.en);
    EXPECT_EQ(title.zh, lesson.title.zh);
  }
  // Neither the steps nor the scene are read: a lesson whose scene is missing still has a
  // title, while load() refuses it.
  const fs::path dir = fixtureDir();
  json lesson = baseLesson();
  lesson["scene"] = "no-such-scene.json";
  std::ofstream(dir / "05-no-scene.json") << lesson.dump();
  EXPECT_EQ(LessonIO::readTitle((dir / "05-no-scene.json").string()).en, "Test lesson");
  EXPECT_THROW(LessonIO::load((dir / "05-no-scene.json").string()), LessonIO::LoadError);
  // The version and the title are checked, with the file and the place named.
  const auto titleError = [&dir](const json& j) {
    std::ofstream(dir / "06-bad.json") << j.dump();
    try {
      LessonIO::readTitle((dir / "06-bad.json").string());
    } catch (const LessonIO::LoadError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  json badVersion = baseLesson();
  badVersion["raylab_lesson"] = 7;
  EXPECT_THAT(titleError(badVersion), HasSubstr("06-bad.json: at /raylab_lesson: unsupported"));
  json noChinese = baseLesson();
  noChinese["title"].erase("zh");
  EXPECT_THAT(titleError(noChinese), HasSubstr("06-bad.json: at /title: missing \"zh\""));
  EXPECT_THROW(LessonIO::readTitle("/nonexistent/lessons/01-x.json"), LessonIO::LoadError);
}

/// Every text of a lesson, with where it is, for the language checks.
std::vector<std::pair<std::string, const LocalText*>> textsOf(const Lesson& lesson) {
  std::vector<std::pair<std::string, const LocalText*>> texts = {{"title", &lesson.title},
                                                                 {"summary", &lesson.summary}};
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const LessonStep& s = lesson.steps[i];
    const std::string at = "step " + std::to_string(i + 1) + " ";
    texts.push_back({at + "title", &s.title});
    texts.push_back({at + "text", &s.text});
    if (!s.teacherNotes.empty()) texts.push_back({at + "teacher notes", &s.teacherNotes});
    if (s.question) {
      texts.push_back({at + "prompt", &s.question->prompt});
      texts.push_back({at + "explanation", &s.question->explanation});
      for (const LocalText& c : s.question->choices) texts.push_back({at + "choice", &c});
    }
  }
  return texts;
}

TEST(Lesson, 07_EveryStepHasBothLanguages) {
  for (const std::string& file : shippedLessons()) {
    const Lesson lesson = LessonIO::load(file);
    for (const auto& [where, text] : textsOf(lesson)) {
      SCOPED_TRACE(file + " " + where);
      EXPECT_FALSE(text->en.empty());
      EXPECT_FALSE(text->zh.empty());
      // A Chinese text is not a copy of the English one.
      EXPECT_TRUE(text->en != text->zh ||
                  text->en.find_first_not_of("0123456789.,-+ ") == std::string::npos)
          << text->en;
    }
  }
}

TEST(Lesson, 08_ComputedAnswersMatchTheProgram) {
  int checked = 0;
  for (const std::string& file : shippedLessons()) {
    const Lesson lesson = LessonIO::load(file);
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
      const LessonStep& step = lesson.steps[i];
      if (!step.question || !step.question->check) continue;
      SCOPED_TRACE(file + " step " + std::to_string(i + 1) + " (" + step.title.en + ")");
      // Numbers and what a ray reaches (a choice's "value") alike.
      try {
        EXPECT_EQ(answerProblem(step), std::nullopt);
      } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        continue;
      }
      ++checked;
    }
  }
  // The lessons ask computed questions, not only typed ones.
  EXPECT_GE(checked, 8);
}

// The samples view's point cloud: unit directions with the sampler's density. Cosine-
// weighted directions have mean cos(theta) = integral of cos * cos / pi = 2/3; uniform
// ones over the hemisphere 1/2; over the sphere the mean z is 0. The standard error of
// the mean of 4000 values with variance <= 1/12 is <= 0.0046: 0.02 is > 4 of them.
TEST(Lesson, 10_SamplesViewDirectionsHaveTheSamplersDensity) {
  const auto meanZ = [](LessonSamples::Sampler sampler, double* minZ) {
    LessonSamples samples;
    samples.sampler = sampler;
    samples.count = 4000;
    const std::vector<Vec3> d = samples.directions();
    EXPECT_EQ(d.size(), 4000u);
    double sum = 0.0;
    *minZ = 1.0;
    for (const Vec3& v : d) {
      EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
      sum += v.z;
      *minZ = std::min(*minZ, v.z);
    }
    EXPECT_EQ(samples.directions(), d);  // the same cloud every time
    return sum / double(d.size());
  };
  double minZ = 0.0;
  EXPECT_NEAR(meanZ(LessonSamples::Sampler::Cosine, &minZ), 2.0 / 3.0, 0.02);
  EXPECT_GE(minZ, 0.0);
  EXPECT_NEAR(meanZ(LessonSamples::Sampler::Uniform, &minZ), 0.5, 0.02);
  EXPECT_GE(minZ, 0.0);
  EXPECT_NEAR(meanZ(LessonSamples::Sampler::Sphere, &minZ), 0.0, 0.04);
  EXPECT_LT(minZ, -0.9);
}

// A bundle and all_hits are read for the scene view with a pixel; without a pixel they
// are refused.
TEST(Lesson, 11_BundleAndAllHitsNeedAPixel) {
  json l = baseLesson();
  l["steps"][1]["bundle"] = 16;
  l["steps"][1]["all_hits"] = true;
  const Lesson lesson = LessonIO::parse(l.dump(), fixtureOrigin());
  EXPECT_EQ(lesson.steps[1].bundle, 16);
  EXPECT_TRUE(lesson.steps[1].allHits);
  EXPECT_EQ(lesson.steps[0].bundle, 1);
  EXPECT_FALSE(lesson.steps[0].allHits);

  l = baseLesson();
  l["defaults"].erase("pixel");
  l["steps"][1].erase("select_ray");
  l["steps"][1].erase("reveal");
  l["steps"][1]["bundle"] = 4;
  EXPECT_THAT(loadError(l), HasSubstr("at /steps/1/bundle: bundle needs a pixel"));
}

// "close_up" without a BVH mesh looks at the hit of the step's traced ray (lesson 4's
// refraction and total internal reflection), so it needs a pixel or a chosen ray.
TEST(Lesson, 11b_CloseUpNeedsABvhMeshOrATracedRay) {
  json l = baseLesson();
  l["steps"][1]["camera_view"] = "close_up";
  const Lesson lesson = LessonIO::parse(l.dump(), fixtureOrigin());
  EXPECT_EQ(lesson.steps[1].cameraView, LessonCameraView::CloseUp);
  EXPECT_FALSE(lesson.steps[1].bvh);

  l["defaults"].erase("pixel");
  l["steps"][1].erase("select_ray");
  l["steps"][1].erase("reveal");
  EXPECT_THAT(loadError(l), HasSubstr("at /steps/1/camera_view: the close_up view looks at the "
                                      "step's BVH mesh or at the hit of its traced ray: it needs "
                                      "a \"bvh\" block, a \"pixel\" or a \"ray\""));
  l["steps"][1]["ray"] = {{"origin", {0, 1, 5}}, {"direction", {0, 0, -1}}};
  EXPECT_EQ(LessonIO::parse(l.dump(), fixtureOrigin()).steps[1].cameraView,
            LessonCameraView::CloseUp);
}

// A step may name a scene file of its own (lesson 6's glossy plates under four lights): its
// scene changes edit that scene, and the steps after it go back to the lesson's scene.
TEST(Lesson, 11c_AStepMayShowAnotherScene) {
  const std::string dir = fixtureDir();
  std::ofstream(dir + "/other.json") << R"({
    "raylab_scene": 2, "name": "other",
    "materials": [{"name": "white"}, {"name": "lamp", "emission": [5, 5, 5]}],
    "objects": [{"name": "plate", "material": "white",
                 "shape": {"type": "quad", "corner": [-1, 0, 1], "u": [2, 0, 0], "v": [0, 0, -2]}},
                {"name": "bulb", "material": "lamp",
                 "shape": {"type": "sphere", "centre": [0, 2, 0], "radius": 0.5}}],
    "camera": {"position": [0, 1, 4], "look_at": [0, 0, 0], "width": 320, "height": 200}})";
  json l = baseLesson();
  l["steps"][0]["scene"] = "other.json";
  l["steps"][0]["scene_changes"] = {{{"render", {{"multiple_importance", false}}}}};
  const Lesson lesson = LessonIO::parse(l.dump(), fixtureOrigin());
  EXPECT_EQ(lesson.steps[0].scene->name, "other");
  EXPECT_EQ(lesson.steps[0].scene->camera.height, 200);
  EXPECT_FALSE(lesson.steps[0].settings().multipleImportance);
  EXPECT_EQ(lesson.steps[1].scene->name, "lesson test");
  EXPECT_EQ(lesson.scene->name, "lesson test");

  l["steps"][0]["scene"] = "missing.json";
  EXPECT_THAT(loadError(l), HasSubstr("at /steps/0/scene: scene file \"missing.json\" not found"));
  l["steps"][0]["scene"] = "other.json";
  l["steps"][0]["scene_changes"] = {{{"object", "ball"}, {"remove", true}}};  // not in other.json
  EXPECT_THAT(loadError(l), HasSubstr("at /steps/0/scene_changes/0"));
}

// A chosen "ray" is traced in place of the pixel's camera ray: the tree's root is that
// ray, the rest of the tree is the real algorithm's, and the trace is deterministic. A step
// with a ray needs no pixel; a bundle of a ray, or a ray in an image step, is refused.
TEST(Lesson, 12_ChosenRayIsTracedInPlaceOfTheCameraRay) {
  json l = baseLesson();
  l["steps"][1]["ray"] = {{"origin", {0, 1, 5}}, {"direction", {0, 0, -2}}};
  l["steps"][1]["view"] = "inspector";
  l["steps"][1]["exactness"] = true;
  l["steps"][1].erase("reveal");
  l["steps"][1]["select_ray"] = 1;
  const Lesson lesson = LessonIO::parse(l.dump(), fixtureOrigin());
  const LessonStep& step = lesson.steps[1];
  ASSERT_TRUE(step.ray);
  EXPECT_TRUE(step.exactness);
  const PixelTrace trace = step.trace();
  ASSERT_TRUE(trace.root);
  const RaySegment& root = trace.tree.segments.at(0);
  EXPECT_EQ(root.origin, Point3(0, 1, 5));
  EXPECT_EQ(root.direction, Vec3(0, 0, -1));  // normalised
  // Straight at the glass ball's centre: it meets the front at t = 4 and Whitted splits it.
  ASSERT_TRUE(root.hit);
  EXPECT_NEAR(glm::length(root.endPoint - root.origin), 4.0, 1e-12);
  std::vector<RayKind> kinds;
  for (int c = 0; c < root.childCount; ++c)
    kinds.push_back(trace.tree.segments.at(std::size_t(root.firstChild + c)).kind);
  EXPECT_THAT(kinds, ::testing::IsSupersetOf({RayKind::Reflection, RayKind::Refraction}));
  // Not the pixel's own camera ray, and the same tree every time.
  const RayTree own = tracePixel(*step.scene, step.settings(), 160, 100, 0).tree;
  EXPECT_NE(own.segments.at(0).direction, root.direction);
  const PixelTrace again = step.trace();
  ASSERT_EQ(again.tree.segments.size(), trace.tree.segments.size());
  for (std::size_t i = 0; i < trace.tree.segments.size(); ++i) {
    EXPECT_EQ(again.tree.segments[i].endPoint, trace.tree.segments[i].endPoint);
    EXPECT_EQ(again.tree.segments[i].radiance, trace.tree.segments[i].radiance);
  }
  EXPECT_EQ(step.cameraRay()->direction, Vec3(0, 0, -1));

  // Without any pixel the chosen ray still makes a tree for the inspector.
  l["defaults"].erase("pixel");
  l["steps"][0].erase("reveal");
  EXPECT_NO_THROW(LessonIO::parse(l.dump(), fixtureOrigin()));

  json bad = l;
  bad["steps"][1]["ray"]["direction"] = {0, 0, 0};
  EXPECT_THAT(loadError(bad),
              HasSubstr("at /steps/1/ray/direction: the direction must not be zero"));
  bad = l;
  bad["steps"][1]["ray"]["origin"] = {0, 1e13, 0};
  EXPECT_THAT(loadError(bad), HasSubstr("at /steps/1/ray/origin/1: coordinates are at most 1e12"));
  bad = l;
  bad["steps"][1]["ray"]["towards"] = {0, 0, 1};
  EXPECT_THAT(loadError(bad), HasSubstr("at /steps/1/ray/towards: unknown key \"towards\""));
  bad = l;
  bad["steps"][1]["select_ray"] = 5000;
  EXPECT_THAT(loadError(bad), HasSubstr("ray 5000 is not in the whitted tree of the chosen ray: "
                                        "it has"));
  bad = l;
  bad["steps"][1]["view"] = "image";
  bad["steps"][1].erase("select_ray");
  bad["steps"][1].erase("exactness");
  EXPECT_THAT(loadError(bad), HasSubstr("at /steps/1/ray: \"ray\" belongs to the scene and"));
  bad = l;
  bad["steps"][1]["view"] = "scene";
  bad["steps"][1].erase("select_ray");
  EXPECT_THAT(loadError(bad), HasSubstr("at /steps/1/exactness: \"exactness\" belongs to the "
                                        "inspector view"));
}

// Lesson 2's tangent and knife-edge steps say what the oracle finds: the first chosen ray
// is exactly tangent (double precision agrees on t = 5), the second misses in exact
// arithmetic while double precision hits. Their words would be wrong otherwise.
TEST(Lesson, 13_LessonTwoTangentRaysAreWhatTheTextSays) {
  const Lesson lesson = LessonIO::load(std::string(RAYLAB_SOURCE_DIR) +
                                       "/lessons/02-intersections-and-exactness.json");
  const auto find = [&](const std::string& title) -> const LessonStep& {
    for (const LessonStep& s : lesson.steps)
      if (s.title.en == title) return s;
    throw std::runtime_error("no step " + title);
  };
  const auto oracleOf = [](const LessonStep& step) {
    EXPECT_TRUE(step.exactness);
    const PixelTrace trace = step.trace();
    return *RayInspector::inspect(*step.scene, trace.tree, 0).oracle;
  };
  const OracleCheck tangent = oracleOf(find("A tangent ray"));
  EXPECT_EQ(tangent.comparison.exact.classification, ExactClass::Tangent);
  EXPECT_EQ(tangent.comparison.exact.t, 5.0);
  ASSERT_TRUE(tangent.comparison.floating);
  EXPECT_EQ(tangent.comparison.floating->t, 5.0);
  EXPECT_FALSE(tangent.agrees);  // flagged all the same

  const OracleCheck knife = oracleOf(find("On the knife edge"));
  EXPECT_EQ(knife.comparison.exact.classification, ExactClass::Miss);
  ASSERT_TRUE(knife.comparison.floating);  // double precision hits
  EXPECT_NEAR(knife.comparison.floating->t, 8.6, 0.05);
  EXPECT_LT(knife.comparison.exact.margin, 0.0);
  EXPECT_GT(knife.comparison.exact.margin, -1e-17);  // "-7 x 10^-18"
  EXPECT_FALSE(knife.agrees);
}

TEST(Lesson, 09_ListFindsNumberedLessonFilesInOrder) {
  const fs::path dir = fs::path(RAYLAB_TEMP_DIR) / "lesson-list";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const char* name : {"02-b.json", "01-a.json", "notes.json", "1-short.json", "03-c.txt"})
    std::ofstream(dir / name) << "{}";
  const std::vector<std::string> files = LessonIO::list(dir.string());
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(fs::path(files[0]).filename(), "01-a.json");
  EXPECT_EQ(fs::path(files[1]).filename(), "02-b.json");
}

}  // namespace
}  // namespace raylab
