// The 1991 era model (src/prime/render/era_cost.h): each event's cost is
// its operations times the per-operation costs, the figures
// docs/prime/pace-1991.md lists, and a render's time is the events' sum.
#include "src/prime/render/era_cost.h"

#include <gtest/gtest.h>

namespace {

using prime::EventOps1991;
using prime::listingOps1991;
using prime::OpCosts1991;
using prime::TraceStats;

TEST(EraCost, EachEventCostsWhatThePageSays) {
  const OpCosts1991 c;
  const EventOps1991 o = listingOps1991();
  // docs/prime/pace-1991.md, "What each event costs" (microseconds).
  EXPECT_NEAR(o.primaryRay.microseconds(c), 178.4, 0.05);
  EXPECT_NEAR(o.secondaryRay.microseconds(c), 212.2, 0.05);
  EXPECT_NEAR(o.boundTest.microseconds(c), 473.0, 0.05);
  EXPECT_NEAR(o.objectTest.microseconds(c), 35.2, 0.05);
  EXPECT_NEAR(o.primitiveTest.microseconds(c), 598.2, 0.05);
  EXPECT_NEAR(o.hit.microseconds(c), 1294.6, 0.05);
  EXPECT_NEAR(o.lightChannel.microseconds(c), 961.2, 0.05);
  EXPECT_NEAR(o.pixel.microseconds(c) + c.putPixel + c.fileWrite, 176.2, 0.05);
}

TEST(EraCost, ARendersTimeIsItsEventsSummed) {
  const OpCosts1991 c;
  const EventOps1991 o = listingOps1991();
  EXPECT_NEAR(prime::seconds1991(TraceStats{}, 1000, 2), 1000 * 176.2e-6, 1e-9);
  TraceStats s;
  s.primaryRays = 10;
  s.reflectedRays = 2;
  s.transmittedRays = 3;
  s.boundTests = 40;
  s.objectTests = 20;
  s.primitiveTests = 30;
  s.hits = 7;
  const double us = 10 * o.primaryRay.microseconds(c) + 5 * o.secondaryRay.microseconds(c) +
                    40 * o.boundTest.microseconds(c) + 20 * o.objectTest.microseconds(c) +
                    30 * o.primitiveTest.microseconds(c) +
                    7 * (o.hit.microseconds(c) + 3 * 2 * o.lightChannel.microseconds(c)) +
                    10 * 176.2;
  EXPECT_NEAR(prime::seconds1991(s, 10, 2), us * 1e-6, 1e-9);
  // Twice the work, twice the time; a third light costs three channels more a hit.
  TraceStats twice = s;
  twice += s;
  EXPECT_NEAR(prime::seconds1991(twice, 20, 2), 2 * prime::seconds1991(s, 10, 2), 1e-9);
  EXPECT_NEAR(prime::seconds1991(s, 10, 3) - prime::seconds1991(s, 10, 2),
              7 * 3 * o.lightChannel.microseconds(c) * 1e-6, 1e-9);
}

TEST(EraCost, RowCountsSubtract) {
  TraceStats a, b;
  a.primaryRays = 9;
  a.boundTests = 5;
  a.hits = 4;
  b.primaryRays = 2;
  b.boundTests = 1;
  const TraceStats d = a - b;
  EXPECT_EQ(d.primaryRays, 7u);
  EXPECT_EQ(d.boundTests, 4u);
  EXPECT_EQ(d.hits, 4u);
}

}  // namespace
