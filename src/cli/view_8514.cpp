#include "src/cli/view_8514.h"

#include "palette/png_image.h"
#include "palette/prime/color_num.h"
#include "palette/prime/dac.h"
#include "palette/prime/palettes.h"

namespace prime::cli {

void write8514Png(const std::string& path, const RgbImage& picture) {
  const Rgb8Table screen = present(findBuiltinPalette("listing")->dac);
  Image8 img;
  img.width = picture.width;
  img.height = picture.height;
  img.rgb.reserve(picture.pixels.size() * 3);
  for (const Rgb& c : picture.pixels) {
    // IBM8514HI (graphType 1); ColorNum's index is stored as the screen's
    // low byte, as putpixel did (Q12).
    const Rgb8 shown = screen[static_cast<std::size_t>(colorNum(c, 1) & 0xFF)];
    img.rgb.push_back(shown.r);
    img.rgb.push_back(shown.g);
    img.rgb.push_back(shown.b);
  }
  writePng(path, img);
}

}  // namespace prime::cli
