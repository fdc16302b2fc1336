// The 8514/A DAC model: what setrgbpalette loads (Borland: "only the 6 most
// significant bits [of the lower byte] are loaded", errata Q13), and the three
// 6-to-8-bit conversions, entry by entry.
//
// The 64-entry tables below were computed independently of this code, with
// exact rational arithmetic (floor(v*255/63 + 1/2), (v<<2)|(v>>4),
// floor(v*255/63)), and checked by hand at these entries:
//   v = 11: 2805/63 = 44.52 -> round 45, replicate 44|0 = 44, truncate 44
//   v = 32: 8160/63 = 129.52 -> round 130, replicate 128|2 = 130, truncate 129
//   v = 48: 12240/63 = 194.29 -> round 194, replicate 192|3 = 195, truncate 194
//   v = 63: 16065/63 = 255 exactly, all three 255
#include "palette/prime/dac.h"

#include <gtest/gtest.h>

#include <array>

namespace prime {
namespace {

constexpr std::array<int, 64> kRound{
    0,   4,   8,   12,  16,  20,  24,  28,  32,  36,  40,  45,  49,  53,  57,  61,
    65,  69,  73,  77,  81,  85,  89,  93,  97,  101, 105, 109, 113, 117, 121, 125,
    130, 134, 138, 142, 146, 150, 154, 158, 162, 166, 170, 174, 178, 182, 186, 190,
    194, 198, 202, 206, 210, 215, 219, 223, 227, 231, 235, 239, 243, 247, 251, 255};
constexpr std::array<int, 64> kReplicate{
    0,   4,   8,   12,  16,  20,  24,  28,  32,  36,  40,  44,  48,  52,  56,  60,
    65,  69,  73,  77,  81,  85,  89,  93,  97,  101, 105, 109, 113, 117, 121, 125,
    130, 134, 138, 142, 146, 150, 154, 158, 162, 166, 170, 174, 178, 182, 186, 190,
    195, 199, 203, 207, 211, 215, 219, 223, 227, 231, 235, 239, 243, 247, 251, 255};
constexpr std::array<int, 64> kTruncate{
    0,   4,   8,   12,  16,  20,  24,  28,  32,  36,  40,  44,  48,  52,  56,  60,
    64,  68,  72,  76,  80,  85,  89,  93,  97,  101, 105, 109, 113, 117, 121, 125,
    129, 133, 137, 141, 145, 149, 153, 157, 161, 165, 170, 174, 178, 182, 186, 190,
    194, 198, 202, 206, 210, 214, 218, 222, 226, 230, 234, 238, 242, 246, 250, 255};

TEST(Dac, SetrgbpaletteKeepsTheSixMostSignificantBitsOfTheLowByte) {
  EXPECT_EQ(setrgbToDac6(0), 0);
  EXPECT_EQ(setrgbToDac6(3), 0);  // the two low bits are lost
  EXPECT_EQ(setrgbToDac6(4), 1);
  EXPECT_EQ(setrgbToDac6(80), 20);
  EXPECT_EQ(setrgbToDac6(83), 20);   // 80 and 83 are the same colour
  EXPECT_EQ(setrgbToDac6(224), 56);  // InitPalette's top red level: DAC 56 of 63
  EXPECT_EQ(setrgbToDac6(255), 63);
  EXPECT_EQ(setrgbToDac6(256), 0);  // only the lower byte is used
  EXPECT_EQ(setrgbToDac6(256 + 40), 10);
  EXPECT_EQ(setrgbToDac6(-1), 63);  // 0xFFFF: low byte 0xFF
  for (int v = 0; v < 256; ++v) EXPECT_EQ(setrgbToDac6(v), v / 4) << v;
}

TEST(Dac, RoundConversionEntryByEntry) {
  for (int v = 0; v < 64; ++v)
    EXPECT_EQ(dacTo8(v, DacTo8::Round), kRound[static_cast<std::size_t>(v)]) << v;
}

TEST(Dac, ReplicateConversionEntryByEntry) {
  for (int v = 0; v < 64; ++v)
    EXPECT_EQ(dacTo8(v, DacTo8::Replicate), kReplicate[static_cast<std::size_t>(v)]) << v;
}

TEST(Dac, TruncateConversionEntryByEntry) {
  for (int v = 0; v < 64; ++v)
    EXPECT_EQ(dacTo8(v, DacTo8::Truncate), kTruncate[static_cast<std::size_t>(v)]) << v;
}

TEST(Dac, RoundIsTheDefaultAndTheOthersAreWithinOneOfIt) {
  EXPECT_EQ(kDefaultDacTo8, DacTo8::Round);
  int replicateDiffers = 0, truncateDiffers = 0;
  for (std::size_t v = 0; v < 64; ++v) {
    EXPECT_LE(std::abs(kReplicate[v] - kRound[v]), 1) << v;
    EXPECT_LE(kRound[v] - kTruncate[v], 1) << v;
    EXPECT_GE(kRound[v] - kTruncate[v], 0) << v;
    replicateDiffers += kReplicate[v] != kRound[v];
    truncateDiffers += kTruncate[v] != kRound[v];
  }
  EXPECT_EQ(replicateDiffers, 10);  // 11..15 and 48..52 (docs/prime/palette.md)
  EXPECT_EQ(truncateDiffers, 30);
}

TEST(Dac, NamesRoundTrip) {
  for (DacTo8 how : {DacTo8::Round, DacTo8::Replicate, DacTo8::Truncate})
    EXPECT_EQ(dacTo8FromName(dacTo8Name(how)), how);
  EXPECT_EQ(dacTo8Name(DacTo8::Round), "round");
  EXPECT_FALSE(dacTo8FromName("nearest").has_value());
}

TEST(Dac, LoadAndPresentATable) {
  PaletteTable calls{};
  calls[0] = {80, 178, 60};
  calls[255] = {255, 3, 131};
  const DacTable dac = loadDac(calls);
  EXPECT_EQ(dac[0], (Dac6{20, 44, 15}));
  EXPECT_EQ(dac[255], (Dac6{63, 0, 32}));
  EXPECT_EQ(dac[1], (Dac6{0, 0, 0}));
  const Rgb8Table shown = present(dac);
  EXPECT_EQ(shown[0], (Rgb8{81, 178, 61}));  // 20 -> 81, 44 -> 178, 15 -> 61
  EXPECT_EQ(shown[255], (Rgb8{255, 0, 130}));
  EXPECT_EQ(present(dac, DacTo8::Replicate)[0],
            (Rgb8{81, 178, 60}));  // 20 -> 80|1, 44 -> 176|2, 15 -> 60|0
  EXPECT_EQ(present(dac, DacTo8::Truncate)[0],
            (Rgb8{80, 178, 60}));  // 5100/63, 11220/63, 3825/63 rounded down
}

}  // namespace
}  // namespace prime
