#include "src/cli/quantize_options.h"

#include <stdexcept>

#include "palette/prime/color_num.h"
#include "palette/prime/palettes.h"
#include "palette/quantize/libimagequant_reference.h"

namespace prime::cli {

void addQuantizeOptions(CLI::App* cmd, QuantizeOptions& o, const std::string& what) {
  cmd->add_option("--quantize", o.method,
                  "Quantize " + what +
                      " to 256 colours a 6-bit DAC can load (thesis 4.4): popularity, median-cut "
                      "or octree (docs/prime/quantization.md)")
      ->check(CLI::IsMember({"popularity", "median-cut", "octree"}));
  cmd->add_option("--dither", o.dither,
                  "With --quantize: none (default), ordered (Bayer 8x8) or floyd-steinberg")
      ->check(CLI::IsMember({"none", "ordered", "floyd-steinberg"}));
  cmd->add_option("--colours", o.colours, "With --quantize: palette entries, 2..256 (256)")
      ->check(CLI::Range(2, 256));
}

quantize::Settings settingsOf(const QuantizeOptions& o) {
  quantize::Settings s;
  s.method = quantize::methodFromName(o.method).value_or(quantize::Method::MedianCut);
  s.dither = quantize::ditherFromName(o.dither).value_or(quantize::Dither::None);
  s.colours = o.colours;
  s.dacBits = 6;
  return s;
}

Image8 quantizedImage(const Image8& image, const QuantizeOptions& o) {
  if (o.method.empty()) return image;
  return quantize::present(quantize::quantize(image, settingsOf(o)), image.width, image.height);
}

quantize::Result quantizeBy(const Image8& image, const std::string& method, quantize::Dither dither,
                            int colours) {
  if (method == "libimagequant")
    return quantize::quantizeWithLibimagequant(image, colours, 6, dither);
  if (method == "listing") {
    // PRIME's 1991 display: ColorNum (K16) of each pixel as a colour in 0..1,
    // through the listing's DAC (InitPalette with its overrides, K17). No
    // dithering: the listing had none.
    if (dither != quantize::Dither::None)
      throw std::invalid_argument("the listing's fixed palette is not dithered");
    quantize::Result r;
    r.palette.dacBits = 6;
    for (const Dac6& e : listingDac()) r.palette.levels.push_back({e.r, e.g, e.b});
    const std::size_t n = image.rgb.size() / 3;
    r.indices.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Rgb c{image.rgb[3 * i] / 255.0, image.rgb[3 * i + 1] / 255.0,
                  image.rgb[3 * i + 2] / 255.0};
      r.indices[i] = static_cast<std::uint8_t>(colorNum(c, 1) & 0xFF);  // Q12: the low byte
    }
    return r;
  }
  const auto m = quantize::methodFromName(method);
  if (!m) throw std::invalid_argument("unknown quantization method '" + method + "'");
  return quantize::quantize(image, {*m, dither, colours, 6});
}

}  // namespace prime::cli
