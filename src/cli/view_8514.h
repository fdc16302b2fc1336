// Any system's true-colour picture as the IBM 8514/A of PRIME (1991) would
// have shown it: each pixel through PRIME's ColorNum (the listing's fixed
// 3-3-2 palette, errata K16) and the 8514/A DAC. For people who want to see a
// 1995 scene on the 1991 display. It lives in the front end because it joins
// two systems: the picture is the other system's, the display PRIME's.
#pragma once
#include <string>

#include "palette/png_image.h"
#include "src/render/rgb_image.h"

namespace prime::cli {

// Writes `picture` as the 8514/A would have shown it: through ColorNum
// (IBM8514HI) as the screen's indices, with the listing's palette (its DAC
// rounded to 8 bits) as an indexed PNG, and `meta`.
void write8514Png(const std::string& path, const RgbImage& picture, PngMeta meta = {});

}  // namespace prime::cli
