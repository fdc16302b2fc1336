#include "palette/quantize/colour_difference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prime::quantize {
namespace {

// Sharma, Wu and Dalal (2005), Table 1: the 34 pairs L1 a1 b1, L2 a2 b2 and
// their CIEDE2000, given to 4 decimals.
struct Pair {
  double l1, a1, b1, l2, a2, b2, de;
};
constexpr Pair kSharma[] = {
    {50.0000, 2.6772, -79.7751, 50.0000, 0.0000, -82.7485, 2.0425},
    {50.0000, 3.1571, -77.2803, 50.0000, 0.0000, -82.7485, 2.8615},
    {50.0000, 2.8361, -74.0200, 50.0000, 0.0000, -82.7485, 3.4412},
    {50.0000, -1.3802, -84.2814, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, -1.1848, -84.8006, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, -0.9009, -85.5211, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, 0.0000, 0.0000, 50.0000, -1.0000, 2.0000, 2.3669},
    {50.0000, -1.0000, 2.0000, 50.0000, 0.0000, 0.0000, 2.3669},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0009, 7.1792},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0010, 7.1792},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0011, 7.2195},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0012, 7.2195},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0009, -2.4900, 4.8045},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0010, -2.4900, 4.8045},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0011, -2.4900, 4.7461},
    {50.0000, 2.5000, 0.0000, 50.0000, 0.0000, -2.5000, 4.3065},
    {50.0000, 2.5000, 0.0000, 73.0000, 25.0000, -18.0000, 27.1492},
    {50.0000, 2.5000, 0.0000, 61.0000, -5.0000, 29.0000, 22.8977},
    {50.0000, 2.5000, 0.0000, 56.0000, -27.0000, -3.0000, 31.9030},
    {50.0000, 2.5000, 0.0000, 58.0000, 24.0000, 15.0000, 19.4535},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.1736, 0.5854, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.2972, 0.0000, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 1.8634, 0.5757, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.2592, 0.3350, 1.0000},
    {60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644},
    {63.0109, -31.0961, -5.8663, 62.8187, -29.7946, -4.0864, 1.2630},
    {61.2901, 3.7196, -5.3901, 61.4292, 2.2480, -4.9620, 1.8731},
    {35.0831, -44.1164, 3.7933, 35.0232, -40.0716, 1.5901, 1.8645},
    {22.7233, 20.0904, -46.6940, 23.0331, 14.9730, -42.5619, 2.0373},
    {36.4612, 47.8580, 18.3852, 36.2715, 50.5065, 21.2231, 1.4146},
    {90.8027, -2.0831, 1.4410, 91.1528, -1.6435, 0.0447, 1.4441},
    {90.9257, -0.5406, -0.9208, 88.6381, -0.8985, -0.7239, 1.5381},
    {6.7747, -0.2908, -2.4247, 5.8714, -0.0985, -2.2286, 0.6377},
    {2.0776, 0.0795, -1.1350, 0.9033, -0.0636, -0.5514, 0.9082},
};

TEST(Ciede2000, SharmaWuDalalTable1BothWays) {
  ASSERT_EQ(std::size(kSharma), 34u);
  for (std::size_t i = 0; i < std::size(kSharma); ++i) {
    const Pair& p = kSharma[i];
    const Lab x{p.l1, p.a1, p.b1}, y{p.l2, p.a2, p.b2};
    // The table rounds to 4 decimals: within half a unit of the last place.
    EXPECT_NEAR(ciede2000(x, y), p.de, 0.5e-4) << "pair " << i + 1;
    EXPECT_NEAR(ciede2000(y, x), p.de, 0.5e-4) << "pair " << i + 1 << " reversed";
  }
}

TEST(Ciede2000, ZeroForEqualColours) {
  EXPECT_EQ(ciede2000({50, 10, -20}, {50, 10, -20}), 0.0);
  EXPECT_EQ(ciede2000({0, 0, 0}, {0, 0, 0}), 0.0);
}

TEST(SrgbToLab, WhiteBlackAndPrimaries) {
  // White is the D65 white: L* 100, a* = b* = 0 (to the 4 digits of the matrix).
  const Lab white = srgbToLab(255, 255, 255);
  EXPECT_NEAR(white.L, 100.0, 0.01);
  EXPECT_NEAR(white.a, 0.0, 0.01);
  EXPECT_NEAR(white.b, 0.0, 0.02);
  const Lab black = srgbToLab(0, 0, 0);
  EXPECT_EQ(black.L, 0.0);
  // sRGB red is L* 53.24, a* 80.09, b* 67.20 (the usual published value).
  const Lab red = srgbToLab(255, 0, 0);
  EXPECT_NEAR(red.L, 53.24, 0.02);
  EXPECT_NEAR(red.a, 80.09, 0.05);
  EXPECT_NEAR(red.b, 67.20, 0.05);
  // Mid grey 128: linear 0.2158605, L* = 116 * cbrt(0.2158605) - 16 = 53.585.
  EXPECT_NEAR(srgbToLab(128, 128, 128).L, 53.585, 0.002);
}

TEST(CompareImages, PsnrAndDeltaEByHand) {
  Image8 a{2, 1, {0, 0, 0, 10, 20, 30}};
  Image8 b{2, 1, {0, 0, 3, 10, 20, 30}};
  const ImageError e = compareImages(a, b);
  // MSE = 3^2 / 6 channels = 1.5; PSNR = 10 log10(65025 / 1.5) = 46.3699.
  EXPECT_NEAR(e.psnr, 46.3699, 1e-4);
  const double d = ciede2000(srgbToLab(0, 0, 0), srgbToLab(0, 0, 3));
  EXPECT_GT(d, 0.0);
  EXPECT_DOUBLE_EQ(e.maxDeltaE, d);
  EXPECT_DOUBLE_EQ(e.meanDeltaE, d / 2);  // the second pixel is exact
  EXPECT_TRUE(std::isinf(compareImages(a, a).psnr));
  EXPECT_EQ(compareImages(a, a).meanDeltaE, 0.0);
  EXPECT_THROW(compareImages(a, Image8{1, 1, {0, 0, 0}}), std::invalid_argument);
}

}  // namespace
}  // namespace prime::quantize
