#include "palette/quantize/libimagequant_reference.h"

#include <libimagequant.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace prime::quantize {

namespace {
struct Free {
  void operator()(liq_attr* p) const { liq_attr_destroy(p); }
  void operator()(liq_image* p) const { liq_image_destroy(p); }
  void operator()(liq_result* p) const { liq_result_destroy(p); }
};
}  // namespace

Result quantizeWithLibimagequant(const Image8& image, int colours, int dacBits, Dither dither) {
  if (dither == Dither::Ordered)
    throw std::invalid_argument("libimagequant has no ordered dithering");
  if (colours < 2 || colours > 256)  // liq_set_max_colors accepts 2..256
    throw std::invalid_argument("libimagequant: colours must be 2..256");
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  std::vector<std::uint8_t> rgba(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) rgba[4 * i + c] = image.rgb[3 * i + c];
    rgba[4 * i + 3] = 255;
  }
  std::unique_ptr<liq_attr, Free> attr(liq_attr_create());
  if (!attr) throw std::runtime_error("libimagequant: liq_attr_create failed");
  liq_set_max_colors(attr.get(), colours);
  liq_set_min_posterization(attr.get(), 8 - dacBits);
  std::unique_ptr<liq_image, Free> img(
      liq_image_create_rgba(attr.get(), rgba.data(), image.width, image.height, 0));
  if (!img) throw std::runtime_error("libimagequant: liq_image_create_rgba failed");
  liq_result* raw = nullptr;
  if (const liq_error e = liq_image_quantize(img.get(), attr.get(), &raw); e != LIQ_OK)
    throw std::runtime_error("libimagequant: liq_image_quantize failed (" + std::to_string(e) +
                             ")");
  std::unique_ptr<liq_result, Free> result(raw);
  liq_set_dithering_level(result.get(), dither == Dither::FloydSteinberg ? 1.0f : 0.0f);
  Result r;
  r.indices.resize(n);
  if (liq_write_remapped_image(result.get(), img.get(), r.indices.data(), n) != LIQ_OK)
    throw std::runtime_error("libimagequant: liq_write_remapped_image failed");
  const liq_palette* pal = liq_get_palette(result.get());
  r.palette.dacBits = dacBits;
  for (unsigned i = 0; i < pal->count; ++i)
    r.palette.levels.push_back({r.palette.levelOf(pal->entries[i].r),
                                r.palette.levelOf(pal->entries[i].g),
                                r.palette.levelOf(pal->entries[i].b)});
  return r;
}

}  // namespace prime::quantize
