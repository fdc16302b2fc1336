// Graph module (lines 3821-3967): the colour-number mapping ColorNum and the
// lookup table InitPalette builds, plus the Colour Plate 3 variant (X1).
// Tables and mappings only; the DAC model, window and PNG come later.
#pragma once
#include <array>
#include <cstdint>

#include "src/math/rgb.h"

namespace prime {

// One setrgbpalette() entry, 0..255 per component as the listing passes them.
struct PaletteRgb {
  int r = 0;
  int g = 0;
  int b = 0;
  bool operator==(const PaletteRgb&) const = default;
};
using PaletteTable = std::array<PaletteRgb, 256>;

// X3 diagnostics for ColorNum, owned by the caller (e.g. one per thread).
struct ColorNumCounters {
  std::uint64_t nanColours = 0;  // a NaN in a channel the mapping uses
  std::uint64_t outOfRange = 0;  // returned index outside 0..255 (K15)
};

// ColorNum(color, graphType), lines 3932-3960, with E15:
//   r = floor(R*7), g = floor(G*7), b = floor(B*3)   (K16)
//   index = r*32 + g*4 + b; 0 -> 1
// Both branches (graphType 0 "VGA" and anything else "8514/A") are the same
// code, so graphType has no effect. Negative colours give negative indices
// (K15); NaN channels count as level 0 (docs/prime/port-notes/shading.md S10).
int colorNum(const Rgb& color, int graphType, ColorNumCounters* counters = nullptr);

// Colour Plate 3 (X1, Q10): index = 16*floor(R*15) + floor(G*15), 0 -> 1;
// blue is ignored.
int colorNumPlate3(const Rgb& color, ColorNumCounters* counters = nullptr);

// InitPalette(), lines 3894-3929 (K17): the 3-3-2 table (entry
// 32*(r/32) + 4*(g/32) + b/64 = (r, g, b), r, g in steps of 32, b in steps of
// 64), then the overrides of entries 0, 1, 2, 3, 4, 5, 6, 20, 8, 9, 7.
// The listing calls it only for graphType 1 (InitGraph, line 3874).
PaletteTable initPalette();

// The Colour Plate 3 table (X1): entry 16*r4 + g4 = (r4*17, g4*17, 0); no
// overrides.
PaletteTable plate3Palette();

}  // namespace prime
