// The modern profile's Hall shading (hall_modern.h): the light vector points
// at the light, so a lit front face gets a positive diffuse term (K10 fixed);
// sums are clamped, and a non-finite one gives 0 and is counted.
#include "src/prime/render/hall_modern.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prime {
namespace {

TEST(HallModern, LitFrontFaceHasPositiveDiffuseReflection) {
  const HallHue hue{0.5, 1.0, {0.8, 0.4, 0.2}, 1.0, 10.0, 10.0, 1.0};  // kST = 0
  const HallLight light{{0, 0, -100}, {1, 1, 1}};                      // straight in front
  const Vec3 n{0, 0, -1}, view{0, 0, 1}, refl{0, 0, -1};
  const auto terms = hallTermsModern(hue, {0.5, 0.5, 0.5}, {}, {}, 0.0, {0, 0, 0}, view, n, refl,
                                     {&light, 1}, {0.1, 0.1, 0.1});
  for (int c = 0; c < 3; ++c) {
    const HallTerms& t = terms[static_cast<std::size_t>(c)];
    EXPECT_DOUBLE_EQ(t.diffuseReflection, 0.5 * hue.fDR[c] * (0.1 + 1.0));  // N.L = 1
    EXPECT_EQ(t.specularTransmission, 0.0);                                 // kST = 0
    EXPECT_GT(t.specularReflection, 0.0);  // N.H = 1: the highlight's peak
  }
}

TEST(HallModern, ColourIsClampedAndNonFiniteSumsCounted) {
  std::array<HallTerms, 3> terms{};
  terms[0].diffuseReflection = 2.0;
  terms[1].reflected = -1.0;
  terms[2].transmitted = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t nonFinite = 0;
  const Rgb c = hallColourModern(terms, nonFinite);
  EXPECT_EQ(c[0], 0.999999);
  EXPECT_EQ(c[1], 0.0);
  EXPECT_EQ(c[2], 0.0);
  EXPECT_EQ(nonFinite, 1u);
}

}  // namespace
}  // namespace prime
