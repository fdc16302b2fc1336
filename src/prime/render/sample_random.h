// Counter-based random numbers for sampling: a number is a pure function of
// its key (seed, row, column, sample index, dimension), so a render draws the
// same numbers whichever thread renders which row, in whatever order, and a
// pixel's k-th sample is the same however many samples follow it. The mixing
// is SplitMix64's finaliser (Steele, Lea and Flood, "Fast splittable
// pseudorandom number generators", OOPSLA 2014) applied to the key's words in
// turn: cheap, no state, no allocation.
#pragma once
#include <cstdint>

namespace prime {

constexpr std::uint64_t splitMix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// 64 random bits for the key.
constexpr std::uint64_t sampleBits(std::uint64_t seed, std::uint64_t row, std::uint64_t column,
                                   std::uint64_t index, std::uint64_t dimension) {
  std::uint64_t h = splitMix64(seed);
  h = splitMix64(h ^ row);
  h = splitMix64(h ^ (column << 1));
  h = splitMix64(h ^ index);
  return splitMix64(h ^ (dimension * 0x632be59bd9b4e019ULL));
}

// A uniform number in [0, 1): the top 53 bits of sampleBits.
constexpr double sampleUniform(std::uint64_t seed, std::uint64_t row, std::uint64_t column,
                               std::uint64_t index, std::uint64_t dimension) {
  return static_cast<double>(sampleBits(seed, row, column, index, dimension) >> 11) * 0x1.0p-53;
}

// The radical inverse of k in base 2 (van der Corput) and base 3: the
// first two dimensions of the Halton sequence, whose first n points are
// stratified for every n (soft-shadow points over a pixel's samples).
constexpr double radicalInverse2(std::uint32_t k) {
  std::uint32_t b = k;
  b = (b << 16) | (b >> 16);
  b = ((b & 0x00ff00ffu) << 8) | ((b & 0xff00ff00u) >> 8);
  b = ((b & 0x0f0f0f0fu) << 4) | ((b & 0xf0f0f0f0u) >> 4);
  b = ((b & 0x33333333u) << 2) | ((b & 0xccccccccu) >> 2);
  b = ((b & 0x55555555u) << 1) | ((b & 0xaaaaaaaau) >> 1);
  return static_cast<double>(b) * 0x1.0p-32;
}
constexpr double radicalInverse3(std::uint32_t k) {
  double r = 0.0, f = 1.0 / 3.0;
  while (k > 0) {
    r += f * static_cast<double>(k % 3);
    k /= 3;
    f /= 3.0;
  }
  return r;
}

}  // namespace prime
