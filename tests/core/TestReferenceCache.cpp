// The reference cache: a comparison that finds its reference cached gives the same
// figures as one that renders it; any change to the scene or to a setting path tracing
// reads misses; a damaged, foreign or stale entry is ignored and rewritten, never used.
#include "raylab/core/ReferenceCache.h"

#include "raylab/core/Comparison.h"
#include "raylab/core/Image.h"
#include "raylab/core/SceneIO.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace raylab {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty folder for one test, removed at the end.
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "raylab-cache-test-XXXXXX").string();
    const char* made = ::mkdtemp(pattern.data());
    if (made == nullptr) throw std::runtime_error("mkdtemp failed");
    m_path = made;
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(m_path, ec);
  }
  const std::string& path() const { return m_path; }

 private:
  std::string m_path;
};

Scene smallCornell() {
  Scene scene = SceneIO::load(std::string(RAYLAB_SOURCE_DIR) + "/lessons/scenes/cornell.json");
  scene.camera.width = 20;
  scene.camera.height = 15;
  return scene;
}

RenderSettings smallSettings(const Scene& scene) {
  RenderSettings settings = scene.render;
  settings.maxDepth = 4;
  settings.seed = 5;
  return settings;
}

ComparisonSettings smallCompare() {
  ComparisonSettings compare;
  compare.samplesPerPixel = 2;
  compare.referenceSamplesPerPixel = 32;
  compare.threads = 2;
  return compare;
}

ComparisonResult compareWith(const Scene& scene, const RenderSettings& settings,
                             std::optional<ReferenceCache> cache) {
  Comparison comparison(scene, settings, smallCompare());
  comparison.setReferenceCache(std::move(cache));
  return comparison.run();
}

bool samePixels(const FloatImage& a, const FloatImage& b) {
  return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

/// The figures' JSON without what is measured by the clock (it differs from run to run
/// whatever the cache does).
nlohmann::json withoutTimes(const std::string& text) {
  nlohmann::json json = nlohmann::json::parse(text);
  for (auto& a : json.at("algorithms")) {
    a.erase("seconds");
    a.erase("raysPerSecond");
    for (auto& point : a.at("series")) point.erase("seconds");
  }
  return json;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void writeFile(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(ReferenceCache, 01_HitGivesTheFiguresOfAFreshRun) {
  TempFolder folder;
  const Scene scene = smallCornell();
  const RenderSettings settings = smallSettings(scene);
  const ComparisonResult fresh = compareWith(scene, settings, std::nullopt);
  const ComparisonResult first = compareWith(scene, settings, ReferenceCache(folder.path()));
  const ComparisonResult second = compareWith(scene, settings, ReferenceCache(folder.path()));

  // The first run renders and stores, the second reads.
  EXPECT_FALSE(fresh.reference.cached);
  EXPECT_TRUE(fresh.reference.cacheFile.empty());
  EXPECT_FALSE(first.reference.cached);
  EXPECT_TRUE(first.reference.cacheNote.empty()) << first.reference.cacheNote;
  ASSERT_FALSE(first.reference.cacheFile.empty());
  EXPECT_TRUE(fs::exists(first.reference.cacheFile));
  EXPECT_TRUE(second.reference.cached);
  EXPECT_EQ(second.reference.cacheFile, first.reference.cacheFile);
  EXPECT_TRUE(second.reference.cacheNote.empty()) << second.reference.cacheNote;

  // The same reference bit for bit, and the same figures and JSON (times aside; the
  // reference's time is the one it took when rendered).
  EXPECT_TRUE(samePixels(second.reference.image, fresh.reference.image));
  EXPECT_EQ(second.reference.samplesPerPixel, 32);
  EXPECT_EQ(second.reference.seed, fresh.reference.seed);
  EXPECT_DOUBLE_EQ(second.reference.seconds, first.reference.seconds);
  ASSERT_EQ(second.algorithms.size(), fresh.algorithms.size());
  for (std::size_t i = 0; i < fresh.algorithms.size(); ++i) {
    EXPECT_TRUE(samePixels(second.algorithms[i].image, fresh.algorithms[i].image));
    EXPECT_EQ(second.algorithms[i].rmse, fresh.algorithms[i].rmse);
    EXPECT_EQ(second.algorithms[i].stats.rays.total(), fresh.algorithms[i].stats.rays.total());
  }
  nlohmann::json a = withoutTimes(comparisonJson(second));
  nlohmann::json b = withoutTimes(comparisonJson(fresh));
  a.at("reference").erase("seconds");
  b.at("reference").erase("seconds");
  EXPECT_EQ(a, b);
  EXPECT_EQ(withoutTimes(comparisonJson(second)), withoutTimes(comparisonJson(first)));
}

TEST(ReferenceCache, 02_ChangingTheSceneOrASettingMisses) {
  TempFolder folder;
  const ReferenceCache cache(folder.path());
  const Scene scene = smallCornell();
  const RenderSettings settings = smallSettings(scene);
  const RenderSettings reference = Comparison::referenceSettings(settings, smallCompare());
  compareWith(scene, settings, cache);
  ASSERT_TRUE(cache.load(scene, reference).reference.has_value());

  // The scene: a material's colour, the camera, the size; each is another key.
  Scene colour = scene;
  colour.materials.front().colour *= 0.5;
  Scene moved = scene;
  moved.camera.position.x += 0.01;
  Scene larger = scene;
  larger.camera.width = 24;
  for (const Scene* changed : {&colour, &moved, &larger}) {
    EXPECT_NE(ReferenceCache::key(*changed, reference), ReferenceCache::key(scene, reference));
    const ReferenceCache::Lookup lookup = cache.load(*changed, reference);
    EXPECT_FALSE(lookup.reference.has_value());
    EXPECT_TRUE(lookup.problem.empty()) << lookup.problem;  // a miss, not a damaged entry
  }

  // The settings path tracing reads: spp, seed, depth, next-event estimation.
  RenderSettings spp = reference, seed = reference, depth = reference, nee = reference;
  spp.samplesPerPixel = 64;
  seed.seed += 1;
  depth.maxDepth = 6;
  nee.nextEventEstimation = false;
  for (const RenderSettings* changed : {&spp, &seed, &depth, &nee}) {
    EXPECT_NE(ReferenceCache::key(scene, *changed), ReferenceCache::key(scene, reference));
    EXPECT_FALSE(cache.load(scene, *changed).reference.has_value());
  }
  // The comparison's seed changes its reference's seed, and so the key.
  RenderSettings otherSeed = settings;
  otherSeed.seed = 6;
  EXPECT_FALSE(compareWith(scene, otherSeed, cache).reference.cached);

  // What path tracing does not read shares the entry: the scene's name and render block,
  // the distributed rays, the threads.
  Scene renamed = scene;
  renamed.name = "another name";
  renamed.render.samplesPerPixel = 999;
  RenderSettings distributed = reference;
  distributed.glossySamples = 9;
  EXPECT_TRUE(cache.load(renamed, reference).reference.has_value());
  EXPECT_TRUE(cache.load(scene, distributed).reference.has_value());
}

TEST(ReferenceCache, 03_DamagedEntriesAreIgnoredAndRewritten) {
  TempFolder folder;
  const ReferenceCache cache(folder.path());
  const Scene scene = smallCornell();
  const RenderSettings settings = smallSettings(scene);
  const RenderSettings reference = Comparison::referenceSettings(settings, smallCompare());
  const ComparisonResult fresh = compareWith(scene, settings, cache);
  const std::string key = ReferenceCache::key(scene, reference);
  const std::string pfm = cache.imagePath(key), sidecar = cache.sidecarPath(key);
  const std::string goodPfm = readFile(pfm), goodSidecar = readFile(sidecar);
  ASSERT_FALSE(goodPfm.empty());
  ASSERT_FALSE(goodSidecar.empty());

  // Each damage: the entry is ignored with a reason naming the file, and the next
  // comparison renders the reference again (the same image) and rewrites a good entry.
  struct Damage {
    std::string name, file, bytes, reason;
  };
  std::string flipped = goodPfm;
  flipped[flipped.size() / 2] ^= 0x10;
  nlohmann::json otherKey = nlohmann::json::parse(goodSidecar);
  otherKey["key"] = std::string(32, '0');
  nlohmann::json otherSpp = nlohmann::json::parse(goodSidecar);
  otherSpp["settings"]["samplesPerPixel"] = 16;
  const std::vector<Damage> damages = {
      {"a flipped bit in the image", pfm, flipped, "hash"},
      {"a truncated image", pfm, goodPfm.substr(0, goodPfm.size() - 7), "hash"},
      {"a truncated sidecar", sidecar, goodSidecar.substr(0, goodSidecar.size() / 2), "JSON"},
      {"a sidecar of another key", sidecar, otherKey.dump(), "another key"},
      {"a sidecar of other settings", sidecar, otherSpp.dump(), "other settings"},
  };
  for (const Damage& damage : damages) {
    SCOPED_TRACE(damage.name);
    writeFile(damage.file, damage.bytes);
    const ReferenceCache::Lookup lookup = cache.load(scene, reference);
    EXPECT_FALSE(lookup.reference.has_value());
    EXPECT_NE(lookup.problem.find(damage.file), std::string::npos) << lookup.problem;
    EXPECT_NE(lookup.problem.find(damage.reason), std::string::npos) << lookup.problem;
    const ComparisonResult again = compareWith(scene, settings, cache);
    EXPECT_FALSE(again.reference.cached);
    EXPECT_NE(again.reference.cacheNote.find(damage.file), std::string::npos);
    EXPECT_TRUE(samePixels(again.reference.image, fresh.reference.image));
    EXPECT_EQ(readFile(pfm), goodPfm);
    EXPECT_TRUE(cache.load(scene, reference).reference.has_value());
  }
}

TEST(ReferenceCache, 04_AnEntryThePathTracerDisagreesWithIsNotUsed) {
  // An entry whose files are consistent (the sidecar's hash is the image's) but whose
  // pixels are not what the path tracer computes now, as a cache written by an older
  // version would be: the re-traced pixels catch it.
  TempFolder folder;
  const ReferenceCache cache(folder.path());
  const Scene scene = smallCornell();
  const RenderSettings settings = smallSettings(scene);
  const RenderSettings reference = Comparison::referenceSettings(settings, smallCompare());
  ComparisonReference stale = compareWith(scene, settings, std::nullopt).reference;
  for (glm::vec3& p : stale.image.pixels) p *= 1.01f;
  ASSERT_FALSE(cache.store(scene, reference, stale).has_value());
  const ReferenceCache::Lookup lookup = cache.load(scene, reference);
  EXPECT_FALSE(lookup.reference.has_value());
  EXPECT_NE(lookup.problem.find("traced now"), std::string::npos) << lookup.problem;
}

TEST(ReferenceCache, 05_FolderComesFromTheEnvironment) {
  const auto restore = [](const char* name, const char* value) {
    if (value)
      ::setenv(name, value, 1);
    else
      ::unsetenv(name);
  };
  const char* names[] = {"RAYLAB_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  std::string saved[3];
  bool had[3];
  for (int i = 0; i < 3; ++i) {
    const char* value = std::getenv(names[i]);
    had[i] = value != nullptr;
    saved[i] = value ? value : "";
  }
  ::setenv("RAYLAB_CACHE_DIR", "/tmp/rc", 1);
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  ::setenv("HOME", "/tmp/home", 1);
  EXPECT_EQ(ReferenceCache::defaultDirectory(), "/tmp/rc");
  ::unsetenv("RAYLAB_CACHE_DIR");
  EXPECT_EQ(ReferenceCache::defaultDirectory(), "/tmp/xdg/raylab/references");
  ::setenv("XDG_CACHE_HOME", "", 1);
  EXPECT_EQ(ReferenceCache::defaultDirectory(), "/tmp/home/.cache/raylab/references");
  ::unsetenv("HOME");
  EXPECT_EQ(ReferenceCache::defaultDirectory(), "");
  EXPECT_FALSE(ReferenceCache::fromEnvironment().has_value());
  for (int i = 0; i < 3; ++i) restore(names[i], had[i] ? saved[i].c_str() : nullptr);
}

TEST(ReferenceCache, 06_AnUnwritableFolderIsANoteNotAFailure) {
  TempFolder folder;
  const std::string file = folder.path() + "/a-file";
  writeFile(file, "not a folder");
  const Scene scene = smallCornell();
  const ComparisonResult result =
      compareWith(scene, smallSettings(scene), ReferenceCache(file + "/references"));
  EXPECT_EQ(result.algorithms.size(), 4u);
  EXPECT_FALSE(result.reference.cached);
  EXPECT_TRUE(result.reference.cacheFile.empty());
  EXPECT_NE(result.reference.cacheNote.find("cannot create the cache folder"), std::string::npos)
      << result.reference.cacheNote;
}

// The window's order (pictures first) with a cached reference: nothing rendered for the
// reference, nothing provisional, the figures of the first run (issue 33 item 3).
TEST(ReferenceCache, 07_PicturesFirstWithACachedReferenceRendersNoReference) {
  TempFolder folder;
  const Scene scene = smallCornell();
  const RenderSettings settings = smallSettings(scene);
  const ComparisonResult first = compareWith(scene, settings, ReferenceCache(folder.path()));
  Comparison comparison(scene, settings, smallCompare());
  comparison.setReferenceCache(ReferenceCache(folder.path()));
  comparison.setPicturesFirst(true);
  int referencePasses = 0, provisionalPasses = 0;
  comparison.setProgress(
      [&](const std::string& stage, double, int) { referencePasses += stage == "reference"; });
  comparison.setPassCallback(
      [&](const ComparisonResult& soFar, int, double) { provisionalPasses += soFar.provisional; });
  const ComparisonResult second = comparison.run();
  EXPECT_TRUE(second.reference.cached);
  EXPECT_EQ(referencePasses, 0) << "the cached reference was rendered again";
  EXPECT_EQ(provisionalPasses, 0);
  EXPECT_FALSE(second.provisional);
  EXPECT_EQ(withoutTimes(comparisonJson(second)), withoutTimes(comparisonJson(first)));
}

}  // namespace
}  // namespace raylab
