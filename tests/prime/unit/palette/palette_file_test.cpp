// The user palette file: what it reads, and the message for each mistake
// (file, line, field, expected, found). Nothing may crash it.
#include "palette/prime/palette_file.h"

#include <gtest/gtest.h>

#include <random>

#include "legacy_io/common/error.h"

namespace prime {
namespace {

// A complete file: `values setrgbpalette`, entry i = (i, 255 - i, 4).
std::string fullFile(const std::string& values = "setrgbpalette", const std::string& extra = "") {
  std::string s =
      "# a test palette\nprime-palette 1\nname ramp  test \nvalues " + values + "\n" + extra;
  for (int i = 0; i < 256; ++i)
    s += std::to_string(i) + " " + std::to_string(values == "dac" ? i / 4 : i) + "\t" +
         std::to_string(values == "dac" ? 63 - i / 4 : 255 - i) + " 4  # entry\r\n";
  return s;
}

std::string errorOf(const std::string& text) {
  try {
    parsePaletteText(text, "my.pal");
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(PaletteFile, ReadsSetrgbpaletteValuesThroughTheDac) {
  const Palette p = parsePaletteText(fullFile(), "dir/my.pal");
  EXPECT_EQ(p.name, "ramp  test");
  EXPECT_EQ(p.dac[0], (Dac6{0, 63, 1}));     // 255 >> 2 = 63, 4 >> 2 = 1
  EXPECT_EQ(p.dac[3], (Dac6{0, 63, 1}));     // 3 >> 2 = 0, 252 >> 2 = 63
  EXPECT_EQ(p.dac[130], (Dac6{32, 31, 1}));  // 130 >> 2, 125 >> 2
  EXPECT_EQ(p.dac[255], (Dac6{63, 0, 1}));
}

TEST(PaletteFile, ReadsDacValuesAsTheyAre) {
  const Palette p = parsePaletteText(fullFile("dac"), "my.pal");
  EXPECT_EQ(p.dac[0], (Dac6{0, 63, 4}));
  EXPECT_EQ(p.dac[255], (Dac6{63, 0, 4}));
}

TEST(PaletteFile, NameDefaultsToTheFileName) {
  std::string s = fullFile();
  s.replace(s.find("name ramp  test \n"), 17, "");
  EXPECT_EQ(parsePaletteText(s, "some/dir/sunset.pal").name, "sunset.pal");
}

TEST(PaletteFile, BaseFillsTheEntriesNotGiven) {
  const Palette p =
      parsePaletteText("prime-palette 1\nbase listing\nvalues dac\n1 0 0 0\n", "my.pal");
  EXPECT_EQ(p.dac[1], (Dac6{0, 0, 0}));
  EXPECT_EQ(p.dac[8], (Dac6{63, 63, 63}));  // the listing's white
  EXPECT_EQ(p.dac[255], (Dac6{56, 56, 48}));
}

TEST(PaletteFile, FormatReadsBack) {
  for (const auto& name : builtinPaletteNames()) {
    const Palette p = *findBuiltinPalette(name);
    const Palette q = parsePaletteText(formatPaletteText(p), "x.pal");
    EXPECT_EQ(q.dac, p.dac) << name;
    EXPECT_EQ(q.name, p.name);
  }
  const std::string text = formatPaletteText(*findBuiltinPalette("listing"));
  EXPECT_NE(text.find("\n  1 20 44 15  # #51b23d\n"), std::string::npos) << text.substr(0, 400);
}

TEST(PaletteFile, Errors) {
  EXPECT_EQ(errorOf(""), "my.pal: header: expected \"prime-palette 1\", found an empty file");
  EXPECT_EQ(errorOf("# only a comment\n\n"),
            "my.pal: header: expected \"prime-palette 1\", found an empty file");
  EXPECT_EQ(errorOf("\n0 0 0 0\n"),
            "my.pal:2: header: expected \"prime-palette 1\" as the first line that is not a "
            "comment, found "
            "\"0 0 0 0\"");
  EXPECT_EQ(errorOf("prime-palette 2\n"), "my.pal:1: version: expected 1, found \"2\"");
  EXPECT_EQ(errorOf("prime-palette\n"), "my.pal:1: version: expected 1, found nothing");
  EXPECT_EQ(errorOf("prime-palette 1\n0 0 0 0\n"),
            "my.pal:2: values: expected a \"values setrgbpalette\" or \"values dac\" line before "
            "the first "
            "entry, found an entry");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues rgb\n"),
            "my.pal:2: values: expected \"setrgbpalette\" (0..255 per channel) or \"dac\" (0..63), "
            "found \"rgb\"");
  EXPECT_EQ(errorOf("prime-palette 1\nbase ega\n"),
            "my.pal:2: base: expected listing, plate3 or vga, found \"ega\"");
  EXPECT_EQ(errorOf("prime-palette 1\ncolour 1 2 3\n"),
            "my.pal:2: directive: expected name, values, base, or an entry INDEX RED GREEN BLUE, "
            "found \"colour\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n0 0 0\n"),
            "my.pal:3: entry: expected 4 fields: INDEX RED GREEN BLUE, found 3 fields");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n256 0 0 0\n"),
            "my.pal:3: index: expected an integer 0..255, found \"256\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n-1 0 0 0\n"),
            "my.pal:3: index: expected an integer 0..255, found \"-1\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n0 0 64 0\n"),
            "my.pal:3: green: expected an integer 0..63 (values dac), found \"64\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues setrgbpalette\n0 256 0 0\n"),
            "my.pal:3: red: expected an integer 0..255 (values setrgbpalette), found \"256\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues setrgbpalette\n0 1 2 3.5\n"),
            "my.pal:3: blue: expected an integer 0..255 (values setrgbpalette), found \"3.5\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n0 1 2 0x3\n"),
            "my.pal:3: blue: expected an integer 0..63 (values dac), found \"0x3\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n7 0 0 0\n\n7 1 1 1\n"),
            "my.pal:5: index: expected each index once, found 7 again (first on line 3)");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n0 0 0 0\nname late\n"),
            "my.pal:4: name: expected an entry INDEX RED GREEN BLUE (directives come before the "
            "entries), "
            "found \"name\"");
  EXPECT_EQ(errorOf("prime-palette 1\nvalues dac\n0 0 0 0\n1 0 0 0\n"),
            "my.pal: entries: expected all 256 indices 0..255 (or a \"base\" palette for the "
            "rest), found 2 "
            "(missing 2, 3, 4, 5, 6, 7, 8, 9, ...)");
  std::string most = fullFile();
  most.erase(most.find("\n17 17"), most.find("\n18 18") - most.find("\n17 17"));
  EXPECT_EQ(errorOf(most),
            "my.pal: entries: expected all 256 indices 0..255 (or a \"base\" palette for the "
            "rest), found 255 "
            "(missing 17)");
  EXPECT_EQ(errorOf(std::string("prime-palette 1\nvalues dac\n0 \x01\xff 0 0\n")),
            "my.pal:3: red: expected an integer 0..63 (values dac), found \"\\x01\\xFF\"");
  EXPECT_EQ(
      errorOf("prime-palette 1\nvalues dac\n0 99999999999999999999 0 0\n"),
      "my.pal:3: red: expected an integer 0..63 (values dac), found \"99999999999999999999\"");
}

TEST(PaletteFile, MissingFileAndLongNames) {
  try {
    readPaletteFile("/nonexistent/dir/p.pal");
    FAIL();
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "/nonexistent/dir/p.pal: no such file (expected a palette file)"),
              std::string::npos)
        << e.what();
  }
  const std::string word(100, 'x');
  EXPECT_EQ(errorOf("prime-palette 1\n" + word + "\n"),
            "my.pal:2: directive: expected name, values, base, or an entry INDEX RED GREEN BLUE, "
            "found \"" +
                std::string(40, 'x') + "...\"");
}

TEST(PaletteFile, RandomBytesNeverCrash) {
  std::mt19937 rng(1991);
  const std::string seed = fullFile("dac");
  for (int round = 0; round < 2000; ++round) {
    std::string text = seed;
    const int edits = 1 + static_cast<int>(rng() % 8);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0:
          text[at] = static_cast<char>(rng() % 256);
          break;
        case 1:
          text.erase(at, 1 + rng() % 20);
          break;
        default:
          text.insert(at, 1, static_cast<char>(rng() % 256));
      }
      if (text.empty()) text = "x";
    }
    try {
      const Palette p = parsePaletteText(text, "fuzz.pal");
      for (const Dac6& d : p.dac) ASSERT_TRUE(d.r < 64 && d.g < 64 && d.b < 64);
    } catch (const io::InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("fuzz.pal", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace prime
