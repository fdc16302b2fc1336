// The emulated 8514/A screen: putpixel clipping and masking (E09, Q12), lines,
// and graph files drawn where RayTrace.c's PutPixel drew them (K21).
#include "palette/prime/screen.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace prime {
namespace {

using Pixels = std::set<std::pair<int, int>>;

Pixels lit(const Screen& s) {
  Pixels out;
  for (int y = 0; y < s.height(); ++y)
    for (int x = 0; x < s.width(); ++x)
      if (s.getPixel(x, y) != 0) out.insert({x, y});
  return out;
}

TEST(Screen, IsThe8514HiModeClearedToZero) {
  const Screen s;
  EXPECT_EQ(s.width(), 1024);
  EXPECT_EQ(s.height(), 768);
  for (auto v : s.pixels()) ASSERT_EQ(v, 0);
  EXPECT_THROW(Screen(0, 10), std::invalid_argument);
  EXPECT_THROW(Screen(20000, 10), std::invalid_argument);
}

TEST(Screen, PutPixelClipsAndMasksToEightBits) {
  Screen s;
  EXPECT_TRUE(s.putPixel(0, 0, 5));
  EXPECT_TRUE(s.putPixel(1023, 767, 255));
  EXPECT_FALSE(s.putPixel(1024, 0, 7));  // getmaxx() = 1023 (K21: column 1024 is off-screen)
  EXPECT_FALSE(s.putPixel(0, 768, 7));
  EXPECT_FALSE(s.putPixel(-1, 5, 7));
  EXPECT_FALSE(s.putPixel(5, -1, 7));
  EXPECT_TRUE(s.putPixel(10, 10, -146));  // Q12: -146 & 0xFF = 110
  EXPECT_TRUE(s.putPixel(11, 10, 256 + 9));
  EXPECT_TRUE(s.putPixel(12, 10, -1));
  EXPECT_EQ(s.getPixel(0, 0), 5);
  EXPECT_EQ(s.getPixel(1023, 767), 255);
  EXPECT_EQ(s.getPixel(10, 10), 110);
  EXPECT_EQ(s.getPixel(11, 10), 9);
  EXPECT_EQ(s.getPixel(12, 10), 255);
  EXPECT_EQ(s.getPixel(1024, 0), 0);
  EXPECT_EQ(lit(s).size(), 5u);
  s.clear(3);
  EXPECT_EQ(s.getPixel(500, 500), 3);
}

TEST(ScreenLine, EndPointsIncludedAndNearestPixels) {
  Screen s(16, 8);
  s.line(1, 1, 5, 3,
         9);  // dx 4, dy 2: y = 1 + round(t/2), ties up: t=1 -> 1.5 -> 2, t=3 -> 2.5 -> 3
  EXPECT_EQ(lit(s), (Pixels{{1, 1}, {2, 2}, {3, 2}, {4, 3}, {5, 3}}));
  EXPECT_EQ(s.getPixel(3, 2), 9);
}

TEST(ScreenLine, SymmetricAndAllOctants) {
  const std::pair<int, int> ends[] = {{0, 0}, {15, 3}, {2, 15}, {15, 15}, {7, 0}, {0, 9}, {11, 6}};
  for (auto [x0, y0] : ends)
    for (auto [x1, y1] : ends) {
      Screen a(16, 16), b(16, 16);
      a.line(x0, y0, x1, y1, 1);
      b.line(x1, y1, x0, y0, 1);
      const Pixels pa = lit(a);
      EXPECT_EQ(pa, lit(b)) << x0 << "," << y0 << " " << x1 << "," << y1;
      EXPECT_TRUE(pa.count({x0, y0}) && pa.count({x1, y1}));
      const int n = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
      EXPECT_EQ(pa.size(),
                static_cast<std::size_t>(n + 1));  // one pixel per step on the longer axis
    }
}

TEST(ScreenLine, HorizontalVerticalPointAndDiagonal) {
  Screen s(8, 8);
  s.line(2, 3, 2, 3, 4);
  EXPECT_EQ(lit(s), (Pixels{{2, 3}}));
  s.clear();
  s.line(6, 1, 1, 1, 4);
  EXPECT_EQ(lit(s), (Pixels{{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {6, 1}}));
  s.clear();
  s.line(0, 7, 3, 4, 4);
  EXPECT_EQ(lit(s), (Pixels{{0, 7}, {1, 6}, {2, 5}, {3, 4}}));
}

TEST(ScreenLine, ClippedAgainstTheScreenWithoutChangingWhichPixelsAreOn) {
  // The part of a long line that is on the screen is the same pixels as
  // when the whole line fits: compare a line on a big screen with the same
  // line on a small screen that sees a window of it.
  Screen big(64, 64), small(16, 16);
  big.line(-40 + 24, -10 + 24, 50 + 24, 30 + 24, 1);  // shifted by 24 to fit
  small.line(-40, -10, 50, 30, 1);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      EXPECT_EQ(small.getPixel(x, y), big.getPixel(x + 24, y + 24)) << x << "," << y;
  Screen huge(8, 8);
  huge.line(-2000000000, 3, 2000000000, 3, 2);  // bounded work, no overflow
  EXPECT_EQ(lit(huge).size(), 8u);
  huge.clear();
  huge.line(-2147483647 - 1, -2147483647 - 1, 2147483647, 2147483647, 2);
  EXPECT_EQ(lit(huge), (Pixels{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}, {6, 6}, {7, 7}}));
  huge.clear();
  huge.line(20, 20, 30, 40, 2);  // entirely off-screen
  EXPECT_TRUE(lit(huge).empty());
}

io::GraphFile graphOf(int across, int down, std::int16_t value) {
  io::GraphFile g;
  g.numPixAcross = static_cast<std::int16_t>(across);
  g.numPixDown = static_cast<std::int16_t>(down);
  g.pixels.assign(static_cast<std::size_t>(across + 1) * (down + 1), value);
  return g;
}

TEST(GraphOnScreen, TheListingsFileLandsAtColumn675AndLosesItsLastColumnAndRow) {
  EXPECT_EQ(listingPlacement(1024, 768).left, 675);  // (int)(0.66 * 1024) = (int)675.84
  EXPECT_EQ(listingPlacement(1024, 768).top, 0);
  EXPECT_EQ(listingPlacement(640, 480).left, 422);  // (int)422.4
  Screen s;
  const io::GraphFile g = graphOf(349, 768, 109);  // 350 x 769 pixels (K22)
  drawGraph(s, g, listingPlacement(1024, 768));
  EXPECT_EQ(graphArea(s, g, {675, 0}), (Rect{675, 0, 349, 768}));
  EXPECT_EQ(s.getPixel(674, 0), 0);
  EXPECT_EQ(s.getPixel(675, 0), 109);
  EXPECT_EQ(s.getPixel(1023, 767), 109);
  EXPECT_EQ(lit(s).size(), 349u * 768u);
}

TEST(GraphOnScreen, RowsAndPartialFiles) {
  Screen s(10, 4);
  const std::int16_t row[] = {1, -255, 300, 4};
  drawGraphRow(s, {8, 2}, 1, row);  // screen row 3, columns 8, 9 (10, 11 clipped)
  EXPECT_EQ(s.getPixel(8, 3), 1);
  EXPECT_EQ(s.getPixel(9, 3), 1);  // -255 & 0xFF = 1
  EXPECT_EQ(lit(s).size(), 2u);
  drawGraphRow(s, {0, 2}, 5, row);  // row 7: off-screen
  drawGraphRow(s, {0, -3}, 0, row);
  EXPECT_EQ(lit(s).size(), 2u);
  Screen t(10, 10);
  io::GraphFile g = graphOf(2, 2, 7);  // 3 x 3
  drawGraph(t, g, {0, 0}, 4);          // only the first 4 pixels: row 0 and one of row 1
  EXPECT_EQ(lit(t), (Pixels{{0, 0}, {1, 0}, {2, 0}, {0, 1}}));
  EXPECT_TRUE(graphArea(t, g, {20, 0}).empty());
  EXPECT_EQ(graphArea(t, g, {-1, 8}), (Rect{0, 8, 2, 2}));
}

}  // namespace
}  // namespace prime
