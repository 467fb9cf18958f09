#pragma once

#include "raylab/core/Types.h"

#include <cstdint>

namespace raylab {

/**
 * \brief Deterministic random numbers for one (pixel, sample): a counter-based generator.
 *
 * Each value is a hash of (seed, pixel, sample index, dimension), so any path can be
 * replayed exactly — by the image renderer, by the stepper, on any thread, in any order
 * (pbrt's IndependentSampler::StartPixelSample; never `rand()`). Dimensions are consumed
 * in the order the tracer asks for them.
 */
class Sampler {
 public:
  /// Starts the stream for pixel (x, y), sample `sampleIndex`, under `seed`.
  Sampler(std::uint64_t seed, int x, int y, int sampleIndex);

  /// Uniform double in [0, 1).
  double next1D();
  /// Two uniform doubles in [0, 1)^2.
  Vec2 next2D() { return {next1D(), next1D()}; }
  /// Jumps to a given dimension (to decorrelate branches that spawn a variable number of rays).
  void setDimension(std::uint64_t dimension) { m_dimension = dimension; }
  std::uint64_t dimension() const { return m_dimension; }

 private:
  std::uint64_t m_key;
  std::uint64_t m_dimension = 0;
};

}  // namespace raylab
