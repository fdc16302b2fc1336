// PRIME's --png as an archivist needs it (docs/user-guide.md, "What a
// picture says about itself"): decoded here with libpng's own API, not the
// project's reader, the file is an 8-bit palette PNG whose PLTE is the DAC
// (6-bit values through the documented rounding), whose every pixel is the
// graph file's index, with pHYs 1:1 and the render's provenance in tEXt;
// two runs give the same bytes, and the companion says the same.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <png.h>

#include <csetjmp>
#include <filesystem>
#include <fstream>
#include <map>

#include "legacy_io/prime/graph_file.h"
#include "palette/prime/dac.h"
#include "palette/prime/palettes.h"
#include "tests/support/child_process.h"
#include "tests/support/temp_scene.h"

namespace indexed_png {

namespace fs = std::filesystem;
using prime::test::ChildProcess;
using ::testing::HasSubstr;

struct Decoded {
  png_uint_32 width = 0, height = 0;
  int depth = 0, colourType = 0;
  std::vector<png_color> palette;
  std::vector<std::uint8_t> pixels;  // one byte a pixel
  bool hasPhys = false;
  png_uint_32 physX = 0, physY = 0;
  int physUnit = -1;
  std::map<std::string, std::string> text;
  bool hasTime = false;
};

Decoded decode(const fs::path& path) {
  Decoded d;
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    ADD_FAILURE() << "cannot open " << path;
    return d;
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(f);
    ADD_FAILURE() << "libpng could not read " << path;
    return Decoded{};
  }
  png_init_io(png, f);
  png_read_info(png, info);
  png_get_IHDR(png, info, &d.width, &d.height, &d.depth, &d.colourType, nullptr, nullptr, nullptr);
  png_colorp plte = nullptr;
  int n = 0;
  if (png_get_PLTE(png, info, &plte, &n) != 0) d.palette.assign(plte, plte + n);
  d.pixels.resize(static_cast<std::size_t>(d.width) * d.height);
  for (png_uint_32 y = 0; y < d.height; ++y)
    png_read_row(png, &d.pixels[static_cast<std::size_t>(y) * d.width], nullptr);
  png_read_end(png, info);
  d.hasPhys = png_get_pHYs(png, info, &d.physX, &d.physY, &d.physUnit) != 0;
  png_textp texts = nullptr;
  const int t = png_get_text(png, info, &texts, nullptr);
  for (int i = 0; i < t; ++i) d.text[texts[i].key] = texts[i].text;
  png_timep time = nullptr;
  d.hasTime = png_get_tIME(png, info, &time) != 0;
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(f);
  return d;
}

std::string fileText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int tracePrime(const std::vector<std::string>& args, std::string* err = nullptr) {
  std::vector<std::string> argv{PRIME_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildProcess p(argv, {{"DISPLAY", ""}, {"WAYLAND_DISPLAY", ""}});
  const int status = p.wait(300000).value_or(-1);
  if (err != nullptr) *err = p.err();
  return status;
}

TEST(IndexedPng, Plate2IsTheScreensIndicesWithTheDacAsItsPaletteAndItsProvenance) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "plate2", s.path(), fs::copy_options::recursive);
  const fs::path a = s.path("a.png"), b = s.path("b.png"), file = s.path("file.png");
  std::string err;
  ASSERT_EQ(tracePrime({"trace", s.path().string(), "--model", "--png", a.string(), "-q"}, &err), 0)
      << err;
  // The second run without --model: the same scene, so the same bytes.
  ASSERT_EQ(tracePrime({"trace", s.path().string(), "--png", b.string(), "-q"}, &err), 0) << err;
  EXPECT_EQ(fileText(a), fileText(b)) << "two runs of one render must give the same PNG bytes";

  Decoded d = decode(a);
  EXPECT_EQ(d.colourType, PNG_COLOR_TYPE_PALETTE);
  EXPECT_EQ(d.depth, 8);
  // The DAC after InitPalette's setrgbpalette calls, each 6-bit value to 8
  // bits by (v * 255 + 31) / 63 (docs/prime/palette.md).
  const prime::DacTable dac = prime::findBuiltinPalette("listing")->dac;
  ASSERT_EQ(d.palette.size(), 256u);
  for (std::size_t i = 0; i < 256; ++i) {
    const auto expand = [](int v6) { return (v6 * 255 + 31) / 63; };
    EXPECT_EQ(d.palette[i].red, expand(dac[i].r)) << "entry " << i;
    EXPECT_EQ(d.palette[i].green, expand(dac[i].g)) << "entry " << i;
    EXPECT_EQ(d.palette[i].blue, expand(dac[i].b)) << "entry " << i;
    // ... and back: an archivist recovers the DAC's 6-bit values.
    EXPECT_EQ((d.palette[i].red * 63 + 127) / 255, dac[i].r) << "entry " << i;
  }
  // The image area: the listing's 350 x 769 file at (675, 0) on the 1024 x
  // 768 screen is 349 x 768 pixels (K21); each the graph file's value & 0xFF.
  const prime::io::GraphFile g = prime::io::readGraphFile(s.path("graph_scr").string());
  ASSERT_EQ(d.width, 349u);
  ASSERT_EQ(d.height, 768u);
  std::size_t differ = 0, nonZero = 0;
  for (png_uint_32 y = 0; y < d.height; ++y)
    for (png_uint_32 x = 0; x < d.width; ++x) {
      const int want = g.pixels[static_cast<std::size_t>(y) * g.width() + x] & 0xFF;
      const int got = d.pixels[static_cast<std::size_t>(y) * d.width + x];
      differ += want != got;
      nonZero += got != 0;
    }
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(nonZero, 10000u) << "a picture, not a blank screen";
  // --png-area file: every pixel of the file, the off-screen column and row too.
  ASSERT_EQ(
      tracePrime({"trace", s.path().string(), "--png", file.string(), "--png-area", "file", "-q"},
                 &err),
      0)
      << err;
  const Decoded f = decode(file);
  ASSERT_EQ(f.width, 350u);
  ASSERT_EQ(f.height, 769u);
  differ = 0;
  for (std::size_t i = 0; i < g.pixels.size(); ++i) differ += (g.pixels[i] & 0xFF) != f.pixels[i];
  EXPECT_EQ(differ, 0u);

  // Square pixels, no time stamp, and what made it.
  EXPECT_TRUE(d.hasPhys);
  EXPECT_EQ(d.physX, 1u);
  EXPECT_EQ(d.physY, 1u);
  EXPECT_EQ(d.physUnit, PNG_RESOLUTION_UNKNOWN);
  EXPECT_FALSE(d.hasTime);
  EXPECT_THAT(d.text["Software"], HasSubstr("prime "));
  EXPECT_EQ(d.text["System"], "PRIME (1991)");
  EXPECT_EQ(d.text["Scene"], s.path().filename().string());
  EXPECT_THAT(d.text["Scene digest"], ::testing::MatchesRegex("xxh3 [0-9a-f]{16} .*"));
  EXPECT_EQ(d.text["Profile"], "1991");
  EXPECT_EQ(d.text["Settings"], "(the defaults)");
  EXPECT_THAT(d.text["Palette"], HasSubstr("listing"));
  EXPECT_THAT(d.text["DAC to 8 bits"], HasSubstr("(v6 * 255 + 31) / 63"));
  // The companion says the same.
  const std::string info = fileText(s.path("graph_scr.info"));
  EXPECT_THAT(info, HasSubstr("text Scene digest: " + d.text["Scene digest"] + "\n"));
  EXPECT_THAT(info, HasSubstr("text Software: " + d.text["Software"] + "\n"));
}

TEST(IndexedPng, SettingsThatChangePixelsAreNamedAndAnUpscaledCopyIsWhole) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "plate2", s.path(), fs::copy_options::recursive);
  const fs::path png = s.path("p.png"), up = s.path("up.png");
  std::string err;
  ASSERT_EQ(
      tracePrime({"trace", s.path().string(), "--model", "--fix", "K10", "--png", png.string(),
                  "--png-upscaled", up.string(), "--upscale-fit", "1100", "1600", "-q"},
                 &err),
      0)
      << err;
  Decoded d = decode(png), u = decode(up);
  EXPECT_THAT(d.text["Settings"], HasSubstr("--fix K10"));
  EXPECT_THAT(d.text["Fixes"], HasSubstr("K10"));
  // 349 x 768 into 1100 x 1600: factor 2 (3 would need 2304 rows).
  ASSERT_EQ(u.width, 698u);
  ASSERT_EQ(u.height, 1536u);
  EXPECT_EQ(u.colourType, PNG_COLOR_TYPE_PALETTE);
  std::size_t differ = 0;
  for (png_uint_32 y = 0; y < u.height; ++y)
    for (png_uint_32 x = 0; x < u.width; ++x)
      differ += u.pixels[static_cast<std::size_t>(y) * u.width + x] !=
                d.pixels[static_cast<std::size_t>(y / 2) * d.width + x / 2];
  EXPECT_EQ(differ, 0u);
  EXPECT_THAT(u.text["Upscaled"], HasSubstr("2 x 2"));
}

// --monitor 8503: the same indices, the palette the monochrome display
// showed (the green signal as grey); 8503-summed the VGA BIOS's sum.
TEST(IndexedPng, TheMonochromeMonitorShowsTheGreenSignalAsGrey) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "plate2", s.path(), fs::copy_options::recursive);
  std::string err;
  const fs::path colour = s.path("c.png"), mono = s.path("m.png"), summed = s.path("s.png");
  ASSERT_EQ(
      tracePrime({"trace", s.path().string(), "--model", "--png", colour.string(), "-q"}, &err), 0)
      << err;
  ASSERT_EQ(
      tracePrime({"trace", s.path().string(), "--png", mono.string(), "--monitor", "8503", "-q"},
                 &err),
      0)
      << err;
  ASSERT_EQ(tracePrime({"trace", s.path().string(), "--png", summed.string(), "--monitor",
                        "8503-summed", "-q"},
                       &err),
            0)
      << err;
  Decoded c = decode(colour), m = decode(mono), v = decode(summed);
  EXPECT_EQ(m.pixels, c.pixels) << "the monitor changes no index";
  const prime::DacTable dac = prime::findBuiltinPalette("listing")->dac;
  ASSERT_EQ(m.palette.size(), 256u);
  ASSERT_EQ(v.palette.size(), 256u);
  for (std::size_t i = 0; i < 256; ++i) {
    const int green = (dac[i].g * 255 + 31) / 63;
    EXPECT_EQ(m.palette[i].red, green) << i;
    EXPECT_EQ(m.palette[i].green, green) << i;
    EXPECT_EQ(m.palette[i].blue, green) << i;
    const int sum6 = std::min(63, (77 * dac[i].r + 151 * dac[i].g + 28 * dac[i].b + 128) >> 8);
    EXPECT_EQ(v.palette[i].green, (sum6 * 255 + 31) / 63) << i;
  }
  EXPECT_THAT(m.text["Palette"], HasSubstr("8503 monochrome"));
  EXPECT_THAT(m.text["Settings"], HasSubstr("--monitor 8503"));
}

}  // namespace indexed_png
