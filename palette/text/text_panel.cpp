#include "palette/text/text_panel.h"

#ifndef PRIME_FONT_FILE
#include <fontconfig/fontconfig.h>
#endif
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace prime {

namespace {

// The panel's type: 12 pixels, the size of a terminal's text.
constexpr int kPixelSize = 12;
constexpr int kPadding = 6;

// UTF-8 to code points; a malformed byte is taken as U+FFFD.
std::u32string decode(std::string_view s) {
  std::u32string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto b = static_cast<unsigned char>(s[i]);
    int extra = b < 0x80 ? 0 : (b >> 5) == 6 ? 1 : (b >> 4) == 14 ? 2 : (b >> 3) == 30 ? 3 : -1;
    char32_t cp = extra == 0 ? b : extra == 1 ? b & 0x1F : extra == 2 ? b & 0x0F : b & 0x07;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= s.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto c = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      ok = ok && (c >> 6) == 2;
      cp = (cp << 6) | (c & 0x3F);
    }
    out.push_back(ok ? cp : 0xFFFD);
    i += ok ? static_cast<std::size_t>(extra) + 1 : 1;
  }
  return out;
}

std::string encode(std::u32string_view s) {
  std::string out;
  for (const char32_t c : s) {
    if (c < 0x80) {
      out.push_back(static_cast<char>(c));
    } else if (c < 0x800) {
      out.push_back(static_cast<char>(0xC0 | (c >> 6)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    } else if (c < 0x10000) {
      out.push_back(static_cast<char>(0xE0 | (c >> 12)));
      out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    } else {
      out.push_back(static_cast<char>(0xF0 | (c >> 18)));
      out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    }
  }
  return out;
}

// The monospace font, found by fontconfig and opened by FreeType once; every
// use under the lock (a FreeType face is not shared between threads).
class Font {
 public:
  static Font& get() {
    static Font font;
    if (!font.error_.empty()) throw std::runtime_error(font.error_);
    return font;
  }
  ~Font() {
    if (face_) FT_Done_Face(face_);
    if (library_) FT_Done_FreeType(library_);
  }
  std::mutex& lock() { return lock_; }
  TextCell cell() const { return cell_; }
  int ascender() const { return ascender_; }

  // Blends code point `c`'s glyph in `ink` over `img` with its pen at (x,
  // baseline y).
  void draw(Image8& img, int x, int y, char32_t c, std::array<std::uint8_t, 3> ink) {
    if (FT_Load_Char(face_, c, FT_LOAD_RENDER) != 0) return;
    const FT_GlyphSlot g = face_->glyph;
    const FT_Bitmap& b = g->bitmap;
    if (b.pixel_mode != FT_PIXEL_MODE_GRAY) return;
    for (unsigned r = 0; r < b.rows; ++r)
      for (unsigned col = 0; col < b.width; ++col) {
        const int px = x + g->bitmap_left + static_cast<int>(col);
        const int py = y - g->bitmap_top + static_cast<int>(r);
        if (px < 0 || py < 0 || px >= img.width || py >= img.height) continue;
        const unsigned a = b.buffer[static_cast<std::ptrdiff_t>(r) * b.pitch + col];
        if (a == 0) continue;
        std::uint8_t* p = &img.rgb[(static_cast<std::size_t>(py) * img.width + px) * 3];
        for (int k = 0; k < 3; ++k)
          p[k] = static_cast<std::uint8_t>(
              (ink[static_cast<std::size_t>(k)] * a + p[k] * (255u - a) + 127u) / 255u);
      }
  }

 private:
  Font() {
    std::string file;
    int index = 0;
#ifdef PRIME_FONT_FILE
    file = PRIME_FONT_FILE;  // the web build: no fontconfig; the font is among its files
#else
    if (FcConfig* config = FcInitLoadConfigAndFonts()) {
      FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>("monospace"));
      FcConfigSubstitute(config, pattern, FcMatchPattern);
      FcDefaultSubstitute(pattern);
      FcResult result = FcResultNoMatch;
      if (FcPattern* match = FcFontMatch(config, pattern, &result)) {
        FcChar8* path = nullptr;
        if (FcPatternGetString(match, FC_FILE, 0, &path) == FcResultMatch && path)
          file = reinterpret_cast<const char*>(path);
        FcPatternGetInteger(match, FC_INDEX, 0, &index);
        FcPatternDestroy(match);
      }
      FcPatternDestroy(pattern);
      FcConfigDestroy(config);
    }
#endif
    const std::string hint = " (Debian: apt install fonts-dejavu-core)";
    if (file.empty()) {
      error_ = "no monospace font: fontconfig found none" + hint;
      return;
    }
    if (FT_Init_FreeType(&library_) != 0) {
      library_ = nullptr;
      error_ = "FreeType could not start";
      return;
    }
    if (FT_New_Face(library_, file.c_str(), index, &face_) != 0 ||
        FT_Set_Pixel_Sizes(face_, 0, kPixelSize) != 0) {
      if (face_) FT_Done_Face(face_);
      face_ = nullptr;
      error_ = "the monospace font " + file + " cannot be opened by FreeType" + hint;
      return;
    }
    const FT_Size_Metrics& m = face_->size->metrics;
    ascender_ = static_cast<int>((m.ascender + 63) >> 6);
    cell_.lineHeight = static_cast<int>((m.height + 63) >> 6);
    cell_.advance = FT_Load_Char(face_, 'M', FT_LOAD_DEFAULT) == 0
                        ? static_cast<int>((face_->glyph->advance.x + 32) >> 6)
                        : kPixelSize * 6 / 10;
    cell_.advance = std::max(cell_.advance, 1);
    cell_.lineHeight = std::max(cell_.lineHeight, 1);
  }

  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  std::string error_;
  TextCell cell_;
  int ascender_ = 0;
  std::mutex lock_;
};

}  // namespace

std::vector<std::string> wrapLines(std::string_view text, int columns, int maxLines) {
  columns = std::max(columns, 8);
  std::vector<std::string> all;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::u32string line = decode(text.substr(start, end - start));
    std::replace(line.begin(), line.end(), U'\t', U' ');
    while (!line.empty() && (line.back() == U' ' || line.back() == U'\r')) line.pop_back();
    const std::size_t indent =
        std::min<std::size_t>(
            line.find_first_not_of(U' ') == std::u32string::npos ? 0 : line.find_first_not_of(U' '),
            static_cast<std::size_t>(columns / 2)) +
        2;
    // Broken after the last space that fits (if it leaves half a line or
    // more), else at the width; a continuation indented.
    const auto width = static_cast<std::size_t>(columns);
    std::size_t at = 0, room = width;
    std::string lead;
    while (line.size() - at > room) {
      std::size_t cut = room;
      const std::size_t space = line.rfind(U' ', at + room - 1);
      if (space != std::u32string::npos && space > at && space - at >= room / 2)
        cut = space - at + 1;
      all.push_back(lead + encode(line.substr(at, cut)));
      at += cut;
      lead.assign(indent, ' ');
      room = width - indent;
    }
    all.push_back(lead + encode(line.substr(at)));
    if (end == text.size()) break;
    start = end + 1;
  }
  while (!all.empty() && all.back().empty()) all.pop_back();
  if (maxLines >= 1 && static_cast<int>(all.size()) > maxLines) {
    const std::size_t more = all.size() - static_cast<std::size_t>(maxLines) + 1;
    all.resize(static_cast<std::size_t>(maxLines) - 1);
    all.push_back("... " + std::to_string(more) + " more lines");
  }
  return all;
}

void drawText(Image8& image, int x, int top, std::string_view text,
              std::array<std::uint8_t, 3> ink) {
  Font& font = Font::get();
  const std::lock_guard<std::mutex> hold(font.lock());
  const int baseline = top + font.ascender();
  for (const char32_t c : decode(text)) {
    font.draw(image, x, baseline, c, ink);
    x += font.cell().advance;
  }
}

TextCell textCell() {
  return Font::get().cell();
}

Rect drawTextPanel(Image8& image, std::string_view text, int keepClear) {
  Font& font = Font::get();
  const std::lock_guard<std::mutex> hold(font.lock());
  const TextCell cell = font.cell();
  const int columns = (image.width - 2 * kPadding) / cell.advance;
  const int maxLines = std::max(1, (image.height / 2 - 2 * kPadding) / cell.lineHeight);
  const std::vector<std::string> lines = wrapLines(text, columns, maxLines);
  const int h =
      std::min(image.height, static_cast<int>(lines.size()) * cell.lineHeight + 2 * kPadding);
  // Top or bottom: the edge farther from the row to keep clear.
  const bool top = keepClear >= image.height / 2;
  const Rect box{0, top ? 0 : image.height - h, image.width, h};
  for (int y = box.y; y < box.y + box.h; ++y)
    for (int x = 0; x < box.w; ++x) {
      std::uint8_t* p = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
      for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>((p[k] + 2) / 4 + 8);
    }
  int baseline = box.y + kPadding + font.ascender();
  for (const std::string& line : lines) {
    int x = kPadding;
    for (const char32_t c : decode(line)) {
      font.draw(image, x, baseline, c, {235, 235, 225});
      x += cell.advance;
    }
    baseline += cell.lineHeight;
  }
  return box;
}

}  // namespace prime
