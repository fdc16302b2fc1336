// ColorNum (listing lines 3932-3960; E15, K15, K16), InitPalette (3894-3929;
// K17) and the Colour Plate 3 table (X1). Expected values are worked out by
// hand from the printed code.
//
// Exact boundaries k/7 and k/3: is floor((k/7.0)*7) == k in doubles? Worked
// by hand from the binary expansions: fl(k/7) = k/7 + e with 7e = -2^-54
// (k=1), -2^-53 (k=2), -1.5*2^-53 (k=3), -2^-52 (k=4), +2^-53 (k=5),
// -3*2^-53 (k=6); in each case k + 7e rounds back to exactly k (a tie to
// even for k = 1, 2, 4). Likewise fl(k/3)*3 rounds to k for k = 1, 2
// (ties to even). So the exact boundary values land on level k.
#include "palette/prime/color_num.h"

#include <gtest/gtest.h>

#include <limits>

namespace prime {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

int cn(double r, double g, double b) {
  const int v0 = colorNum({r, g, b}, 0);
  const int v1 = colorNum({r, g, b}, 1);
  EXPECT_EQ(v0, v1) << "graphType 0 and 1 differ";  // both branches are the same code
  return v1;
}

TEST(ColorNum, BlackIsOne) {
  EXPECT_EQ(cn(0, 0, 0), 1);  // r*32+g*4+b = 0 -> 1 (E15, K16)
  EXPECT_EQ(cn(-0.0, -0.0, -0.0), 1);
  EXPECT_EQ(cn(0.1, 0.1, 0.3), 1);  // floor(.7) = floor(.7) = floor(.9) = 0
}

TEST(ColorNum, RedLevelBoundaries) {
  for (int k = 1; k <= 6; ++k) {
    const double edge = k / 7.0;
    EXPECT_EQ(cn(edge, 0, 0), 32 * k) << k;
    EXPECT_EQ(cn(edge + 1e-12, 0, 0), 32 * k) << k;
    const int below = 32 * (k - 1);
    EXPECT_EQ(cn(edge - 1e-12, 0, 0), below == 0 ? 1 : below) << k;
  }
}

TEST(ColorNum, GreenLevelBoundaries) {
  for (int k = 1; k <= 6; ++k) {
    const double edge = k / 7.0;
    EXPECT_EQ(cn(0, edge, 0), 4 * k) << k;
    EXPECT_EQ(cn(0, edge + 1e-12, 0), 4 * k) << k;
    const int below = 4 * (k - 1);
    EXPECT_EQ(cn(0, edge - 1e-12, 0), below == 0 ? 1 : below) << k;
  }
}

TEST(ColorNum, BlueLevelBoundaries) {
  EXPECT_EQ(cn(0, 0, 1.0 / 3.0), 1);
  EXPECT_EQ(cn(0, 0, 1.0 / 3.0 - 1e-12), 1);  // level 0 -> index 0 -> 1
  EXPECT_EQ(cn(0, 0, 2.0 / 3.0), 2);
  EXPECT_EQ(cn(0, 0, 2.0 / 3.0 - 1e-12), 1);
  EXPECT_EQ(cn(0, 0, 2.0 / 3.0 + 1e-12), 2);
  // With red set, blue level 0 is a real 0: 32 + 0.
  EXPECT_EQ(cn(1.0 / 7.0, 0, 1.0 / 3.0 - 1e-12), 32);
  EXPECT_EQ(cn(1.0 / 7.0, 0, 1.0 / 3.0), 33);
}

TEST(ColorNum, JustBelowOneAndOne) {
  // 1 - 2^-53: *7 rounds to 7 - 2^-50 -> 6; *3 rounds to 3 - 2^-51 -> 2.
  const double below = 0.9999999999999999;
  EXPECT_EQ(cn(below, below, below), 6 * 32 + 6 * 4 + 2);  // 218
  // ProcessColor's clamp value: 6.999993 -> 6, 2.999997 -> 2.
  EXPECT_EQ(cn(0.999999, 0.999999, 0.999999), 218);
  // Exactly 1 (ColorNum alone; ProcessColor never passes it): 7, 7, 3.
  EXPECT_EQ(cn(1, 1, 1), 224 + 28 + 3);  // 255
  EXPECT_EQ(cn(1, 0, 0), 224);
  EXPECT_EQ(cn(0, 1, 0), 28);
  EXPECT_EQ(cn(0, 0, 1), 3);
}

TEST(ColorNum, MixedChannels) {
  EXPECT_EQ(cn(0.5, 0.5, 0.5), 3 * 32 + 3 * 4 + 1);  // 109
  EXPECT_EQ(cn(0.3, 0.6, 0.9), 2 * 32 + 4 * 4 + 2);  // 2.1, 4.2, 2.7 -> 82
}

TEST(ColorNum, NegativeColoursGiveNegativeOrShiftedIndices) {
  // K15: nothing clamps negatives.
  EXPECT_EQ(cn(-0.1, 0, 0), -32);  // floor(-0.7) = -1
  EXPECT_EQ(cn(0, -0.1, 0), -4);
  EXPECT_EQ(cn(0, 0, -0.1), -1);      // floor(-0.3) = -1
  EXPECT_EQ(cn(-1e-300, 0, 0), -32);  // floor(-7e-300) = -1
  EXPECT_EQ(cn(0.5, -0.2, 0), 88);    // 3*32 + floor(-1.4)*4 = 96 - 8
  // A nonzero mix that sums to 0 is also drawn with 1: g 1 (0.15*7 = 1.05),
  // b -4 (floor(-3.6)): 4 - 4 = 0 -> 1.
  EXPECT_EQ(cn(0, 0.15, -1.2), 1);
}

TEST(ColorNum, NaNChannelIsLevelZeroAndCounted) {
  ColorNumCounters c;
  EXPECT_EQ(colorNum({kNaN, 0.5, 0.5}, 1, &c), 3 * 4 + 1);  // 13
  EXPECT_EQ(colorNum({kNaN, kNaN, kNaN}, 1, &c), 1);
  EXPECT_EQ(c.nanColours, 2u);
  EXPECT_EQ(c.outOfRange, 0u);
}

TEST(ColorNum, HugeMagnitudesAreLevelZero) {
  // Beyond the 8087's 64-bit integer range: integer indefinite, low bits 0.
  EXPECT_EQ(cn(1e300, 0, 0), 1);
  EXPECT_EQ(cn(-1e300, 0.5, 0), 12);
  EXPECT_EQ(cn(100, 0, 0), 700 * 32);  // 22400: large but exact
}

TEST(ColorNum, OutOfRangeCounter) {
  ColorNumCounters c;
  EXPECT_EQ(colorNum({1, 1, 1}, 1, &c), 255);     // in range
  EXPECT_EQ(colorNum({0, 0, 0}, 1, &c), 1);       // 0 -> 1: in range
  EXPECT_EQ(colorNum({1, 1, 1.34}, 1, &c), 256);  // b = floor(4.02) = 4
  EXPECT_EQ(colorNum({-0.1, 0, 0}, 1, &c), -32);
  EXPECT_EQ(c.outOfRange, 2u);
  EXPECT_EQ(c.nanColours, 0u);
}

TEST(ColorNum, GraphTypeHasNoEffect) {
  for (int type : {0, 1, 2, -1}) {
    EXPECT_EQ(colorNum({0.5, 0.5, 0.5}, type), 109);
    EXPECT_EQ(colorNum({0, 0, 0}, type), 1);
  }
}

// ------------------------------------------------------ Colour Plate 3 (X1)

TEST(ColorNumPlate3, LevelsAndZeroRule) {
  EXPECT_EQ(colorNumPlate3({0, 0, 0}), 1);
  EXPECT_EQ(colorNumPlate3({0, 0, 1}), 1);                 // blue ignored
  EXPECT_EQ(colorNumPlate3({0.5, 0.5, 0.9}), 16 * 7 + 7);  // 7.5 -> 7: 119
  EXPECT_EQ(colorNumPlate3({1, 1, 0}), 255);
  EXPECT_EQ(colorNumPlate3({0.999999, 0.999999, 0}), 16 * 14 + 14);  // 14.999985: 238
  EXPECT_EQ(colorNumPlate3({0.1, 0.1, 0}), 17);                      // 1.5 -> 1
  for (int k = 1; k <= 14; ++k) {
    const double edge = k / 15.0;
    EXPECT_EQ(colorNumPlate3({edge + 1e-12, 0, 0}), 16 * k) << k;
    EXPECT_EQ(colorNumPlate3({edge - 1e-12, 0, 0}), k == 1 ? 1 : 16 * (k - 1)) << k;
    EXPECT_EQ(colorNumPlate3({0, edge + 1e-12, 0}), k) << k;
    EXPECT_EQ(colorNumPlate3({0, edge - 1e-12, 0}), k == 1 ? 1 : k - 1) << k;
  }
}

TEST(ColorNumPlate3, NegativeAndNaN) {
  ColorNumCounters c;
  EXPECT_EQ(colorNumPlate3({-0.01, 0, 0}, &c), -16);  // floor(-0.15) = -1
  EXPECT_EQ(colorNumPlate3({kNaN, 0.5, 0}, &c), 7);
  EXPECT_EQ(colorNumPlate3({0.1, 0.1, kNaN}, &c), 17);  // unused blue: not counted
  EXPECT_EQ(c.outOfRange, 1u);
  EXPECT_EQ(c.nanColours, 1u);
}

// --------------------------------------------------------- palette tables

TEST(InitPalette, OverriddenEntries) {
  const PaletteTable p = initPalette();
  EXPECT_EQ(p[0], (PaletteRgb{0, 0, 0}));
  EXPECT_EQ(p[1], (PaletteRgb{80, 178, 60}));  // the background / black index
  EXPECT_EQ(p[2], (PaletteRgb{255, 0, 40}));
  EXPECT_EQ(p[3], (PaletteRgb{150, 239, 130}));
  EXPECT_EQ(p[4], (PaletteRgb{145, 25, 180}));
  EXPECT_EQ(p[5], (PaletteRgb{255, 255, 0}));
  EXPECT_EQ(p[6], (PaletteRgb{234, 209, 240}));
  EXPECT_EQ(p[7], (PaletteRgb{135, 135, 250}));
  EXPECT_EQ(p[8], (PaletteRgb{255, 255, 255}));
  EXPECT_EQ(p[9], (PaletteRgb{90, 95, 255}));
  EXPECT_EQ(p[20], (PaletteRgb{0, 100, 100}));
}

TEST(InitPalette, LoopEntries) {
  // i++ runs r (outer, step 32), g (step 32), b (inner, step 64):
  // entry i = (32*(i/32), 32*((i/4)%8), 64*(i%4)).
  const PaletteTable p = initPalette();
  EXPECT_EQ(p[10], (PaletteRgb{0, 64, 128}));  // g 2, b 2
  EXPECT_EQ(p[11], (PaletteRgb{0, 64, 192}));
  EXPECT_EQ(p[12], (PaletteRgb{0, 96, 0}));
  EXPECT_EQ(p[19], (PaletteRgb{0, 128, 192}));
  EXPECT_EQ(p[21], (PaletteRgb{0, 160, 64}));
  EXPECT_EQ(p[31], (PaletteRgb{0, 224, 192}));
  EXPECT_EQ(p[32], (PaletteRgb{32, 0, 0}));
  EXPECT_EQ(p[100], (PaletteRgb{96, 32, 0}));
  EXPECT_EQ(p[109], (PaletteRgb{96, 96, 64}));     // ColorNum(.5,.5,.5)
  EXPECT_EQ(p[218], (PaletteRgb{192, 192, 128}));  // the brightest ColorNum after the clamp
  EXPECT_EQ(p[255], (PaletteRgb{224, 224, 192}));
  for (int i = 0; i < 256; ++i) {
    if (i <= 9 || i == 20) continue;
    const PaletteRgb want{32 * (i / 32), 32 * ((i / 4) % 8), 64 * (i % 4)};
    EXPECT_EQ(p[static_cast<std::size_t>(i)], want) << i;
  }
}

TEST(Plate3Palette, RampEntriesWithoutOverrides) {
  const PaletteTable p = plate3Palette();
  EXPECT_EQ(p[0], (PaletteRgb{0, 0, 0}));
  EXPECT_EQ(p[1], (PaletteRgb{0, 17, 0}));   // black is drawn with index 1
  EXPECT_EQ(p[8], (PaletteRgb{0, 136, 0}));  // not InitPalette's white
  EXPECT_EQ(p[16], (PaletteRgb{17, 0, 0}));
  EXPECT_EQ(p[20], (PaletteRgb{17, 68, 0}));
  EXPECT_EQ(p[119], (PaletteRgb{119, 119, 0}));
  EXPECT_EQ(p[255], (PaletteRgb{255, 255, 0}));
  for (int i = 0; i < 256; ++i) {
    EXPECT_EQ(p[static_cast<std::size_t>(i)], (PaletteRgb{17 * (i / 16), 17 * (i % 16), 0})) << i;
  }
}

}  // namespace
}  // namespace prime
