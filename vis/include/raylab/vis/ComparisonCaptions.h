#pragma once

#include "raylab/core/Comparison.h"

#include <cstdint>
#include <string>
#include <vector>

/// \file ComparisonCaptions.h
/// The words of a comparison of the four algorithms: what the picture's header band, each
/// panel's figures and `raylab compare`'s printout say. One wording, used by all of them.

namespace raylab::vis {

/// "12.3 ms", "0.52 s", "12.5 s": a duration for the figures.
std::string formatSeconds(double seconds);
/// "950", "12.3 k", "4.56 M", "1.23 G": a count for the figures.
std::string formatCount(std::uint64_t count);
/// The budget the algorithms shared: "equal samples: 16 spp each" or "equal time: 500 ms
/// each".
std::string budgetPhrase(const ComparisonResult& result);
/// The header band: scene, size, budget, and what the error is measured against.
std::string headerLine(const ComparisonResult& result);
/// The lines of one algorithm's figures under its title: spp (reached, in time), error
/// against the reference, rays (per second) and rays by kind.
std::vector<std::string> figureLines(const ComparisonResult& result,
                                     const AlgorithmFigures& figures, bool showTimes);

}  // namespace raylab::vis
