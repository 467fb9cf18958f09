#pragma once

#include "raylab/core/Types.h"

#include <cstdint>

namespace raylab {

namespace detail {
/// The splitmix64 finaliser (Steele, Lea and Flood, "Fast Splittable Pseudorandom Number
/// Generators", OOPSLA 2014): a bijection of 64-bit words whose output bits each depend
/// on every input bit. Used as a hash, it turns counters into independent-looking words.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
/// Folds one more value into a running hash; the constant separates the fields, so
/// (x, y) = (1, 2) and (2, 1) give different keys.
constexpr std::uint64_t combine(std::uint64_t key, std::uint64_t value, std::uint64_t field) {
  return mix64(key ^ mix64(value + field));
}
}  // namespace detail

/**
 * \brief Deterministic random numbers for one (pixel, sample): a counter-based generator.
 *
 * Each value is a hash of (seed, pixel, sample index, dimension), so any path can be
 * replayed exactly — by the image renderer, by the stepper, on any thread, in any order
 * (pbrt's IndependentSampler::StartPixelSample; never `rand()`). Dimensions are consumed
 * in the order the tracer asks for them.
 *
 * next2D() gives two independent uniforms. nextStratified2D() gives instead the next point of
 * an Owen-scrambled Sobol (0,2)-sequence, one sequence per (seed, pixel, dimension pair), with
 * the sample index shuffled per pair (Burley 2020, "Practical Hash-based Owen Scrambling",
 * JCGT 9(4)): over the samples of one pixel the pairs drawn at one dimension are stratified
 * (the first 2^m samples put exactly one point in every elementary interval of area 2^-m,
 * whatever its shape), while each point alone is still uniform in [0, 1)^2 and independent
 * of the other dimension pairs and pixels. The camera draws its film and lens samples so.
 */
class Sampler {
 public:
  /// Starts the stream for pixel (x, y), sample `sampleIndex`, under `seed`.
  Sampler(std::uint64_t seed, int x, int y, int sampleIndex);

  /// Uniform double in [0, 1).
  /// The next uniform in [0, 1): a hash of (key, dimension), its top 53 bits, so every
  /// double k / 2^53 in [0, 1) is equally likely and 1.0 is never returned. (Inline: a
  /// path sample draws some thirty.)
  double next1D() {
    const std::uint64_t bits = detail::combine(m_key, m_dimension, 0x082efa98ec4e6c89ull);
    ++m_dimension;
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
  }
  /// Two uniform doubles in [0, 1)^2.
  Vec2 next2D() { return {next1D(), next1D()}; }
  /**
   * \brief A point of this pixel's stratified sequence for the next two dimensions.
   *
   * Sample i of pixel (x, y) at dimension d gets point shuffle(i) of the Sobol (0,2)-sequence
   * Owen-scrambled by a hash of (seed, x, y, d). Uniform in [0, 1)^2 (32-bit resolution);
   * consumes two dimensions, like next2D().
   */
  Vec2 nextStratified2D();
  /// Jumps to a given dimension (to decorrelate branches that spawn a variable number of rays).
  void setDimension(std::uint64_t dimension) { m_dimension = dimension; }
  std::uint64_t dimension() const { return m_dimension; }

 private:
  std::uint64_t m_key;          ///< Hash of (seed, pixel, sample): the next1D() stream.
  std::uint64_t m_pixelKey;     ///< Hash of (seed, pixel): the scrambles of nextStratified2D().
  std::uint32_t m_sampleIndex;  ///< The sample index, shuffled by nextStratified2D().
  std::uint64_t m_dimension = 0;
};

}  // namespace raylab
