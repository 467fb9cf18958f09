// The phrase table (core/src/words/phrases.json) and the algorithm table (AlgorithmInfo.h):
// every phrase exists in both languages with the same placeholders, and the algorithms'
// names read as they did when each front end spelled them itself.

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/InspectorWords.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/RayTree.h"
#include "raylab/core/RayWords.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

using namespace raylab;

namespace {

/// The `{name}` placeholders of a text, as a set.
std::set<std::string> placeholders(const std::string& text) {
  std::set<std::string> names;
  const std::regex mark(R"(\{([a-z_]+)(?::[0-9]+)?\})");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), mark); it != std::sregex_iterator();
       ++it)
    names.insert((*it)[1]);
  return names;
}

bool hasHan(const std::string& text) {
  // UTF-8 lead bytes 0xE4..0xE9 start the CJK Unified Ideographs (U+4E00..U+9FFF).
  for (unsigned char c : text)
    if (c >= 0xE4 && c <= 0xE9) return true;
  return false;
}

}  // namespace

TEST(Phrases, 01_EveryPhraseHasBothLanguagesWithTheSamePlaceholders) {
  const std::vector<std::string> keys = phraseKeys();
  ASSERT_FALSE(keys.empty());
  for (const std::string& key : keys) {
    const std::string en = phrase(key, Language::English);
    const std::string zh = phrase(key, Language::Chinese);
    EXPECT_FALSE(en.empty()) << key;
    EXPECT_FALSE(zh.empty()) << key;
    // One phrase chooses what it says by language: the inspector's ending is the clause
    // after the heading in English and, as the Chinese inspector has always written it,
    // the whole sentence in Chinese (its callers give both).
    if (key != "inspector.ended") {
      EXPECT_EQ(placeholders(en), placeholders(zh)) << key;
    }
    EXPECT_FALSE(hasHan(en)) << key << ": Chinese in the English text";
  }
}

TEST(Phrases, 02_PlaceholdersAreFilledEverywhereAndValuesAreNotReread) {
  // "algorithm.title" is "{name} ({citation})": a value holding a placeholder stays as it is.
  EXPECT_EQ(
      phrase("algorithm.title", Language::English, {{"name", "{citation}"}, {"citation", "x"}}),
      "{citation} (x)");
  EXPECT_EQ(phrase("algorithm.title", Language::Chinese, {{"name", "A"}, {"citation", "B"}}),
            "A（B）");
  EXPECT_TRUE(hasPhrase("algorithm.title"));
  EXPECT_FALSE(hasPhrase("algorithm.no_such_key"));
}

TEST(Phrases, 03_TheTableIsCarriedWholeAsJson) {
  const std::string_view json = phraseTableJson();
  EXPECT_NE(json.find("\"raylab_phrases\""), std::string_view::npos);
  EXPECT_NE(json.find("\"algorithm.whitted.long\""), std::string_view::npos);
}

TEST(Phrases, 04_EveryRayKindHasItsWords) {
  for (int k = 0; k < kRayKindCount; ++k) {
    const std::string word = toString(RayKind(k));
    EXPECT_EQ(phrase("ray_kind." + word, Language::English), word);
    EXPECT_EQ(phrase("ray_kind." + word + ".legend", Language::English), word);
    EXPECT_TRUE(hasHan(phrase("ray_kind." + word + ".legend", Language::Chinese))) << word;
  }
}

TEST(Phrases, 05_AColumnPlaceholderPadsItsValue) {
  // "{field:12}" is printf's "%-12s": the inspector's English column.
  EXPECT_EQ(phrase("inspector.line", Language::English, {{"field", "hit"}, {"value", "x"}}),
            "  hit         x");
  EXPECT_EQ(
      phrase("inspector.line", Language::English, {{"field", "a field too long"}, {"value", "x"}}),
      "  a field too longx");
  EXPECT_EQ(phrase("inspector.line", Language::Chinese, {{"field", "交点"}, {"value", "无"}}),
            "  交点  无");
}

// Every key the words of rays and of the inspector ask for is in the table: each end
// reason, ray kind and material type has its phrases.
TEST(Phrases, 06_EveryFactHasItsPhrases) {
  for (int r = 0; r <= int(EndReason::Stopped); ++r) {
    const std::string json = words(EndReason(r)).json;
    EXPECT_TRUE(hasPhrase("end_reason." + json)) << json;
    EXPECT_TRUE(hasPhrase("end." + json)) << json;
  }
  for (int t = 0; t <= int(MaterialType::Plastic); ++t)
    EXPECT_TRUE(hasPhrase(std::string("material_type.") + toString(MaterialType(t))));
  for (const char* c : {"Miss", "Hit", "Tangent", "ThroughEdge", "ThroughVertex"})
    EXPECT_TRUE(hasPhrase(std::string("oracle.class.") + c)) << c;
}

// What a step of the engine did, said from its facts alone, in both languages: the object
// hit or blocking, a shadow ray's light (an area light or a point light), the children.
TEST(RayWords, 01_AStepIsToldFromItsFacts) {
  const SceneNames names{{"floor", "lamp"}, {"key"}};
  StepEvent e;
  e.ray = 3;
  e.kind = RayKind::Reflection;
  e.end = EndReason::Spawned;
  e.object = 0;
  e.firstChild = 4;
  e.spawned = 2;
  const auto en = [&] { return narrateStep(e, names, Language::English); };
  const auto zh = [&] { return narrateStep(e, names, Language::Chinese); };
  EXPECT_EQ(en(), "reflection ray #3 hit 'floor' and spawned 2 rays (#4..#5)");
  EXPECT_EQ(zh(), "反射光线 #3 击中“floor”，产生 2 条光线（#4..#5）");
  e.spawned = 1;
  EXPECT_EQ(en(), "reflection ray #3 hit 'floor' and spawned 1 ray (#4)");
  e.object = 1;
  e.end = EndReason::HitLight;
  EXPECT_EQ(en(), "reflection ray #3 hit the light 'lamp': the path ends there");
  EXPECT_EQ(zh(), "反射光线 #3 击中光源“lamp”：路径到此结束");
  e.kind = RayKind::Shadow;
  e.end = EndReason::Occluded;
  EXPECT_EQ(en(), "shadow ray #3 was blocked by 'lamp' before reaching its light");
  e.object = 0;
  e.lightObject = 1;
  EXPECT_EQ(en(), "shadow ray #3 was blocked by 'floor' before reaching the light 'lamp'");
  EXPECT_EQ(zh(), "阴影光线 #3 在到达光源“lamp”之前被“floor”遮挡");
  e.lightObject = -1;
  e.pointLight = 0;
  EXPECT_EQ(en(), "shadow ray #3 was blocked by 'floor' before reaching the light 'key'");
  e.object = -1;
  e.end = EndReason::ReachedLight;
  EXPECT_EQ(en(), "shadow ray #3 reached the light 'key' unblocked and delivers its radiance");
  EXPECT_EQ(endClause(e, {}, Language::English),
            "reached its light unblocked and delivers its radiance");
  e.pointLight = -1;
  e.kind = RayKind::Camera;
  e.end = EndReason::Escaped;
  EXPECT_EQ(en(), "camera ray #3 escaped the scene: it gets the background radiance");
  EXPECT_EQ(zh(), "相机光线 #3 逃逸出场景：取背景的辐射亮度");
  // A ray the budget stopped: no children, and how many the step wanted.
  e.end = EndReason::Stopped;
  e.object = 0;
  e.firstChild = -1;
  e.spawned = 0;
  e.wanted = 3;
  EXPECT_EQ(en(),
            "camera ray #3 hit 'floor'; tracing stopped here (ray budget reached, or cancelled): "
            "its children were not traced (3 rays would have been spawned)");
  EXPECT_EQ(zh(),
            "相机光线 #3 击中“floor”；追踪在此停止（达到光线预算或被取消）：它的子光线没有被追踪"
            "（本应产生 3 条光线）");
  EXPECT_EQ(endReasonLabel(EndReason::Stopped, Language::Chinese), "已停止（达到预算）");
  EXPECT_EQ(rayKindWord(RayKind::Glossy, Language::English), "glossy");
}

// A recorded ray is told as the step that processed it; a trace's figures in one line.
TEST(RayWords, 02_ARecordedRayAndATraceSummary) {
  PixelTrace trace;
  trace.tree.segments.resize(3);
  for (int i = 0; i < 3; ++i) trace.tree.segments[std::size_t(i)].id = i;
  RaySegment& camera = trace.tree.segments[0];
  camera.endReason = EndReason::Spawned;
  camera.object = 0;
  camera.firstChild = 1;
  camera.childCount = 2;
  camera.radiance = Vec3(0.5, 0.25, 0.125);
  for (int i = 1; i < 3; ++i) {
    trace.tree.segments[std::size_t(i)].kind = RayKind::Shadow;
    trace.tree.segments[std::size_t(i)].depth = 1;
    trace.tree.segments[std::size_t(i)].parent = 0;
  }
  const SceneNames names{{"ball"}, {}};
  EXPECT_EQ(narrateRay(trace.tree, 0, names, Language::English),
            "camera ray #0 hit 'ball' and spawned 2 rays (#1..#2)");
  EXPECT_EQ(narrateRay(trace.tree, 1, names, Language::Chinese), "阴影光线 #1 在队列中等待");
  EXPECT_EQ(narrateRay(trace.tree, 3, names, Language::English), "") << "no such ray";
  EXPECT_EQ(traceSummary(trace, Language::English),
            "3 rays (camera 1, shadow 2), depth 1, estimate (0.5, 0.25, 0.125)");
  EXPECT_EQ(traceSummary(trace, Language::Chinese),
            "3 条光线（相机 1、阴影 2），深度 1，估计值 (0.5, 0.25, 0.125)");
}

// Why a trace stopped early, from the facts core records (TreeStop, GridStop), and the
// window's trace info headings: the words the engine and the window used to compose
// themselves, now the phrase table's, in both languages (the Chinese as the window's .ts
// had it).
TEST(RayWords, 03_WhyATraceStoppedAndItsHeading) {
  EXPECT_EQ(stopWords(TreeStop{}, Language::English), "");
  const TreeStop budget{StopCause::Budget, 40, 40 * 160, 40};
  EXPECT_EQ(stopWords(budget, Language::English),
            "ray budget reached: the tree stops at 40 rays (0.0061 MiB, at most 40 rays); rays "
            "whose children did not fit end as 'stopped', and the estimate covers the rays traced");
  EXPECT_EQ(stopWords(budget, Language::Chinese),
            "光线预算已用完：光线树停在 40 条光线（0.0061 MiB，最多 40 条光线）；放不下子光线的"
            "光线以“已停止”结束，估计值只计入已追踪的光线");
  EXPECT_EQ(stopWords(TreeStop{StopCause::Cancelled, 12, 0, 0}, Language::English),
            "cancelled after 12 rays: the tree is cut short");
  const GridStop grid{StopCause::Budget, 3, 16, false, std::size_t(2) << 20};
  EXPECT_EQ(stopWords(grid, Language::English),
            "ray-tree memory budget (2 MiB) reached after 3 of 16 pixels; the last tree is cut "
            "short");
  EXPECT_EQ(stopWords(grid, Language::Chinese),
            "共 16 个像素，追踪到第 3 个时用完了光线树的内存预算（2 MiB）；最后一棵光线树不完整");
  EXPECT_EQ(stopWords(GridStop{StopCause::Cancelled, 2, 8, true, 0}, Language::English),
            "cancelled after 2 of 8 samples; the last tree is cut short");

  PixelTrace trace;
  trace.algorithm = Algorithm::Whitted;
  trace.x = 3;
  trace.y = 4;
  trace.sample = 2;
  trace.tree.segments.resize(1);
  trace.tree.segments[0].radiance = Vec3(0.5);
  EXPECT_EQ(traceHeading(trace, Language::English),
            "Whitted ray tracing (1979): pixel (3, 4), sample 2\n1 ray (camera 1), depth 0, "
            "estimate (0.5, 0.5, 0.5)");
  EXPECT_EQ(traceHeading(trace, Language::Chinese).rfind("Whitted 光线追踪", 0), 0u);
  EXPECT_NE(traceHeading(trace, Language::Chinese).find("：像素 (3, 4)，第 2 号样本\n1 条光线"),
            std::string::npos)
      << traceHeading(trace, Language::Chinese);
  trace.root = Ray::make(Point3(-8.0, 2.0, 0.0), Vec3(1.0, 0.0, 0.0));
  EXPECT_NE(traceHeading(trace, Language::English)
                .find(": a chosen ray from (-8, 2, 0) along (1, 0, 0)\n1 ray"),
            std::string::npos)
      << traceHeading(trace, Language::English);
  GridTrace g;
  g.traces.resize(4);
  g.combined.segments.resize(9);
  EXPECT_NE(gridHeading(Algorithm::PathTracing, 2, 2, g, Language::English)
                .find(": Simulate 2 x 2, 4 pixels, 9 rays"),
            std::string::npos);
  EXPECT_NE(gridHeading(Algorithm::PathTracing, 2, 2, g, Language::Chinese)
                .find("：仿真 2 × 2，4 个像素，9 条光线"),
            std::string::npos);
  EXPECT_NE(bundleHeading(Algorithm::Distributed, 5, 6, 0, g, Language::English)
                .find(": pixel (5, 6), samples 0 to 3 drawn together, 9 rays"),
            std::string::npos);
  EXPECT_NE(bundleHeading(Algorithm::Distributed, 5, 6, 0, g, Language::Chinese)
                .find("：像素 (5, 6)，第 0 到第 3 个采样画在一起，共 9 条光线"),
            std::string::npos);
}

// The inspector's rows and lines from an inspection's facts, in both languages: English
// in a column of 12, Chinese with its own field names and words, names in its quotes.
TEST(InspectorWords, 01_RowsAndLinesInBothLanguages) {
  RayInspection r;
  r.segment.id = 2;
  r.segment.kind = RayKind::Refraction;
  r.segment.depth = 1;
  r.segment.parent = 0;
  r.segment.hit = true;
  r.segment.object = 0;
  r.segment.endReason = EndReason::Absorbed;
  r.segment.pdf = 0.5;
  r.objectName = "glass";
  r.material = MaterialSummary{"clear", MaterialType::Dielectric, false, Material{}, std::nullopt};
  r.material->material.type = MaterialType::Dielectric;
  r.material->material.ior = 1.5;
  r.material->material.colour = Vec3(1.0);
  r.material->material.fresnel = FresnelModel::Schlick;
  r.rateWeight = RateWeight{false, 0.5, 0.75, true, FresnelModel::Schlick, 30.0};
  const std::string en = rayText(r, Language::English);
  EXPECT_EQ(en.rfind("Ray #2: refraction ray, depth 1, child of #0\n  origin      (0, 0, 0)\n", 0),
            0u)
      << en;
  EXPECT_NE(en.find("\n  material    'clear' (dielectric)\n  parameters  tint (1, 1, 1), ior 1.5 "
                    "(Schlick's Fresnel)\n"),
            std::string::npos)
      << en;
  EXPECT_NE(en.find("\n  weight      (1, 1, 1) = kt (1 - R) = 0.5 x 0.75 = 0.375 times the tint "
                    "(Schlick's Fresnel, incidence 30 degrees)\n"),
            std::string::npos)
      << en;
  EXPECT_NE(en.find("\n  pdf         0.5 per sr\n"), std::string::npos) << en;
  EXPECT_NE(en.find("\n  ended       hit 'glass' and was absorbed: no further ray leaves this "
                    "hit\n"),
            std::string::npos)
      << en;
  const std::string zh = rayText(r, Language::Chinese);
  EXPECT_EQ(zh.rfind("光线 #2：折射光线，深度 1，父光线为 #0\n  起点  (0, 0, 0)\n", 0), 0u) << zh;
  EXPECT_NE(zh.find("\n  材质  “clear” (电介质)\n  参数  色调 (1, 1, 1), ior 1.5 （Schlick "
                    "近似菲涅耳）\n"),
            std::string::npos)
      << zh;
  EXPECT_NE(zh.find("\n  权重  (1, 1, 1) = kt (1 - R) = 0.5 x 0.75 = 0.375 再乘以色调 (Schlick "
                    "近似菲涅耳, 入射角 30 度)\n"),
            std::string::npos)
      << zh;
  EXPECT_NE(zh.find("\n  结束方式  折射光线 #2 击中“glass”后被吸收：不再有光线从这个交点出发\n"),
            std::string::npos)
      << zh;
  EXPECT_EQ(oracleText(r, Language::English), "Exact oracle: not computed\n");
  EXPECT_EQ(oracleText(r, Language::Chinese), "精确判定器：未计算\n");
}

// The inspector's first lines (the window's "Where / What it carried / Why it stopped"),
// from the facts, in both languages: the words the window composed with tr() before, the
// Chinese as its .ts had it.
TEST(InspectorWords, 02_TheSummaryInBothLanguages) {
  RayInspection r;
  r.segment.kind = RayKind::Reflection;
  r.segment.depth = 2;
  r.segment.hit = true;
  r.segment.endReason = EndReason::Spawned;
  r.objectName = "ball";
  r.distance = 2.123456;
  r.energy = 0.25;
  EXPECT_EQ(inspectionSummary(r, 1.0, Language::English),
            "reflection ray, depth 2\nWhere: it hit 'ball', 2.123 units from where it started\n"
            "What it carried: 25.0% of the light this pixel sample found\n"
            "Why it stopped: spawned children\n");
  EXPECT_EQ(inspectionSummary(r, 1.0, Language::Chinese),
            "反射光线，深度 2\n去向：打中“ball”，距起点 2.123 个单位\n"
            "携带：这个像素采样所得光能的 25.0%\n为何终止：产生子光线\n");
  EXPECT_NE(inspectionSummary(r, 0.0, Language::English)
                .find("\nWhat it carried: no light (this sample found none)\n"),
            std::string::npos);
  r.segment.kind = RayKind::Shadow;
  r.segment.endReason = EndReason::Occluded;
  EXPECT_NE(inspectionSummary(r, 1.0, Language::English)
                .find("\nWhere: towards a light, but 'ball' is in the way, 2.123 units on\n"),
            std::string::npos);
  EXPECT_NE(inspectionSummary(r, 1.0, Language::Chinese)
                .find("\n去向：射向光源，但在 2.123 个单位处被“ball”挡住\n"),
            std::string::npos);
  r.segment.endReason = EndReason::ReachedLight;
  EXPECT_NE(inspectionSummary(r, 1.0, Language::English)
                .find("\nWhere: from the surface to a point on the light, 2.123 units away\n"),
            std::string::npos);
  r.segment.kind = RayKind::Camera;
  r.segment.hit = false;
  r.segment.endReason = EndReason::Escaped;
  EXPECT_NE(inspectionSummary(r, 1.0, Language::Chinese)
                .find("\n去向：没有打中任何物体，离开了场景\n携带：这个像素采样所得光能的 "
                      "25.0%\n为何终止：逃逸出场景\n"),
            std::string::npos);
}

TEST(Algorithms, 01_EveryAlgorithmHasOneRowWordsAndPhrases) {
  std::set<std::string> words;
  std::set<std::array<std::uint8_t, 3>> colours;
  for (Algorithm algorithm : kAllAlgorithms) {
    const AlgorithmInfo& info = algorithmInfo(algorithm);
    EXPECT_EQ(info.algorithm, algorithm);
    words.insert(info.word);
    colours.insert(info.colour);
    // The word round-trips through the parser files and the command line use.
    EXPECT_EQ(parseAlgorithm(info.word), algorithm);
    EXPECT_STREQ(toString(algorithm), info.word);
    for (const char* suffix : {"", ".long"})
      EXPECT_TRUE(hasPhrase(std::string("algorithm.") + info.word + suffix)) << info.word << suffix;
  }
  EXPECT_EQ(words.size(), kAllAlgorithms.size());
  EXPECT_EQ(colours.size(), kAllAlgorithms.size()) << "two algorithms share a colour";
  EXPECT_EQ(algorithmWordList(), "raycast, whitted, distributed or path");
}

TEST(Algorithms, 02_TitlesReadAsThePanelsAndTheWindowWroteThem) {
  // The strings the comparison panels, the plots, `compare --json` and the window's lists
  // wrote before the table existed (their baselines and translations hold them).
  EXPECT_EQ(algorithmTitle(Algorithm::RayCasting), "Ray casting (Appel 1968)");
  EXPECT_EQ(algorithmTitle(Algorithm::Whitted), "Whitted (1979)");
  EXPECT_EQ(algorithmTitle(Algorithm::Distributed), "Distributed (Cook 1984)");
  EXPECT_EQ(algorithmTitle(Algorithm::PathTracing), "Path tracing (Kajiya 1986)");
  EXPECT_EQ(algorithmTitle(Algorithm::Whitted, Language::English, AlgorithmName::Long),
            "Whitted ray tracing (1979)");
  EXPECT_EQ(algorithmTitle(Algorithm::Distributed, Language::English, AlgorithmName::Long),
            "Distributed ray tracing (Cook 1984)");
  EXPECT_EQ(algorithmTitle(Algorithm::Whitted, Language::Chinese), "Whitted 光线追踪（1979）");
  EXPECT_EQ(algorithmTitle(Algorithm::PathTracing, Language::Chinese), "路径追踪（Kajiya 1986）");
  EXPECT_EQ(algorithmTitle(Algorithm::Distributed, Language::Chinese, AlgorithmName::Long),
            "分布式光线追踪（Cook 1984）");
  EXPECT_EQ(algorithmTitleTwoLines(Algorithm::Whitted, Language::English), "Whitted\n1979");
  EXPECT_EQ(algorithmTitleTwoLines(Algorithm::RayCasting, Language::Chinese),
            "光线投射\nAppel 1968");
  EXPECT_EQ(algorithmCitation(Algorithm::PathTracing), "Kajiya 1986");
}
