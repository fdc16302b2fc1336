// The thesis profile (thesis 2.3.2, 4.6.6, 4.7-4.8): shadow rays, a
// transparent blocker, soft shadows, and Hall's terms as the thesis writes
// them, on configurations worked by hand.
#include "src/prime/render/tracer_thesis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "src/prime/math/listing_matrix.h"
#include "src/prime/render/hall_thesis.h"
#include "src/prime/render/renderer.h"

namespace prime {
namespace {

// A floor (the unit cube scaled to 2000 x 10 x 2000 and moved so that its top
// face is y = 0 over x, z in [-1000, 1000]), a sphere of radius 50 centred at
// (0, 200, 0) above it, and a white light of intensity 0.5 at (0, 1000, 0).
// Ambient 0.2, black background, one 1 x 1 map of texel 1.
struct ShadowScene {
  Scene scene;
  ShadowScene(double blockerKDT, double blockerTT) {
    SceneTexture map;
    map.uScale = map.vScale = 1;
    for (auto& c : map.channel) c = {1.0};
    scene.maps = {SceneTexture{}, map};
    scene.ambient = {0.2, 0.2, 0.2};
    scene.background = {0, 0, 0};
    scene.lights = {{{0, 1000, 0}, {0.5, 0.5, 0.5}}};
    add('B', {2000, 10, 2000}, {-1000, -10, -1000});
    add('S', {50, 50, 50}, {0, 200, 0});
    // The floor: kDR = kDT = 1 (no specular part, opaque), fDR 0.5.
    object(0, {1.0, 1.0, {0.5, 0.5, 0.5}, 1.0, 1, 1, 1.5});
    object(1, {0.0, blockerKDT, {0.5, 0.5, 0.5}, blockerTT, 1, 1, 1.5});
  }
  void add(char type, const Vec3& scale, const Vec3& at) {
    ScenePrim p;
    p.type = io::primType(type).value();
    p.transform = identity4();
    transform(p.transform, scale, at, {0, 0, 0}, {0, 0, 0});
    EXPECT_TRUE(inverse(p.transform, p.inverse));
    for (auto& m : p.map) m = {1, 1};
    scene.prims.push_back(p);
  }
  void object(int prim, const io::Hue& hue) {
    SceneObject o;
    o.number = static_cast<int>(scene.objects.size()) + 1;
    o.hue = hue;
    o.entries = {CsgEntry{'P', prim, 0}};
    scene.objects.push_back(o);
  }
};

// The colour seen looking straight down at floor point (x, 0, 0) from y = 100
// (below the sphere, which spans y 150..250).
Rgb floorColour(const TracerThesis& tracer, double x, TraceStats& stats, int sample = 0) {
  return tracer.castRay({{x, 100, 0}, {0, -1, 0}}, 0, stats, SampleId{{1, 0, 0}, sample});
}

TEST(ThesisShadows, APointInShadowAndOneLitByHand) {
  const ShadowScene s(1.0, 1.0);  // an opaque sphere (kST = 1 - kDT = 0)
  const TracerThesis tracer(s.scene);
  TraceStats stats;
  // The floor point (0, 0, 0) is straight under the sphere: the shadow ray
  // up the y axis meets it at y = 150..250, before the light at 1000.
  EXPECT_EQ(tracer.transmittance({0, 1e-9, 0}, {0, 1000, 0}, stats), (Rgb{0, 0, 0}));
  // (500, 0, 0): the ray to the light is at x = 400 at the sphere's height.
  EXPECT_EQ(tracer.transmittance({500, 1e-9, 0}, {0, 1000, 0}, stats), (Rgb{1, 1, 1}));
  EXPECT_EQ(stats.shadowRays, 2u);

  // Hall's terms on the floor (kSR = kST = 0, fDR = 0.5, texel 1, IA = 0.2,
  // I = 0.5, N = (0, 1, 0)):
  //   in shadow: kDR fDR (IA + 0) + kDT (1 - fDR)(IA + 0) = 0.1 + 0.1 = 0.2
  //   lit at (500, 0, 0): N.L = 1000 / sqrt(500^2 + 1000^2) = 0.894427191,
  //     0.5 (0.2 + 0.5 * 0.894427191) + 0.1 = 0.423606798
  TraceStats st;
  const Rgb dark = floorColour(tracer, 0, st);
  const Rgb lit = floorColour(tracer, 500, st);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(dark[c], 0.2, 1e-12);
    EXPECT_NEAR(lit[c], 0.5 * (0.2 + 0.5 * 1000 / std::sqrt(1250000.0)) + 0.1, 1e-12);
  }
  EXPECT_EQ(st.primaryRays, 2u);
  EXPECT_EQ(st.shadowRays, 2u);  // one light, one shaded point each
  // Without shadow rays the point under the sphere is lit: N.L = 1,
  // 0.5 (0.2 + 0.5) + 0.1 = 0.45.
  ThesisOptions off;
  off.shadows = false;
  const TracerThesis unshadowed(s.scene, {}, off);
  EXPECT_NEAR(floorColour(unshadowed, 0, st)[0], 0.45, 1e-12);
}

TEST(ThesisShadows, ATransparentBlockerPassesKstTimesTtToTheChord) {
  // kDT = 0.25: kST = 0.75; tT = 0.99 per unit; the vertical chord through
  // the sphere of radius 50 is 100: 0.75 * 0.99^100 = 0.274529...
  const ShadowScene s(0.25, 0.99);
  const TracerThesis tracer(s.scene);
  TraceStats stats;
  const double pass = 0.75 * std::pow(0.99, 100.0);
  const Rgb t = tracer.transmittance({0, 1e-9, 0}, {0, 1000, 0}, stats);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], pass, 1e-9);
  // Off-centre at x = 30: chord 2 sqrt(50^2 - 30^2) = 80 (the ray is vertical).
  const Rgb t30 = tracer.transmittance({30, 1e-9, 0}, {30, 1000, 0}, stats);
  EXPECT_NEAR(t30[0], 0.75 * std::pow(0.99, 80.0), 1e-9);
  // The floor under it: 0.5 (0.2 + 0.5 pass) + 0.1.
  const Rgb c = floorColour(tracer, 0, stats);
  EXPECT_NEAR(c[1], 0.5 * (0.2 + 0.5 * pass) + 0.1, 1e-9);
}

TEST(ThesisShadows, SoftShadowPenumbraLiesBetweenUmbraAndLit) {
  // A light of radius 200 at height 1000: from (0, 0, 0) the disc subtends
  // atan(200/1000) = 11.3 degrees, the sphere asin(50/200) = 14.5: umbra.
  const ShadowScene s(1.0, 1.0);
  ThesisOptions soft;
  soft.lightRadius = 200;
  const TracerThesis tracer(s.scene, {}, soft);
  auto visible = [&](double x) {  // the mean visibility over 64 samples of pixel (0, 0)
    TraceStats stats;
    double sum = 0;
    for (int k = 0; k < 64; ++k) {
      const Vec3 target = tracer.lightPoint(0, {x, 0, 0}, SampleId{{1, 0, 0}, k}, 0);
      EXPECT_LE(std::hypot(target[0], target[1] - 1000, target[2]), 200 + 1e-9);
      sum += tracer.transmittance({x, 1e-9, 0}, target, stats)[0];
    }
    return sum / 64;
  };
  EXPECT_EQ(visible(0), 0.0);    // umbra
  EXPECT_EQ(visible(500), 1.0);  // fully lit
  // The point-light shadow edge: the tangent from (0, 1000) to the sphere
  // meets the floor at x = 50 * 1000 / sqrt(800^2 - 50^2) = 62.7. Around it,
  // part of the disc is hidden: strictly between.
  const double edge = visible(62.7);
  EXPECT_GT(edge, 0.1);
  EXPECT_LT(edge, 0.9);
  double last = 0;
  for (double x = 0; x <= 200; x += 10) {  // non-decreasing out of the shadow
    const double v = visible(x);
    EXPECT_GE(v, last - 1e-12) << x;
    last = v;
  }
  // With a point light the same point is all or nothing.
  const TracerThesis hard(s.scene);
  TraceStats stats;
  const double h = hard.transmittance({62.7, 1e-9, 0}, {0, 1000, 0}, stats)[0];
  EXPECT_TRUE(h == 0.0 || h == 1.0);
}

// A ray leaving a lone primitive outward is not tested against it again
// (N18: it is convex), but a ray leaving one part of a set operation may meet
// another part of the same object. Sphere A (centre (0, 200, 0)) and sphere B
// (centre (0, 400, 0)), radius 50, opaque and half mirror, light straight
// above: A's top point, looked at from between them, sees B in its mirror
// and is in B's shadow whether B is its own object or A's union partner.
TEST(ThesisShadows, APartOfTheSameObjectStillShadowsAndReflects) {
  enum class B { kNone, kOwnObject, kUnionPartner };
  auto topOfA = [](B b, bool thesis) {
    ShadowScene s(1.0, 1.0);
    s.scene.objects.clear();
    s.scene.prims.clear();
    s.add('S', {50, 50, 50}, {0, 200, 0});
    s.add('S', {50, 50, 50}, {0, 400, 0});
    const io::Hue hue{0.5, 1.0, {0.6, 0.4, 0.2}, 1.0, 1, 1, 1.5};  // kSR 0.5, kST 0
    s.object(0, hue);
    if (b == B::kOwnObject) s.object(1, hue);
    if (b == B::kUnionPartner) s.scene.objects[0].entries = {{'+', 1, 2}, {'P', 0, 0}, {'P', 1, 0}};
    TraceStats stats;
    const Ray down{{0, 300, 0}, {0, -1, 0}};  // meets A at y = 250, normal (0, 1, 0)
    return thesis ? TracerThesis(s.scene).castRay(down, 0, stats)
                  : TracerModern(s.scene).castRay(down, 0, stats);
  };
  for (const bool thesis : {false, true}) {
    const Rgb alone = topOfA(B::kNone, thesis), own = topOfA(B::kOwnObject, thesis),
              partner = topOfA(B::kUnionPartner, thesis);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(partner[c], own[c], 1e-12) << "thesis " << thesis << " channel " << c;
      EXPECT_GT(std::abs(own[c] - alone[c]), 0.01) << "thesis " << thesis << " channel " << c;
    }
  }
}

// The solid of a difference lies in its left operand, not its right one. A
// cube [-100, 100]^3 minus a sphere of radius 50 centred on its top face, a
// light straight below: the bottom of the hollow, (0, 50, 0), is on the
// sphere's surface, and its shadow ray runs down through the cube's own
// material (kDT = 1: the light behind the surface counts). It is in shadow:
// the light adds what a light of intensity 0 adds, and less than with
// shadows off.
TEST(ThesisShadows, AHollowIsShadowedThroughItsOwnSolid) {
  auto bottomOfHollow = [](double intensity, bool shadows) {
    ShadowScene s(1.0, 1.0);
    s.scene.objects.clear();
    s.scene.prims.clear();
    s.scene.lights = {{{0, -1000, 0}, {intensity, intensity, intensity}}};
    s.add('B', {200, 200, 200}, {-100, -100, -100});
    s.add('S', {50, 50, 50}, {0, 100, 0});
    s.object(0, {1.0, 1.0, {0.6, 0.4, 0.2}, 1.0, 1, 1, 1.5});  // opaque, diffuse
    s.scene.objects[0].entries = {{'-', 1, 2}, {'P', 0, 0}, {'P', 1, 0}};
    ThesisOptions options;
    options.shadows = shadows;
    TraceStats stats;
    return TracerThesis(s.scene, {}, options).castRay({{0, 300, 0}, {0, -1, 0}}, 0, stats);
  };
  const Rgb shadowed = bottomOfHollow(0.5, true), dark = bottomOfHollow(0.0, true),
            lit = bottomOfHollow(0.5, false);
  EXPECT_EQ(std::memcmp(shadowed.data(), dark.data(), sizeof shadowed), 0);
  for (int c = 0; c < 3; ++c) EXPECT_GT(lit[c] - shadowed[c], 0.01) << c;
}

TEST(HallThesis, FresnelFromF0AsSection473) {
  // F(0) = 0.04: eta = (1 + 0.2) / (1 - 0.2) = 1.5.
  EXPECT_NEAR(etaFromF0(0.04), 1.5, 1e-15);
  EXPECT_NEAR(fresnelThesis(0.04, 1.0), 0.04, 1e-15);  // normal incidence gives F(0) back
  EXPECT_NEAR(fresnelThesis(0.04, 0.0), 1.0, 1e-15);   // grazing: all reflected
  EXPECT_EQ(fresnelThesis(0.0, 0.5), 0.0);             // eta = 1: no boundary
  EXPECT_EQ(fresnelThesis(1.0, 0.5), 1.0);
  // At 60 degrees, against the s- and p-polarised Fresnel equations (an
  // independent formula): sin t = sin 60 / 1.5, Rs = ((c - n ct)/(c + n ct))^2,
  // Rp = ((ct - n c)/(ct + n c))^2, F = (Rs + Rp) / 2 = 0.0891867...
  const double c = 0.5, n = 1.5, st = std::sqrt(0.75) / n, ct = std::sqrt(1 - st * st);
  const double rs = std::pow((c - n * ct) / (c + n * ct), 2);
  const double rp = std::pow((ct - n * c) / (ct + n * c), 2);
  EXPECT_NEAR(fresnelThesis(0.04, c), (rs + rp) / 2, 1e-12);
  EXPECT_NEAR(fresnelThesis(0.04, c), 0.0891867, 1e-6);
}

TEST(HallThesis, TheCorrectedTermsByHand) {
  // Looking straight down (view (0, -1, 0)) at a surface with N = (0, 1, 0)
  // at the origin; one light of intensity 1; IA = 0.1; texel 0.04 (F(0));
  // hue kDR 0.5 (kSR 0.5), kDT 1 (kST 0), fDR 0.6, kRH 10.
  const HallHue hue{0.5, 1.0, {0.6, 0.6, 0.6}, 1.0, 10, 10, 1.5};
  const Rgb texel{0.04, 0.04, 0.04}, iSR{0.5, 0.5, 0.5}, iST{};
  const Vec3 view{0, -1, 0}, n{0, 1, 0}, p{0, 0, 0};
  // The light overhead (0, 10, 0): L = V = H = N, N.L = N.H = V.H = 1, F = F(0).
  //   specular reflection  kSR I F (N.H)^10   = 0.5 * 0.04            = 0.02
  //   diffuse reflection   kDR fDR texel (IA + I N.L) = 0.5 * 0.024 * 1.1 = 0.0132  (K10, K11)
  //   diffuse transmission kDT (1 - fDR) texel (IA + 0) = 0.016 * 0.1     = 0.0016
  //   reflected            kSR iSR F(N.V = 1)  = 0.5 * 0.5 * 0.04     = 0.01
  //   transmission terms   kST = 0
  ThesisLight above{{0, 10, 0}, {1, 1, 1}};
  auto t = hallTermsThesis(hue, texel, iSR, iST, 0, view, n, p, {&above, 1}, {0.1, 0.1, 0.1}, true);
  EXPECT_NEAR(t[0].specularReflection, 0.02, 1e-15);
  EXPECT_NEAR(t[0].diffuseReflection, 0.0132, 1e-15);
  EXPECT_NEAR(t[0].diffuseTransmission, 0.0016, 1e-15);
  EXPECT_NEAR(t[0].reflected, 0.01, 1e-15);
  EXPECT_EQ(t[0].specularTransmission, 0.0);
  EXPECT_EQ(t[0].transmitted, 0.0);
  // The listing's K10 had these the other way round: a light BELOW the
  // surface (0, -10, 0) lights the diffuse transmission term, not the
  // reflection: 0.016 * (0.1 + 1) = 0.0176, and 0.5 * 0.024 * 0.1 = 0.0012.
  ThesisLight below{{0, -10, 0}, {1, 1, 1}};
  t = hallTermsThesis(hue, texel, iSR, iST, 0, view, n, p, {&below, 1}, {0.1, 0.1, 0.1}, true);
  EXPECT_NEAR(t[1].diffuseTransmission, 0.0176, 1e-15);
  EXPECT_NEAR(t[1].diffuseReflection, 0.0012, 1e-15);
  EXPECT_EQ(t[1].specularReflection, 0.0);
  // In shadow (visibility 0) the light's terms vanish, the ambient stays.
  above.visibility = {0, 0, 0};
  t = hallTermsThesis(hue, texel, iSR, iST, 0, view, n, p, {&above, 1}, {0.1, 0.1, 0.1}, true);
  EXPECT_EQ(t[2].specularReflection, 0.0);
  EXPECT_NEAR(t[2].diffuseReflection, 0.5 * 0.024 * 0.1, 1e-15);
  // With --texel fresnel the texel is F(0) only: fDR = 0.6 uncoloured,
  // 0.5 * 0.6 * 1.1 = 0.33.
  above.visibility = {1, 1, 1};
  t = hallTermsThesis(hue, texel, iSR, iST, 0, view, n, p, {&above, 1}, {0.1, 0.1, 0.1}, false);
  EXPECT_NEAR(t[0].diffuseReflection, 0.33, 1e-15);
  // The transmitted ray: kDT 0 (kST 1), iST 0.5, tT 0.9 over sT = 2:
  // kST iST (1 - F(N.V = 1)) tT^sT = 0.5 * 0.96 * 0.81 = 0.3888.
  const HallHue glass{0.0, 0.0, {0.5, 0.5, 0.5}, 0.9, 10, 10, 1.5};
  t = hallTermsThesis(glass, texel, {}, {0.5, 0.5, 0.5}, 2.0, view, n, p, {&above, 1},
                      {0.1, 0.1, 0.1}, true);
  EXPECT_NEAR(t[0].transmitted, 0.3888, 1e-15);
}

// A small scene the listing's camera sees (as tests/prime/unit/render's
// other render tests): the shadow scene moved into the window.
Scene windowScene() {
  ShadowScene s(0.25, 0.995);
  s.scene.prims.clear();
  s.add('B', {900, 20, 900}, {50, 0, 50});
  s.add('S', {150, 150, 150}, {500, 400, 300});
  s.scene.lights = {{{300, 1500, -500}, {0.7, 0.7, 0.6}}, {{900, 900, -800}, {0.3, 0.3, 0.4}}};
  return s.scene;
}

TEST(ThesisRender, JitteredAndStatisticalAreTheSameBytesOnOneAndTwoThreads) {
  const Scene scene = windowScene();
  for (auto mode : {Sampling::Mode::Jittered, Sampling::Mode::Statistical}) {
    RenderSettings settings;
    settings.profile = Profile::Thesis;
    settings.camera.screenWidth = 160;
    settings.camera.screenHeight = 120;
    settings.sampling.mode = mode;
    settings.sampling.gridN = 2;
    settings.sampling.bound = 0.02;
    settings.sampling.maxSamples = 16;
    settings.sampling.seed = 5;
    settings.thesis.lightRadius = 80;
    settings.threads = 1;
    const RenderResult one = render(scene, settings);
    settings.threads = 2;
    const RenderResult two = render(scene, settings);
    EXPECT_EQ(two.threads, 2);
    ASSERT_EQ(one.rgb.pixels.size(), two.rgb.pixels.size());
    EXPECT_EQ(0, std::memcmp(one.rgb.pixels.data(), two.rgb.pixels.data(),
                             one.rgb.pixels.size() * sizeof(Rgb)));
    EXPECT_EQ(one.graph.pixels, two.graph.pixels);
    EXPECT_EQ(one.stats.rays(), two.stats.rays());
    EXPECT_EQ(one.samples, two.samples);
    EXPECT_GT(one.stats.shadowRays, 0u);
    // Another seed gives another picture (the numbers are used at all).
    settings.sampling.seed = 6;
    const RenderResult other = render(scene, settings);
    EXPECT_NE(0, std::memcmp(one.rgb.pixels.data(), other.rgb.pixels.data(),
                             one.rgb.pixels.size() * sizeof(Rgb)));
  }
}

}  // namespace
}  // namespace prime
