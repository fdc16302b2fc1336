// How far a quantized picture is from the true-colour one: sRGB -> CIE
// L*a*b* (D65), the CIEDE2000 colour difference (Sharma, Wu and Dalal, "The
// CIEDE2000 color-difference formula: implementation notes, supplementary test
// data, and mathematical observations", Color Research and Application 30(1),
// 2005, equations 1-22 with kL = kC = kH = 1) and PSNR over the 8-bit RGB
// channels.
#pragma once
#include <cstdint>

#include "palette/png_image.h"

namespace prime::quantize {

struct Lab {
  double L = 0, a = 0, b = 0;
};

// An 8-bit sRGB colour (IEC 61966-2-1 transfer curve, Rec. 709 primaries) as
// CIE 1976 L*a*b* relative to the D65 white (0.95047, 1, 1.08883).
Lab srgbToLab(std::uint8_t r, std::uint8_t g, std::uint8_t b);

// CIEDE2000 between two L*a*b* colours; symmetric, 0 for equal colours.
double ciede2000(const Lab& x, const Lab& y);

struct ImageError {
  double meanDeltaE = 0;  // mean CIEDE2000 over the pixels
  double maxDeltaE = 0;   // the largest
  double psnr = 0;        // 10 log10(255^2 / MSE) over R, G and B; +inf when equal
};

// `test` against `reference` (same size; std::invalid_argument otherwise).
ImageError compareImages(const Image8& reference, const Image8& test);

}  // namespace prime::quantize
