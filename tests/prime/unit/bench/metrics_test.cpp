// The error metrics of prime bench on hand-made pictures.
#include "src/prime/bench/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

using prime::Rgb;
using prime::bench::compareImages;
using prime::bench::metricValue;

TEST(BenchMetrics, IdenticalPicturesHaveNoError) {
  const std::vector<Rgb> a = {{0.1, 0.2, 0.3}, {0.9, 0.0, 0.5}};
  const std::vector<std::int16_t> ia = {7, 200};
  const auto e = compareImages(a, ia, a, ia);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_EQ(e.maxError, 0.0);
  EXPECT_EQ(e.indexShare, 0.0);
  EXPECT_EQ(e.pixels, 2u);
}

TEST(BenchMetrics, RmseMaxAndIndexShareByHand) {
  // Four pixels; differences per channel: pixel 0: (0.3, 0, 0), pixel 1:
  // (0, 0.4, 0), pixels 2 and 3: none. Sum of squares 0.09 + 0.16 = 0.25
  // over 12 channel values: RMSE = sqrt(0.25 / 12); max 0.4.
  const std::vector<Rgb> ref = {{0.5, 0.5, 0.5}, {0.1, 0.1, 0.1}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
  const std::vector<Rgb> img = {{0.8, 0.5, 0.5}, {0.1, 0.5, 0.1}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
  const std::vector<std::int16_t> iref = {1, 2, 3, 4}, iimg = {1, 9, 3, 9};
  const auto e = compareImages(ref, iref, img, iimg);
  EXPECT_NEAR(e.rmse, std::sqrt(0.25 / 12.0), 1e-15);
  EXPECT_NEAR(e.maxError, 0.4, 1e-15);
  EXPECT_DOUBLE_EQ(e.indexShare, 0.5);
}

TEST(BenchMetrics, ColoursAreClampedToTheUnitRangeAndNanCountsAsZero) {
  EXPECT_EQ(metricValue(-0.7), 0.0);
  EXPECT_EQ(metricValue(3.0), 1.0);
  EXPECT_EQ(metricValue(0.25), 0.25);
  EXPECT_EQ(metricValue(NAN), 0.0);
  // A reference of 1.0 against a wild 5.0 is no error; -2 against 0 neither;
  // NaN against 0.5 is an error of 0.5.
  const std::vector<Rgb> ref = {{1.0, 0.0, 0.5}};
  const std::vector<Rgb> img = {{5.0, -2.0, NAN}};
  const std::vector<std::int16_t> i = {1};
  const auto e = compareImages(ref, i, img, i);
  EXPECT_DOUBLE_EQ(e.maxError, 0.5);
  EXPECT_NEAR(e.rmse, std::sqrt(0.25 / 3.0), 1e-15);
}

TEST(BenchMetrics, DifferentSizesAreRefused) {
  const std::vector<Rgb> a(2), b(3);
  const std::vector<std::int16_t> ia(2), ib(3);
  EXPECT_THROW(compareImages(a, ia, b, ib), std::invalid_argument);
}

TEST(BenchMetrics, EmptyPicturesCompareAsEqual) {
  const auto e = compareImages({}, {}, {}, {});
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_EQ(e.pixels, 0u);
}

}  // namespace
