// The probe's text panel (palette/text/text_panel.h): how its lines wrap
// and are cut, and where the panel goes.
#include "palette/text/text_panel.h"

#include <gtest/gtest.h>

namespace prime {
namespace {

TEST(WrapLines, BreaksAfterTheLastSpaceThatFitsAndIndentsTheRest) {
  // 20 columns: "  hit: object 12 at" is 19, the next word does not fit.
  const auto lines = wrapLines("  hit: object 12 at t = 3.25, point (1, 2, 3)", 20, 0);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "  hit: object 12 at ");
  EXPECT_EQ(lines[1], "    t = 3.25, point ");  // the line's indent (2) plus two
  EXPECT_EQ(lines[2], "    (1, 2, 3)");
  for (const auto& l : lines) EXPECT_LE(l.size(), 20u) << l;
}

TEST(WrapLines, ANumberLongerThanHalfALineIsCutAtTheWidth) {
  const auto lines = wrapLines("x 0123456789012345678901234", 10, 0);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "x 01234567");
  EXPECT_EQ(lines[1], "  89012345");
  EXPECT_EQ(lines[3], "  4");
}

TEST(WrapLines, CountsCodePointsNotBytesAndKeepsUtf8Whole) {
  // 12 columns of "é" (two bytes each) and a tab taken as a space.
  const auto lines = wrapLines(
      "\t\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9"
      "\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9",
      12, 0);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].size(), 1u + 2u * 11u);
  // A broken byte is U+FFFD, not dropped.
  EXPECT_EQ(wrapLines("a\xFF"
                      "b",
                      20, 0)[0],
            "a\xEF\xBF\xBD"
            "b");
}

TEST(WrapLines, SaysHowManyLinesItLeftOut) {
  const auto lines = wrapLines("1\n2\n3\n4\n5\n6\n", 40, 4);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[2], "3");
  EXPECT_EQ(lines[3], "... 3 more lines");
  EXPECT_EQ(wrapLines("1\n2\n3\n4\n", 40, 4).size(), 4u);  // all fit: no note
}

Image8 grey(int w, int h) {
  return {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 3, 200)};
}

TEST(TextPanel, GoesToTheEdgeAwayFromThePixelAndDarkensOnlyItsBox) {
  Image8 low = grey(320, 240);
  const Rect box = drawTextPanel(low, "one line\nand another", 200);  // pixel low: panel on top
  EXPECT_EQ(box.y, 0);
  EXPECT_EQ(box.w, 320);
  const TextCell cell = textCell();
  EXPECT_EQ(box.h, 2 * cell.lineHeight + 12);
  EXPECT_LT(low.rgb[0], 100);                                          // inside: darkened
  EXPECT_EQ(low.rgb[(static_cast<std::size_t>(239) * 320) * 3], 200);  // outside: as it was
  Image8 high = grey(320, 240);
  const Rect other = drawTextPanel(high, "one line\nand another", 10);
  EXPECT_EQ(other.y + other.h, 240);
  // Text was drawn: some pixel of the box is lighter than the box itself.
  bool ink = false;
  for (int y = box.y; y < box.y + box.h; ++y)
    for (int x = 0; x < box.w; ++x)
      ink = ink || low.rgb[(static_cast<std::size_t>(y) * 320 + x) * 3] > 120;
  EXPECT_TRUE(ink);
}

TEST(TextPanel, NeverTakesMoreThanHalfThePicture) {
  std::string text;
  for (int i = 0; i < 200; ++i) text += "line " + std::to_string(i) + "\n";
  Image8 img = grey(200, 100);
  const Rect box = drawTextPanel(img, text, 99);
  EXPECT_LE(box.h, 50);
  EXPECT_GT(textCell().advance, 0);
}

}  // namespace
}  // namespace prime
