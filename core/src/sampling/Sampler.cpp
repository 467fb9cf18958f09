#include "raylab/core/Sampler.h"

namespace raylab {

namespace {

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

}  // namespace

Sampler::Sampler(std::uint64_t seed, int x, int y, int sampleIndex) {
  // Hash the stream's coordinates into one key: a chain of splitmix64 rounds, one per
  // field. Negative pixel coordinates are allowed (they wrap as 32-bit words).
  std::uint64_t key = mix64(seed);
  key = combine(key, static_cast<std::uint32_t>(x), 0x243f6a8885a308d3ull);
  key = combine(key, static_cast<std::uint32_t>(y), 0x13198a2e03707344ull);
  key = combine(key, static_cast<std::uint32_t>(sampleIndex), 0xa4093822299f31d0ull);
  m_key = key;
}

double Sampler::next1D() {
  // Hash (key, dimension), then keep the top 53 bits: every double k / 2^53 in [0, 1)
  // is equally likely, and 1.0 is never returned.
  const std::uint64_t bits = combine(m_key, m_dimension, 0x082efa98ec4e6c89ull);
  ++m_dimension;
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

}  // namespace raylab
