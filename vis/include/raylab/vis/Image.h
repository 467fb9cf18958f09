#pragma once

#include "raylab/core/Image.h"

namespace raylab::vis {

/// Per-channel difference (0..255) that compareImages forgives as shading noise. VTK's
/// default, 105, forgives far too much: it scores a missing flesh-coloured light in front
/// of a grey wall as 0.
constexpr int kCompareChannelTolerance = 20;

/**
 * \brief Difference between two renderings of the same view, on a fixed scale in [0, 1].
 *
 * Wraps VTK 9.1's `vtkImageDifference` and divides its sum by the pixel count. For each
 * pixel VTK looks for the best match in the other image among the pixel itself, its 8
 * neighbours (AllowShift: forgives a one-pixel shift between GL drivers) and 3x3 averages
 * (Averaging: forgives anti-aliased edges); it subtracts kCompareChannelTolerance from
 * each channel's difference, clamps at 0, and the pixel adds (r + g + b) / (3 * 255).
 *
 * Measured on this scale (300x300 pictures):
 *  - identical, or shifted by one pixel: 0; black against (20, 20, 20): 0;
 *  - black against white: 0.90 (near the maximum, (255 - 20) / 255 = 0.92); against
 *    mid-grey: 0.42;
 *  - a 100x100 pure red square (11% of the pixels) missing on black: 0.034;
 *  - the default scene's view (tests/vis/TestSceneView) turned by 1 degree: 6e-7, by
 *    2 degrees: 1.1e-4, by 3: 9.6e-4; its light cube removed: 4.4e-4; its sphere moved
 *    by 0.3 units: 3.8e-4; the sphere selected (yellow outline): 5.8e-4; its cube
 *    recoloured green: 4.9e-3; its walls darkened from 0.75 to 0.6 grey: 0.010.
 *
 * Images of different sizes give 1.0. When Debian ships VTK >= 9.4, switch to
 * `vtkImageSSIM` and rescale the thresholds.
 */
double compareImages(const SrgbImage& a, const SrgbImage& b);

/// `image` enlarged by the largest whole factor that keeps it within maxWidth x maxHeight,
/// each pixel a square block of its colour (nearest neighbour, no smoothing), so a small
/// render shows its pixels (lesson 5's stair steps); unchanged when no factor of 2 or more
/// fits.
SrgbImage enlargedToFit(const SrgbImage& image, int maxWidth, int maxHeight);

}  // namespace raylab::vis
