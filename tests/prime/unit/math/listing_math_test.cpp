// Roundoff (MathFunc, lines 5232-5284; K24, Q6) and the listing's matrix
// helpers, checked against values worked out from the printed code.
#include "src/prime/math/listing_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "src/math/matrix.h"
#include "src/prime/math/listing_matrix.h"

namespace prime {
namespace {

TEST(Roundoff, SnapsPositiveNumbersWithin1e10) {
  EXPECT_EQ(roundoff(2.99999999999), 3.0);        // variance .99999999999 > .9999999999
  EXPECT_EQ(roundoff(2.00000000001), 2.0);        // variance 1e-11 < 1e-10
  EXPECT_EQ(roundoff(2.000000001), 2.000000001);  // 1e-9: outside the window
  EXPECT_EQ(roundoff(0.5), 0.5);
  EXPECT_EQ(roundoff(1e-11), 0.0);
}

TEST(Roundoff, NegativeBranchHasWiderThresholdsAsPrinted) {
  // Q6: the negative branch tests .999999998 and .000000001.
  EXPECT_EQ(roundoff(-2.9999999985), -3.0);         // variance .9999999985 > .999999998
  EXPECT_EQ(roundoff(-2.0000000005), -2.0);         // variance 5e-10 < 1e-9
  EXPECT_EQ(roundoff(2.0000000005), 2.0000000005);  // the positive branch keeps it
  EXPECT_EQ(roundoff(-0.25), -0.25);
}

TEST(Roundoff, ZeroAndNaNGiveZero) {
  EXPECT_EQ(roundoff(0.0), 0.0);
  EXPECT_EQ(roundoff(-0.0), 0.0);
  EXPECT_FALSE(std::signbit(roundoff(-0.0)));
  EXPECT_EQ(roundoff(std::numeric_limits<double>::quiet_NaN()), 0.0);
}

TEST(DegreeTrig, UsesTheSevenDigitRadient) {
  EXPECT_EQ(sinDeg(30.0), std::sin(30.0 / 57.29578));
  EXPECT_EQ(acosDeg(0.0), std::acos(0.0) * 57.29578);
  // K3: 90 degrees is not pi/2 with this constant; cos is ~1.3349e-8.
  EXPECT_NEAR(cosDeg(90.0), 1.3349e-8, 1e-12);
}

TEST(MatrixOps, PointAndVectorProductsUseRowVectors) {
  Matrix4 m = identity4();
  m[0] = {2, 0, 0, 0};
  m[1] = {0, 3, 1, 0};
  m[3] = {10, 20, 30, 1};
  // p = (1,1,1): x = 10 + 2 = 12; y = 20 + 3 = 23; z = 30 + 1 + 1 = 32.
  EXPECT_EQ(pointMatrixMul({1, 1, 1}, m), (Vec3{12, 23, 32}));
  EXPECT_EQ(vectorMatrixMul({1, 1, 1}, m), (Vec3{2, 3, 2}));
}

TEST(MatrixOps, MatrixMulStoresAB) {
  Matrix4 a = identity4(), b = identity4();
  a[3] = {1, 2, 3, 1};  // translate (1,2,3)
  b[0][0] = 2;          // then scale x by 2
  matrixMul(a, b);
  EXPECT_EQ(a[3][0], 2.0);  // (1,2,3) scaled: x doubles
  EXPECT_EQ(a[0][0], 2.0);
  EXPECT_EQ(a[3][1], 2.0);
}

TEST(MatrixOps, InverseRepairsAZeroPivotByAddingALaterRow) {
  // A swap of x and y has a[0][0] = 0: the listing adds row 1 (scaled by
  // 1/a[1][0] = 1) to row 0 and carries on. The true inverse is the swap.
  Matrix4 swap = identity4();
  swap[0] = {0, 1, 0, 0};
  swap[1] = {1, 0, 0, 0};
  Matrix4 inv;
  ASSERT_TRUE(inverse(swap, inv));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_EQ(inv[i][j], swap[i][j]) << i << "," << j;
}

TEST(MatrixOps, InverseReportsSingularMatrices) {
  Matrix4 m = identity4();
  m[1][1] = 0.0;  // zero scale in y
  Matrix4 inv;
  EXPECT_FALSE(inverse(m, inv));
}

// floorExact must be std::floor bit for bit: signed zeros, values either side
// of every integer, the 2^52 boundary, huge values, infinities, NaN, and a
// million random doubles of every magnitude.
TEST(FloorExact, SameBitsAsStdFloor) {
  auto same = [](double x) {
    const double a = floorExact(x), b = std::floor(x);
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
  };
  const double specials[] = {0.0,
                             -0.0,
                             0.5,
                             -0.5,
                             1.0,
                             -1.0,
                             0.9999999999999999,
                             -0.9999999999999999,
                             1e-310,
                             -1e-310,
                             4503599627370495.5,
                             -4503599627370495.5,
                             4503599627370496.0,
                             -4503599627370496.0,
                             9007199254740993.0,
                             1e300,
                             -1e300,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN()};
  for (double x : specials) EXPECT_TRUE(same(x)) << x;
  for (int k = -1000; k <= 1000; ++k)
    for (double x :
         {std::nextafter(double(k), -INFINITY), double(k), std::nextafter(double(k), INFINITY)})
      ASSERT_TRUE(same(x)) << x;
  std::uint64_t state = 52;
  for (int i = 0; i < 1000000; ++i) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    double x;
    std::memcpy(&x, &state, sizeof x);  // every bit pattern: all magnitudes, signs, NaNs
    ASSERT_TRUE(same(x)) << x;
  }
}

}  // namespace
}  // namespace prime
