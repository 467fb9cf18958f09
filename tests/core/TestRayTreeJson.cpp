// Ray tree dumps: every RaySegment field round-trips bit for bit under its documented
// name, the header names the pixel, sample, algorithm and objects, and bad documents and
// unwritable files give errors naming the place.
#include "raylab/core/RayTreeJson.h"
#include "raylab/core/RayWords.h"

#include "TransportScenes.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace raylab {
namespace {

using testing::allMaterialsScene;
using testing::settingsFor;

/// A tree with every field set to a distinct, non-round value (doubles that need all 17
/// digits), every kind and every end reason.
RayTree handMadeTree() {
  RayTree tree;
  tree.pixelX = 7;
  tree.pixelY = 3;
  tree.sample = 5;
  tree.truncated = true;
  tree.stop = TreeStop{StopCause::Budget, 9, 9 * sizeof(RaySegment), 9};
  for (int i = 0; i < 9; ++i) {
    RaySegment s;
    s.id = i;
    s.parent = i == 0 ? -1 : (i - 1) / 2;
    s.firstChild = 2 * i + 1 < 9 ? 2 * i + 1 : -1;
    s.childCount = 2 * i + 1 < 9 ? 2 : 0;
    s.kind = RayKind(i % kRayKindCount);
    s.depth = i / 2;
    const double x = 0.1 * i + 1.0 / 3.0;
    s.origin = Point3(x, -x, 2.0 * x);
    s.direction = glm::normalize(Vec3(1.0, x, -0.7));
    s.time = x / 7.0;
    s.hit = i % 2 == 0;
    s.endPoint = Point3(x + 1e-9, 3.0, -x / 9.0);
    s.lightPoint = Point3(-x, 6.0, x * x);
    s.object = i % 3 - 1;
    s.normal = glm::normalize(Vec3(-x, 1.0, 0.25));
    s.weight = Vec3(0.5 + x, 1.0 / (x + 3.0), 1e-7 * x);
    s.pdf = 1.0 / (3.0 + x);
    s.throughput = Vec3(x, x * x, 1.0 / 7.0);
    s.emitted = Vec3(1e-300 * x, 0.0, 12.0 / 7.0);
    s.radiance = Vec3(3.0 / 11.0, x, 0.0);
    s.endReason = EndReason(i);
    tree.segments.push_back(s);
  }
  return tree;
}

void expectSameVec(const Vec3& a, const Vec3& b, const std::string& what) {
  EXPECT_EQ(a.x, b.x) << what;
  EXPECT_EQ(a.y, b.y) << what;
  EXPECT_EQ(a.z, b.z) << what;
}

TEST(RayTreeJson, 01_EveryFieldRoundTripsExactly) {
  const Scene scene = allMaterialsScene();
  const RayTree tree = handMadeTree();
  RayTreeJson::Info info;
  const RayTree back = RayTreeJson::parse(
      RayTreeJson::serialize(tree, scene, settingsFor(Algorithm::Whitted, 1)), "dump", &info);
  EXPECT_EQ(back.pixelX, 7);
  EXPECT_EQ(back.pixelY, 3);
  EXPECT_EQ(back.sample, 5);
  EXPECT_TRUE(back.truncated);
  // The stop's words are written for people, in English from the phrase table; not read.
  const nlohmann::json doc = nlohmann::json::parse(
      RayTreeJson::serialize(tree, scene, settingsFor(Algorithm::Whitted, 1)));
  EXPECT_EQ(doc.at("message").get<std::string>(), stopWords(tree.stop, Language::English));
  EXPECT_EQ(
      doc.at("message").get<std::string>().rfind("ray budget reached: the tree stops at 9 rays", 0),
      0u);
  ASSERT_EQ(back.segments.size(), tree.segments.size());
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const RaySegment& a = tree.segments[i];
    const RaySegment& b = back.segments[i];
    const std::string at = "segment " + std::to_string(i);
    EXPECT_EQ(a.id, b.id) << at;
    EXPECT_EQ(a.parent, b.parent) << at;
    EXPECT_EQ(a.firstChild, b.firstChild) << at;
    EXPECT_EQ(a.childCount, b.childCount) << at;
    EXPECT_EQ(a.kind, b.kind) << at;
    EXPECT_EQ(a.depth, b.depth) << at;
    expectSameVec(a.origin, b.origin, at + " origin");
    expectSameVec(a.direction, b.direction, at + " direction");
    EXPECT_EQ(a.time, b.time) << at;
    EXPECT_EQ(a.hit, b.hit) << at;
    expectSameVec(a.endPoint, b.endPoint, at + " endPoint");
    expectSameVec(a.lightPoint, b.lightPoint, at + " lightPoint");
    EXPECT_EQ(a.object, b.object) << at;
    expectSameVec(a.normal, b.normal, at + " normal");
    expectSameVec(a.weight, b.weight, at + " weight");
    EXPECT_EQ(a.pdf, b.pdf) << at;
    expectSameVec(a.throughput, b.throughput, at + " throughput");
    expectSameVec(a.emitted, b.emitted, at + " emitted");
    expectSameVec(a.radiance, b.radiance, at + " radiance");
    EXPECT_EQ(a.endReason, b.endReason) << at;
  }
  EXPECT_EQ(info.algorithm, "whitted");
  EXPECT_EQ(info.scene, "all materials");
  EXPECT_EQ(info.seed, 1u);
  expectSameVec(info.estimate, tree.estimate(), "estimate");
  // Object -1 has no name; others are the scene's names.
  ASSERT_EQ(info.objectNames.size(), tree.segments.size());
  EXPECT_EQ(info.objectNames[0], "");
  EXPECT_EQ(info.objectNames[1], scene.objects[0].name);
  EXPECT_EQ(info.objectNames[2], scene.objects[1].name);
}

TEST(RayTreeJson, 02_FieldNamesAndWords) {
  const Scene scene = allMaterialsScene();
  const RayTree tree = handMadeTree();
  const auto doc = nlohmann::json::parse(
      RayTreeJson::serialize(tree, scene, settingsFor(Algorithm::PathTracing, 1)));
  EXPECT_EQ(doc.at("raylab_ray_tree"), 1);
  EXPECT_EQ(doc.at("algorithm"), "path");
  EXPECT_EQ(doc.at("pixel"), nlohmann::json::array({7, 3}));
  EXPECT_EQ(doc.at("sample"), 5);
  EXPECT_EQ(doc.at("rays"), 9);
  // Kinds cycle camera..shadow over the 9 segments: camera, reflection, refraction twice.
  EXPECT_EQ(doc.at("rays_by_kind").at("camera"), 2);
  EXPECT_EQ(doc.at("rays_by_kind").at("refraction"), 2);
  EXPECT_EQ(doc.at("rays_by_kind").at("shadow"), 1);
  const auto& s = doc.at("segments").at(8);
  for (const char* key :
       {"id",      "parent",      "first_child", "child_count", "kind",      "depth",
        "origin",  "direction",   "time",        "hit",         "end_point", "light_point",
        "object",  "object_name", "normal",      "weight",      "pdf",       "throughput",
        "emitted", "radiance",    "end_reason"})
    EXPECT_TRUE(s.contains(key)) << "segment field " << key;
  EXPECT_EQ(s.size(), 21u) << "a field was added: document it and test it";
  EXPECT_EQ(s.at("kind"), "refraction");
  EXPECT_EQ(s.at("end_reason"), "spawned");
  EXPECT_EQ(doc.at("segments").at(4).at("end_reason"), "russian_roulette");
  EXPECT_EQ(doc.at("segments").at(7).at("end_reason"), "reached_light");
  EXPECT_EQ(s.at("origin").size(), 3u);
}

TEST(RayTreeJson, 03_ARecordedTreeRoundTripsWithItsEstimate) {
  const Scene scene = allMaterialsScene();
  const RenderSettings settings = settingsFor(Algorithm::PathTracing, 4);
  const Tracer tracer(scene, settings);
  Stepper stepper(tracer, 8, 6, 1);
  stepper.runToEnd();
  const RayTree& tree = stepper.tree();
  ASSERT_GT(tree.segments.size(), 2u);
  RayTreeJson::Info info;
  RayTree back = RayTreeJson::parse(RayTreeJson::serialize(tree, scene, settings), "t", &info);
  ASSERT_EQ(back.segments.size(), tree.segments.size());
  expectSameVec(info.estimate, tree.estimate(), "estimate in the header");
  // The propagated radiance read back gives the same estimate, and propagating again too.
  expectSameVec(back.estimate(), tree.estimate(), "estimate of the read tree");
  back.propagate();
  expectSameVec(back.estimate(), tree.estimate(), "estimate after propagating again");
}

TEST(RayTreeJson, 04_SaveIsAtomicAndErrorsNameThePlace) {
  const Scene scene = allMaterialsScene();
  const RenderSettings settings = settingsFor(Algorithm::Whitted, 1);
  const RayTree tree = handMadeTree();
  const auto dir = std::filesystem::temp_directory_path() / "raylab_TestRayTreeJson";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "tree.json").string();
  RayTreeJson::save(tree, scene, settings, path);
  EXPECT_EQ(RayTreeJson::load(path).segments.size(), tree.segments.size());
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename(), "tree.json") << "a temporary file was left behind";

  const std::string missing = (dir / "no-such-folder" / "tree.json").string();
  try {
    RayTreeJson::save(tree, scene, settings, missing);
    ADD_FAILURE() << "saving into a missing folder should throw";
  } catch (const RayTreeJson::Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_THROW(RayTreeJson::parse("{\"x\": 1}", "x.json"), RayTreeJson::Error);
  try {
    std::string text = RayTreeJson::serialize(tree, scene, settings);
    text.replace(text.find("\"reached_light\""), 15, "\"bounced_away\"");
    RayTreeJson::parse(text, "bad.json");
    ADD_FAILURE() << "an unknown end reason should throw";
  } catch (const RayTreeJson::Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json: /segments/7/end_reason"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

// Issue 14 (fuzzing the reader): a dump whose links are not a tree the engine makes was
// read as is, and RayTree::propagate then indexed outside the segments; a number too
// large for a double escaped as nlohmann's exception; /dev/zero read without end. Each is
// now a RayTreeJson::Error naming the file and the segment.
TEST(RayTreeJson, 05_BrokenTreesAndFilesAreRefused) {
  const Scene scene = allMaterialsScene();
  const std::string good =
      RayTreeJson::serialize(handMadeTree(), scene, settingsFor(Algorithm::Whitted, 1));
  const auto messageOf = [](const std::string& text) -> std::string {
    try {
      RayTree tree = RayTreeJson::parse(text, "t.json");
      tree.propagate();
      return "";
    } catch (const RayTreeJson::Error& e) {
      return e.what();
    }
  };
  ASSERT_EQ(messageOf(good), "");
  struct Case {
    const char* what;
    int segment;
    const char* key;
    int value;
    const char* expected;
  };
  const Case cases[] = {
      {"children past the end", 3, "first_child", 8,
       "t.json: /segments/3: children 8..9 are not later rays of the tree"},
      {"children before the ray", 2, "first_child", 1,
       "t.json: /segments/2: children 1..2 are not later rays"},
      {"negative child count", 4, "child_count", -3,
       "t.json: /segments/4: child_count is negative"},
      {"id not its index", 5, "id", 6, "t.json: /segments/5: id 6 is not its index"},
      {"parent after the ray", 4, "parent", 7,
       "t.json: /segments/4: parent 7 is not an earlier ray"},
      {"camera ray with a parent", 0, "parent", 0,
       "t.json: /segments/0: parent 0 (the camera ray has none: -1)"},
      {"child of another ray", 4, "parent", 0,
       "t.json: /segments/4: parent is not ray 1, which lists it"},
      {"huge first child", 1, "first_child", 2147483647,
       "t.json: /segments/1: children 2147483647..2147483648"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    nlohmann::json doc = nlohmann::json::parse(good);
    doc["segments"][std::size_t(c.segment)][c.key] = c.value;
    EXPECT_EQ(messageOf(doc.dump()).rfind(c.expected, 0), 0u) << messageOf(doc.dump());
  }
  // Integers that are fractions or out of range (FuzzRayTree found an id of -6.67e33, which
  // nlohmann's get<int> cast to int: undefined behaviour) are refused with their place.
  const std::pair<std::string, std::string> numbers[] = {
      {"/segments/2/id",
       "t.json: /segments/2/id must be a whole number in range, got -6.66667e+33"},
      {"/segments/1/depth", "t.json: /segments/1/depth must be a whole number in range, got 1.5"},
      {"/segments/3/parent",
       "t.json: /segments/3/parent must be a whole number in range, got 4294967298"},
      {"/sample", "t.json: /sample must be a whole number in range, got 1e+40"},
      {"/raylab_ray_tree", "t.json: /raylab_ray_tree must be a whole number in range, got 2.5"},
      {"/seed", "t.json: /seed must be a whole number in range, got -1"},
      {"/pixel/0", "t.json: /pixel must be two whole numbers, got an array of 2 values"},
  };
  const nlohmann::json values[] = {-6.66667e33, 1.5, 4294967298ll, 1e40, 2.5, -1, 3e30};
  for (std::size_t k = 0; k < std::size(numbers); ++k) {
    SCOPED_TRACE(numbers[k].first);
    nlohmann::json doc = nlohmann::json::parse(good);
    doc[nlohmann::json::json_pointer(numbers[k].first)] = values[k];
    EXPECT_EQ(messageOf(doc.dump()), numbers[k].second);
  }
  std::string huge = good;
  huge.replace(huge.find("\"time\": "), 8, "\"time\": 1e999, \"x\": ");
  EXPECT_EQ(messageOf(huge).rfind("t.json: not JSON (", 0), 0u) << messageOf(huge);
  // Only regular files: a device or a folder is named, never read without end.
  for (const std::string& path : {std::string("/dev/zero"), std::string(RAYLAB_TEST_DATA_DIR)}) {
    try {
      RayTreeJson::load(path);
      ADD_FAILURE() << path << " should be refused";
    } catch (const RayTreeJson::Error& e) {
      EXPECT_EQ(std::string(e.what()),
                path + ": cannot read ray tree file: not a regular file (a folder or a device?)");
    }
  }
}

}  // namespace
}  // namespace raylab
