// The CGL package's colour (src/cgl/colour.h; Sweeney 1985, sections 9.1 and
// 10): the CIE table, the phosphor matrices, ToRGB's clipping and truncation,
// colour-vectors converted by hand, and the texture path's round trip.
#include "src/cgl/colour.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prime::cgl {
namespace {

constexpr int index(int nanometres) {
  return (nanometres - 380) / 10;
}

TEST(CglColour, CieTableHasTheKnownShape) {
  const auto& cmf = colourMatching();
  ASSERT_EQ(cmf.size(), 33u);  // 380, 390, ..., 700 nm
  // Spot values of CIE 15:2004 Table T.4 (also Wyszecki & Stiles Table I(3.3.1)).
  EXPECT_DOUBLE_EQ(cmf[index(380)][0], 0.001368);
  EXPECT_DOUBLE_EQ(cmf[index(450)][2], 1.772110);
  EXPECT_DOUBLE_EQ(cmf[index(550)][1], 0.994950);
  EXPECT_DOUBLE_EQ(cmf[index(600)][0], 1.062200);
  EXPECT_DOUBLE_EQ(cmf[index(700)][1], 0.004102);
  // y-bar peaks at 555 nm (1.0); of the 10 nm rows the 560 one is the largest
  // (0.995000 against 550's 0.994950).
  int peak = 0;
  for (int i = 0; i < 33; ++i)
    if (cmf[i][1] > cmf[peak][1]) peak = i;
  EXPECT_EQ(peak, index(560));
  EXPECT_NEAR(cmf[peak][1], 1.0, 0.01);
  // x-bar's long-wave peak is the 600 row, z-bar's the 450 row: section 10's
  // "maxima of the colour matching functions".
  int xPeak = 0, zPeak = 0;
  for (int i = 0; i < 33; ++i) {
    if (cmf[i][0] > cmf[xPeak][0]) xPeak = i;
    if (cmf[i][2] > cmf[zPeak][2]) zPeak = i;
  }
  EXPECT_EQ(xPeak, index(600));
  EXPECT_EQ(zPeak, index(450));
  // Sums: the 1931 functions have equal areas (equal-energy white has X = Y =
  // Z), about 106.86 nm each, so 10.686 at 10 nm over 380-780 nm. Cut at 700 nm
  // x-bar loses 0.0114 (its 710-780 rows) and y-bar 0.0041; z-bar is 0 there.
  double sum[3] = {0, 0, 0};
  for (const auto& row : cmf)
    for (int k = 0; k < 3; ++k) sum[k] += row[k];
  EXPECT_NEAR(sum[0], 10.6722, 1e-9);  // the 33 rows added
  EXPECT_NEAR(sum[1], 10.681647, 1e-9);
  EXPECT_NEAR(sum[2], 10.6769, 1e-9);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(sum[k], 10.686, 0.015);
}

TEST(CglColour, MatricesAsPrintedAndInverted) {
  const Matrix3& e = phosphorMatrix(Phosphors::Electrohome);
  EXPECT_DOUBLE_EQ(e[0][0], 0.62);  // section 9.1, first row
  EXPECT_DOUBLE_EQ(e[1][1], 0.675);
  EXPECT_DOUBLE_EQ(e[2][2], 0.79);
  for (Phosphors p : {Phosphors::Electrohome, Phosphors::Ntsc}) {
    const Matrix3& m = phosphorMatrix(p);
    const Matrix3& inv = inversePhosphorMatrix(p);
    for (int c = 0; c < 3; ++c)  // each column is a chromaticity: x + y + z = 1
      EXPECT_NEAR(m[0][c] + m[1][c] + m[2][c], 1.0, 1e-12);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        double mm = 0, mi = 0;
        for (int k = 0; k < 3; ++k) {
          mm += m[r][k] * inv[k][c];
          mi += inv[r][k] * m[k][c];
        }
        EXPECT_NEAR(mm, r == c ? 1.0 : 0.0, 1e-12) << r << "," << c;
        EXPECT_NEAR(mi, r == c ? 1.0 : 0.0, 1e-12) << r << "," << c;
      }
  }
  // det M = 0.62 (0.675*0.79 - 0.06*0.115) - 0.21 (0.33*0.79 - 0.06*0.05)
  //       + 0.15 (0.33*0.115 - 0.675*0.05) = 0.326337 - 0.054117 + 0.000630 = 0.27285;
  // (M^-1)[0][0] = (0.675*0.79 - 0.06*0.115) / 0.27285 = 0.52635 / 0.27285 = 1.929082.
  EXPECT_NEAR(inversePhosphorMatrix(Phosphors::Electrohome)[0][0], 0.52635 / 0.27285, 1e-12);
  EXPECT_NEAR(inversePhosphorMatrix(Phosphors::Electrohome)[0][0], 1.929082, 1e-6);
}

TEST(CglColour, ChannelClipsThenTruncates) {
  EXPECT_EQ(toChannel(255.9), 255);
  EXPECT_EQ(toChannel(255.0), 255);
  EXPECT_EQ(toChannel(254.999), 254);  // truncated, not rounded
  EXPECT_EQ(toChannel(300.0), 255);
  EXPECT_EQ(toChannel(26.9), 26);
  EXPECT_EQ(toChannel(0.99), 0);
  EXPECT_EQ(toChannel(-0.5), 0);  // (int)-0.5 is 0 too
  EXPECT_EQ(toChannel(-3.0), 0);
  EXPECT_EQ(toChannel(std::nan("")), 0);  // CGL-D20
  EXPECT_EQ(toChannel(std::numeric_limits<double>::infinity()), 255);
  EXPECT_EQ(toChannel(-std::numeric_limits<double>::infinity()), 0);
}

// A colour-vector that is 1.0 at 550 nm and 0 elsewhere, by hand:
//   X = 1360 * 0.433450 = 589.492,  Y = 1360 * 0.994950 = 1353.132,
//   Z = 1360 * 0.008750 = 11.9.
// Electrohome M^-1 (cofactors over det 0.27285; docs/cgl/colour.md):
//   [ 1.92908191 -0.54480484 -0.32490379]
//   [-0.94447499  1.76763790  0.04507971]
//   [ 0.01539307 -0.22283306  1.27982408]
//   r = (1.92908191*589.492 - 0.54480484*1353.132 - 0.32490379*11.9) / 15
//     = (1137.1784 - 737.1929 - 3.8664) / 15 = 396.1191 / 15 = 26.408 -> 26
//   g = (-556.7605 + 2391.8474 + 0.5364) / 15 = 1835.6234 / 15 = 122.375 -> 122
//   b = (9.0741 - 301.5225 + 15.2299) / 15 = -277.2185 / 15 = -18.481 -> 0 (clipped)
TEST(CglColour, OneSampleByHand) {
  Spectrum c{};
  c[index(550)] = 1.0;
  const Xyz xyz = spectrumToXyz(c);
  EXPECT_NEAR(xyz.x, 589.492, 1e-9);
  EXPECT_NEAR(xyz.y, 1353.132, 1e-9);
  EXPECT_NEAR(xyz.z, 11.9, 1e-9);
  const auto rgb = xyzToMonitor(xyz, Phosphors::Electrohome);
  EXPECT_NEAR(rgb[0], 26.408, 0.001);
  EXPECT_NEAR(rgb[1], 122.375, 0.001);
  EXPECT_NEAR(rgb[2], -18.481, 0.001);
  EXPECT_EQ(toRgb(c, Phosphors::Electrohome), (Rgb8{26, 122, 0}));
}

// A flat colour-vector of 0.06 (the checkerboard's "dark gray" mirror,
// section 3 of Appendix 1): X = 1360 * 0.06 * sum x-bar = 81.6 * 10.6722 =
// 870.852, Y = 81.6 * 10.681647 = 871.622, Z = 81.6 * 10.6769 = 871.235.
//   r = (1.92908191*870.852 - 0.54480484*871.622 - 0.32490379*871.235) / 15
//     = (1679.9439 - 474.8641 - 283.0676) / 15 = 922.0122 / 15 = 61.467 -> 61
//   g = (-822.4975 + 1540.7128 + 39.2750) / 15 = 757.4903 / 15 = 50.499 -> 50
//   b = (13.4051 - 194.2263 + 1115.0276) / 15 = 934.2064 / 15 = 62.280 -> 62
// (the monitor's white, M (1 1 1) = (0.98, 1.065, 0.955), is not equal-energy
// white, hence a grey with less green).
TEST(CglColour, FlatSpectrumByHand) {
  Spectrum c;
  c.fill(0.06);
  const Xyz xyz = spectrumToXyz(c);
  EXPECT_NEAR(xyz.x, 870.852, 0.001);
  EXPECT_NEAR(xyz.y, 871.622, 0.001);
  EXPECT_NEAR(xyz.z, 871.235, 0.001);
  const auto rgb = xyzToMonitor(xyz, Phosphors::Electrohome);
  EXPECT_NEAR(rgb[0], 61.467, 0.001);
  EXPECT_NEAR(rgb[1], 50.499, 0.001);
  EXPECT_NEAR(rgb[2], 62.280, 0.001);
  EXPECT_EQ(toRgb(c, Phosphors::Electrohome), (Rgb8{61, 50, 62}));
  // A bright flat spectrum clips every channel.
  c.fill(1.0);
  EXPECT_EQ(toRgb(c, Phosphors::Electrohome), (Rgb8{255, 255, 255}));
  // Black stays black.
  c.fill(0.0);
  EXPECT_EQ(toRgb(c, Phosphors::Electrohome), (Rgb8{0, 0, 0}));
}

TEST(CglColour, NtscDiffersFromElectrohome) {
  // The same flat 0.06: NTSC M^-1 row 0 = (1.73008850, -0.48230088, -0.26106195)
  // r = (1506.6502 - 420.3842 - 227.4463) / 15 = 57.255 -> 57 (Electrohome 61).
  Spectrum c;
  c.fill(0.06);
  EXPECT_EQ(toRgb(c, Phosphors::Ntsc), (Rgb8{57, 47, 69}));
  EXPECT_NE(toRgb(c, Phosphors::Ntsc), toRgb(c, Phosphors::Electrohome));
  EXPECT_NE(phosphorMatrix(Phosphors::Ntsc), phosphorMatrix(Phosphors::Electrohome));
  Spectrum green{};
  green[index(550)] = 1.0;
  EXPECT_EQ(toRgb(green, Phosphors::Ntsc), (Rgb8{24, 117, 0}));
}

TEST(CglColour, RgbToSpectrumSetsOnlyThreeSamplesThatSolveTheSystem) {
  for (Phosphors p : {Phosphors::Electrohome, Phosphors::Ntsc}) {
    const Rgb8 rgb{200, 100, 50};
    const Spectrum d = rgbToSpectrum(rgb, p);
    for (int i = 0; i < 33; ++i) {
      if (i != index(450) && i != index(550) && i != index(600)) {
        EXPECT_EQ(d[i], 0.0) << i;
      }
    }
    // (X Y Z) = 15 M (r g b), and the three samples reproduce it exactly.
    const Matrix3& m = phosphorMatrix(p);
    const Xyz back = spectrumToXyz(d);
    const double want[3] = {15 * (m[0][0] * 200 + m[0][1] * 100 + m[0][2] * 50),
                            15 * (m[1][0] * 200 + m[1][1] * 100 + m[1][2] * 50),
                            15 * (m[2][0] * 200 + m[2][1] * 100 + m[2][2] * 50)};
    EXPECT_NEAR(back.x, want[0], 1e-9);
    EXPECT_NEAR(back.y, want[1], 1e-9);
    EXPECT_NEAR(back.z, want[2], 1e-9);
  }
  // Black is the zero spectrum.
  EXPECT_EQ(rgbToSpectrum({0, 0, 0}, Phosphors::Electrohome), Spectrum{});
  // Electrohome white (255 255 255): X = 15 * 0.98 * 255 = 3748.5, Y = 15 *
  // 1.065 * 255 = 4073.625, Z = 15 * 0.955 * 255 = 3652.875; the solution is
  // D_450 = 1.5044, D_550 = 2.1713, D_600 = 1.2326 (docs/cgl/colour.md).
  const Spectrum white = rgbToSpectrum({255, 255, 255}, Phosphors::Electrohome);
  EXPECT_NEAR(white[index(450)], 1.5044, 1e-4);
  EXPECT_NEAR(white[index(550)], 2.1713, 1e-4);
  EXPECT_NEAR(white[index(600)], 1.2326, 1e-4);
}

// Texture RGB -> colour-vector -> ToRGB gives the RGB back up to one unit:
// the two conversions are exact inverses in real arithmetic (15 M, then the
// 3x3 solve, then 1360 sum, then (1/15) M^-1), but in doubles a channel comes
// back as v +- 1e-12, and ToRGB truncates, so v - 1e-12 becomes v - 1.
TEST(CglColour, TextureRoundTripWithinOne) {
  const Rgb8 triples[] = {{0, 0, 0},      {255, 255, 255}, {255, 0, 0},   {0, 255, 0},
                          {0, 0, 255},    {0, 160, 0},     {0, 0, 200},   {12, 34, 56},
                          {200, 100, 50}, {1, 1, 1},       {254, 128, 3}, {77, 177, 250}};
  for (Phosphors p : {Phosphors::Electrohome, Phosphors::Ntsc})
    for (const Rgb8& in : triples) {
      const Rgb8 out = toRgb(rgbToSpectrum(in, p), p);
      EXPECT_TRUE(out.r == in.r || out.r == in.r - 1) << in.r << " -> " << out.r;
      EXPECT_TRUE(out.g == in.g || out.g == in.g - 1) << in.g << " -> " << out.g;
      EXPECT_TRUE(out.b == in.b || out.b == in.b - 1) << in.b << " -> " << out.b;
      EXPECT_LE(std::abs(out.r - in.r) + std::abs(out.g - in.g) + std::abs(out.b - in.b), 3);
    }
}

TEST(CglColour, ColourVectorTextAsAFileWritesIt) {
  Spectrum c{};
  c[0] = 0.5;
  c[9] = 1.25;
  c[32] = 7;
  const std::string text = colourVectorText(c);
  EXPECT_EQ(text,
            "0.5 0 0 0 0 0 0 0 0 1.25\n"
            "0 0 0 0 0 0 0 0 0 0\n"
            "0 0 0 0 0 0 0 0 0 0\n"
            "0 0 7\n");
}

}  // namespace
}  // namespace prime::cgl
