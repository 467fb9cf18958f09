#pragma once

#include "raylab/core/Comparison.h"
#include "raylab/core/Language.h"
#include "raylab/core/RayTree.h"

#include <cstdint>
#include <string>
#include <vector>

/// \file ComparisonCaptions.h
/// The words of a comparison of the four algorithms: what the picture's header band, each
/// panel's figures, the explanation of the error and `raylab compare`'s printout say. One
/// wording, used by all of them, in English or Simplified Chinese (UTF-8).

namespace raylab::vis {

/// "12.3 ms", "0.52 s", "12.5 s": a duration for the figures (the same in both languages).
std::string formatSeconds(double seconds);
/// "950", "12.3 k", "4.56 M", "1.23 G": a count for the figures.
std::string formatCount(std::uint64_t count);
/// An error figure: three decimals ("0.150"), as the panels and the explanation show it.
std::string formatError(double rmse);

/// A kind of ray in the figures: "shadow"; "阴影光线".
std::string rayKindName(RayKind kind, Language language = Language::English);

/// The budget the algorithms shared: "equal samples: 16 spp each" or "equal time: 500 ms
/// each"; "等采样数：每种算法 16 spp", "等时间：每种算法 500 ms".
std::string budgetPhrase(const ComparisonResult& result, Language language = Language::English);
/// What the errors are measured against: "path tracing at 256 spp" (or the reference
/// file's name); "路径追踪 256 spp".
std::string referencePhrase(const ComparisonResult& result, Language language = Language::English);
/// The header band: scene, size, budget, and what the error is measured against.
std::string headerLine(const ComparisonResult& result, Language language = Language::English);
/// The index into result.algorithms of the lowest error, or -1 when there is none or
/// it is shared, as printed (formatError): 0.09565 and 0.09590 both read 0.096.
int lowestErrorIndex(const ComparisonResult& result);
/// The lines of one algorithm's figures under its title: spp (reached, in time), error
/// against the reference (marked "lowest" for the lowest), rays (per second) and rays by
/// kind.
std::vector<std::string> figureLines(const ComparisonResult& result,
                                     const AlgorithmFigures& figures, bool showTimes,
                                     Language language = Language::English);
/**
 * \brief What the error figure means, shown where the figures are: the first line says
 * what it measures (RMSE of the displayed picture against the path-traced reference at N
 * spp, 0 = identical), the second why path tracing, which looks the noisiest, has the
 * lowest error (its noise averages away, the others' missing light does not) — or, when
 * at these few samples it does not yet, that it will with more.
 */
std::vector<std::string> errorExplanation(const ComparisonResult& result,
                                          Language language = Language::English);

}  // namespace raylab::vis
