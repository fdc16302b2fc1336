#include "palette/prime/color_num.h"

#include <cmath>

#include "src/prime/math/listing_math.h"

namespace prime {

namespace {

// `(int)floor(c * k)`. Turbo C converted through the 8087 (a 64-bit FISTP,
// keeping the low word). NaN, and values outside the 64-bit range, give the
// "integer indefinite" 0x8000000000000000, whose low bits are 0: level 0
// (shading.md S10). Otherwise the exact integer.
std::int64_t level(double c, double k) {
  const double f = floorExact(c * k);  // std::floor, without the call
  constexpr double kTwo63 = 9223372036854775808.0;
  if (std::isnan(f) || f >= kTwo63 || f < -kTwo63) return 0;
  return static_cast<std::int64_t>(f);
}

// r*32 + g*4 + b style sums, computed modulo 2^64 and returned modulo 2^32
// (well defined for any level; exact for every realistic colour).
int wrapIndex(std::uint64_t sum) {
  return static_cast<int>(static_cast<std::uint32_t>(sum));
}

int finish(int r, ColorNumCounters* counters) {
  r = (r != 0) ? r : 1;  // E15: `return((r != 0)?r:1);`
  if (counters != nullptr && (r < 0 || r > 255)) ++counters->outOfRange;
  return r;
}

}  // namespace

int colorNum(const Rgb& color, int graphType, ColorNumCounters* counters) {
  (void)graphType;  // `if(graphType == 0)` and its `else` are identical (E15)
  if (counters != nullptr &&
      (std::isnan(color[0]) || std::isnan(color[1]) || std::isnan(color[2]))) {
    ++counters->nanColours;
  }
  const auto r = static_cast<std::uint64_t>(level(color[0], 7));
  const auto g = static_cast<std::uint64_t>(level(color[1], 7));
  const auto b = static_cast<std::uint64_t>(level(color[2], 3));
  return finish(wrapIndex(r * 32u + g * 4u + b), counters);
}

int colorNumPlate3(const Rgb& color, ColorNumCounters* counters) {
  if (counters != nullptr && (std::isnan(color[0]) || std::isnan(color[1]))) {
    ++counters->nanColours;
  }
  const auto r4 = static_cast<std::uint64_t>(level(color[0], 15));
  const auto g4 = static_cast<std::uint64_t>(level(color[1], 15));
  return finish(wrapIndex(16u * r4 + g4), counters);
}

PaletteTable initPalette() {
  PaletteTable p{};
  int i = 0;
  for (int r = 0; r < 256; r += 32) {
    for (int g = 0; g < 256; g += 32) {
      for (int b = 0; b < 256; b += 64) p[static_cast<std::size_t>(i++)] = {r, g, b};
    }
  }
  // The overrides, in the listing's order (K17).
  p[0] = {0, 0, 0};
  p[1] = {80, 178, 60};
  p[2] = {255, 0, 40};
  p[3] = {150, 239, 130};
  p[4] = {145, 25, 180};
  p[5] = {255, 255, 0};
  p[6] = {234, 209, 240};
  p[20] = {0, 100, 100};
  p[8] = {255, 255, 255};
  p[9] = {90, 95, 255};
  p[7] = {135, 135, 250};
  return p;
}

PaletteTable plate3Palette() {
  PaletteTable p{};
  for (int r4 = 0; r4 < 16; ++r4) {
    for (int g4 = 0; g4 < 16; ++g4)
      p[static_cast<std::size_t>(16 * r4 + g4)] = {r4 * 17, g4 * 17, 0};
  }
  return p;
}

}  // namespace prime
