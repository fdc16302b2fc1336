// The shared pixel sampler: Single is the system's own ray, Grid averages
// n x n sub-pixel points, Adaptive subdivides only where the colours differ
// and traces each shared lattice point once.
#include "src/prime/render/pixel_sampling.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace prime {
namespace {

TEST(PixelSampling, SingleIsTheSystemsOwnRay) {
  Sampling s;
  int primaries = 0, others = 0;
  const Rgb c = samplePixel(
      s, nullptr,
      [&] {
        ++primaries;
        return Rgb{0.25, 0.5, 0.75};
      },
      [&](double, double) {
        ++others;
        return Rgb{};
      });
  EXPECT_EQ(c, (Rgb{0.25, 0.5, 0.75}));
  EXPECT_EQ(primaries, 1);
  EXPECT_EQ(others, 0);
}

TEST(PixelSampling, GridAveragesTheCentresOfNByNSubPixels) {
  Sampling s;
  s.mode = Sampling::Mode::Grid;
  s.gridN = 2;
  std::vector<std::pair<double, double>> points;
  const Rgb c = samplePixel(
      s, nullptr, [] { return Rgb{}; },
      [&](double fx, double fy) {
        points.push_back({fx, fy});
        return Rgb{fx + 0.5, fy + 0.5, 1.0};
      });
  const std::vector<std::pair<double, double>> want = {
      {-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}};
  EXPECT_EQ(points, want);
  EXPECT_DOUBLE_EQ(c[0], 0.5);
  EXPECT_DOUBLE_EQ(c[1], 0.5);
  EXPECT_DOUBLE_EQ(c[2], 1.0);
}

TEST(PixelSampling, AdaptiveStopsAtFiveRaysWhereTheColoursAgree) {
  Sampling s;
  s.mode = Sampling::Mode::Adaptive;
  s.tolerance = 0.1;
  SampleLattice lattice(SampleLattice::levelsFor(s));
  int traced = 0;
  const Rgb c = samplePixel(
      s, &lattice, [] { return Rgb{}; },
      [&](double, double) {
        ++traced;
        return Rgb{0.2, 0.2, 0.2};
      });
  EXPECT_EQ(traced, 5);  // centre and four corners
  EXPECT_DOUBLE_EQ(c[0], 0.2);
}

TEST(PixelSampling, AdaptiveSubdividesAnEdgeAndTracesSharedPointsOnce) {
  Sampling s;
  s.mode = Sampling::Mode::Adaptive;
  s.tolerance = 0.1;
  s.maxLevel = 1;
  SampleLattice lattice(SampleLattice::levelsFor(s));
  std::map<std::pair<double, double>, int> seen;
  // Black left of x = 0.1, white right of it.
  const Rgb c = samplePixel(
      s, &lattice, [] { return Rgb{}; },
      [&](double fx, double fy) {
        ++seen[{fx, fy}];
        return fx < 0.1 ? Rgb{0, 0, 0} : Rgb{1, 1, 1};
      });
  for (const auto& [point, n] : seen) EXPECT_EQ(n, 1) << point.first << " " << point.second;
  // Level 0: the centre and 4 corners; level 1: four quarters of 5 points
  // each, whose corners are the 3 x 3 grid at x, y in {-0.5, 0, 0.5} (holding
  // the 5 parent points) plus their 4 centres: 13 distinct points.
  EXPECT_EQ(seen.size(), 13u);
  // Left quarters: x in {-0.5, -0.25, 0}, all black. Right quarters: the two
  // corners at x = 0 black, the centre and the corners at x = 0.5 white: 3/5.
  // The pixel: (0 + 0 + 0.6 + 0.6) / 4 = 0.3.
  EXPECT_DOUBLE_EQ(c[0], 0.3);
}

}  // namespace
}  // namespace prime
