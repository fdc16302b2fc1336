// The beta-spline basis (src/prime/plate1/beta_spline.h) against values worked out
// by hand, the uniform cubic B-spline it must reduce to, and the
// beta-constraints its segments must meet at every joint.
#include "src/prime/plate1/beta_spline.h"

#include <gtest/gtest.h>

#include <random>

namespace prime::spline {
namespace {

TEST(BetaBasis, ReducesToTheUniformCubicBSplineForBias1Tension0) {
  const BetaShape bspline{1.0, 0.0};
  for (double u : {0.0, 0.1, 0.25, 0.5, 0.9, 1.0}) {
    const auto b = betaBasis(bspline, u);
    EXPECT_NEAR(b[0], (1 - u) * (1 - u) * (1 - u) / 6, 1e-15) << u;
    EXPECT_NEAR(b[1], (3 * u * u * u - 6 * u * u + 4) / 6, 1e-15) << u;
    EXPECT_NEAR(b[2], (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6, 1e-15) << u;
    EXPECT_NEAR(b[3], u * u * u / 6, 1e-15) << u;
  }
}

// Colour Plate 1's shape, skew = tension = 1: delta = 2 + 4 + 4 + 1 + 2 = 13.
// u = 0: b = (2, 4+4+1, 2, 0)/13.  u = 1/2: b_-2 = 2(1/8)/13, b_1 = 2(1/8)/13,
// b_-1 = [2(1/2)(7/4) + 2(11/8) + 2(5/8) + 1/2]/13 = 6.25/13 and
// b_0 = [2(1/4)(5/2) + 2(1/2)(11/4) + (1/4)(2) + 2(7/8)]/13 = 6.25/13.
TEST(BetaBasis, Plate1ShapeByHand) {
  const BetaShape plate1{1.0, 1.0};
  const auto b0 = betaBasis(plate1, 0.0);
  EXPECT_DOUBLE_EQ(b0[0], 2.0 / 13);
  EXPECT_DOUBLE_EQ(b0[1], 9.0 / 13);
  EXPECT_DOUBLE_EQ(b0[2], 2.0 / 13);
  EXPECT_DOUBLE_EQ(b0[3], 0.0);
  const auto bh = betaBasis(plate1, 0.5);
  EXPECT_DOUBLE_EQ(bh[0], 0.25 / 13);
  EXPECT_DOUBLE_EQ(bh[1], 6.25 / 13);
  EXPECT_DOUBLE_EQ(bh[2], 6.25 / 13);
  EXPECT_DOUBLE_EQ(bh[3], 0.25 / 13);
}

TEST(BetaBasis, PartitionOfUnityAndDerivativesSumToZero) {
  for (const BetaShape s :
       {BetaShape{1, 0}, BetaShape{1, 1}, BetaShape{2, 5}, BetaShape{0.5, 0}, BetaShape{3, 150}}) {
    for (int k = 0; k <= 20; ++k) {
      const double u = k / 20.0;
      const auto b = betaBasis(s, u), d1 = betaBasisD1(s, u), d2 = betaBasisD2(s, u);
      EXPECT_NEAR(b[0] + b[1] + b[2] + b[3], 1.0, 1e-14);
      EXPECT_NEAR(d1[0] + d1[1] + d1[2] + d1[3], 0.0, 1e-12);
      EXPECT_NEAR(d2[0] + d2[1] + d2[2] + d2[3], 0.0, 1e-12);
      for (double x : b) EXPECT_GE(x, -1e-15);  // convex hull property
    }
  }
}

// Segments i and i+1 share three control vertices: segment i uses V0..V3 and
// segment i+1 uses V1..V4. The beta-constraints (Barsky and Beatty 1983):
//   Q_{i+1}(0) = Q_i(1), Q'_{i+1}(0) = b1 Q'_i(1), Q''_{i+1}(0) = b1^2 Q''_i(1) + b2 Q'_i(1).
TEST(BetaBasis, SegmentsMeetTheBetaConstraints) {
  std::mt19937 rng(1991);
  std::uniform_real_distribution<double> coord(-500.0, 500.0);
  for (const BetaShape s :
       {BetaShape{1, 1}, BetaShape{2, 5}, BetaShape{0.5, 0}, BetaShape{1.5, 20}}) {
    for (int trial = 0; trial < 10; ++trial) {
      double v[5];
      for (double& x : v) x = coord(rng);
      auto eval = [&](const std::array<double, 4>& b, int first) {
        return b[0] * v[first] + b[1] * v[first + 1] + b[2] * v[first + 2] + b[3] * v[first + 3];
      };
      const double q1 = eval(betaBasis(s, 1.0), 0), q0 = eval(betaBasis(s, 0.0), 1);
      const double d1 = eval(betaBasisD1(s, 1.0), 0), d0 = eval(betaBasisD1(s, 0.0), 1);
      const double e1 = eval(betaBasisD2(s, 1.0), 0), e0 = eval(betaBasisD2(s, 0.0), 1);
      EXPECT_NEAR(q0, q1, 1e-9);
      EXPECT_NEAR(d0, s.beta1 * d1, 1e-9);
      EXPECT_NEAR(e0, s.beta1 * s.beta1 * e1 + s.beta2 * d1, 1e-8);
    }
  }
}

TEST(BetaBasis, RejectsAShapeWithNoPositiveDelta) {
  EXPECT_THROW(betaBasis(BetaShape{1.0, -20.0}, 0.5), std::invalid_argument);
}

TEST(KnotGrid, NeedsFourByFourAndTheRightCount) {
  EXPECT_THROW(KnotGrid(3, 8, std::vector<Vec3>(24)), std::invalid_argument);
  EXPECT_THROW(KnotGrid(8, 8, std::vector<Vec3>(63)), std::invalid_argument);
  const KnotGrid g(8, 8, std::vector<Vec3>(64));
  EXPECT_EQ(g.patchRows(), 5);
  EXPECT_EQ(g.patchCols(), 5);
}

// A flat grid V(r, c) = (100c, 0, 100r): every beta-spline reproduces linear
// functions, so the surface is the plane and patch (i, j) at (u, v) lies at
// x = 100(j + 1 + u') where the parametrisation is not linear unless b1 = 1,
// b2 = 0. With those, x = 100(j + 1 + u), z = 100(i + 1 + v).
TEST(SurfacePoint, UniformBSplineReproducesAPlane) {
  std::vector<Vec3> knots;
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c) knots.push_back({100.0 * c, 0.0, 100.0 * r});
  const KnotGrid g(8, 8, knots);
  const Vec3 p = surfacePoint(BetaShape{1, 0}, g, 2, 3, 0.25, 0.5);
  EXPECT_NEAR(p[X], 100.0 * (3 + 1 + 0.25), 1e-12);
  EXPECT_NEAR(p[Y], 0.0, 1e-12);
  EXPECT_NEAR(p[Z], 100.0 * (2 + 1 + 0.5), 1e-12);
  // Plate 1's shape keeps the plane (affine invariance) but not the spacing.
  const Vec3 q = surfacePoint(BetaShape{1, 1}, g, 0, 0, 0.0, 0.0);
  EXPECT_NEAR(q[X], 100.0 * (2.0 / 13 * 0 + 9.0 / 13 * 1 + 2.0 / 13 * 2), 1e-12);  // = 100
  EXPECT_NEAR(q[Y], 0.0, 1e-12);
  EXPECT_THROW(surfacePoint(BetaShape{1, 1}, g, 5, 0, 0.0, 0.0), std::out_of_range);
}

}  // namespace
}  // namespace prime::spline
