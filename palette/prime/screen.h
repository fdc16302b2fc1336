// The emulated IBM 8514/A screen in IBM8514HI mode (errata E09): 1024 x 768
// pixels of 8-bit palette indices, getmaxx() = 1023, getmaxy() = 767. It
// starts cleared to index 0, as initgraph leaves it. putpixel clips to the
// screen and stores `color & 0xFF` (Q12): the graph file keeps the raw 16-bit
// value, the screen only its low byte.
//
// Anything that wants to draw what the 1991 program drew can draw into a
// Screen: the renderer's rows (drawGraphRow), a whole graph file (drawGraph),
// or lines (Screen::line) for wireframes.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "legacy_io/prime/graph_file.h"
#include "palette/rect.h"

namespace prime {

class Screen {
 public:
  static constexpr int kWidth = 1024, kHeight = 768;  // IBM8514HI

  // Throws std::invalid_argument unless 1 <= width, height <= 16384.
  explicit Screen(int width = kWidth, int height = kHeight);

  int width() const { return width_; }
  int height() const { return height_; }
  Rect bounds() const { return {0, 0, width_, height_}; }

  void clear(std::uint8_t index = 0);
  // putpixel(x, y, color): off-screen pixels are dropped (returns false);
  // on-screen ones store color & 0xFF.
  bool putPixel(int x, int y, int color);
  // getpixel: the index at (x, y); 0 off the screen.
  std::uint8_t getPixel(int x, int y) const;
  // line(x0, y0, x1, y1): both end points included; at each step along the
  // longer axis the pixel nearest the ideal line (an exact tie goes to the
  // larger coordinate), drawn from the end with the smaller coordinate on that
  // axis, so line(a, b) and line(b, a) draw the same pixels. Clipped like
  // putPixel; any int coordinates are fine (the work is bounded by the
  // screen, not by the line's length).
  void line(int x0, int y0, int x1, int y1, int color);

  std::span<const std::uint8_t> row(int y) const {
    return {pixels_.data() + static_cast<std::size_t>(y) * width_,
            static_cast<std::size_t>(width_)};
  }
  std::span<const std::uint8_t> pixels() const { return pixels_; }

 private:
  int width_, height_;
  std::vector<std::uint8_t> pixels_;
};

// Where RayTrace.c's AssignScrPts(0.66, 0.0, 1.0, 1.0) puts the image's top
// left corner on a screen of this size: ((int)(0.66*w), (int)(0.0*h)) =
// (675, 0) on the 8514/A. The graph file does not record it; this is where
// `prime view` and `prime export` put a file unless told otherwise.
struct Placement {
  int left = 0, top = 0;
};
Placement listingPlacement(int screenWidth, int screenHeight);

// PutPixel(left + x, top + row, value) for each value of one graph-file row,
// as RayTrace.c's inner loop did.
void drawGraphRow(Screen& screen, Placement at, int row, std::span<const std::int16_t> values);
// The first `pixels` pixels of the file (all by default), row by row.
void drawGraph(Screen& screen, const io::GraphFile& graph, Placement at,
               std::size_t pixels = std::numeric_limits<std::size_t>::max());
// The part of the screen a graph file covers: its pixel grid at `at`,
// clipped to the screen (349 x 768 at (675, 0) for the listing's
// 350 x 769 file: column 1024 and row 768 are off-screen, K21).
Rect graphArea(const Screen& screen, const io::GraphFile& graph, Placement at);

}  // namespace prime
