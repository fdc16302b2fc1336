// The named palettes as DAC tables, entry by entry, worked out by hand from
// the listing (InitPalette 3894-3929, K17), section 5.10 (X1) and Borland's
// BGI documentation (the 16 EGA/VGA default colours), and the whole chain
// colour -> ColorNum index -> DAC -> screen colour at the edges.
#include "palette/prime/palettes.h"

#include <gtest/gtest.h>

#include "legacy_io/common/error.h"

namespace prime {
namespace {

TEST(ListingDac, LoopEntriesAreTheSetrgbpaletteValuesOverFour) {
  // InitPalette's loop gives entry i = (32*(i/32), 32*((i/4)%8), 64*(i%4)); the
  // DAC keeps v >> 2: 32k -> 8k, 64k -> 16k.
  const DacTable dac = listingDac();
  for (int i = 0; i < 256; ++i) {
    if (i <= 9 || i == 20) continue;  // the overrides
    const Dac6 want{static_cast<std::uint8_t>(8 * (i / 32)),
                    static_cast<std::uint8_t>(8 * ((i / 4) % 8)),
                    static_cast<std::uint8_t>(16 * (i % 4))};
    EXPECT_EQ(dac[static_cast<std::size_t>(i)], want) << i;
  }
  EXPECT_EQ(dac[255], (Dac6{56, 56, 48}));  // (224, 224, 192): red 224 is DAC 56 of 63
  EXPECT_EQ(dac[218], (Dac6{48, 48, 32}));  // (192, 192, 128)
  EXPECT_EQ(dac[109], (Dac6{24, 24, 16}));  // (96, 96, 64)
}

TEST(ListingDac, OverriddenEntries) {
  const DacTable dac = listingDac();
  EXPECT_EQ(dac[0], (Dac6{0, 0, 0}));
  EXPECT_EQ(dac[1], (Dac6{20, 44, 15}));  // (80, 178, 60): 178/4 = 44.5, 60/4 = 15
  EXPECT_EQ(dac[2], (Dac6{63, 0, 10}));   // (255, 0, 40)
  EXPECT_EQ(dac[3], (Dac6{37, 59, 32}));  // (150, 239, 130): 37.5, 59.75, 32.5
  EXPECT_EQ(dac[4], (Dac6{36, 6, 45}));   // (145, 25, 180): 36.25, 6.25, 45
  EXPECT_EQ(dac[5], (Dac6{63, 63, 0}));   // (255, 255, 0)
  EXPECT_EQ(dac[6], (Dac6{58, 52, 60}));  // (234, 209, 240): 58.5, 52.25, 60
  EXPECT_EQ(dac[7], (Dac6{33, 33, 62}));  // (135, 135, 250): 33.75, 62.5
  EXPECT_EQ(dac[8], (Dac6{63, 63, 63}));  // (255, 255, 255)
  EXPECT_EQ(dac[9], (Dac6{22, 23, 63}));  // (90, 95, 255): 22.5, 23.75
  EXPECT_EQ(dac[20], (Dac6{0, 25, 25}));  // (0, 100, 100)
}

TEST(ListingDac, ShownWithTheDefaultConversion) {
  const Rgb8Table shown = present(listingDac());
  EXPECT_EQ(shown[1], (Rgb8{81, 178, 61}));      // 20 -> 5100/63 = 80.95, 44 -> 178.1, 15 -> 60.7
  EXPECT_EQ(shown[255], (Rgb8{227, 227, 194}));  // 56 -> 226.67, 48 -> 194.29
  EXPECT_EQ(shown[8], (Rgb8{255, 255, 255}));
  EXPECT_EQ(shown[32], (Rgb8{32, 0, 0}));  // 8 -> 2040/63 = 32.38
}

TEST(Plate3Dac, RampOfSeventeensOverFour) {
  // X1: entry 16*r4 + g4 = (17*r4, 17*g4, 0); 17*k >> 2 by hand:
  const int ramp[16] = {0, 4, 8, 12, 17, 21, 25, 29, 34, 38, 42, 46, 51, 55, 59, 63};
  const DacTable dac = plate3Dac();
  for (int i = 0; i < 256; ++i) {
    const Dac6 want{static_cast<std::uint8_t>(ramp[i / 16]),
                    static_cast<std::uint8_t>(ramp[i % 16]), 0};
    EXPECT_EQ(dac[static_cast<std::size_t>(i)], want) << i;
  }
  EXPECT_EQ(present(dac)[255], (Rgb8{255, 255, 0}));  // yellow: no blue at all
  EXPECT_EQ(present(dac)[1], (Rgb8{0, 16, 0}));       // 4 -> 1020/63 = 16.19
}

TEST(VgaDac, SixteenDefaultColoursRepeatedByTheLowNibble) {
  const Dac6 ega[16] = {{0, 0, 0},    {0, 0, 42},   {0, 42, 0},   {0, 42, 42},
                        {42, 0, 0},   {42, 0, 42},  {42, 21, 0},  {42, 42, 42},
                        {21, 21, 21}, {21, 21, 63}, {21, 63, 21}, {21, 63, 63},
                        {63, 21, 21}, {63, 21, 63}, {63, 63, 21}, {63, 63, 63}};
  const DacTable dac = vgaDac();
  for (int i = 0; i < 256; ++i) EXPECT_EQ(dac[static_cast<std::size_t>(i)], ega[i % 16]) << i;
  // 21 and 42 are exactly 85 and 170 whichever conversion is used.
  for (DacTo8 how : {DacTo8::Round, DacTo8::Replicate, DacTo8::Truncate}) {
    EXPECT_EQ(present(dac, how)[1], (Rgb8{0, 0, 170}));   // ColorNum's black is blue in VGA mode
    EXPECT_EQ(present(dac, how)[6], (Rgb8{170, 85, 0}));  // brown
    EXPECT_EQ(present(dac, how)[255], (Rgb8{255, 255, 255}));
  }
}

TEST(NamedPalettes, NamesAliasesAndGraphTypes) {
  EXPECT_EQ(builtinPaletteNames(), (std::vector<std::string>{"listing", "plate3", "vga"}));
  EXPECT_EQ(findBuiltinPalette("listing")->dac, listingDac());
  EXPECT_EQ(findBuiltinPalette("8514")->name, "listing");
  EXPECT_EQ(findBuiltinPalette("plate3")->dac, plate3Dac());
  EXPECT_EQ(findBuiltinPalette("vga")->dac, vgaDac());
  EXPECT_FALSE(findBuiltinPalette("ega").has_value());
  EXPECT_EQ(paletteNameForGraphType(1), "listing");
  EXPECT_EQ(paletteNameForGraphType(0), "vga");
  EXPECT_EQ(paletteNameForGraphType(7), "listing");
  EXPECT_EQ(resolvePalette("vga").name, "vga");
  try {
    resolvePalette("no-such-palette");
    FAIL() << "expected an error";
  } catch (const io::InputError& e) {
    EXPECT_STREQ(
        e.what(),
        "no-such-palette: palette: expected a built-in palette (listing, plate3, vga) or a palette "
        "file, found no such palette or file");
  }
}

// colour -> index -> DAC -> screen, at 0, 1, just below 1 and the level
// boundaries (the ColorNum values themselves are tested in color_num_test).
Rgb8 onScreen(const Rgb& c) {
  return present(listingDac())[static_cast<std::size_t>(colorNum(c, 1) & 0xFF)];
}
Rgb8 onPlate3(const Rgb& c) {
  return present(plate3Dac())[static_cast<std::size_t>(colorNumPlate3(c) & 0xFF)];
}

TEST(ColourToScreen, ListingEdges) {
  EXPECT_EQ(onScreen({0, 0, 0}), (Rgb8{81, 178, 61}));    // index 1: the green "black" (K17)
  EXPECT_EQ(onScreen({1, 1, 1}), (Rgb8{227, 227, 194}));  // 255
  const double below = 0.9999999999999999;
  EXPECT_EQ(onScreen({below, below, below}), (Rgb8{194, 194, 130}));    // 218: DAC (48, 48, 32)
  EXPECT_EQ(onScreen({1.0 / 7.0, 0, 0}), (Rgb8{32, 0, 0}));             // 32: DAC (8, 0, 0)
  EXPECT_EQ(onScreen({1.0 / 7.0 - 1e-12, 0, 0}), (Rgb8{81, 178, 61}));  // back to index 1
  // Green level 1 and 2 are indices 4 and 8, which InitPalette overrides (K17):
  EXPECT_EQ(onScreen({0, 1.0 / 7.0, 0}), (Rgb8{146, 24, 182}));   // 4: DAC (36, 6, 45), purple
  EXPECT_EQ(onScreen({0, 2.0 / 7.0, 0}), (Rgb8{255, 255, 255}));  // 8: white
  EXPECT_EQ(onScreen({0, 3.0 / 7.0, 0}), (Rgb8{0, 97, 0}));       // 12: DAC (0, 24, 0), 24 -> 97.14
}

TEST(ColourToScreen, Plate3Edges) {
  EXPECT_EQ(onPlate3({0, 0, 0}), (Rgb8{0, 16, 0}));  // index 1
  EXPECT_EQ(onPlate3({1, 1, 0}), (Rgb8{255, 255, 0}));
  const double below = 0.9999999999999999;
  EXPECT_EQ(onPlate3({below, below, 0}), (Rgb8{239, 239, 0}));  // 238 = 16*14 + 14: DAC 59 -> 238.8
  EXPECT_EQ(onPlate3({1.0 / 15.0 + 1e-12, 0, 0}), (Rgb8{16, 0, 0}));  // 16: DAC (4, 0, 0)
}

}  // namespace
}  // namespace prime
