// Rays per pixel, for any system that offers the port's supersampling (a
// system that replays its own historical anti-aliasing, as the Waterloo CGL
// package's aalevel does, keeps that as its own code). Single is the system's
// own one ray per pixel; Grid shoots n x n rays over the pixel's footprint;
// Adaptive is Whitted's adaptive supersampling (PRIME thesis 2.6.1): the
// centre and four corners, and the four quarters again wherever those differ
// by more than `tolerance` in any channel, down to `maxLevel` subdivisions.
// Jittered is stochastic supersampling (PRIME thesis 2.6.2): n x n strata,
// one uniformly random point in each. Statistical is statistical
// supersampling (thesis 2.6.3): batches of four random rays (one in each
// quarter of the pixel) until the confidence interval of the pixel's mean is
// narrower than a bound, or a maximum count is reached. The random numbers
// come from a counter-based generator keyed by (seed, row, column, sample
// index): the same picture whatever thread renders which row.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "src/math/rgb.h"
#include "src/prime/render/sample_random.h"

namespace prime {

struct Sampling {
  enum class Mode { Single, Grid, Adaptive, Jittered, Statistical } mode = Mode::Single;
  int gridN = 1;  // Grid and Jittered: n x n rays
  double tolerance = 0.05;
  int maxLevel = 2;
  std::uint64_t seed = 1;  // Jittered and Statistical
  // Statistical: stop when t(confidence, n-1) * s / sqrt(n) <= bound in every
  // channel (s the sample standard deviation of n rays), after at least
  // minSamples and at most maxSamples rays, added four at a time.
  double bound = 0.02;
  double confidence = 0.95;
  int minSamples = 4;
  int maxSamples = 64;
};

// Which pixel a sample belongs to: the key of its random numbers.
struct PixelKey {
  std::uint64_t seed = 1;
  std::uint32_t row = 0, column = 0;
};

// The standard normal quantile: z with P(Z <= z) = p, 0 < p < 1 (bisection
// on erfc, to 1e-12).
inline double normalQuantile(double p) {
  double lo = -40.0, hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// Student's t quantile t(p, nu) by the Cornish-Fisher expansion around the
// normal quantile (Abramowitz and Stegun 26.7.5), exact for nu = 1 and 2. At
// p = 0.975 it gives 3.1786 for nu = 3 (tables: 3.1824), 2.7756 for 4
// (2.7764), 2.2281 for 10 (2.2281): within 0.12%.
inline double studentQuantile(double p, int nu) {
  if (nu <= 0) return std::numeric_limits<double>::infinity();
  if (nu == 1) return std::tan(3.14159265358979323846 * (p - 0.5));  // Cauchy
  if (nu == 2) {
    const double a = 4.0 * p * (1.0 - p);
    return (2.0 * p - 1.0) * std::sqrt(2.0 / a);
  }
  const double z = normalQuantile(p), v = nu;
  const double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, z9 = z7 * z2;
  return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
         (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v) +
         (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / (92160 * v * v * v * v);
}

// Statistical supersampling's stopping rule over running sums: n samples,
// per channel the sum and the sum of squares. True when the half-width of the
// two-sided `confidence` interval of every channel's mean is <= bound.
class MeanBound {
 public:
  explicit MeanBound(const Sampling& s) : s_(s) {
    const int maxN = std::max(2, s.maxSamples);
    const double p = 0.5 + 0.5 * s.confidence;
    // t(p, n-1) for every n up to the maximum, once per render (no per-pixel work).
    quantile_.resize(static_cast<std::size_t>(maxN) + 1, 0.0);
    for (int n = 2; n <= maxN; ++n)
      quantile_[static_cast<std::size_t>(n)] = studentQuantile(p, n - 1);
  }
  bool met(int n, const Rgb& sum, const Rgb& sumSq) const {
    if (n < 2) return false;
    const double t = quantile_[static_cast<std::size_t>(
        std::min<int>(n, static_cast<int>(quantile_.size()) - 1))];
    for (int k = 0; k < 3; ++k) {
      const double mean = sum[k] / n;
      const double var = std::max(0.0, (sumSq[k] - n * mean * mean) / (n - 1));
      if (t * std::sqrt(var / n) > s_.bound) return false;
    }
    return true;
  }

 private:
  const Sampling& s_;
  std::vector<double> quantile_;
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

// colourAt(fx, fy, k) if it takes the sample's index, else colourAt(fx, fy).
template <class ColourAt>
Rgb sampleAt(ColourAt& colourAt, double fx, double fy, int k) {
  if constexpr (std::is_invocable_v<ColourAt&, double, double, int>)
    return colourAt(fx, fy, k);
  else
    return colourAt(fx, fy);
}

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
    c[k] = lattice.at(x, y, [&] { return sampleAt(colourAt, x, y, 0); });
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
// A colourAt that also takes the sample's index, colourAt(fx, fy, k), is told
// which sample it traces (0, 1, ... within the pixel; a system's distributed
// effects, as soft shadows, stratify over it); primary() is sample 0.
// `lattice` is needed for Adaptive only; `key` for Jittered and Statistical
// (`bounds`: Statistical's stopping rule, built once per render); `count`,
// if given, receives the number of samples taken.
template <class Primary, class ColourAt>
Rgb samplePixel(const Sampling& s, SampleLattice* lattice, const PixelKey& key,
                const MeanBound* bounds, Primary&& primary, ColourAt&& colourAt,
                int* count = nullptr) {
  int taken = 1;
  Rgb result{};
  switch (s.mode) {
    case Sampling::Mode::Single:
      result = primary();
      break;
    case Sampling::Mode::Grid: {
      Rgb sum{};
      const int n = std::max(1, s.gridN);
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const Rgb c = sampleAt(colourAt, (b + 0.5) / n - 0.5, (a + 0.5) / n - 0.5, a * n + b);
          for (int k = 0; k < 3; ++k) sum[k] += c[k];
        }
      for (auto& v : sum) v /= n * n;
      taken = n * n;
      result = sum;
      break;
    }
    case Sampling::Mode::Adaptive:
      lattice->nextPixel();
      result = detail::adaptive(colourAt, 0.0, 0.0, 0.5, 0, s, *lattice);
      taken = 0;  // not counted here (the lattice shares points)
      break;
    case Sampling::Mode::Jittered: {
      // Stochastic supersampling (thesis 2.6.2): stratum (a, b) of n x n,
      // one uniform point in it.
      Rgb sum{};
      const int n = std::max(1, s.gridN);
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const int k = a * n + b;
          const double u = sampleUniform(key.seed, key.row, key.column, k, 0);
          const double v = sampleUniform(key.seed, key.row, key.column, k, 1);
          const Rgb c = sampleAt(colourAt, (b + u) / n - 0.5, (a + v) / n - 0.5, k);
          for (int q = 0; q < 3; ++q) sum[q] += c[q];
        }
      for (auto& v : sum) v /= n * n;
      taken = n * n;
      result = sum;
      break;
    }
    case Sampling::Mode::Statistical: {
      // Statistical supersampling (thesis 2.6.3): four random rays at a
      // time, one in each quarter of the pixel, until the mean is known to
      // within the bound at the confidence (MeanBound) or maxSamples.
      Rgb sum{}, sumSq{};
      const int minN = std::max(4, s.minSamples), maxN = std::max(minN, s.maxSamples);
      int n = 0;
      while (n < maxN) {
        for (int q = 0; q < 4 && n < maxN; ++q, ++n) {
          const double u = sampleUniform(key.seed, key.row, key.column, n, 0);
          const double v = sampleUniform(key.seed, key.row, key.column, n, 1);
          const Rgb c = sampleAt(colourAt, ((q & 1) + u) / 2 - 0.5, ((q >> 1) + v) / 2 - 0.5, n);
          for (int k = 0; k < 3; ++k) {
            sum[k] += c[k];
            sumSq[k] += c[k] * c[k];
          }
        }
        if (n >= minN && n % 4 == 0 && bounds && bounds->met(n, sum, sumSq)) break;
      }
      for (int k = 0; k < 3; ++k) result[k] = sum[k] / n;
      taken = n;
      break;
    }
  }
  if (count) *count = taken;
  return result;
}

// The same for the modes that need no key (Single, Grid, Adaptive).
template <class Primary, class ColourAt>
Rgb samplePixel(const Sampling& s, SampleLattice* lattice, Primary&& primary, ColourAt&& colourAt) {
  return samplePixel(s, lattice, PixelKey{}, nullptr, primary, colourAt);
}

}  // namespace prime
