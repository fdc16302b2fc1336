// The IBM 8514/A's colour lookup: setrgbpalette takes 0..255 per channel, the
// DAC keeps the six most significant bits (errata Q13), and we present the
// 6-bit value on an 8-bit screen as round(v6 * 255 / 63).
#pragma once
#include <cstdint>

#include "palette/color_num.h"
#include "palette/png_image.h"

namespace prime {

inline int dac6(int v8) { return (v8 & 0xFF) >> 2; }
inline std::uint8_t dacTo8(int v6) { return static_cast<std::uint8_t>((v6 * 255 + 31) / 63); }

// The screen colour of palette `index` (masked to 8 bits as putpixel does, Q12).
inline void indexToRgb8(const PaletteTable& table, int index, std::uint8_t out[3]) {
  const PaletteRgb& c = table[static_cast<std::size_t>(index & 0xFF)];
  out[0] = dacTo8(dac6(c.r));
  out[1] = dacTo8(dac6(c.g));
  out[2] = dacTo8(dac6(c.b));
}

}  // namespace prime
