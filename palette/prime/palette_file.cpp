#include "palette/prime/palette_file.h"

#include <array>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/text_reader.h"

namespace prime {

namespace {

constexpr std::size_t kMaxFileBytes = 1 << 20;

// A word as a message shows it: quoted, non-printable bytes escaped, long
// words cut.
std::string shown(std::string_view word) {
  std::string out = "\"";
  std::size_t n = 0;
  for (unsigned char c : word) {
    if (++n > 40) {
      out += "...";
      break;
    }
    if (c >= 0x20 && c < 0x7F && c != '"' && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
  }
  return out + "\"";
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::optional<int> integer(std::string_view word) {
  int v = 0;
  const char* end = word.data() + word.size();
  auto [p, ec] = std::from_chars(word.data(), end, v);
  if (ec != std::errc() || p != end) return std::nullopt;
  return v;
}

enum class Values { Unset, Setrgbpalette, Dac };

class Parser {
 public:
  Parser(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  Palette parse() {
    Palette p;
    p.name = std::filesystem::path(file_).filename().string();
    p.description = "user palette " + file_;
    std::array<int, 256> seenOn{};  // line of each index's entry, 0 = not yet
    std::optional<Palette> base;
    Values values = Values::Unset;
    bool header = false, entries = false;
    std::size_t pos = 0;
    while (pos <= text_.size()) {
      const std::size_t eol = std::min(text_.find('\n', pos), text_.size());
      std::string_view line = text_.substr(pos, eol - pos);
      pos = eol + 1;
      ++line_;
      if (const auto hash = line.find('#'); hash != std::string_view::npos)
        line = line.substr(0, hash);
      const auto w = words(line);
      if (w.empty()) continue;
      if (!header) {
        if (w[0] != "prime-palette")
          fail("header", "\"prime-palette 1\" as the first line that is not a comment",
               shown(line));
        if (w.size() != 2 || w[1] != "1")
          fail("version", "1",
               w.size() < 2 ? "nothing" : shown(w[1]) + (w.size() > 2 ? " and more" : ""));
        header = true;
        continue;
      }
      if (!integer(w[0])) {  // a directive
        if (entries)
          fail(std::string(w[0]),
               "an entry INDEX RED GREEN BLUE (directives come before the entries)", shown(w[0]));
        if (w[0] == "name") {
          if (w.size() < 2) fail("name", "a name after \"name\"", "nothing");
          p.name =
              std::string(trim(line.substr(static_cast<std::size_t>(w[1].data() - line.data()))));
          p.description = "user palette " + file_;
        } else if (w[0] == "values") {
          if (w.size() != 2 || (w[1] != "setrgbpalette" && w[1] != "dac"))
            fail("values", "\"setrgbpalette\" (0..255 per channel) or \"dac\" (0..63)",
                 w.size() < 2 ? "nothing" : shown(w[1]) + (w.size() > 2 ? " and more" : ""));
          values = w[1] == "dac" ? Values::Dac : Values::Setrgbpalette;
        } else if (w[0] == "base") {
          if (w.size() != 2)
            fail("base", "one built-in palette name", w.size() < 2 ? "nothing" : "more");
          base = findBuiltinPalette(w[1]);
          if (!base) fail("base", "listing, plate3 or vga", shown(w[1]));
          p.dac = base->dac;
        } else {
          fail("directive", "name, values, base, or an entry INDEX RED GREEN BLUE", shown(w[0]));
        }
        continue;
      }
      entries = true;
      if (values == Values::Unset)
        fail("values", "a \"values setrgbpalette\" or \"values dac\" line before the first entry",
             "an entry");
      if (w.size() != 4)
        fail("entry", "4 fields: INDEX RED GREEN BLUE", std::to_string(w.size()) + " fields");
      const int index = *integer(w[0]);
      if (index < 0 || index > 255) fail("index", "an integer 0..255", shown(w[0]));
      if (seenOn[static_cast<std::size_t>(index)] != 0)
        fail("index", "each index once",
             std::to_string(index) + " again (first on line " +
                 std::to_string(seenOn[static_cast<std::size_t>(index)]) + ")");
      seenOn[static_cast<std::size_t>(index)] = line_;
      const int top = values == Values::Dac ? 63 : 255;
      const std::string range =
          "an integer 0.." + std::to_string(top) +
          (values == Values::Dac ? " (values dac)" : " (values setrgbpalette)");
      std::array<int, 3> c{};
      static const char* const kChannel[3] = {"red", "green", "blue"};
      for (int k = 0; k < 3; ++k) {
        const auto v = integer(w[static_cast<std::size_t>(k) + 1]);
        if (!v || *v < 0 || *v > top)
          fail(kChannel[k], range, shown(w[static_cast<std::size_t>(k) + 1]));
        c[static_cast<std::size_t>(k)] = *v;
      }
      p.dac[static_cast<std::size_t>(index)] =
          values == Values::Dac
              ? Dac6{static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
                     static_cast<std::uint8_t>(c[2])}
              : Dac6{setrgbToDac6(c[0]), setrgbToDac6(c[1]), setrgbToDac6(c[2])};
    }
    line_ = 0;  // the remaining errors are about the whole file
    if (!header) fail("header", "\"prime-palette 1\"", "an empty file");
    if (!base) {
      std::vector<int> missing;
      for (int i = 0; i < 256; ++i)
        if (seenOn[static_cast<std::size_t>(i)] == 0) missing.push_back(i);
      if (!missing.empty()) {
        std::string list;
        for (std::size_t k = 0; k < missing.size() && k < 8; ++k)
          list += (k ? ", " : "") + std::to_string(missing[k]);
        if (missing.size() > 8) list += ", ...";
        fail("entries", "all 256 indices 0..255 (or a \"base\" palette for the rest)",
             std::to_string(256 - missing.size()) + " (missing " + list + ")");
      }
    }
    return p;
  }

 private:
  static std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
      s.remove_suffix(1);
    return s;
  }
  [[noreturn]] void fail(const std::string& field, const std::string& expected,
                         const std::string& found) const {
    throw io::InputError(
        {file_, line_ > 0 ? std::optional<int>(line_) : std::nullopt, std::nullopt}, field,
        expected, found);
  }

  std::string_view text_;
  std::string file_;
  int line_ = 0;
};

}  // namespace

Palette parsePaletteText(std::string_view text, const std::string& fileName) {
  const std::string lines = io::normalizeLineBreaks(std::string(text));  // CR-only too (M21)
  return Parser(lines, fileName).parse();
}

Palette readPaletteFile(const std::string& path) {
  io::InputFileOptions input;
  input.maxBytes = kMaxFileBytes;
  input.what = "a palette file";
  return parsePaletteText(io::readInputText(path, input), path);
}

std::string formatPaletteText(const Palette& palette, DacTo8 how) {
  std::string out =
      "# " + palette.description + "\n# shown with the " + std::string(dacTo8Name(how)) +
      " 6-to-8-bit conversion as #rrggbb\nprime-palette 1\nname " + palette.name + "\nvalues dac\n";
  const Rgb8Table shownAs = present(palette.dac, how);
  char buf[64];
  for (std::size_t i = 0; i < palette.dac.size(); ++i) {
    const Dac6& d = palette.dac[i];
    const Rgb8& s = shownAs[i];
    std::snprintf(buf, sizeof buf, "%3zu %2d %2d %2d  # #%02x%02x%02x\n", i, d.r, d.g, d.b, s.r,
                  s.g, s.b);
    out += buf;
  }
  return out;
}

}  // namespace prime
