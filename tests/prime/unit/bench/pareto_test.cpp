// The Pareto front of prime bench's time-against-error points, by hand.
#include "src/prime/bench/pareto.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using prime::bench::CostError;
using prime::bench::paretoFront;
using ::testing::ElementsAre;

TEST(BenchPareto, DominatedPointsAreDropped) {
  //   0: (1, 10)  front: cheapest
  //   1: (2, 5)   front
  //   2: (3, 6)   dominated by 1
  //   3: (4, 1)   front
  //   4: (5, 1)   dominated by 3 (same error, dearer)
  //   5: (2.5, 5) dominated by 1 (same error, dearer)
  const std::vector<CostError> p = {{1, 10}, {2, 5}, {3, 6}, {4, 1}, {5, 1}, {2.5, 5}};
  EXPECT_THAT(paretoFront(p), ElementsAre(0, 1, 3));
}

TEST(BenchPareto, TheFrontComesOutInIncreasingCost) {
  const std::vector<CostError> p = {{9, 0.1}, {1, 3}, {4, 1}};
  EXPECT_THAT(paretoFront(p), ElementsAre(1, 2, 0));
}

TEST(BenchPareto, EqualCostKeepsTheSmallerErrorAndIdenticalPointsKeepTheFirst) {
  const std::vector<CostError> p = {{2, 4}, {2, 3}, {1, 5}, {1, 5}};
  EXPECT_THAT(paretoFront(p), ElementsAre(2, 1));
}

TEST(BenchPareto, ZeroErrorEndsTheFront) {
  const std::vector<CostError> p = {{1, 0.5}, {3, 0.0}, {5, 0.0}, {7, 0.2}};
  EXPECT_THAT(paretoFront(p), ElementsAre(0, 1));
}

TEST(BenchPareto, NanPointsAreNeverOnTheFront) {
  const std::vector<CostError> p = {{NAN, 0.0}, {1, NAN}, {2, 1}};
  EXPECT_THAT(paretoFront(p), ElementsAre(2));
}

TEST(BenchPareto, EmptyInputGivesAnEmptyFront) {
  EXPECT_TRUE(paretoFront({}).empty());
}

}  // namespace
