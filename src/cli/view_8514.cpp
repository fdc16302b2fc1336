#include "src/cli/view_8514.h"

#include "palette/png_image.h"
#include "palette/prime/color_num.h"
#include "palette/prime/dac.h"
#include "palette/prime/export.h"
#include "palette/prime/palettes.h"

namespace prime::cli {

void write8514Png(const std::string& path, const RgbImage& picture, PngMeta meta) {
  IndexedImage8 img;
  img.width = picture.width;
  img.height = picture.height;
  img.indices.reserve(picture.pixels.size());
  // IBM8514HI (graphType 1); ColorNum's index is stored as the screen's low
  // byte, as putpixel did (Q12).
  for (const Rgb& c : picture.pixels)
    img.indices.push_back(static_cast<std::uint8_t>(colorNum(c, 1) & 0xFF));
  img.palette = pngPalette(present(findBuiltinPalette("listing")->dac));
  meta.aspectX = meta.aspectY = 1;
  meta.text.push_back({"Palette",
                       "listing (the IBM 8514/A DAC, 6 bits a channel), through "
                       "PRIME's ColorNum (IBM8514HI)"});
  meta.text.push_back({"DAC to 8 bits", std::string(dacTo8Rule(kDefaultDacTo8))});
  writeIndexedPng(path, img, meta);
}

}  // namespace prime::cli
