#include "palette/prime/live_screen.h"

#include <cstdio>

#include "palette/text/text_panel.h"

namespace prime::display {

// 8 columns of 32 entries: each cell a swatch of the colour, then "INDEX
// R G B" (the DAC's 6-bit values) in black or white, whichever shows.
bool LiveScreen::paletteChart(Image8& out) const {
  Palette shown;
  DacTo8 how;
  {
    std::lock_guard lock(mutex_);
    shown = palettes_[paletteIndex_];
    how = dac_;
  }
  const Rgb8Table colours = present(shown.dac, how);
  out.width = screen_.width();
  out.height = screen_.height();
  out.rgb.assign(static_cast<std::size_t>(out.width) * out.height * 3, 24);
  const int cellW = out.width / 8, cellH = out.height / 32;
  if (cellW < 1 || cellH < 1) return false;
  for (int i = 0; i < 256; ++i) {
    const int x0 = (i / 32) * cellW, y0 = (i % 32) * cellH;
    const Rgb8 c = colours[static_cast<std::size_t>(i)];
    for (int y = y0 + 1; y < y0 + cellH - 1; ++y)
      for (int x = x0 + 1; x < x0 + cellW - 1; ++x) {
        std::uint8_t* p = &out.rgb[(static_cast<std::size_t>(y) * out.width + x) * 3];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
      }
    const Dac6 e = shown.dac[static_cast<std::size_t>(i)];
    char label[32];
    std::snprintf(label, sizeof label, "%3d  %2d %2d %2d", i, e.r, e.g, e.b);
    const bool light = 299 * c.r + 587 * c.g + 114 * c.b > 128000;
    const std::uint8_t ink = light ? 0 : 255;
    drawText(out, x0 + 4, y0 + 2, label, {ink, ink, ink});
  }
  return true;
}

std::string LiveScreen::pixelAbout(int x, int y) const {
  std::lock_guard lock(mutex_);
  if (x < 0 || y < 0 || x >= screen_.width() || y >= screen_.height()) return {};
  const std::uint8_t index = screen_.getPixel(x, y);
  const Dac6 e = palettes_[paletteIndex_].dac[index];
  const std::uint32_t rgb = lut_[index];
  char text[128];
  std::snprintf(text, sizeof text, "pixel (%d, %d): index %d -> DAC %d %d %d -> RGB %u %u %u", x, y,
                index, e.r, e.g, e.b, (rgb >> 16) & 0xFFu, (rgb >> 8) & 0xFFu, rgb & 0xFFu);
  return text;
}

}  // namespace prime::display
