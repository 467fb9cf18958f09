#pragma once

#include "raylab/core/Language.h"
#include "raylab/core/RenderSettings.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/**
 * \brief What RayLab knows of each of its algorithms, in one table: the word scene files,
 * lessons, the command line and Python use, the paper it comes from, and its colour in
 * comparisons and plots. Every list, menu, caption and test reads this table, so a fifth
 * algorithm is one more row here, its words in the phrase table and its rule (SpawnRule.cpp).
 * The names people read are in the phrase table (`algorithm.<word>`, `algorithm.<word>.long`).
 */
struct AlgorithmInfo {
  Algorithm algorithm;                 ///< The enum value.
  const char* word;                    ///< "whitted": files, lessons, the command line, Python.
  const char* author;                  ///< "Whitted": the first author of the paper.
  int year;                            ///< 1979: the year the algorithm was presented.
  std::array<std::uint8_t, 3> colour;  ///< sRGB colour of its panel band and curve (Okabe–Ito).
};

/// Every algorithm, in historical order (the order of every list and comparison).
inline constexpr std::array<Algorithm, 4> kAllAlgorithms = {
    Algorithm::RayCasting, Algorithm::Whitted, Algorithm::Distributed, Algorithm::PathTracing};

/// The table's row of `algorithm`.
const AlgorithmInfo& algorithmInfo(Algorithm algorithm);

/// "raycast", "whitted", "distributed", "path": the words, in historical order.
std::vector<std::string> algorithmWords();

/// "raycast, whitted, distributed or path": the words for a message or --help.
std::string algorithmWordList();

/// How an algorithm is named.
enum class AlgorithmName {
  Short,  ///< "Whitted (1979)", "Ray casting (Appel 1968)": panels, plots, JSON titles.
  Long,   ///< "Whitted ray tracing (1979)": the window's lists and status lines.
};

/// The algorithm's name with its citation, in `language`: "Path tracing (Kajiya 1986)",
/// "路径追踪（Kajiya 1986）"; the year alone where the name holds the author ("Whitted (1979)").
std::string algorithmTitle(Algorithm algorithm, Language language = Language::English,
                           AlgorithmName form = AlgorithmName::Short);

/// The name alone ("Whitted", "路径追踪") and, on the next line, the citation (the year
/// alone where the name holds the author): a comparison panel's two-line title.
std::string algorithmTitleTwoLines(Algorithm algorithm, Language language);

/// "Kajiya 1986".
std::string algorithmCitation(Algorithm algorithm);

}  // namespace raylab
