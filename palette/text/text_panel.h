// Text drawn onto a picture: the panel of `prime probe`'s text that the ray
// tree of a clicked (or --overlay) pixel carries, for every system. The
// font is the system's monospace one as fontconfig names it (Debian:
// DejaVu Sans Mono, fonts-dejavu-core), rendered by FreeType, anti-aliased;
// it is found and opened once per process, on the first panel.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "palette/png_image.h"
#include "palette/rect.h"

namespace prime {

// The panel's layout for a picture of `width` pixels: the lines of `text`
// (UTF-8, split at '\n', tabs as spaces), each wrapped at `columns` code
// points (after the last space that fits, when that leaves at least half a
// line; else at the width), a wrapped part indented as its line plus two; at
// most `maxLines`, the rest replaced by "... N more lines". Pure, for tests.
std::vector<std::string> wrapLines(std::string_view text, int columns, int maxLines);

// Draws `text` on a dark box (three quarters opaque: the picture shows
// through) across the whole width of `image`, at its top or its bottom edge,
// whichever is farther from row `keepClear` (the probed pixel's), at most half
// the picture high. Returns the box. Throws std::runtime_error when no
// monospace font can be found or opened (saying which package gives one).
Rect drawTextPanel(Image8& image, std::string_view text, int keepClear);

// One line of `text` (UTF-8) in `ink`, its cells' top-left at (x, top),
// clipped to the picture (throws as drawTextPanel).
void drawText(Image8& image, int x, int top, std::string_view text,
              std::array<std::uint8_t, 3> ink);

// The font's cell: the advance of a character and the height of a line, in
// pixels (throws as drawTextPanel).
struct TextCell {
  int advance = 0, lineHeight = 0;
};
TextCell textCell();

}  // namespace prime
