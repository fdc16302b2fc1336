// The bounds docs/prime/numerics.md promises, held on a modest ray count: the
// modern profile has no NaN/Inf, no wrong decision and no self-intersection
// in any class; the 1991 profile runs every class without crashing and its
// NaNs and known deviations are counted, not hidden.
#include "src/prime/stress/stress.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "src/math/matrix.h"

namespace prime::stress {
namespace {

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PRIME_STRESS_SLOW 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || !defined(__OPTIMIZE__)
#define PRIME_STRESS_SLOW 1
#endif

// Rays per class and profile: PRIME_STRESS_RAYS overrides. Sanitized or
// unoptimised builds (CI's ASan run) use a tenth.
std::uint64_t raysPerClass() {
  if (const char* env = std::getenv("PRIME_STRESS_RAYS")) return std::strtoull(env, nullptr, 10);
#ifdef PRIME_STRESS_SLOW
  return 400;
#else
  return 4000;
#endif
}

// One test, so that ctest (one process per test) runs the suite once.
TEST(StressSuite, BoundsHoldInEveryClass) {
  const std::vector<ClassResult> results = [] {
    StressOptions o;
    o.raysPerClass = raysPerClass();
    o.threads = 2;
    return runStress(o);
  }();
  ASSERT_EQ(results.size(), stressClasses().size());
  std::uint64_t secondary = 0, k7 = 0, k4 = 0, wrong1991 = 0;
  for (const ClassResult& c : results) {
    SCOPED_TRACE("class " + c.name);
    // Both profiles ran the class (the 1991 one without crashing).
    EXPECT_GT(c.modern.rays, raysPerClass() / 2);
    EXPECT_GT(c.f1991.rays, 0u);
    // Modern: no NaN/Inf, and "fewer than 1 wrong decision per million
    // rays" held as 0 wrong decisions here.
    EXPECT_EQ(c.modern.nanInf, 0u);
    EXPECT_EQ(c.modern.wrongHitMiss, 0u);
    EXPECT_EQ(c.modern.wrongInOut, 0u);
    EXPECT_EQ(c.modern.wrongSurface, 0u);
    // Secondary rays never meet their own surface again.
    EXPECT_EQ(c.modern.selfHits, 0u);
    secondary += c.modern.secondary;
    // Reflection chains never escape.
    if (c.name == "tir-chain" || c.name == "mirrors") {
      EXPECT_GT(c.modern.chains, 0u);
      EXPECT_EQ(c.modern.chainsComplete, c.modern.chains);
    }
    // Well-conditioned classes: errors at the level of the conditioning.
    if (c.name == "uniform" || c.name == "on-surface" || c.name == "mirrors") {
      EXPECT_LT(c.modern.tRel.max, 1e-9);
      EXPECT_LT(c.modern.normalAngle.max, 1e-8);
    }
    // The reference: long double and binary128 agree on the baseline.
    if (c.name == "uniform") {
      EXPECT_EQ(c.modern.refDisagree, 0u);
    }
    k7 += c.f1991.semanticK7;
    k4 += c.f1991.semanticK4;
    wrong1991 += c.f1991.wrongDecisions();
  }
  EXPECT_GT(secondary, raysPerClass());
  // The 1991 profile's deviations are counted, not hidden.
  EXPECT_GT(k7, 0u);         // K7: no hit from inside
  EXPECT_GT(k4, 0u);         // K4: forward-matrix normals under non-uniform scale
  EXPECT_GT(wrong1991, 0u);  // Roundoff, K42's inverse, P1's constant ...
  // The report names every class.
  const std::string table = formatTable(results, true), csv = formatCsv(results);
  for (const ClassInfo& c : stressClasses()) {
    EXPECT_NE(table.find("| " + c.name + " |"), std::string::npos) << c.name;
    EXPECT_NE(csv.find(c.name + ",1991,"), std::string::npos) << c.name;
  }
}

// K28: the listing's cylinder cap mapping divides by the distance from the
// axis; a hit on the axis gives NaN (u, v). The suite counts it for both
// profiles (the modern one then reads texel 0, N11), and the 1991 hit
// itself is finite.
TEST(Stress1991, CountsTheNaNOfTheInverseMapping) {
  const std::array<std::array<double, 4>, 4> id = identity4();
  const std::vector<RayCase> rays{{{0, 0, 3}, {0, 0, -1}}};
  const Figures f91 = measureRays('C', id, rays, true);
  EXPECT_EQ(f91.rays, 1u);
  EXPECT_EQ(f91.uvNan, 1u);
  EXPECT_EQ(f91.nanInf, 0u);
  const Figures fm = measureRays('C', id, rays, false);
  EXPECT_EQ(fm.uvNan, 1u);
  EXPECT_EQ(fm.nanInf, 0u);
}

}  // namespace
}  // namespace prime::stress
