// stepAway against std::nextafter, to the bit: ordinary values of both signs
// and every magnitude, subnormals, zeros of both signs, the largest finite
// values, infinities and NaN.
#include "src/prime/math/float_step.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace prime {
namespace {

void expectNextafter(double x) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const bool up : {true, false}) {
    const double want = std::nextafter(x, up ? inf : -inf), got = stepAway(x, up);
    if (std::isnan(want)) {
      EXPECT_TRUE(std::isnan(got)) << x;
      continue;
    }
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want))
        << x << (up ? " up" : " down") << ": " << got << " vs " << want;
  }
}

TEST(FloatStep, IsNextafterTowardsEitherInfinity) {
  using L = std::numeric_limits<double>;
  const std::vector<double> special = {
      0.0,         -0.0,          L::denorm_min(), -L::denorm_min(), L::min(), -L::min(), L::max(),
      L::lowest(), L::infinity(), -L::infinity(),  L::quiet_NaN(),   1.0,      -1.0,      0.5,
      1e-300,      -1e300};
  for (const double x : special) expectNextafter(x);
  std::mt19937_64 rng(7);
  for (int k = 0; k < 100000; ++k) expectNextafter(std::bit_cast<double>(rng()));  // every exponent
  std::uniform_real_distribution<double> u(-1500.0, 1500.0);  // scene coordinates
  for (int k = 0; k < 100000; ++k) expectNextafter(u(rng));
}

}  // namespace
}  // namespace prime
