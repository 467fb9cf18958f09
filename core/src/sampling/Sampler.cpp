#include "raylab/core/Sampler.h"

namespace raylab {

namespace {

using detail::combine;  // Sampler.h: the hash, inline there for next1D
using detail::mix64;

/// Reverses the order of the 32 bits of x (bit 0 becomes bit 31): the bytes by one byte
/// swap (an instruction), then the nibbles, pairs and bits within each byte.
constexpr std::uint32_t reverseBits(std::uint32_t x) {
  x = __builtin_bswap32(x);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}
static_assert(reverseBits(1u) == 0x80000000u && reverseBits(0x12345678u) == 0x1e6a2c48u);

/// A seeded bijection of 32-bit words in which each bit is flipped by a function of the seed
/// and of the bits below it only (Laine and Karras 2011, with Burley's constants): adding the
/// seed carries upwards only, and x ^= x * even never touches a bit from itself or above.
constexpr std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

/// Owen scrambling of a 32-bit fixed-point value in [0, 1): read with its most significant bit
/// first, each digit is flipped by a function of the seed and of the digits before it (the
/// Laine-Karras permutation on the reversed bits). Applied to a sample index it is a shuffle
/// that maps every aligned block of 2^m indices onto an aligned block of 2^m indices.
constexpr std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
  return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

/// The generator matrix of Sobol's second dimension, one column per index bit: column 0 is
/// 1/2 and each next column is c ^ (c >> 1) (Pascal's triangle mod 2, primitive polynomial
/// x + 1). Stored as the products of the matrix with every byte value at each of the four
/// byte positions of the index, so a product costs four look-ups instead of a 32-step loop
/// whose branches a shuffled index makes unpredictable.
struct SobolMatrix {
  std::uint32_t byByte[4][256];
  constexpr SobolMatrix() : byByte() {
    std::uint32_t columns[32] = {};
    std::uint32_t c = 0x80000000u;
    for (std::uint32_t& column : columns) {
      column = c;
      c ^= c >> 1;
    }
    for (int position = 0; position < 4; ++position)
      for (int value = 0; value < 256; ++value)
        for (int bit = 0; bit < 8; ++bit)
          if (value & (1 << bit)) byByte[position][value] ^= columns[8 * position + bit];
  }
};
constexpr SobolMatrix kSobolDimension1;

/// The first two dimensions of the Sobol sequence, as 32-bit fixed point: the first is the
/// van der Corput radical inverse (the identity generator matrix), the second multiplies the
/// index bits by kSobolDimension1 over GF(2). Together they form a (0,2)-sequence in base 2.
constexpr std::uint32_t sobol0(std::uint32_t index) { return reverseBits(index); }
constexpr std::uint32_t sobol1(std::uint32_t index) {
  return kSobolDimension1.byByte[0][index & 0xffu] ^
         kSobolDimension1.byByte[1][(index >> 8) & 0xffu] ^
         kSobolDimension1.byByte[2][(index >> 16) & 0xffu] ^
         kSobolDimension1.byByte[3][index >> 24];
}

// The first points of the second dimension: 0, 1/2, 3/4, 1/4, 5/8 (direction numbers
// m = 1, 3, 5, 15 of Joe and Kuo, in index order rather than Gray-code order).
static_assert(sobol1(1) == 0x80000000u && sobol1(2) == 0xc0000000u && sobol1(3) == 0x40000000u &&
              sobol1(4) == 0xa0000000u && sobol1(8) == 0xf0000000u);

}  // namespace

Sampler::Sampler(std::uint64_t seed, int x, int y, int sampleIndex) {
  // Hash the stream's coordinates into one key: a chain of splitmix64 rounds, one per
  // field. Negative pixel coordinates are allowed (they wrap as 32-bit words).
  std::uint64_t key = mix64(seed);
  key = combine(key, static_cast<std::uint32_t>(x), 0x243f6a8885a308d3ull);
  key = combine(key, static_cast<std::uint32_t>(y), 0x13198a2e03707344ull);
  m_pixelKey = key;
  m_sampleIndex = static_cast<std::uint32_t>(sampleIndex);
  key = combine(key, static_cast<std::uint32_t>(sampleIndex), 0xa4093822299f31d0ull);
  m_key = key;
}

Vec2 Sampler::nextStratified2D() {
  // One hash of (seed, pixel, dimension) seeds the shuffle and the two scrambles.
  const std::uint64_t h = combine(m_pixelKey, m_dimension, 0xbe5466cf34e90c6cull);
  const std::uint64_t h2 = mix64(h);
  m_dimension += 2;
  // Shuffle the sample index, so that dimension pairs do not share the same sequence order.
  const std::uint32_t index = nestedUniformScramble(m_sampleIndex, static_cast<std::uint32_t>(h));
  // Owen-scramble the Sobol point: uniform in [0, 1)^2 and still a (0,2)-sequence.
  const std::uint32_t x = nestedUniformScramble(sobol0(index), static_cast<std::uint32_t>(h >> 32));
  const std::uint32_t y = nestedUniformScramble(sobol1(index), static_cast<std::uint32_t>(h2));
  return {static_cast<double>(x) * 0x1.0p-32, static_cast<double>(y) * 0x1.0p-32};
}

}  // namespace raylab
