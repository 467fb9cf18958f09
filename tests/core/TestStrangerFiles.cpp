// Files from strangers (issue 38): each finding's reproduction, or a smaller one, against
// the core: message excerpts cut inside a UTF-8 character, thread counts, an ior the
// tracers cannot take, the exact oracle with NaN, the lesson budget, PFM headers, the
// reference cache's damaged and forged entries, folders and files written whole, and
// lesson text in a Markdown handout.
#include "raylab/core/AtomicFile.h"
#include "raylab/core/AtomicFolder.h"
#include "raylab/core/Comparison.h"
#include "raylab/core/ExactOracle.h"
#include "raylab/core/Image.h"
#include "raylab/core/Lesson.h"
#include "raylab/core/Limits.h"
#include "raylab/core/MeshIO.h"
#include "raylab/core/ReferenceCache.h"
#include "raylab/core/Renderer.h"
#include "raylab/core/SceneEdit.h"
#include "raylab/core/SceneIO.h"
#include "raylab/core/Sphere.h"
#include "raylab/core/Text.h"
#include "raylab/core/TriangleMesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

/// A fresh folder for one test (CTest runs tests side by side), emptied first.
fs::path testDir() {
  const fs::path dir =
      fs::path(RAYLAB_TEMP_DIR) /
      ("stranger-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// The message of what `load` throws (derived from raylab::Exception), or "" when nothing.
template <class F>
std::string errorOf(F&& load) {
  try {
    load();
  } catch (const Exception& e) {
    return e.what();
  }
  return {};
}

const char* kScene = R"({
  "raylab_scene": 2,
  "materials": [{"name": "white", "colour": [0.7, 0.7, 0.7]},
                {"name": "lamp", "emission": [10, 10, 10]}],
  "objects": [
    {"name": "ball", "material": "white",
     "shape": {"type": "sphere", "centre": [0, 1, 0], "radius": 1}},
    {"name": "light", "material": "lamp",
     "shape": {"type": "quad", "corner": [-1, 4, 1], "u": [2, 0, 0], "v": [0, 0, -2]}}],
  "camera": {"position": [0, 1.5, 5], "look_at": [0, 1, 0], "width": 32, "height": 24},
  "render": {"algorithm": "path", "spp": 4, "max_depth": 5}
})";

TEST(StrangerFiles, 01_AnExcerptIsNeverCutInsideACharacter) {
  // Finding 1: 59 'a' then 中文 as the camera's width; the excerpt's 60 bytes ended in the
  // middle of 中, and dump() threw "incomplete UTF-8 string" (exit 3, no file named).
  json scene = json::parse(kScene);
  scene["camera"]["width"] = std::string(59, 'a') + "中文";
  const std::string message = errorOf([&] { SceneIO::parse(scene.dump(), "s.json"); });
  EXPECT_THAT(message, HasSubstr("s.json: at /camera/width: expected an integer, got \"" +
                                 std::string(59, 'a') + "\"..."));
  // The prefix keeps whole characters only: 60 bytes of "aaa…中" are the 59 a's.
  EXPECT_EQ(utf8Prefix(std::string(59, 'a') + "中文", 60), std::string(59, 'a'));
  EXPECT_EQ(utf8Prefix(std::string(57, 'a') + "中文", 60), std::string(57, 'a') + "中");
  EXPECT_EQ(utf8Prefix("short", 60), "short");
}

TEST(StrangerFiles, 02_AnIorTheTracersCannotTakeIsRefusedWithItsPlace) {
  // Finding 3: an ior of 1e20 on a mirror aborted in Ray.h's check; refused by the loader.
  for (const char* type : {"mirror", "phong", "blinn_phong", "dielectric"}) {
    json scene = json::parse(kScene);
    scene["materials"][0]["type"] = type;
    scene["materials"][0]["ior"] = 1e20;
    EXPECT_THAT(
        errorOf([&] { SceneIO::parse(scene.dump(), "s.json"); }),
        HasSubstr("s.json: at /materials/0/ior: ior 1e+20 is outside [0.01, 100] (real media"))
        << type;
    scene["materials"][0]["ior"] = 1.5;
    scene["materials"][0]["ior_outside"] = 0.001;
    EXPECT_THAT(errorOf([&] { SceneIO::parse(scene.dump(), "s.json"); }),
                HasSubstr("at /materials/0/ior_outside: ior_outside 0.001 is outside"))
        << type;
  }
}

TEST(StrangerFiles, 03_ARenderSurvivesThreadsTheSystemCannotCreate) {
  // Finding 2: under a 4 GB address-space limit, 600 threads failed to start and the vector
  // of joinable threads was destroyed (std::terminate). Here the limit leaves room for a
  // few of the 256 threads' 8 MiB stacks: the render completes with the threads it got,
  // with the pixels of a one-thread render.
  Scene scene = SceneIO::parse(kScene, "s.json");
  scene.camera.width = 256;
  scene.camera.height = 256;  // 256 tiles: all 256 threads would have work
  RenderSettings settings = scene.render;
  settings.samplesPerPixel = 1;
  settings.algorithm = Algorithm::RayCasting;
  Renderer one(scene, settings);
  one.setThreads(1);
  const FloatImage expected = one.render();

  std::ifstream status("/proc/self/status");
  std::string line;
  long vmKiB = 0;
  while (std::getline(status, line))
    if (line.rfind("VmSize:", 0) == 0) vmKiB = std::stol(line.substr(7));
  ASSERT_GT(vmKiB, 0);
  const rlim_t limit = rlim_t(vmKiB + 256 * 1024) * 1024;  // 256 MiB more than now
  rlimit before{};
  ASSERT_EQ(::getrlimit(RLIMIT_AS, &before), 0);
  const rlimit as{limit, before.rlim_max};
  ASSERT_EQ(::setrlimit(RLIMIT_AS, &as), 0);
  Renderer many(scene, settings);
  many.setThreads(100000);  // clamped to limits::kMaxThreads, most of which cannot start
  const FloatImage image = many.render();
  ::setrlimit(RLIMIT_AS, &before);
  EXPECT_EQ(image.pixels, expected.pixels);
}

TEST(StrangerFiles, 04_TheExactOracleRefusesNaNAndInfinities) {
  // Finding 4: GMP stopped the program with SIGFPE for a NaN origin.
  const Sphere sphere(Point3(0.0), 1.0);
  const double nan = std::nan("");
  for (const Ray& ray :
       {Ray{Point3(nan, 0, 0), Vec3(0, 0, 1)}, Ray{Point3(0, 0, -5), Vec3(kInfinity, 0, 1)}}) {
    EXPECT_THROW(ExactOracle::classify(sphere, ray), std::invalid_argument);
    EXPECT_THROW(ExactOracle::compare(sphere, ray), std::invalid_argument);
  }
}

/// A lesson on kScene (written beside it) with the given steps.
fs::path writeLesson(const fs::path& dir, const json& steps) {
  writeFile(dir / "scene.json", kScene);
  json lesson = {{"raylab_lesson", 1},
                 {"id", "38-test"},
                 {"title", {{"en", "Test"}, {"zh", "测试"}}},
                 {"summary", {{"en", "Test."}, {"zh", "测试。"}}},
                 {"scene", "scene.json"},
                 {"steps", steps}};
  writeFile(dir / "lesson.json", lesson.dump());
  return dir / "lesson.json";
}

json luminanceStep(int spp) {
  return json::parse(R"({"title": {"en": "T", "zh": "题"}, "text": {"en": "T", "zh": "文"},
    "view": "image",
    "question": {"type": "number", "prompt": {"en": "P", "zh": "问"}, "answer": 0.1,
                 "explanation": {"en": "E", "zh": "解"},
                 "tolerance": 1, "check": {"quantity": "pixel_luminance", "pixel": [16, 12],
                 "spp": )" +
                     std::to_string(spp) + "}}}");
}

TEST(StrangerFiles, 05_ALessonsCountsAreBoundedBeforeAnyWork) {
  // Finding 5: a check's spp of 2^31 - 1 ran for hours; a samples step's count of 2^31 - 1
  // threw bad_alloc (exit 3). Each is refused when the lesson is read, with its place.
  const fs::path dir = testDir();
  EXPECT_THAT(
      errorOf([&] { LessonIO::load(writeLesson(dir, json::array({luminanceStep(2147483647)}))); }),
      HasSubstr("at /steps/0/question/check/spp: must be at most 1048576"));
  // Within the spp limit each, past the lesson's budget together (4 x 2^20 > 2^22 - 1...).
  json steps = json::array();
  for (int i = 0; i < 5; ++i) steps.push_back(luminanceStep(1 << 20));
  EXPECT_THAT(errorOf([&] { LessonIO::load(writeLesson(dir, steps)); }),
              HasSubstr("at /steps/4/question/check/spp: the answer's 1048576 samples per pixel "
                        "takes the lesson past its budget of 4194304"));
  json samples = json::parse(R"({"title": {"en": "T", "zh": "题"}, "text": {"en": "T", "zh": "文"},
    "view": "samples", "samples": {"sampler": "cosine", "count": 2147483647}})");
  EXPECT_THAT(errorOf([&] { LessonIO::load(writeLesson(dir, json::array({samples}))); }),
              HasSubstr("at /steps/0/samples/count: must be at most 65536"));
  // A lesson within the budget loads.
  EXPECT_EQ(errorOf([&] { LessonIO::load(writeLesson(dir, json::array({luminanceStep(64)}))); }),
            "");
}

TEST(StrangerFiles, 06_ALessonsStepsAndSceneChangesAreBounded) {
  const fs::path dir = testDir();
  const json plain = json::parse(
      R"({"title": {"en": "T", "zh": "题"}, "text": {"en": "T", "zh": "文"}, "view": "image"})");
  json steps = json::array();
  for (std::size_t i = 0; i <= limits::kMaxLessonSteps; ++i) steps.push_back(plain);
  EXPECT_THAT(errorOf([&] { LessonIO::load(writeLesson(dir, steps)); }),
              HasSubstr("at /steps: a lesson has at most 1000 steps, this one 1001"));
  json changed = plain;
  changed["scene_changes"] = json::array();
  for (int i = 0; i < 6000; ++i)
    changed["scene_changes"].push_back({{"object", "ball"}, {"translate", {0, 0, 0}}});
  EXPECT_THAT(errorOf([&] {
                LessonIO::load(writeLesson(dir, json::array({changed, changed})));
              }),
              HasSubstr("at /steps/1/scene_changes: a lesson has at most 10000 scene changes"));
}

TEST(StrangerFiles, 07_ABrokenSceneChangeIsNamedAfterOneReadOfTheChangedScene) {
  // The changes of a step are applied together and the scene read once; a change that
  // breaks it is still named, at its own place.
  const fs::path dir = testDir();
  json step = json::parse(
      R"({"title": {"en": "T", "zh": "题"}, "text": {"en": "T", "zh": "文"}, "view": "image"})");
  step["scene_changes"] = json::array();
  for (int i = 0; i < 50; ++i)
    step["scene_changes"].push_back({{"object", "ball"}, {"translate", {0, 0.01, 0}}});
  step["scene_changes"][37] = {{"material", "white"}, {"set", {{"colour", {2, 0, 0}}}}};
  EXPECT_THAT(errorOf([&] { LessonIO::load(writeLesson(dir, json::array({step}))); }),
              HasSubstr("at /steps/0/scene_changes/37/set/colour: colour components must be in"));
  step["scene_changes"][37] = {{"object", "ball"}, {"translate", {0, 0.01, 0}}};
  const Lesson lesson = LessonIO::load(writeLesson(dir, json::array({step})));
  const Bounds3 ball = lesson.steps[0].scene->objects[0].shape->bounds();
  EXPECT_NEAR((ball.lower.y + ball.upper.y) / 2, 1.5, 1e-9);  // 50 moves of 0.01
}

TEST(StrangerFiles, 08_APfmHeaderIsCheckedAgainstTheImageLimitBeforeAllocating) {
  // Finding 9: the 19-byte header of a 65536 x 65536 image threw bad_alloc (exit 3).
  EXPECT_THAT(errorOf([] { imageio::decodePfm("PF\n65536 65536\n-1\n", "big.pfm"); }),
              HasSubstr("big.pfm: the PFM image is 65536x65536; RayLab's images have sides of "
                        "at most 8192"));
  EXPECT_THAT(errorOf([] { imageio::decodePfm("PF\n8192 8192\n-1\n", "big.pfm"); }),
              HasSubstr("at most 4096 x 4096 pixels"));
  // Within the limit, the data must be in the file before the image is made.
  EXPECT_THAT(errorOf([] { imageio::decodePfm("PF\n4096 4096\n-1\n0123456789", "t.pfm"); }),
              HasSubstr("t.pfm: truncated PFM data (the header announces 4096x4096 pixels"));
  // A NaN pixel is refused (a NaN reference gave finite error figures).
  FloatImage image(2, 1);
  image.at(1, 0) = glm::vec3(0.0f, std::nanf(""), 0.0f);
  EXPECT_THAT(errorOf([&] { imageio::decodePfm(imageio::encodePfm(image), "n.pfm"); }),
              HasSubstr("n.pfm: pixel (1, 0) is not a finite number"));
  // A FIFO is named, not waited on.
  const fs::path dir = testDir();
  ASSERT_EQ(::mkfifo((dir / "f.pfm").c_str(), 0600), 0);
  EXPECT_THAT(errorOf([&] { imageio::readPfm((dir / "f.pfm").string()); }),
              HasSubstr("not a regular file"));
}

/// The reference cache's entry of kScene at small settings, stored in `dir`; returns its key.
struct CacheFixture {
  Scene scene = SceneIO::parse(kScene, "s.json");
  RenderSettings settings;
  ComparisonReference reference;
  ReferenceCache cache;
  std::string key;

  explicit CacheFixture(const fs::path& dir) : cache(dir.string()) {
    scene.camera.width = 16;
    scene.camera.height = 12;
    settings = scene.render;
    settings.samplesPerPixel = 2;
    settings.background = Vec3(0.3);  // no pixel is black: a zeroed one is always wrong
    Renderer renderer(scene, settings);
    renderer.setThreads(1);
    reference.image = renderer.render();
    reference.samplesPerPixel = 2;
    reference.seed = settings.seed;
    key = ReferenceCache::key(scene, settings);
    const auto problem = cache.store(scene, settings, reference);
    EXPECT_FALSE(problem) << *problem;
  }
  ReferenceCache::Lookup load() const { return cache.load(scene, settings); }
};

TEST(StrangerFiles, 09_ADamagedOrForeignTypedSidecarIsIgnored) {
  // Finding 10: "seconds" as a string or "imageHash" as a number threw from JSON's value()
  // (exit 3); a FIFO hung; a link to /dev/zero read until bad_alloc.
  const fs::path dir = testDir();
  CacheFixture f(dir);
  ASSERT_TRUE(f.load().reference) << f.load().problem;
  const fs::path sidecar = f.cache.sidecarPath(f.key);
  const std::string good = readFile(sidecar);
  for (const auto& [field, value] :
       {std::pair{"seconds", json("slow")}, std::pair{"imageHash", json(12345)},
        std::pair{"format", json(7)}}) {
    json broken = json::parse(good);
    broken[field] = value;
    writeFile(sidecar, broken.dump());
    const ReferenceCache::Lookup lookup = f.load();
    EXPECT_FALSE(lookup.reference) << field;
    EXPECT_THAT(lookup.problem, HasSubstr("ignored")) << field;
  }
  // A FIFO sidecar or image: ignored at once (O_NONBLOCK, then not a regular file).
  fs::remove(sidecar);
  ASSERT_EQ(::mkfifo(sidecar.c_str(), 0600), 0);
  EXPECT_THAT(f.load().problem, HasSubstr("not a regular file"));
  fs::remove(sidecar);
  writeFile(sidecar, good);
  const fs::path image = f.cache.imagePath(f.key);
  fs::remove(image);
  ASSERT_EQ(::mkfifo(image.c_str(), 0600), 0);
  EXPECT_THAT(f.load().problem, HasSubstr("not a regular file"));
  // A symbolic link (to /dev/zero) is never followed.
  fs::remove(image);
  fs::create_symlink("/dev/zero", image);
  EXPECT_THAT(f.load().problem, HasSubstr("a symbolic link"));
  fs::remove(sidecar);
  fs::create_symlink("/dev/zero", sidecar);
  EXPECT_THAT(f.load().problem, HasSubstr("a symbolic link"));
  // An oversized sidecar is not read.
  fs::remove(sidecar);
  writeFile(sidecar, std::string(limits::kMaxCacheSidecarBytes + 1, ' '));
  EXPECT_THAT(f.load().problem, HasSubstr("larger than any cache file"));
}

TEST(StrangerFiles, 10_AForgedReferenceIsDetected) {
  // Finding 11: a reference zeroed except at the six re-traced pixels, whose places
  // followed from the key, with its hash recomputed, was accepted. The places are drawn
  // afresh at each check now: the same forgery, even with a seal recomputed by hand (as
  // anyone can: SHA-256 is no secret), fails at a pixel, run after run.
  const fs::path dir = testDir();
  CacheFixture f(dir);
  ASSERT_TRUE(f.load().reference);
  // The forgery keeps the pixels the old check re-traced (the centre, then five places from
  // a generator seeded by the key's first 16 hex digits) and zeroes every other one.
  FloatImage forged = f.reference.image;
  std::vector<std::pair<int, int>> oldPlaces = {{forged.width / 2, forged.height / 2}};
  std::uint64_t state = std::strtoull(f.key.substr(0, 16).c_str(), nullptr, 16);
  for (int i = 1; i < 6; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    oldPlaces.emplace_back(int((state >> 33) % std::uint64_t(forged.width)),
                           int((state >> 13) % std::uint64_t(forged.height)));
  }
  int kept = 0;
  for (int y = 0; y < forged.height; ++y)
    for (int x = 0; x < forged.width; ++x)
      if (std::find(oldPlaces.begin(), oldPlaces.end(), std::pair{x, y}) == oldPlaces.end())
        forged.at(x, y) = glm::vec3(0.0f);
      else
        ++kept;
  ASSERT_GT(kept, 0);
  ComparisonReference forgery = f.reference;
  forgery.image = forged;
  ASSERT_FALSE(f.cache.store(f.scene, f.settings, forgery));  // the store recomputes the seal
  for (int run = 0; run < 5; ++run) {
    const ReferenceCache::Lookup lookup = f.load();
    EXPECT_FALSE(lookup.reference) << "run " << run;
    EXPECT_THAT(lookup.problem, HasSubstr("differs from the same pixel traced now"));
  }
  // One pixel changed without a new seal: the seal (SHA-256 over every byte) catches it.
  ASSERT_FALSE(f.cache.store(f.scene, f.settings, f.reference));
  std::string bytes = readFile(f.cache.imagePath(f.key));
  bytes[bytes.size() - 1] ^= 1;
  writeFile(f.cache.imagePath(f.key), bytes);
  EXPECT_THAT(f.load().problem, HasSubstr("do not match the hash (SHA-256)"));
  EXPECT_EQ(f.key.size(), 64u);  // a SHA-256 in hex
}

/// The names in `dir`, sorted, hidden ones too.
std::vector<std::string> namesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

bool pngName(const std::string& name) {
  return name.size() > 4 && name.rfind(".png") == name.size() - 4;
}

TEST(StrangerFiles, 11_AFolderIsReplacedWholeOrNotAtAll) {
  // Findings 12 and 13: a handout interrupted at step 6 of 13 left steps 1-5 new and 6-13
  // old. A folder is written beside the target and swapped in whole.
  const fs::path dir = testDir();
  const fs::path out = dir / "handout";
  fs::create_directories(out);
  writeFile(out / "a.png", "old a");
  writeFile(out / "b.png", "old b");
  try {
    AtomicFolder folder(out.string(), pngName);
    writeFile(folder.file("a.png"), "new a");
    throw std::runtime_error("the disk is full");  // before commit
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(readFile(out / "a.png"), "old a");
  EXPECT_EQ(namesIn(dir), std::vector<std::string>{"handout"});  // nothing left beside it
  {
    AtomicFolder folder(out.string(), pngName);
    writeFile(folder.file("a.png"), "new a");
    folder.commit();
  }
  EXPECT_EQ(namesIn(out), std::vector<std::string>{"a.png"});  // b.png was the old run's
  EXPECT_EQ(readFile(out / "a.png"), "new a");
  EXPECT_EQ(namesIn(dir), std::vector<std::string>{"handout"});
  // A folder left by a killed run (its process is gone) is removed by the next one.
  fs::create_directories(dir / ".handout.raylab-new-999999999-0");
  { AtomicFolder folder(out.string(), pngName); }
  EXPECT_EQ(namesIn(dir), std::vector<std::string>{"handout"});
  // A folder holding a file the command did not write is refused, not replaced.
  writeFile(out / "thesis.tex", "mine");
  EXPECT_THAT(errorOf([&] { AtomicFolder(out.string(), pngName); }),
              HasSubstr("holds \"thesis.tex\", which RayLab did not write"));
  EXPECT_EQ(readFile(out / "thesis.tex"), "mine");
}

TEST(StrangerFiles, 12_SavingKeepsLinksDevicesAndPermissions) {
  // Finding 14: saving onto a symbolic link or a FIFO replaced it with a regular file, and
  // every file became 0644.
  const fs::path dir = testDir();
  writeFile(dir / "real.json", "old");
  fs::create_symlink("real.json", dir / "link.json");
  ASSERT_FALSE(writeFileAtomically((dir / "link.json").string(), "new"));
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_EQ(readFile(dir / "real.json"), "new");
  ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
  const auto refused = writeFileAtomically((dir / "fifo.json").string(), "x");
  ASSERT_TRUE(refused);
  EXPECT_THAT(*refused, HasSubstr("not a regular file"));
  EXPECT_TRUE(fs::is_fifo(dir / "fifo.json"));
  ::chmod((dir / "real.json").c_str(), 0600);
  ASSERT_FALSE(writeFileAtomically((dir / "real.json").string(), "newer"));
  struct stat st {};
  ASSERT_EQ(::stat((dir / "real.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  const mode_t old = ::umask(077);
  ASSERT_FALSE(writeFileAtomically((dir / "fresh.json").string(), "x"));
  ::umask(old);
  ASSERT_EQ(::stat((dir / "fresh.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(namesIn(dir),
            (std::vector<std::string>{"fifo.json", "fresh.json", "link.json", "real.json"}));
}

TEST(StrangerFiles, 13_LessonTextInAHandoutShowsAndDoesNothingElse) {
  // Finding 16: raw HTML, links and headings from a lesson reached the handout verbatim.
  EXPECT_EQ(markdownText("<img src=http://x/a.png><script>alert(1)</script>"),
            "&lt;img src=http://x/a.png>&lt;script>alert(1)&lt;/script>");
  EXPECT_EQ(markdownText("see [this](javascript:alert(1))"), "see [this]\\(javascript:alert(1))");
  EXPECT_EQ(markdownText("ok\n# Fake heading\n  [x]: javascript:y\n==="),
            "ok\n\\# Fake heading\n  \\[x]: javascript:y\n\\===");
  EXPECT_EQ(markdownText("Title\n# two", true), "Title # two");
  EXPECT_EQ(markdownText("t₁ < t₂, |o − c|² − r²"), "t₁ &lt; t₂, |o − c|² − r²");
  EXPECT_EQ(markdownFence("plain"), "```");
  EXPECT_EQ(markdownFence("name ```` end"), "`````");
  // Finding 15: what a terminal shows of a file's string has its controls escaped.
  EXPECT_EQ(printableText("\x1b]52;c;aGk=\x07title"), "\\x1b]52;c;aGk=\\x07title");
}

TEST(StrangerFiles, 14_MeshFacesAreCountedBeforeCgalRepairsThem) {
  // Finding 8: one face listing the same few vertices over and over was quadratic in CGAL's
  // repair (300,000 corners: 19-43 s); faces of 4,096 corners took a second each to check.
  const fs::path dir = testDir();
  // 9,000 corners: past the face limit, which used to apply only after the repair.
  std::string repeated = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
  for (int i = 0; i < 3000; ++i) repeated += " 1 2 3";
  writeFile(dir / "repeated.obj", repeated + "\n");
  EXPECT_THAT(errorOf([&] { MeshIO::load((dir / "repeated.obj").string()); }),
              HasSubstr("repeated.obj: cannot triangulate a face of 9000 corners: RayLab "
                        "triangulates faces of at most 4096 corners"));
  // 3,000 corners, within it: the repeated vertex is named, before the repair.
  repeated = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
  for (int i = 0; i < 1000; ++i) repeated += " 1 2 3";
  writeFile(dir / "repeated.obj", repeated + "\n");
  EXPECT_THAT(errorOf([&] { MeshIO::load((dir / "repeated.obj").string()); }),
              HasSubstr("repeated.obj: face 1 names vertex 1 twice; a polygonal face must be a "
                        "simple polygon"));
  std::string big;
  for (int i = 0; i < 4096; ++i)
    big += "v " + std::to_string(std::cos(i * 2 * M_PI / 4096)) + " " +
           std::to_string(std::sin(i * 2 * M_PI / 4096)) + " 0\n";
  for (int f = 0; f < 5; ++f) {  // 5 x 4096^2 > 2^26
    big += "f";
    for (int i = 0; i < 4096; ++i) big += " " + std::to_string(i + 1);
    big += "\n";
  }
  writeFile(dir / "big.obj", big);
  // An ASCII STL's triangles are counted before CGAL reads it whole (4.5M took 2.4 GB).
  {
    std::ofstream stl(dir / "many.stl", std::ios::binary);
    stl << "solid many\n";
    const std::string facet = "facet\n";
    for (std::size_t i = 0; i <= limits::kMaxMeshTriangles; ++i) stl << facet;
  }
  EXPECT_THAT(errorOf([&] { MeshIO::load((dir / "many.stl").string()); }),
              HasSubstr("many.stl: cannot parse STL file: the ASCII STL file has more than "
                        "4000000 triangles"));
  fs::remove(dir / "many.stl");
  EXPECT_THAT(errorOf([&] { MeshIO::load((dir / "big.obj").string()); }),
              HasSubstr("big.obj: the polygonal faces are too large together to check (at face 5"));
}

TEST(StrangerFiles, 15_ASetPlaceThatIsNotUtf8IsRefused) {
  // Found by the new FuzzSet target: `--set` with a place holding a byte that is not UTF-8
  // added that key to the scene's JSON, whose writer then threw (exit 3).
  const Scene scene = SceneIO::parse(kScene, "s.json");
  EXPECT_THAT(
      errorOf([&] { edit::setValue(scene, "/render/oooooooa(\xf1_epmth", "63", "s.json"); }),
      HasSubstr("not a place in a scene file"));
  EXPECT_THAT(errorOf([&] { edit::setValue(scene, "/render/\x1b[2J", "1", "s.json"); }),
              HasSubstr("/render/\\x1b[2J"));
  EXPECT_EQ(edit::setValue(scene, "/render/max_depth", "3", "s.json").render.maxDepth, 3);
}

TEST(StrangerFiles, 16_LessonStepsShareTheirMeshesData) {
  // Each step with scene changes reads its scene again: the mesh came from the mesh cache,
  // but each step held its own copy of vertices, triangles, BVH and normals (40 steps over
  // 200,000 triangles: 1.3 GB). Now the steps share them; an edit changes only its mesh.
  const fs::path dir = testDir();
  const json step = json::parse(
      R"({"title": {"en": "T", "zh": "题"}, "text": {"en": "T", "zh": "文"}, "view": "image"})");
  json grey = step, lighter = step, moved = step;
  grey["scene_changes"] = {{{"material", "white"}, {"set", {{"colour", {0.5, 0.5, 0.5}}}}}};
  lighter["scene_changes"] = {{{"material", "white"}, {"set", {{"colour", {0.6, 0.6, 0.6}}}}}};
  moved["scene_changes"] = {{{"object", "gem"}, {"translate", {0, 1, 0}}}};
  const fs::path lessonFile = writeLesson(dir, json::array({grey, lighter, moved}));
  writeFile(dir / "gem.obj",
            "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
            "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\n"
            "f 1 4 6\n");
  json scene = json::parse(kScene);
  scene["objects"].push_back(json::parse(R"({"name": "gem", "material": "white",
      "shape": {"type": "mesh", "file": "gem.obj", "normals": "smooth", "crease_angle": 80},
      "transform": [{"scale": [0.5, 0.5, 0.5]}, {"translate": [2, 0.5, 0]}]})"));
  writeFile(dir / "scene.json", scene.dump());
  const Lesson lesson = LessonIO::load(lessonFile);
  const auto gem = [](const Scene& s) -> const TriangleMesh& {
    return dynamic_cast<const TriangleMesh&>(*s.objects.at(2).shape);
  };
  const TriangleMesh& first = gem(lesson.sceneOfStep(0));
  const TriangleMesh& second = gem(lesson.sceneOfStep(1));
  const TriangleMesh& third = gem(lesson.sceneOfStep(2));
  ASSERT_TRUE(first.hasNormals());
  EXPECT_NE(&first, &second);                        // two scenes, two objects...
  EXPECT_EQ(&first.vertices(), &second.vertices());  // ...one mesh's data
  EXPECT_EQ(&first.triangles(), &second.triangles());
  EXPECT_EQ(&first.bvh(), &second.bvh());
  EXPECT_EQ(&first.normals(), &second.normals());
  EXPECT_EQ(&first.vertices(), &gem(*lesson.scene).vertices());
  // The moved mesh has data of its own, one unit higher.
  EXPECT_NE(&third.vertices(), &first.vertices());
  EXPECT_NEAR(third.bounds().lower.y, first.bounds().lower.y + 1.0, 1e-12);

  // Editing a copy leaves the original and the other step as they were.
  const std::vector<Point3> before = first.vertices();
  const std::vector<Normal3> normalsBefore = first.normals();
  TriangleMesh edited = first;
  EXPECT_EQ(&edited.vertices(), &first.vertices());
  edited.apply(glm::translate(Mat4(1.0), Vec3(0, 0, 3)));
  edited.clearNormals();
  EXPECT_NE(&edited.vertices(), &first.vertices());
  EXPECT_EQ(first.vertices(), before);
  EXPECT_EQ(first.normals(), normalsBefore);
  EXPECT_TRUE(first.hasNormals());
  EXPECT_EQ(&first.vertices(), &second.vertices());
  EXPECT_NEAR(edited.bounds().lower.z - first.bounds().lower.z, 3.0, 1e-12);
  EXPECT_FALSE(edited.hasNormals());
}

}  // namespace
}  // namespace raylab
