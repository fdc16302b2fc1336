// The per-quirk switches (src/prime/render/listing_fixes.h), each against a
// result worked out by hand: the corrected code path's answer computed here
// independently, and everything the quirk does not touch unchanged.
#include "src/prime/render/listing_fixes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <stdexcept>
#include <string>

#include "src/prime/math/listing_matrix.h"
#include "src/prime/render/hall_1991.h"
#include "src/prime/render/tracer_1991.h"
#include "tests/prime/unit/render/small_scene.h"

namespace prime {
namespace {

TEST(ListingFixes, ParseNamesEverySwitchAndRefusesTheRest) {
  const ListingFixes f = parseListingFixes("K18,k10");
  EXPECT_TRUE(f.k18 && f.k10 && !f.k4 && !f.k5 && !f.k15);
  EXPECT_EQ(fixIds(f), "K10,K18");
  EXPECT_EQ(fixIds(parseListingFixes("all")), "K4,K5,K10,K15,K18");
  EXPECT_FALSE(ListingFixes{}.any());
  try {
    parseListingFixes("K18,K7");
    FAIL() << "K7 has no switch";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "K7 has no switch: K6, K7, K8 and K19 are tangled: no correction of one alone "
              "renders; --fix takes K4, K5, K10, K15, K18, or all; prime errata lists every quirk");
  }
  const std::string noQuirk = "K" + std::to_string(99);  // (no id for the docs check)
  try {
    parseListingFixes(noQuirk);
    FAIL() << noQuirk << " is no quirk";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "'" + noQuirk +
                  "' is no listing quirk (K1 .. K44); --fix takes K4, K5, K10, K15, K18, or all; "
                  "prime errata lists every quirk");
  }
  EXPECT_THROW(parseListingFixes("K" + std::to_string(45)),
               std::invalid_argument);  // past the last
  EXPECT_THROW(parseListingFixes(""), std::invalid_argument);
  // Every K id of the errata is listed once, in order, with a switch or a reason.
  int k = 0;
  for (const ListingQuirk& q : listingQuirks()) {
    EXPECT_EQ(std::string(q.id), "K" + std::to_string(++k));
    EXPECT_TRUE((q.fix == nullptr) != (q.noSwitch == nullptr)) << q.id;
  }
  EXPECT_EQ(k, 44);
}

// K18: the listing moves the reflected ray's origin one unit along it; the
// fix leaves it at the hit point. The direction is the same either way.
TEST(ListingFixes, K18StartsTheReflectedRayAtTheHitPoint) {
  const Scene scene = test::sphereScene();
  TraceOptions listing, fixed;
  fixed.fixes.k18 = true;
  const Tracer1991 a(scene, listing), b(scene, fixed);
  const Ray ray{{500, 500, -1500}, {0.1, -0.05, 1.0}};
  const Vec3 n = normalized(Vec3{-0.3, 0.2, -1.0});
  const double t = 1234.5;
  const Ray ra = a.reflectedRay(ray, t, n), rb = b.reflectedRay(ray, t, n);
  // By hand: the hit point, and d - 2 (d.n) n made unit.
  const Vec3 hit = ray.o + ray.d * t;
  const Vec3 dir = normalized(ray.d - n * (2.0 * dot(ray.d, n)));
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(rb.o[i], hit[i]);
    EXPECT_NEAR(rb.d[i], dir[i], 1e-15);
    EXPECT_EQ(ra.d[i], rb.d[i]);
    EXPECT_EQ(ra.o[i], hit[i] + rb.d[i]);  // the listing's one unit along
  }
}

// The eye looks along +z at the origin on a face facing it (hall_1991_test.cpp's head-on case).
HallGeometry facingTheEye() {
  HallGeometry g;
  g.pt = {0, 0, 0};
  g.v = {0, 0, 1};
  g.n = {0, 0, -1};
  g.r = {0, 0, -1};  // v - 2(v.n)n
  g.t = {0, 0, 1};
  return g;
}

// K10: l and v turned round. Fixed, Hall's sum is what the listing's code
// gives when it is handed the corrected vectors (the light mirrored through
// the point, the view reversed): with the point at the origin the mirror is
// exact, so the two must agree to the bit. And the lit face is lit.
TEST(ListingFixes, K10TurnsLAndVTowardsTheLightAndTheEye) {
  const HallHue hue{0.5, 1.0, {0.8, 0.8, 0.8}, 0.9, 1.0, 1.0, 2.0};
  const Rgb ia = {0.2, 0.2, 0.2};
  const HallGeometry g = facingTheEye();  // the light in front
  const std::vector<HallLight> lights = {{{0, 0, -10}, {1.0, 0.5, 0.25}}};
  HallGeometry fixed = g;
  fixed.v = -g.v;  // what the tracer passes with --fix K10
  fixed.towardsLight = true;
  HallGeometry byHand = g;
  byHand.v = -g.v;
  const std::vector<HallLight> mirrored = {{{0, 0, 10}, {1.0, 0.5, 0.25}}};
  const Rgb a =
      processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, fixed, lights, ia);
  const Rgb b =
      processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, byHand, mirrored, ia);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(a[k], b[k]) << k;
  // Lit, the diffuse reflection term is kDR fDR (IA + I N.L) > 0 (the
  // listing's is negative: -0.32 for red, hall_1991_test.cpp), and the
  // diffuse transmission kDT fDT (IA - I N.L), kDT fDT = 0.2 as there, < 0.
  const auto terms =
      hallTermsRgb1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, fixed, lights, ia);
  EXPECT_NEAR(terms[0].diffuseReflection, 0.5 * 0.8 * (0.2 + 1.0), 1e-12);
  EXPECT_NEAR(terms[0].diffuseTransmission, 0.2 * (0.2 - 1.0), 1e-12);
}

// K15: the listing leaves negative colours (-0.83 and -0.1675 for this
// head-on case, worked by hand in hall_1991_test.cpp); fixed they are 0 and
// the positive channel is untouched.
TEST(ListingFixes, K15ClampsNegativeColoursOnly) {
  const HallHue hue{0.5, 1.0, {0.8, 0.8, 0.8}, 0.9, 1.0, 1.0, 2.0};
  const HallGeometry g = facingTheEye();
  const std::vector<HallLight> lights = {{{0, 0, -10}, {1.0, 0.5, 0.25}}};
  const Rgb ia = {0.2, 0.2, 0.2};
  const Rgb listing =
      processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, g, lights, ia);
  const Rgb fixed =
      processColor1991(hue, {0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0}, 0.0, g, lights, ia, {}, true);
  EXPECT_NEAR(listing[0], -0.83, 1e-12);
  EXPECT_NEAR(listing[1], -0.1675, 1e-12);
  EXPECT_EQ(fixed[0], 0.0);
  EXPECT_EQ(fixed[1], 0.0);
  EXPECT_EQ(fixed[2], listing[2]);
  EXPECT_NEAR(fixed[2], 0.023125, 1e-12);
}

// The first "normal":[x,y,z] of a probe's hit events.
Vec3 probedNormal(const Probe& p) {
  for (const ProbeEvent& e : p.events) {
    if (e.kind != "hit") continue;
    static const std::regex re(R"re("normal":\[([-0-9.eE+]+),([-0-9.eE+]+),([-0-9.eE+]+)\])re");
    std::smatch m;
    if (std::regex_search(e.json, m, re))
      return {std::stod(m[1].str()), std::stod(m[2].str()), std::stod(m[3].str())};
  }
  ADD_FAILURE() << "no hit";
  return {};
}

// K4: on an ellipsoid (a sphere scaled 300 x 100 x 200, not turned) the
// fixed normal is the ellipsoid's, worked out by hand as the gradient
// ((x - cx)/a^2, (y - cy)/b^2, (z - cz)/c^2); the listing's is not.
TEST(ListingFixes, K4GivesTheEllipsoidsNormal) {
  test::SmallScene small;
  ScenePrim p;
  p.type = io::primType('S').value();
  p.transform = identity4();
  const Vec3 centre{500, 500, 300}, radii{300, 100, 200};
  transform(p.transform, radii, centre, {0, 0, 0}, {0, 0, 0});
  ASSERT_TRUE(inverse(p.transform, p.inverse));
  for (auto& m : p.map) m = {1, 1};
  small.scene.prims.push_back(p);
  small.object(0.6, {0.9, 0.3, 0.2}, 0);
  TraceOptions fixed;
  fixed.fixes.k4 = true;
  const Ray ray{{650, 540, -1000}, {0, 0, 1}};
  auto normalOf = [&](const TraceOptions& o) {
    const Tracer1991 tracer(small.scene, o);
    TraceStats stats;
    Probe probe;
    tracer.castRay(ray, 0, stats, &probe);
    return probedNormal(probe);
  };
  const Vec3 got = normalOf(fixed), listing = normalOf({});
  // The hit, by hand: z where ((650-500)/300)^2 + ((540-500)/100)^2 + ((z-300)/200)^2 = 1.
  const double dz = -200.0 * std::sqrt(1.0 - 0.25 - 0.16);
  const Vec3 want =
      normalized(Vec3{150.0 / (300.0 * 300.0), 40.0 / (100.0 * 100.0), dz / (200.0 * 200.0)});
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-6) << i;  // the probe's %.17g
  EXPECT_GT(length(listing - want), 1e-2) << "the listing's normal is the forward matrix's";
}

// K5: a sphere is the same whatever way it is turned, so the ray leaving a
// glass sphere must not depend on the turn. Fixed, it does not (to
// rounding); the listing refracts out with the normal in the turned local
// frame, so turning the sphere moves the ray.
TEST(ListingFixes, K5MakesTheExitIndependentOfTheSpheresTurn) {
  auto leaving = [](const Vec3& turn, bool fix) {
    test::SmallScene small;
    ScenePrim p;
    p.type = io::primType('S').value();
    p.transform = identity4();
    transform(p.transform, {200, 200, 200}, {500, 500, 300}, {0, 0, 0}, turn);
    EXPECT_TRUE(inverse(p.transform, p.inverse));
    for (auto& m : p.map) m = {1, 1};
    small.scene.prims.push_back(p);
    small.object(0.1, {0.9, 0.9, 0.9}, 0);
    small.scene.objects[0].hue.kDT = 0.1;  // glass: mostly transmitted
    TraceOptions o;
    o.fixes.k5 = fix;
    const Tracer1991 tracer(small.scene, o);
    const Ray ray{{560, 530, -1000}, normalized(Vec3{0.0, 0.0, 1.0})};
    // The entry: t by hand from |o + t d - c| = 200.
    const Vec3 oc = ray.o - Vec3{500, 500, 300};
    const double b = dot(oc, ray.d), c = dot(oc, oc) - 200.0 * 200.0;
    const double t = -b - std::sqrt(b * b - c);
    const Vec3 n = normalized(ray.o + ray.d * t - Vec3{500, 500, 300});
    double distance = 0;
    TraceStats stats;
    return tracer.transmittedRay(ray, small.scene.objects[0], t, n, 1.5, distance, stats);
  };
  const Ray straight = leaving({0, 0, 0}, true), turned = leaving({30, 50, 10}, true);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(turned.d[i], straight.d[i], 1e-9) << i;
    EXPECT_NEAR(turned.o[i], straight.o[i], 1e-6) << i;
  }
  const Ray listingStraight = leaving({0, 0, 0}, false),
            listingTurned = leaving({30, 50, 10}, false);
  EXPECT_GT(length(listingTurned.d - listingStraight.d), 1e-3) << "K5 showed nothing to fix";
  // Unturned, the local frame is the world's up to the scale: the fix changes
  // the direction only by the normal's length (the unit sphere's is 1).
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(listingStraight.d[i], straight.d[i], 1e-9) << i;
}

}  // namespace
}  // namespace prime
