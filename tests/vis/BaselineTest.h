#pragma once

#include "raylab/vis/Image.h"

#include <string>

namespace raylab::testing {

using namespace raylab::vis;  // the tests speak vis's types unqualified

/// Default for expectMatchesBaseline, on compareImages' scale (see Image.h for the
/// measurements it rests on): 2e-4 is ~18 pixels of a 300x300 picture completely wrong.
/// It forgives a 1-degree turn of the view (6e-7) and driver noise up to 20 levels per
/// channel, and catches a missing light cube (4.4e-4), a sphere moved by 0.3 units
/// (3.8e-4), a selection outline (5.8e-4) and any recoloured object (>= 4.9e-3).
constexpr double kDefaultBaselineThreshold = 2e-4;

/**
 * \brief Compares a rendering with tests/baselines/<name>.png (gtest expectation).
 *
 * When the baseline is missing, writes the image to <build>/Testing/Temporary/<name>.png
 * and fails, saying how to bless it. When compareImages exceeds `threshold`, writes the
 * image there too and fails, printing the error, the threshold and both sizes.
 */
void expectMatchesBaseline(const SrgbImage& image, const std::string& name,
                           double threshold = kDefaultBaselineThreshold);

}  // namespace raylab::testing
