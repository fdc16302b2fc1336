// Rays per pixel, for any system that offers the port's supersampling (a
// system that replays its own historical anti-aliasing, as the Waterloo CGL
// package's aalevel does, keeps that as its own code). Single is the system's
// own one ray per pixel; Grid shoots n x n rays over the pixel's footprint;
// Adaptive is Whitted's adaptive supersampling (PRIME thesis 2.6.1): the
// centre and four corners, and the four quarters again wherever those differ
// by more than `tolerance` in any channel, down to `maxLevel` subdivisions.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "src/math/rgb.h"

namespace prime {

struct Sampling {
  enum class Mode { Single, Grid, Adaptive } mode = Mode::Single;
  int gridN = 1;
  double tolerance = 0.05;
  int maxLevel = 2;
};

inline Rgb average(const Rgb* c, int n) {
  Rgb sum{};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) sum[k] += c[i][k];
  for (auto& v : sum) v /= n;
  return sum;
}

// The largest difference between two of the colours, over the channels.
inline double spread(const Rgb* c, int n) {
  double d = 0.0;
  for (int k = 0; k < 3; ++k) {
    double lo = c[0][k], hi = c[0][k];
    for (int i = 1; i < n; ++i) {
      lo = std::min(lo, c[i][k]);
      hi = std::max(hi, c[i][k]);
    }
    d = std::max(d, hi - lo);
  }
  return d;
}

// The colours of one pixel's adaptive samples, by lattice point. The
// squares of Whitted's subdivision share points: a child's corners are its
// parent's corners, centre and edge midpoints. Every offset is a multiple of
// 2^-(maxLevel+1) pixel, exact in binary, so the same point always gives the
// same ray and the same colour: each is traced once per pixel. One lattice
// per thread; deeper than 6 levels the samples are traced uncached.
class SampleLattice {
 public:
  explicit SampleLattice(int maxLevel)
      : scale_(static_cast<double>(1 << (maxLevel + 1))),
        side_((1 << (maxLevel + 1)) + 1),
        stamp_(static_cast<std::size_t>(side_) * side_, 0),
        colour_(stamp_.size()) {}
  static int levelsFor(const Sampling& s) { return std::clamp(s.maxLevel, 0, 6); }
  void nextPixel() { ++generation_; }
  // The colour at offset (fx, fy), traced by `trace` the first time.
  template <class Trace>
  Rgb at(double fx, double fy, Trace&& trace) {
    const double u = (fx + 0.5) * scale_, v = (fy + 0.5) * scale_;
    if (!(u >= 0.0 && v >= 0.0 && u < side_ && v < side_) || u != std::floor(u) ||
        v != std::floor(v))
      return trace();  // not a lattice point (cannot happen for the subdivision)
    const std::size_t k =
        static_cast<std::size_t>(v) * static_cast<std::size_t>(side_) + static_cast<std::size_t>(u);
    if (stamp_[k] != generation_) {
      colour_[k] = trace();
      stamp_[k] = generation_;
    }
    return colour_[k];
  }

 private:
  double scale_;
  int side_;
  std::uint32_t generation_ = 1;
  std::vector<std::uint32_t> stamp_;
  std::vector<Rgb> colour_;
};

namespace detail {
// Whitted's adaptive supersampling over the square centred at (fx, fy) with
// half-width h, in pixel steps.
template <class ColourAt>
Rgb adaptive(ColourAt& colourAt, double fx, double fy, double h, int level, const Sampling& s,
             SampleLattice& lattice) {
  Rgb c[5];
  const double off[5][2] = {{0, 0}, {-h, -h}, {h, -h}, {-h, h}, {h, h}};
  for (int k = 0; k < 5; ++k) {
    const double x = fx + off[k][0], y = fy + off[k][1];
    c[k] = lattice.at(x, y, [&] { return colourAt(x, y); });
  }
  if (level >= s.maxLevel || !(spread(c, 5) > s.tolerance)) return average(c, 5);
  Rgb q[4];
  for (int k = 0; k < 4; ++k)
    q[k] = adaptive(colourAt, fx + off[k + 1][0] / 2, fy + off[k + 1][1] / 2, h / 2, level + 1, s,
                    lattice);
  return average(q, 4);
}
}  // namespace detail

// One pixel's colour. primary() is the system's own ray for the pixel (Single
// mode: exactly what the system did); colourAt(fx, fy) the colour of the ray
// offset by (fx, fy) pixel steps, -0.5..0.5, from the pixel's sample point.
// `lattice` is needed for Adaptive only.
template <class Primary, class ColourAt>
Rgb samplePixel(const Sampling& s, SampleLattice* lattice, Primary&& primary, ColourAt&& colourAt) {
  switch (s.mode) {
    case Sampling::Mode::Single:
      return primary();
    case Sampling::Mode::Grid: {
      Rgb sum{};
      const int n = std::max(1, s.gridN);
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const Rgb c = colourAt((b + 0.5) / n - 0.5, (a + 0.5) / n - 0.5);
          for (int k = 0; k < 3; ++k) sum[k] += c[k];
        }
      for (auto& v : sum) v /= n * n;
      return sum;
    }
    case Sampling::Mode::Adaptive:
      lattice->nextPixel();
      return detail::adaptive(colourAt, 0.0, 0.0, 0.5, 0, s, *lattice);
  }
  return {};
}

}  // namespace prime
