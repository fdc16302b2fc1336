// The IBM 8514/A colour lookup table as the hardware held it, and how its
// 6-bit entries are shown on a modern 8-bit-per-channel display.
//
// setrgbpalette(colornum, red, green, blue) takes 0..255 per channel, but the
// 8514/A's DAC stores 6 bits per channel (262,144 colours). Borland's
// documentation of setrgbpalette for the IBM 8514 driver: "Only the lower byte
// of red, green, or blue is used, and out of each byte, only the 6 most
// significant bits are loaded in the palette" (errata Q13). So InitPalette's
// red 224 becomes DAC 56 of 63, and 80 and 83 are the same colour.
//
// The tables keep the 6-bit values; they become 8-bit only when presented
// (DacTo8). docs/prime/palette.md explains why rounding is the default.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "palette/prime/color_num.h"

namespace prime {

// One lookup-table entry as the DAC holds it: 0..63 per channel.
struct Dac6 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Dac6&) const = default;
};
using DacTable = std::array<Dac6, 256>;

// What setrgbpalette loads into the DAC from one 0..255 argument.
constexpr std::uint8_t setrgbToDac6(int v) {
  return static_cast<std::uint8_t>((v & 0xFF) >> 2);
}

// The DAC after setrgbpalette(i, t[i].r, t[i].g, t[i].b) for every i.
DacTable loadDac(const PaletteTable& setrgbpaletteCalls);

// The three 6-bit -> 8-bit conversions emulators use. The DAC's analogue
// output is proportional to v/63 of full scale, so:
//   Round      (v*255 + 31) / 63   nearest 8-bit level to v/63 (the default)
//   Replicate  (v << 2) | (v >> 4) bit replication (DOSBox, MAME); within 1 of Round
//   Truncate   v*255 / 63          always rounds down; within 1 of Round
// All three map 0 -> 0 and 63 -> 255.
enum class DacTo8 { Round, Replicate, Truncate };
inline constexpr DacTo8 kDefaultDacTo8 = DacTo8::Round;

constexpr std::uint8_t dacTo8(int v6, DacTo8 how) {
  const int v = v6 & 0x3F;
  switch (how) {
    case DacTo8::Replicate:
      return static_cast<std::uint8_t>((v << 2) | (v >> 4));
    case DacTo8::Truncate:
      return static_cast<std::uint8_t>(v * 255 / 63);
    case DacTo8::Round:
      break;
  }
  return static_cast<std::uint8_t>((v * 255 + 31) / 63);
}

std::string_view dacTo8Name(DacTo8 how);                      // "round", "replicate", "truncate"
std::optional<DacTo8> dacTo8FromName(std::string_view name);  // the inverse; nullopt if unknown
// The rule as a formula and its inverse, for what a picture says about
// itself (a PNG's "DAC to 8 bits" text): "round: v8 = (v6 * 255 + 31) / 63, ...".
std::string_view dacTo8Rule(DacTo8 how);

// A colour on an 8-bit-per-channel display (PNG, window).
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};
// What each of the 256 indices looks like on the screen.
using Rgb8Table = std::array<Rgb8, 256>;

Rgb8Table present(const DacTable& dac, DacTo8 how = kDefaultDacTo8);

}  // namespace prime
