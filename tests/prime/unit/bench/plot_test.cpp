// The chart renderer of prime bench: text, labels and marks land where they should.
#include "src/prime/bench/plot.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using namespace prime::bench;

int countColour(const prime::Image8& im, Colour c) {
  int n = 0;
  for (std::size_t i = 0; i + 2 < im.rgb.size(); i += 3)
    n += im.rgb[i] == c[0] && im.rgb[i + 1] == c[1] && im.rgb[i + 2] == c[2];
  return n;
}

TEST(BenchPlot, DecadeLabels) {
  EXPECT_EQ(decadeLabel(0), "1");
  EXPECT_EQ(decadeLabel(2), "100");
  EXPECT_EQ(decadeLabel(-1), "0.1");
  EXPECT_EQ(decadeLabel(-3), "0.001");
  EXPECT_EQ(decadeLabel(-4), "1E-4");
  EXPECT_EQ(decadeLabel(5), "1E5");
}

TEST(BenchPlot, TextIsDrawnInTheFontGrid) {
  prime::Image8 im{20, 12, std::vector<std::uint8_t>(20 * 12 * 3, 255)};
  // "1" at scale 2: rows ".#.", "##.", ".#.", ".#.", "###" -> 1+2+1+1+3 = 8 font pixels, 4 image
  // pixels each.
  EXPECT_EQ(drawText(im, 0, 0, "1", {0, 0, 0}, 2), 8);
  EXPECT_EQ(countColour(im, {0, 0, 0}), 32);
  EXPECT_EQ(textWidth("abc", 2), 24);
}

TEST(BenchPlot, SeriesAppearInTheirColours) {
  Series a{"A", {200, 0, 0}, {{1, 1}, {10, 0.1}}, {{1, 1}, {10, 0.1}}, {{10, 0.1}}, false};
  Series b{"B", {0, 0, 200}, {{2, 0.5}}, {}, {}, false};
  PlotSpec spec;
  spec.title = "T";
  const std::vector<Series> s = {a, b};
  const prime::Image8 im = drawPlot(spec, s);
  EXPECT_EQ(im.width, spec.width);
  EXPECT_EQ(im.height, spec.height);
  EXPECT_GT(countColour(im, {200, 0, 0}), 100);  // the line, two dots, a marker, the legend
  EXPECT_GT(countColour(im, {0, 0, 200}), 10);   // one dot and the legend
}

}  // namespace
