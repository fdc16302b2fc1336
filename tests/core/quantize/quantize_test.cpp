#include "palette/quantize/quantize.h"

#include <gtest/gtest.h>

#include <set>

#include "palette/quantize/colour_difference.h"

namespace prime::quantize {
namespace {

Image8 imageOf(const std::vector<Colour8>& pixels, int width) {
  Image8 img{width, static_cast<int>(pixels.size()) / width, {}};
  for (const Colour8& c : pixels) img.rgb.insert(img.rgb.end(), c.begin(), c.end());
  return img;
}

// The 8-bit colour a 6-bit DAC level shows as: round(v * 255 / 63).
std::uint8_t shown6(int v) {
  return static_cast<std::uint8_t>((v * 255 + 31) / 63);
}

constexpr Method kMethods[] = {Method::Popularity, Method::MedianCut, Method::Octree};

TEST(Names, RoundTrip) {
  for (Method m : kMethods) EXPECT_EQ(methodFromName(methodName(m)), m);
  for (Dither d : {Dither::None, Dither::Ordered, Dither::FloydSteinberg})
    EXPECT_EQ(ditherFromName(ditherName(d)), d);
  EXPECT_FALSE(methodFromName("kmeans"));
  EXPECT_FALSE(ditherFromName("bayer"));
}

TEST(Palette, ShownAndLevelOfAreTheDacRounding) {
  Palette p;  // 6 bits
  p.levels = {{0, 31, 63}};
  EXPECT_EQ(p.shown(0), (Colour8{0, 125, 255}));  // 31*255/63 = 125.48 -> 125
  EXPECT_EQ(p.levelOf(80), 20);                   // 80*63/255 = 19.76
  EXPECT_EQ(p.levelOf(83), 21);                   // 20.5 rounds up
  EXPECT_EQ(p.levelOf(-5), 0);
  EXPECT_EQ(p.levelOf(300), 63);
}

// 200 distinct colours the DAC can show exactly: every method gives every
// one its own entry, and the picture comes back unchanged (Floyd-Steinberg
// too: there is no error to spread).
TEST(Quantize, AnImageOfAtMost256DacColoursComesBackExact) {
  std::vector<Colour8> pixels;
  for (int i = 0; i < 200; ++i) {
    const Colour8 c{shown6(i % 8 * 9), shown6(i / 8 % 5 * 15), shown6(i / 40 * 12)};
    for (int k = 0; k <= i % 3; ++k) pixels.push_back(c);  // 1 to 3 pixels each
  }
  while (pixels.size() % 10) pixels.push_back(pixels.front());
  const Image8 img = imageOf(pixels, 10);
  for (Method m : kMethods)
    for (Dither d : {Dither::None, Dither::FloydSteinberg}) {
      const Result r = quantize(img, {m, d, 256, 6});
      EXPECT_EQ(r.palette.levels.size(), 200u) << methodName(m);
      EXPECT_EQ(present(r, img.width, img.height).rgb, img.rgb)
          << methodName(m) << " " << ditherName(d);
    }
}

// Two tight clusters, two colours: each entry is its cluster's mean at the
// nearest DAC level, whatever the method (popularity: each cluster is one DAC
// cell, pixels 0..3 away from its centre).
TEST(Quantize, TwoClustersGiveTheirMeans) {
  std::vector<Colour8> pixels;
  for (int i = 0; i < 8; ++i) pixels.push_back({static_cast<std::uint8_t>(40 + i % 2), 40, 40});
  for (int i = 0; i < 8; ++i) pixels.push_back({200, static_cast<std::uint8_t>(100 + i % 2), 50});
  const Image8 img = imageOf(pixels, 4);
  // Means (40.5, 40, 40) -> levels round(40.5*63/255)=10, round(9.88)=10, 10;
  // (200, 100.5, 50) -> round(49.41)=49, round(24.83)=25, round(12.35)=12.
  const std::set<Levels> expected{{10, 10, 10}, {49, 25, 12}};
  for (Method m : kMethods) {
    const Palette p = choosePalette(img, m, 2, 6);
    EXPECT_EQ(std::set<Levels>(p.levels.begin(), p.levels.end()), expected) << methodName(m);
    const Result r = quantize(img, {m, Dither::None, 2, 6});
    for (int i = 0; i < 16; ++i)
      EXPECT_EQ(r.palette.levels[r.indices[static_cast<std::size_t>(i)]],
                i < 8 ? (Levels{10, 10, 10}) : (Levels{49, 25, 12}))
          << methodName(m) << " pixel " << i;
  }
}

// Popularity keeps the most frequent colours: counts 5, 3, 1 and two
// entries: the one-pixel colour is lost and maps to its nearest entry.
TEST(Popularity, KeepsTheMostFrequentColours) {
  const Colour8 a{shown6(10), 0, 0}, b{0, shown6(40), 0}, c{shown6(12), 0, 0};
  const Image8 img = imageOf({a, b, a, b, a, b, a, a, c}, 9);
  const Palette p = choosePalette(img, Method::Popularity, 2, 6);
  ASSERT_EQ(p.levels.size(), 2u);
  EXPECT_EQ(p.levels[0], (Levels{10, 0, 0}));  // most popular first
  EXPECT_EQ(p.levels[1], (Levels{0, 40, 0}));
  EXPECT_EQ(mapToPalette(img, p, Dither::None)[8], 0);  // c -> a, the nearest
}

// Median cut on a hand-worked example: pure reds 0 (1 pixel), 64 (1), 128
// (2), 255 (4). The first cut is across red at the median: cumulative counts
// 1, 2, 4 reach half of 8 at 128, which closes the lower box {0, 64, 128}.
// Its mean (0 + 64 + 2*128)/4 = 80 is DAC level round(80*63/255) = 20; the
// upper box {255} is level 63. A third entry splits the box with the most
// pixels that can be split (the lower, 4 pixels; the upper is one cell) at
// its median: cumulative 1, 2 of 4 -> {0, 64} (mean 32, level round(7.91) =
// 8) and {128} (level round(31.62) = 32).
TEST(MedianCut, SplitsAtTheMedianOfTheLongestSide) {
  const auto red = [](int r) { return Colour8{static_cast<std::uint8_t>(r), 0, 0}; };
  const Image8 img =
      imageOf({red(0), red(64), red(128), red(128), red(255), red(255), red(255), red(255)}, 8);
  const Palette two = choosePalette(img, Method::MedianCut, 2, 6);
  ASSERT_EQ(two.levels.size(), 2u);
  EXPECT_EQ(two.levels[0], (Levels{20, 0, 0}));
  EXPECT_EQ(two.levels[1], (Levels{63, 0, 0}));
  const Palette three = choosePalette(img, Method::MedianCut, 3, 6);
  ASSERT_EQ(three.levels.size(), 3u);
  EXPECT_EQ(three.levels[0], (Levels{8, 0, 0}));
  EXPECT_EQ(three.levels[1], (Levels{63, 0, 0}));
  EXPECT_EQ(three.levels[2], (Levels{32, 0, 0}));
}

// After the first cut, the longest side decides: a box spread 0..255 in green
// but only 0..8 in red is cut across green. (8 bits: levels are the values.)
TEST(MedianCut, LaterCutsFollowTheLongestSide) {
  std::vector<Colour8> pixels;
  for (int i = 0; i < 4; ++i) pixels.push_back({0, static_cast<std::uint8_t>(i * 85), 0});
  for (int i = 0; i < 4; ++i) pixels.push_back({8, static_cast<std::uint8_t>(i * 85), 0});
  for (int i = 0; i < 8; ++i) pixels.push_back({255, 255, 255});
  const Image8 img = imageOf(pixels, 8);
  const Palette p = choosePalette(img, Method::MedianCut, 3, 8);  // 8 bits: levels are values
  ASSERT_EQ(p.levels.size(), 3u);
  // Red cut first: sorted by red, the cumulative count reaches half of 16 at
  // the last red-8 cell -> {red 0, red 8} | {white}. Both boxes hold 8
  // pixels, but white is one cell: the reds are cut, across green (range 255
  // against 8), at their median: sorted by green, 1, 2, 3, 4 of 8 pixels
  // reach half at the second green-85 cell -> greens {0, 85} | {170, 255}.
  EXPECT_EQ(p.levels[0], (Levels{4, 43, 0}));  // mean red 4, green 42.5 -> 43
  EXPECT_EQ(p.levels[1], (Levels{255, 255, 255}));
  EXPECT_EQ(p.levels[2], (Levels{4, 213, 0}));  // green 212.5 -> 213
}

// Octree on a hand-worked example, 8-bit levels so the means show: A =
// (0,0,0) three times, B = (0,0,1), C = (255,255,254) twice, D =
// (255,255,255), in that order, three colours. A and B are siblings below one
// level-7 node P1, C and D below P2. D makes a fourth leaf: the deepest level
// with inner nodes is 7, holding P1 (4 pixels) and P2 (3 pixels, D counted);
// the fewer pixels go: P2 becomes one leaf, mean (255, 255, 254.33).
TEST(Octree, ReducesTheDeepestNodeWithFewestPixels) {
  const Colour8 a{0, 0, 0}, b{0, 0, 1}, c{255, 255, 254}, d{255, 255, 255};
  const Image8 img = imageOf({a, a, a, b, c, c, d}, 7);
  const Palette p = choosePalette(img, Method::Octree, 3, 8);
  ASSERT_EQ(p.levels.size(), 3u);
  EXPECT_EQ(p.levels[0], (Levels{0, 0, 0}));
  EXPECT_EQ(p.levels[1], (Levels{0, 0, 1}));
  EXPECT_EQ(p.levels[2], (Levels{255, 255, 254}));
  // The pixels after the reduction still find their leaf: D is in P2's mean.
  const std::vector<std::uint8_t> idx = mapToPalette(img, p, Dither::None);
  EXPECT_EQ(idx, (std::vector<std::uint8_t>{0, 0, 0, 1, 2, 2, 2}));
}

// With a third A instead of a third C, P1 has 4 and P2 2 pixels: still P2.
// With the counts swapped (A once, C three times) P1 goes instead.
TEST(Octree, TheCountDecidesWhichSiblingsMerge) {
  const Colour8 a{0, 0, 0}, b{0, 0, 1}, c{255, 255, 254}, d{255, 255, 255};
  const Palette p = choosePalette(imageOf({a, b, c, c, c, d}, 6), Method::Octree, 3, 8);
  ASSERT_EQ(p.levels.size(), 3u);
  EXPECT_EQ(p.levels[0], (Levels{0, 0, 1}));  // (0 + 1) / 2 = 0.5 rounds away from 0
  EXPECT_EQ(p.levels[1], (Levels{255, 255, 254}));
  EXPECT_EQ(p.levels[2], (Levels{255, 255, 255}));
}

TEST(Dither, FloydSteinbergKeepsAFlatGreysMean) {
  Palette bw;
  bw.dacBits = 8;
  bw.levels = {{0, 0, 0}, {255, 255, 255}};
  const Image8 grey = imageOf(std::vector<Colour8>(32 * 32, Colour8{64, 64, 64}), 32);
  for (Dither d : {Dither::FloydSteinberg, Dither::Ordered}) {
    const std::vector<std::uint8_t> idx = mapToPalette(grey, bw, d);
    double white = 0;
    for (std::uint8_t i : idx) white += i;
    // 64/255 = 25.1 % white. Ordered: offsets (t + 0.5)/64 - 0.5 of 255 lift
    // 64 past 127.5 for t >= 48: 16 of 64 thresholds, 25 % exactly.
    if (d == Dither::Ordered)
      EXPECT_EQ(white / idx.size(), 0.25);
    else
      EXPECT_NEAR(white / idx.size(), 64.0 / 255.0, 0.01);
  }
  EXPECT_EQ(mapToPalette(grey, bw, Dither::None), std::vector<std::uint8_t>(32 * 32, 0));
}

TEST(Dither, IsDeterministic) {
  std::vector<Colour8> pixels;
  for (int i = 0; i < 64 * 48; ++i)
    pixels.push_back({static_cast<std::uint8_t>(i * 7), static_cast<std::uint8_t>(i / 64 * 5),
                      static_cast<std::uint8_t>(i % 64 * 4)});
  const Image8 img = imageOf(pixels, 64);
  for (Method m : kMethods)
    for (Dither d : {Dither::None, Dither::Ordered, Dither::FloydSteinberg}) {
      const Result r1 = quantize(img, {m, d, 16, 6});
      const Result r2 = quantize(img, {m, d, 16, 6});
      EXPECT_EQ(r1.palette.levels, r2.palette.levels);
      EXPECT_EQ(r1.indices, r2.indices);
      EXPECT_LE(r1.palette.levels.size(), 16u);
      for (std::uint8_t i : r1.indices) ASSERT_LT(i, r1.palette.levels.size());
    }
}

// Error diffusion lowers the error of a smooth ramp's local averages: a 3 x 3
// box filter of the dithered picture is nearer the original than the plain
// mapping's (what dithering is for).
TEST(Dither, FloydSteinbergIsNearerOnAverage) {
  std::vector<Colour8> pixels;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 128; ++x) pixels.push_back({static_cast<std::uint8_t>(x * 2), 0, 0});
  const Image8 ramp = imageOf(pixels, 128);
  const auto blurredError = [&](Dither d) {
    const Result r = quantize(ramp, {Method::MedianCut, d, 4, 6});
    const Image8 out = present(r, 128, 32);
    double err = 0;
    for (int y = 1; y < 31; ++y)
      for (int x = 1; x < 127; ++x) {
        double sum = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) sum += out.rgb[((y + dy) * 128 + x + dx) * 3];
        err += std::abs(sum / 9 - x * 2);
      }
    return err;
  };
  EXPECT_LT(blurredError(Dither::FloydSteinberg), 0.5 * blurredError(Dither::None));
}

TEST(Quantize, RejectsBadSettings) {
  const Image8 img = imageOf({{1, 2, 3}}, 1);
  EXPECT_THROW(choosePalette(img, Method::Octree, 0, 6), std::invalid_argument);
  EXPECT_THROW(choosePalette(img, Method::Octree, 257, 6), std::invalid_argument);
  EXPECT_THROW(choosePalette(img, Method::Octree, 4, 9), std::invalid_argument);
  EXPECT_THROW(mapToPalette(img, Palette{}, Dither::None), std::invalid_argument);
  // An empty picture gets one black entry and no indices.
  const Result r = quantize(Image8{0, 0, {}}, {});
  EXPECT_EQ(r.palette.levels.size(), 1u);
  EXPECT_TRUE(r.indices.empty());
}

}  // namespace
}  // namespace prime::quantize
