#include "src/prime/bench/plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

namespace prime::bench {

namespace {

// The 3x5 font: five rows of three pixels per glyph, '#' set.
struct Glyph {
  char c;
  const char* rows[5];
};
constexpr Glyph kFont[] = {
    {'0', {"###", "#.#", "#.#", "#.#", "###"}}, {'1', {".#.", "##.", ".#.", ".#.", "###"}},
    {'2', {"###", "..#", "###", "#..", "###"}}, {'3', {"###", "..#", "###", "..#", "###"}},
    {'4', {"#.#", "#.#", "###", "..#", "..#"}}, {'5', {"###", "#..", "###", "..#", "###"}},
    {'6', {"###", "#..", "###", "#.#", "###"}}, {'7', {"###", "..#", "..#", "..#", "..#"}},
    {'8', {"###", "#.#", "###", "#.#", "###"}}, {'9', {"###", "#.#", "###", "..#", "###"}},
    {'A', {".#.", "#.#", "###", "#.#", "#.#"}}, {'B', {"##.", "#.#", "##.", "#.#", "##."}},
    {'C', {".##", "#..", "#..", "#..", ".##"}}, {'D', {"##.", "#.#", "#.#", "#.#", "##."}},
    {'E', {"###", "#..", "##.", "#..", "###"}}, {'F', {"###", "#..", "##.", "#..", "#.."}},
    {'G', {".##", "#..", "#.#", "#.#", ".##"}}, {'H', {"#.#", "#.#", "###", "#.#", "#.#"}},
    {'I', {"###", ".#.", ".#.", ".#.", "###"}}, {'J', {"..#", "..#", "..#", "#.#", ".#."}},
    {'K', {"#.#", "#.#", "##.", "#.#", "#.#"}}, {'L', {"#..", "#..", "#..", "#..", "###"}},
    {'M', {"#.#", "###", "###", "#.#", "#.#"}}, {'N', {"##.", "#.#", "#.#", "#.#", "#.#"}},
    {'O', {".#.", "#.#", "#.#", "#.#", ".#."}}, {'P', {"##.", "#.#", "##.", "#..", "#.."}},
    {'Q', {".#.", "#.#", "#.#", "###", ".##"}}, {'R', {"##.", "#.#", "##.", "#.#", "#.#"}},
    {'S', {".##", "#..", ".#.", "..#", "##."}}, {'T', {"###", ".#.", ".#.", ".#.", ".#."}},
    {'U', {"#.#", "#.#", "#.#", "#.#", "###"}}, {'V', {"#.#", "#.#", "#.#", "#.#", ".#."}},
    {'W', {"#.#", "#.#", "###", "###", "#.#"}}, {'X', {"#.#", "#.#", ".#.", "#.#", "#.#"}},
    {'Y', {"#.#", "#.#", ".#.", ".#.", ".#."}}, {'Z', {"###", "..#", ".#.", "#..", "###"}},
    {'-', {"...", "...", "###", "...", "..."}}, {'.', {"...", "...", "...", "...", ".#."}},
    {'+', {"...", ".#.", "###", ".#.", "..."}}, {'(', {"..#", ".#.", ".#.", ".#.", "..#"}},
    {')', {"#..", ".#.", ".#.", ".#.", "#.."}}, {'/', {"..#", "..#", ".#.", "#..", "#.."}},
    {'=', {"...", "###", "...", "###", "..."}}, {':', {"...", ".#.", "...", ".#.", "..."}},
    {'_', {"...", "...", "...", "...", "###"}}, {',', {"...", "...", "...", ".#.", "#.."}},
    {'%', {"#.#", "..#", ".#.", "#..", "#.#"}}, {'*', {"...", "#.#", ".#.", "#.#", "..."}},
    {'<', {"..#", ".#.", "#..", ".#.", "..#"}}, {'>', {"#..", ".#.", "..#", ".#.", "#.."}},
    {' ', {"...", "...", "...", "...", "..."}}, {'?', {"##.", "..#", ".#.", "...", ".#."}},
};
constexpr Glyph kUnknown = {'?', {"###", "#.#", "#.#", "#.#", "###"}};

const Glyph& glyphOf(char c) {
  const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const auto& g : kFont)
    if (g.c == u) return g;
  return kUnknown;
}

void setPixel(Image8& im, int x, int y, Colour c) {
  if (x < 0 || y < 0 || x >= im.width || y >= im.height) return;
  auto* p = &im.rgb[(static_cast<std::size_t>(y) * im.width + x) * 3];
  p[0] = c[0];
  p[1] = c[1];
  p[2] = c[2];
}

void fillRect(Image8& im, int x0, int y0, int x1, int y1, Colour c) {
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) setPixel(im, x, y, c);
}

struct Clip {
  int x0, y0, x1, y1;
  bool inside(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// Bresenham, two pixels thick, clipped; dashed: 6 on, 4 off.
void drawLine(Image8& im, int xa, int ya, int xb, int yb, Colour c, const Clip& clip, bool dashed,
              int thickness = 2) {
  const int dx = std::abs(xb - xa), dy = -std::abs(yb - ya);
  const int sx = xa < xb ? 1 : -1, sy = ya < yb ? 1 : -1;
  int err = dx + dy, step = 0;
  for (;;) {
    if (!dashed || step % 10 < 6)
      for (int t = 0; t < thickness; ++t) {
        const int px = dx >= -dy ? xa : xa + t, py = dx >= -dy ? ya + t : ya;
        if (clip.inside(px, py)) setPixel(im, px, py, c);
      }
    ++step;
    if (xa == xb && ya == yb) break;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      xa += sx;
    }
    if (e2 <= dx) {
      err += dx;
      ya += sy;
    }
  }
}

struct Axis {
  bool log = true;
  double lo = 0, hi = 1;  // in axis units (log10 when log)
  double floor = 0;
  double map(double v) const {
    if (!log) return v;
    if (!(v > floor)) v = floor;
    return std::log10(v);
  }
};

// Decade range covering [lo, hi] (in log10 units).
void decadeRange(Axis& a, double lo, double hi) {
  a.lo = std::floor(lo + 1e-9);
  a.hi = std::ceil(hi - 1e-9);
  if (a.hi <= a.lo) a.hi = a.lo + 1;
}

double niceStep(double range) {
  const double raw = range / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * mag) return m * mag;
  return 10.0 * mag;
}

void linearRange(Axis& a, double lo, double hi) {
  if (hi <= lo) hi = lo + 1;
  const double step = niceStep(hi - lo);
  a.lo = std::floor(lo / step) * step;
  a.hi = std::ceil(hi / step) * step;
}

std::string linearLabel(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

}  // namespace

std::string decadeLabel(int e) {
  if (e >= 0 && e <= 4) return "1" + std::string(static_cast<std::size_t>(e), '0');
  if (e < 0 && e >= -3) return "0." + std::string(static_cast<std::size_t>(-e - 1), '0') + "1";
  return "1E" + std::to_string(e);
}

int textWidth(const std::string& text, int scale) {
  return static_cast<int>(text.size()) * 4 * scale;
}

int drawText(Image8& image, int x, int y, const std::string& text, Colour colour, int scale) {
  int cx = x;
  for (char ch : text) {
    const Glyph& g = glyphOf(ch);
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 3; ++c)
        if (g.rows[r][c] == '#')
          fillRect(image, cx + c * scale, y + r * scale, cx + (c + 1) * scale - 1,
                   y + (r + 1) * scale - 1, colour);
    cx += 4 * scale;
  }
  return cx - x;
}

Colour seriesColour(int i) {
  static constexpr Colour kColours[] = {{31, 119, 180},  {214, 39, 40},   {44, 160, 44},
                                        {255, 127, 14},  {148, 103, 189}, {140, 86, 75},
                                        {227, 119, 194}, {80, 80, 80},    {188, 189, 34},
                                        {23, 190, 207},  {0, 0, 128},     {128, 0, 0}};
  return kColours[static_cast<std::size_t>(i) % std::size(kColours)];
}

Image8 drawPlot(const PlotSpec& spec, std::span<const Series> series) {
  Image8 im;
  im.width = spec.width;
  im.height = spec.height;
  im.rgb.assign(static_cast<std::size_t>(im.width) * im.height * 3, 255);
  const Colour black{0, 0, 0}, grid{225, 225, 225}, grey{90, 90, 90};

  // Data ranges.
  Axis ax, ay;
  ax.log = spec.logX;
  ay.log = spec.logY;
  double minPosX = std::numeric_limits<double>::infinity(), minPosY = minPosX;
  auto each = [&](auto f) {
    for (const auto& s : series)
      for (const auto* v : {&s.dots, &s.line, &s.marked})
        for (const auto& p : *v) f(p);
  };
  each([&](const PlotPoint& p) {
    if (p.x > 0) minPosX = std::min(minPosX, p.x);
    if (p.y > 0) minPosY = std::min(minPosY, p.y);
  });
  ax.floor = spec.xFloor > 0 ? spec.xFloor : (std::isfinite(minPosX) ? minPosX : 1.0);
  ay.floor = spec.yFloor > 0 ? spec.yFloor : (std::isfinite(minPosY) ? minPosY : 1.0);
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  each([&](const PlotPoint& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    xlo = std::min(xlo, ax.map(p.x));
    xhi = std::max(xhi, ax.map(p.x));
    ylo = std::min(ylo, ay.map(p.y));
    yhi = std::max(yhi, ay.map(p.y));
  });
  if (!std::isfinite(xlo)) xlo = 0, xhi = 1, ylo = 0, yhi = 1;
  if (ax.log)
    decadeRange(ax, xlo, xhi);
  else
    linearRange(ax, xlo, xhi);
  if (ay.log)
    decadeRange(ay, ylo, yhi);
  else
    linearRange(ay, spec.yFromZero ? std::min(ylo, 0.0) : ylo, yhi);

  // Layout: title on top, legend on the right.
  int legendW = 0;
  for (const auto& s : series) legendW = std::max(legendW, textWidth(s.name) + 40);
  for (const auto& n : spec.notes) legendW = std::max(legendW, textWidth(n) + 16);
  const int left = 80, top = 50, right = im.width - legendW - 30, bottom = im.height - 60;
  const Clip clip{left, top, right, bottom};
  auto px = [&](double v) {
    return left +
           static_cast<int>(std::lround((ax.map(v) - ax.lo) / (ax.hi - ax.lo) * (right - left)));
  };
  auto py = [&](double v) {
    return bottom -
           static_cast<int>(std::lround((ay.map(v) - ay.lo) / (ay.hi - ay.lo) * (bottom - top)));
  };

  // Grid and ticks.
  auto ticks = [](const Axis& a) {
    std::vector<std::pair<double, bool>> t;  // axis units, labelled
    if (a.log) {
      for (int e = static_cast<int>(a.lo); e <= static_cast<int>(a.hi); ++e) {
        t.push_back({static_cast<double>(e), true});
        if (e < a.hi)
          for (int m = 2; m <= 9; ++m) t.push_back({e + std::log10(m), false});
      }
    } else {
      const double step = niceStep(a.hi - a.lo);
      for (double v = a.lo; v <= a.hi + step * 1e-6; v += step) t.push_back({v, true});
    }
    return t;
  };
  for (const auto& [u, major] : ticks(ax)) {
    const int x =
        left + static_cast<int>(std::lround((u - ax.lo) / (ax.hi - ax.lo) * (right - left)));
    drawLine(im, x, top, x, bottom, major ? grid : Colour{242, 242, 242}, clip, false, 1);
    drawLine(im, x, bottom, x, bottom + (major ? 6 : 3), black, {0, 0, im.width, im.height}, false,
             1);
    if (major) {
      const std::string l = ax.log ? decadeLabel(static_cast<int>(std::lround(u))) : linearLabel(u);
      drawText(im, x - textWidth(l) / 2, bottom + 10, l, black);
    }
  }
  for (const auto& [u, major] : ticks(ay)) {
    const int y =
        bottom - static_cast<int>(std::lround((u - ay.lo) / (ay.hi - ay.lo) * (bottom - top)));
    drawLine(im, left, y, right, y, major ? grid : Colour{242, 242, 242}, clip, false, 1);
    drawLine(im, left - (major ? 6 : 3), y, left, y, black, {0, 0, im.width, im.height}, false, 1);
    if (major) {
      const std::string l = ay.log ? decadeLabel(static_cast<int>(std::lround(u))) : linearLabel(u);
      drawText(im, left - 10 - textWidth(l), y - 5, l, black);
    }
  }
  drawLine(im, left, bottom, right, bottom, black, {0, 0, im.width, im.height}, false, 1);
  drawLine(im, left, top, left, bottom, black, {0, 0, im.width, im.height}, false, 1);

  // Labels.
  drawText(im, left, 12, spec.title, black, 3);
  drawText(im, (left + right) / 2 - textWidth(spec.xLabel) / 2, bottom + 34, spec.xLabel, grey);
  drawText(im, 8, top - 20, spec.yLabel, grey);

  // Data: lines first, then dots, then markers on top.
  for (const auto& s : series)
    for (std::size_t i = 1; i < s.line.size(); ++i)
      drawLine(im, px(s.line[i - 1].x), py(s.line[i - 1].y), px(s.line[i].x), py(s.line[i].y),
               s.colour, clip, s.dashed);
  for (const auto& s : series)
    for (const auto& p : s.dots) {
      const int x = px(p.x), y = py(p.y);
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
          if (dx * dx + dy * dy <= 5 && clip.inside(x + dx, y + dy))
            setPixel(im, x + dx, y + dy, s.colour);
    }
  for (const auto& s : series)
    for (const auto& p : s.marked) {
      const int x = px(p.x), y = py(p.y);
      for (int k = -5; k <= 5; ++k)
        for (int w : {5, 6}) {
          for (int sgn : {-1, 1}) {
            if (clip.inside(x + k, y + sgn * w)) setPixel(im, x + k, y + sgn * w, s.colour);
            if (clip.inside(x + sgn * w, y + k)) setPixel(im, x + sgn * w, y + k, s.colour);
          }
        }
    }

  // Legend.
  int ly = top;
  const int lx = right + 20;
  for (const auto& s : series) {
    if (!s.line.empty())
      drawLine(im, lx, ly + 5, lx + 24, ly + 5, s.colour, {0, 0, im.width, im.height}, s.dashed);
    if (!s.dots.empty() || s.line.empty()) fillRect(im, lx + 10, ly + 3, lx + 14, ly + 7, s.colour);
    drawText(im, lx + 32, ly, s.name, black);
    ly += 18;
  }
  ly += 8;
  for (const auto& n : spec.notes) {
    drawText(im, lx, ly, n, grey);
    ly += 16;
  }
  return im;
}

}  // namespace prime::bench
