#include "raylab/core/AlgorithmInfo.h"

#include "raylab/core/Check.h"
#include "raylab/core/Phrases.h"

namespace raylab {

namespace {

// One row per algorithm, in kAllAlgorithms' order. Colours: Okabe and Ito's palette, told
// apart with any colour vision (orange, bluish green, blue, vermillion).
constexpr AlgorithmInfo kTable[] = {
    {Algorithm::RayCasting, "raycast", "Appel", 1968, {230, 159, 0}},
    {Algorithm::Whitted, "whitted", "Whitted", 1979, {0, 158, 115}},
    {Algorithm::Distributed, "distributed", "Cook", 1984, {0, 114, 178}},
    {Algorithm::PathTracing, "path", "Kajiya", 1986, {213, 94, 0}},
};
static_assert(std::size(kTable) == kAllAlgorithms.size());

std::string nameOf(Algorithm algorithm, Language language, AlgorithmName form) {
  const std::string key = std::string("algorithm.") + algorithmInfo(algorithm).word;
  return phrase(form == AlgorithmName::Long ? key + ".long" : key, language);
}

// The citation after a name: the year alone when the name already says who.
std::string citationAfter(const std::string& name, Algorithm algorithm) {
  const AlgorithmInfo& info = algorithmInfo(algorithm);
  return name.find(info.author) != std::string::npos ? std::to_string(info.year)
                                                     : algorithmCitation(algorithm);
}

}  // namespace

const AlgorithmInfo& algorithmInfo(Algorithm algorithm) {
  for (const AlgorithmInfo& info : kTable)
    if (info.algorithm == algorithm) return info;
  RAYLAB_CHECK(false && "an algorithm without a row in the table");
  return kTable[0];
}

std::vector<std::string> algorithmWords() {
  std::vector<std::string> words;
  for (Algorithm algorithm : kAllAlgorithms) words.emplace_back(algorithmInfo(algorithm).word);
  return words;
}

std::string algorithmWordList() {
  const std::vector<std::string> words = algorithmWords();
  std::string list;
  for (std::size_t i = 0; i < words.size(); ++i)
    list += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return list;
}

std::string algorithmCitation(Algorithm algorithm) {
  const AlgorithmInfo& info = algorithmInfo(algorithm);
  return std::string(info.author) + " " + std::to_string(info.year);
}

std::string algorithmTitle(Algorithm algorithm, Language language, AlgorithmName form) {
  const std::string name = nameOf(algorithm, language, form);
  return phrase("algorithm.title", language,
                {{"name", name}, {"citation", citationAfter(name, algorithm)}});
}

std::string algorithmTitleTwoLines(Algorithm algorithm, Language language) {
  const std::string name = nameOf(algorithm, language, AlgorithmName::Short);
  return name + "\n" + citationAfter(name, algorithm);
}

}  // namespace raylab
