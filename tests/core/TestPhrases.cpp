// The phrase table (core/src/words/phrases.json) and the algorithm table (AlgorithmInfo.h):
// every phrase exists in both languages with the same placeholders, and the algorithms'
// names read as they did when each front end spelled them itself.

#include "raylab/core/AlgorithmInfo.h"
#include "raylab/core/Phrases.h"
#include "raylab/core/RayTree.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

using namespace raylab;

namespace {

/// The `{name}` placeholders of a text, as a set.
std::set<std::string> placeholders(const std::string& text) {
  std::set<std::string> names;
  const std::regex mark(R"(\{([a-z_]+)\})");
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
    EXPECT_EQ(placeholders(en), placeholders(zh)) << key;
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
