#include "palette/prime/screen.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace prime {

Screen::Screen(int width, int height) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument("screen size " + std::to_string(width) + " x " +
                                std::to_string(height) + ": expected 1..16384 pixels each way");
  pixels_.assign(static_cast<std::size_t>(width) * height, 0);
}

void Screen::clear(std::uint8_t index) {
  std::fill(pixels_.begin(), pixels_.end(), index);
}

bool Screen::putPixel(int x, int y, int color) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return false;
  pixels_[static_cast<std::size_t>(y) * width_ + x] =
      static_cast<std::uint8_t>(color & 0xFF);  // Q12
  return true;
}

std::uint8_t Screen::getPixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return 0;
  return pixels_[static_cast<std::size_t>(y) * width_ + x];
}

void Screen::line(int x0, int y0, int x1, int y1, int color) {
  using Wide = __int128;  // products of two 33-bit differences
  long long dx = static_cast<long long>(x1) - x0, dy = static_cast<long long>(y1) - y0;
  const bool xMajor = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  if (xMajor ? dx < 0 : dy < 0) {
    std::swap(x0, x1);
    std::swap(y0, y1);
    dx = -dx;
    dy = -dy;
  }
  const long long n = xMajor ? dx : dy;  // steps along the major axis, >= 0
  const long long m = xMajor ? dy : dx;  // |m| <= n
  const long long a0 = xMajor ? x0 : y0, b0 = xMajor ? y0 : x0;
  const long long size = xMajor ? width_ : height_;
  const long long tBegin = std::max<long long>(0, -a0),
                  tEnd = std::min<long long>(n, size - 1 - a0);
  for (long long t = tBegin; t <= tEnd; ++t) {
    // nearest integer to t*m/n, ties up: floor((2tm + n) / 2n)
    long long minor = 0;
    if (n > 0) {
      const Wide num = Wide(2) * t * m + n, den = Wide(2) * n;
      Wide q = num / den;
      if ((num % den != 0) && (num < 0)) --q;  // floor for negative numerators
      minor = static_cast<long long>(q);
    }
    const long long a = a0 + t, b = b0 + minor;
    const long long x = xMajor ? a : b, y = xMajor ? b : a;
    if (x >= 0 && y >= 0 && x < width_ && y < height_)
      putPixel(static_cast<int>(x), static_cast<int>(y), color);
  }
}

Placement listingPlacement(int screenWidth, int screenHeight) {
  // SetScrCoordsX/Y: (int)(normalised * (getmax + 1)), as src/prime/render/camera.cpp.
  return {static_cast<int>(0.66 * static_cast<double>(screenWidth)),
          static_cast<int>(0.0 * static_cast<double>(screenHeight))};
}

void drawGraphRow(Screen& screen, Placement at, int row, std::span<const std::int16_t> values) {
  const long long y = static_cast<long long>(at.top) + row;
  if (y < 0 || y >= screen.height()) return;
  for (std::size_t j = 0; j < values.size(); ++j) {
    const long long x = static_cast<long long>(at.left) + static_cast<long long>(j);
    if (x >= 0 && x < screen.width())
      screen.putPixel(static_cast<int>(x), static_cast<int>(y), values[j]);
  }
}

void drawGraph(Screen& screen, const io::GraphFile& graph, Placement at, std::size_t pixels) {
  const std::size_t w = static_cast<std::size_t>(graph.width());
  if (w == 0) return;
  const std::size_t n = std::min(pixels, graph.pixels.size());
  for (std::size_t start = 0, row = 0; start < n; start += w, ++row) {
    const std::size_t count = std::min(w, n - start);
    drawGraphRow(screen, at, static_cast<int>(row), std::span(graph.pixels).subspan(start, count));
  }
}

Rect graphArea(const Screen& screen, const io::GraphFile& graph, Placement at) {
  return intersect(screen.bounds(), {at.left, at.top, graph.width(), graph.height()});
}

}  // namespace prime
