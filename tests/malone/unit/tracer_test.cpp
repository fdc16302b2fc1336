// Malone's trace (src/malone/tracer.h) by hand at chosen rays: the primary
// ray of section 1.6, the document's scene's centre pixel (notes 4.2), each
// Phong term with r^-2 (101) and without (104), shadows, the corrected
// reflection and refraction directions (Snell checked), total internal
// reflection, the depth and MIN_WEIGHT cut-offs, escaped rays, the debug
// renders and the --no switches.
#include "src/malone/tracer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "legacy_io/malone/ppm.h"
#include "tests/malone/unit/scene_text.h"

namespace prime::malone {
namespace {

using test::rayOf;
using test::sceneOf;
using test::unitVec;
using ::testing::HasSubstr;

void expectRgb(const Rgb& got, const Rgb& want, double tol = 1e-12) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tol) << "channel " << k;
}
void expectVec(const Vec3& got, const Vec3& want, double tol = 1e-12) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tol) << "component " << k;
}

// With `probe`: the probe's events, one text line each; `json` their data.
Rgb traceOnce(const Scene& s, const MRay& ray, TraceStats& stats, TraceSettings settings = {},
              double index = 1.0, std::string* probe = nullptr, std::string* json = nullptr) {
  const Tracer tracer(s, settings);
  Probe log;
  const Rgb c = tracer.trace(ray, 1, 1.0, index, stats, probe ? &log : nullptr);
  for (const ProbeEvent& e : log.events) {
    if (probe) *probe += e.kind + " " + e.text + "\n";
    if (json) *json += e.json + "\n";
  }
  return c;
}

// The direction printed after `what ... along (` in a probe.
Vec3 probedDirection(const std::string& probe, const std::string& what) {
  const auto at = probe.find(what);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no '" << what << "' in:\n" << probe;
    return {};
  }
  const auto along = probe.find("along (", at);
  Vec3 v{};
  EXPECT_EQ(std::sscanf(probe.c_str() + along, "along (%lf, %lf, %lf)", &v[0], &v[1], &v[2]), 3);
  return v;
}

// ---- The primary ray (section 1.6): e toward v((2X - X_RES)/X_RES, -(2Y - Y_RES)/Y_RES).

TEST(MaloneTracer, PrimaryRay) {
  // The document's viewer: e = (0,2,3), l = 0, x = (1,0,0), y = (0,1,0), 256 x 256.
  const Scene s = buildScene(readSceneFile(MALONE_SCENES "/doc-scene.mal"), "doc");
  const Tracer tracer(s, {});
  const double r13 = std::sqrt(13.0);
  const Vec3 f{0, -2 / r13, -3 / r13};  // (l - e)/|l - e|
  // (128,128): alpha = (256 - 256)/256 = 0, beta = 0: the view direction.
  MRay ray = tracer.primaryRay(128, 128);
  expectVec(ray.o, {0, 2, 3});
  expectVec(ray.d, f);
  EXPECT_EQ(ray.length, kInfinite);
  // (0,0): alpha = -1, beta = -(0 - 256)/256 = 1: f - x + y, normalised.
  expectVec(tracer.primaryRay(0, 0).d, unitVec(f + Vec3{-1, 1, 0}));
  // (192,64): alpha = (384 - 256)/256 = 0.5, beta = -(128 - 256)/256 = 0.5.
  expectVec(tracer.primaryRay(192, 64).d, unitVec(f + Vec3{0.5, 0.5, 0}));
  // (255,255): alpha = 254/256 = 0.9921875, beta = -0.9921875 (no half-pixel offset).
  expectVec(tracer.primaryRay(255, 255).d, unitVec(f + Vec3{0.9921875, -0.9921875, 0}));
  // Column X_RES/2 - k and X_RES/2 + k mirror each other.
  const Vec3 a = tracer.primaryRay(128 - 37, 100).d, b = tracer.primaryRay(128 + 37, 100).d;
  EXPECT_DOUBLE_EQ(a[0], -b[0]);
  EXPECT_DOUBLE_EQ(a[1], b[1]);
  EXPECT_DOUBLE_EQ(a[2], b[2]);
}

TEST(MaloneTracer, DocumentSceneCentrePixel) {
  // The centre ray hits the plane y = 0 at the origin (t = sqrt 13). The light
  // (-2,5,2): l^2 = 4 + 25 + 4 = 33, s = (-2,5,2)/sqrt 33, d.s = 5/sqrt 33;
  // k_d = 1, colour 1, k_s = 0 (no specular), no ambient. With r^-2 (101):
  // 5 / (33 sqrt 33) = 0.0263752..., byte round(6.73) = 7 (notes 4.2: 0.02638).
  SceneFile f = readSceneFile(MALONE_SCENES "/doc-scene.mal");
  Scene s = buildScene(f, "doc");
  TraceStats stats;
  const Rgb c = Tracer(s, {}).pixel(128, 128, stats);
  const double want = 5 / (33 * std::sqrt(33.0));
  EXPECT_NEAR(want, 0.02638, 5e-6);
  expectRgb(c, {want, want, want}, 1e-15);
  EXPECT_EQ(toByte(c[0]), 7);
  EXPECT_EQ(stats.primaryRays, 1u);
  EXPECT_EQ(stats.shadowRays, 1u);
  EXPECT_EQ(stats.reflectedRays, 0u);
  EXPECT_EQ(stats.hits, 1u);
  // Without r^-2 (104): 5 / sqrt 33 = 0.870388 (notes: 0.8704, byte 222).
  f.lights[0].id = ObjectId::PointLightNoFalloff;
  s = buildScene(f, "doc");
  const Rgb d = Tracer(s, {}).pixel(128, 128, stats);
  expectRgb(d, {5 / std::sqrt(33.0), 5 / std::sqrt(33.0), 5 / std::sqrt(33.0)}, 1e-15);
  EXPECT_EQ(toByte(d[0]), 222);  // 221.95 + 0.5
}

// ---- Phong (notes 4.1): I_a K_d + sum I_l (K_d (d.s) + k_s' (r.s)^k_e) / l^2.
// The plane y = 0 with colour (1, 0.5, 0.25), k_s 0.5, k_e 2, k_d 0.8:
// K_d = (0.8, 0.4, 0.2); ambient (0.1, 0.2, 0.3): I_a K_d = (0.08, 0.08, 0.06).
// The ray from (0,3,-4) along (0,-0.6,0.8) hits the origin (t = 5): d = (0,1,0),
// r = i - 2 (i.d) d = (0, 0.6, 0.8).

const std::string kPhongPlane = "2 0 0 1 0 100 1 0.5 0.25 0.5 2 0.8 0 1\n103 0.1 0.2 0.3\n";
const MRay kPhongRay{{0, 3, -4}, {0, -0.6, 0.8}, kInfinite};

TEST(MalonePhong, SpecularAlongTheMirrorDirection) {
  // Light (0,6,8): l = 10, s = (0, 0.6, 0.8) = r: r.s = 1, d.s = 0.6.
  // R: 0.08 + 100 (0.8 * 0.6 + 0.5 * 1^2) / 100 = 0.08 + 0.98 = 1.06
  // G: 0.08 + 50 (0.4 * 0.6 + 0.5) / 100 = 0.08 + 0.37 = 0.45
  // B: 0.06 + 20 (0.2 * 0.6 + 0.5) / 100 = 0.06 + 0.124 = 0.184
  const Scene s = sceneOf(kPhongPlane + "101 0 6 8 100 50 20\n");
  TraceStats stats;
  expectRgb(traceOnce(s, kPhongRay, stats), {1.06, 0.45, 0.184});
  EXPECT_EQ(stats.shadowRays, 1u);
  EXPECT_EQ(stats.reflectedRays, 1u);  // k_s > 0: the reflected ray escapes (black)
}

TEST(MalonePhong, SpecularOffTheMirror) {
  // Light (0,8,6): l = 10, s = (0, 0.8, 0.6): d.s = 0.8, r.s = 0.48 + 0.48 = 0.96,
  // k_s (r.s)^2 = 0.5 * 0.9216 = 0.4608; I = 100.
  // R: 0.08 + 0.8 * 0.8 + 0.4608 = 1.1808; G: 0.08 + 0.32 + 0.4608 = 0.8608;
  // B: 0.06 + 0.16 + 0.4608 = 0.6808.
  const Scene s = sceneOf(kPhongPlane + "101 0 8 6 100 100 100\n");
  TraceStats stats;
  expectRgb(traceOnce(s, kPhongRay, stats), {1.1808, 0.8608, 0.6808});
}

TEST(MalonePhong, NoSpecularWhenRDotSIsNegative) {
  // Light (0,6,-8): s = (0, 0.6, -0.8), r.s = 0.36 - 0.64 = -0.28 < 0: no
  // specular (with k_e = 2 an unguarded (-0.28)^2 would add 0.0392).
  // d.s = 0.6: R 0.08 + 0.48 = 0.56, G 0.08 + 0.24 = 0.32, B 0.06 + 0.12 = 0.18.
  const Scene s = sceneOf(kPhongPlane + "101 0 6 -8 100 100 100\n");
  TraceStats stats;
  expectRgb(traceOnce(s, kPhongRay, stats), {0.56, 0.32, 0.18});
}

TEST(MalonePhong, NothingFromALightTheSurfaceDoesNotFace) {
  // Light (0,-6,8) below the plane: d.s = -0.6, although r.s = -0.36 + 0.64 =
  // 0.28 > 0: neither diffuse nor specular, no shadow ray; ambient only.
  const Scene s = sceneOf(kPhongPlane + "101 0 -6 8 100 100 100\n");
  TraceStats stats;
  expectRgb(traceOnce(s, kPhongRay, stats), {0.08, 0.08, 0.06});
  EXPECT_EQ(stats.shadowRays, 0u);
}

TEST(MalonePhong, LightWithoutInverseSquare) {
  // 104 at (0,6,8), I = 1, no division by l^2 = 100:
  // R 0.08 + 0.48 + 0.5 = 1.06, G 0.08 + 0.24 + 0.5 = 0.82, B 0.06 + 0.12 + 0.5 = 0.68.
  const Scene s = sceneOf(kPhongPlane + "104 0 6 8 1 1 1\n");
  TraceStats stats;
  expectRgb(traceOnce(s, kPhongRay, stats), {1.06, 0.82, 0.68});
}

TEST(MalonePhong, AmbientIsIaTimesKd) {
  // Two ambient lights add: (0.1,0.2,0.3) + (0.3,0.2,0.1) = (0.4,0.4,0.4), times
  // K_d = (0.8, 0.4, 0.2): (0.32, 0.16, 0.08).
  const Scene s = sceneOf(kPhongPlane + "103 0.3 0.2 0.1\n");
  TraceStats stats;
  expectRgb(traceOnce(s, kPhongRay, stats), {0.32, 0.16, 0.08});
}

TEST(MaloneShadows, AnyObjectBlocks) {
  // The light (0,8,6) of SpecularOffTheMirror, a sphere of radius 0.5 at
  // (0,4,3) halfway along the shadow ray. The eye ray passes it at distance 5
  // (closest at t = 5, the origin) and the reflected ray (0,0.6,0.8) at
  // |(0,4,3) x (0,0.6,0.8)| = |3.2 - 1.8| = 1.4: only the shadow ray meets it.
  const std::string light = "101 0 8 6 100 100 100\n";
  for (const char* blocker : {"1 0.5 0 4 3 100 1 1 1 0 1 1 0 1\n",       // opaque
                              "1 0.5 0 4 3 100 1 1 1 0 1 0 1 1.5\n"}) {  // fully transparent
    SCOPED_TRACE(blocker);
    const Scene s = sceneOf(kPhongPlane + light + blocker);
    TraceStats stats;
    expectRgb(traceOnce(s, kPhongRay, stats), {0.08, 0.08, 0.06});  // ambient only
    EXPECT_EQ(stats.shadowRays, 1u);
    EXPECT_EQ(stats.reflectedRays, 1u);
    // --no shadows: the light counts again, and no shadow ray is cast.
    TraceSettings noShadows;
    noShadows.shadows = false;
    TraceStats quiet;
    expectRgb(traceOnce(s, kPhongRay, quiet, noShadows), {1.1808, 0.8608, 0.6808});
    EXPECT_EQ(quiet.shadowRays, 0u);
  }
  // A sphere beyond the light (at distance 20 > l = 10) does not shadow.
  const Scene beyond = sceneOf(kPhongPlane + light + "1 0.5 0 16 12 100 1 1 1 0 1 1 0 1\n");
  TraceStats stats;
  expectRgb(traceOnce(beyond, kPhongRay, stats), {1.1808, 0.8608, 0.6808});
}

TEST(MaloneReflection, CorrectedDirection) {
  // A mirror (k_s 1, k_d 0) at y = 0 and a sphere (colour (0.2,0.4,0.6), k_d 1)
  // of radius 0.5 at (0,3,4), ambient 1, no lights. r = i - 2 (i.d) d =
  // (0,-0.6,0.8) + 1.2 (0,1,0) = (0,0.6,0.8) passes (0,3,4): the sphere, seen in
  // the mirror, gives 1 * I_a K_d = (0.2, 0.4, 0.6). (The printed r = i + 2(i.d)d
  // would be (0,-1.8,0.8), into the mirror.)
  const Scene s = sceneOf(
      "2 0 0 1 0 100 1 1 1 1 1 0 0 1\n"
      "1 0.5 0 3 4 100 0.2 0.4 0.6 0 1 1 0 1\n"
      "103 1 1 1\n");
  TraceStats stats;
  std::string probe;
  expectRgb(traceOnce(s, kPhongRay, stats, {}, 1.0, &probe), {0.2, 0.4, 0.6});
  EXPECT_EQ(stats.reflectedRays, 1u);
  EXPECT_EQ(stats.hits, 2u);
  expectVec(probedDirection(probe, "reflected"), {0, 0.6, 0.8}, 1e-6);
  // --no reflection: the mirror alone, K_d = 0: black, no reflected ray.
  TraceSettings off;
  off.reflection = false;
  TraceStats quiet;
  expectRgb(traceOnce(s, kPhongRay, quiet, off), {0, 0, 0});
  EXPECT_EQ(quiet.reflectedRays, 0u);
}

// ---- Refraction (notes 4.5): t = eta i - (eta c + sqrt D) d_f, c = i.d_f,
// D = 1 - eta^2 (1 - c^2). A clear plane y = 0 (k_t 1, index 1.5, k_s 0, k_d 0).

const std::string kGlassPlane = "2 0 0 1 0 100 1 1 1 0 1 0 1 1.5\n";

TEST(MaloneRefraction, EnteringSnell) {
  // i = (1,-1,0)/sqrt 2 from above (i.n < 0: entering), eta = 1/1.5:
  // sin(theta_t) = sin 45 / 1.5 = 0.471405, cos = sqrt(1 - 2/9) = 0.881917.
  const Scene s = sceneOf(kGlassPlane);
  TraceStats stats;
  std::string probe, json;
  traceOnce(s, rayOf({-1, 1, 0}, {1, -1, 0}), stats, {}, 1.0, &probe, &json);
  // The same event as data: the probe's JSON (one schema for every system).
  EXPECT_THAT(json, HasSubstr("{\"leaving\":false,\"eta\":0.66666666666666663,"));
  EXPECT_EQ(stats.transmittedRays, 1u);
  EXPECT_EQ(stats.totalInternalReflections, 0u);
  EXPECT_THAT(probe, HasSubstr("transmitted (entering, eta = 0.666667)"));
  const Vec3 t = probedDirection(probe, "transmitted");
  expectVec(t, {std::sqrt(0.5) / 1.5, -std::sqrt(7.0 / 9.0), 0}, 2e-6);
  // Snell: 1 * sin(theta_i) = 1.5 * sin(theta_t).
  EXPECT_NEAR(1.0 * std::sqrt(0.5), 1.5 * t[0], 2e-6);
}

TEST(MaloneRefraction, LeavingSnell) {
  // Inside (index 1.5 carried), i = (0.5, sqrt 0.75, 0) upward (i.n > 0: leaving),
  // eta = 1.5: sin(theta_t) = 1.5 * 0.5 = 0.75, cos = sqrt(1 - 0.5625) = 0.661438.
  const Scene s = sceneOf(kGlassPlane);
  TraceStats stats;
  std::string probe;
  traceOnce(s, rayOf({-0.5, -std::sqrt(0.75), 0}, {0.5, std::sqrt(0.75), 0}), stats, {}, 1.5,
            &probe);
  EXPECT_EQ(stats.transmittedRays, 1u);
  EXPECT_THAT(probe, HasSubstr("transmitted (leaving, eta = 1.5)"));
  const Vec3 t = probedDirection(probe, "transmitted");
  expectVec(t, {0.75, std::sqrt(1 - 0.5625), 0}, 2e-6);
  EXPECT_NEAR(1.5 * 0.5, 1.0 * t[0], 2e-6);
  // Normal incidence: no bending (the printed form would have length 2 for eta 0.5).
  std::string straight;
  traceOnce(s, rayOf({0, 1, 0}, {0, -1, 0}), stats, {}, 1.0, &straight);
  expectVec(probedDirection(straight, "transmitted"), {0, -1, 0}, 1e-6);
}

TEST(MaloneRefraction, TotalInternalReflection) {
  // Inside, sin(theta_i) = 0.8: D = 1 - 2.25 (1 - 0.36) = -0.44 < 0: TIR, no
  // transmitted ray, k_s' = k_s + k_t = 1, and the reflected ray is cast.
  // A light at (8,-6,0) along r = (0.8,0.6,0) - 2 (-0.6)(0,-1,0) = (0.8,-0.6,0),
  // l = 10, I = 100: specular k_s' (r.s)^1 = 1, diffuse 0: 100 * 1 / 100 = 1.
  const Scene s = sceneOf(kGlassPlane + "101 8 -6 0 100 100 100\n");
  TraceStats stats;
  std::string probe;
  expectRgb(traceOnce(s, rayOf({-0.8, -0.6, 0}, {0.8, 0.6, 0}), stats, {}, 1.5, &probe), {1, 1, 1});
  EXPECT_EQ(stats.totalInternalReflections, 1u);
  EXPECT_EQ(stats.transmittedRays, 0u);
  EXPECT_EQ(stats.reflectedRays, 1u);
  EXPECT_THAT(probe, HasSubstr("total internal reflection: k_s' = 1"));
  expectVec(probedDirection(probe, "reflected"), {0.8, -0.6, 0}, 1e-6);
  // From outside at the same angle there is no TIR (eta < 1): k_s' stays 0.
  TraceStats outside;
  traceOnce(s, rayOf({-0.8, 0.6, 0}, {0.8, -0.6, 0}), outside);
  EXPECT_EQ(outside.totalInternalReflections, 0u);
  EXPECT_EQ(outside.transmittedRays, 1u);
  EXPECT_EQ(outside.reflectedRays, 0u);
  // --no refraction: no transmission and no TIR either.
  TraceSettings off;
  off.refraction = false;
  TraceStats quiet;
  expectRgb(traceOnce(s, rayOf({-0.8, -0.6, 0}, {0.8, 0.6, 0}), quiet, off, 1.5), {0, 0, 0});
  EXPECT_EQ(quiet.totalInternalReflections + quiet.transmittedRays + quiet.reflectedRays, 0u);
}

TEST(MaloneRefraction, TransmittedColourWeightedByKt) {
  // k_t 0.5 plane at y = 0 over a white diffuse plane at y = -1 lit by ambient
  // 1: the straight-down ray sees 0.5 * 1 * 1 = 0.5 (plus the glass's own
  // ambient term, k_d 0 here).
  const Scene s = sceneOf(
      "2 0 0 1 0 100 1 1 1 0 1 0 0.5 1.5\n"
      "2 -1 0 1 0 100 1 1 1 0 1 1 0 1\n"
      "103 1 1 1\n");
  TraceStats stats;
  expectRgb(traceOnce(s, rayOf({0, 1, 0}, {0, -1, 0}), stats), {0.5, 0.5, 0.5});
  EXPECT_EQ(stats.transmittedRays, 1u);
}

// ---- The cut-offs (notes 4.7): depth 1 primary, traced while depth <= max;
// MIN_WEIGHT = 0.01/256.

// Two parallel mirrors y = 0 and y = 1 with k_s `ks`; a vertical ray between them.
Scene mirrors(const std::string& ks) {
  const std::string surface = " 100 1 1 1 " + ks + " 1 0 0 1\n";
  return sceneOf("2 0 0 1 0" + surface + "2 1 0 1 0" + surface);
}

TEST(MaloneCutoffs, Depth) {
  EXPECT_EQ(TraceSettings{}.maxDepth, 7);
  const Scene s = mirrors("1");
  const MRay down{{0, 0.5, 0}, {0, -1, 0}, kInfinite};
  for (int maxDepth : {1, 3, 7}) {
    TraceSettings settings;
    settings.maxDepth = maxDepth;
    TraceStats stats;
    traceOnce(s, down, stats, settings);
    // Hits at depths 1..max, a reflected ray from each but the last, which is cut.
    EXPECT_EQ(stats.hits, static_cast<std::uint64_t>(maxDepth)) << maxDepth;
    EXPECT_EQ(stats.reflectedRays, static_cast<std::uint64_t>(maxDepth - 1)) << maxDepth;
    EXPECT_EQ(stats.cutByDepth, 1u) << maxDepth;
    EXPECT_EQ(stats.cutByWeight, 0u) << maxDepth;
  }
}

TEST(MaloneCutoffs, MinWeight) {
  EXPECT_EQ(TraceSettings{}.minWeight, 0.01 / 256);
  EXPECT_EQ(0.01 / 256, 3.90625e-5);
  // k_s 0.1: children of weight 0.1, 0.01, 1e-3, 1e-4 (>= 3.9e-5) are traced;
  // the next, 1e-5, is cut at depth 5 (before the depth limit 7).
  const Scene s = mirrors("0.1");
  TraceStats stats;
  traceOnce(s, MRay{{0, 0.5, 0}, {0, -1, 0}, kInfinite}, stats);
  EXPECT_EQ(stats.hits, 5u);
  EXPECT_EQ(stats.reflectedRays, 4u);
  EXPECT_EQ(stats.cutByWeight, 1u);
  EXPECT_EQ(stats.cutByDepth, 0u);
  // k_s 0.5: 0.5^14 = 6.1e-5 >= MIN_WEIGHT > 0.5^15 = 3.05e-5; with max depth
  // 20 the chain of children 0.5 .. 0.5^14 is traced (14 reflected rays), the
  // 15th cut by weight.
  TraceSettings deep;
  deep.maxDepth = 20;
  TraceStats half;
  traceOnce(mirrors("0.5"), MRay{{0, 0.5, 0}, {0, -1, 0}, kInfinite}, half, deep);
  EXPECT_EQ(half.reflectedRays, 14u);
  EXPECT_EQ(half.cutByWeight, 1u);
}

TEST(MaloneTracer, EscapedRaysAreBlack) {
  // A lit sphere, an ambient light: a ray that misses everything is black
  // (not the ambient light).
  const Scene s = sceneOf("1 1 0 0 0" + test::kSurface + "103 0.5 0.5 0.5\n101 5 5 5 1 1 1\n");
  TraceStats stats;
  expectRgb(traceOnce(s, rayOf({0, 0, 5}, {0, 0, 1}), stats), {0, 0, 0});
  EXPECT_EQ(stats.hits, 0u);
  EXPECT_EQ(stats.shadowRays, 0u);
}

TEST(MaloneTracer, EqualTKeepsTheEarlierObject) {
  // Two coincident unit spheres, red then green, lit only by ambient 1: both
  // are hit at t = 4; the earlier in the file wins (notes 2.10), with the BVH
  // and with the linear search alike.
  const std::string red = "1 1 0 0 0 100 1 0 0 0 1 1 0 1\n",
                    green = "1 1 0 0 0 100 0 1 0 0 1 1 0 1\n";
  for (bool linear : {false, true}) {
    TraceSettings settings;
    settings.linearSearch = linear;
    TraceStats stats;
    const MRay ray = rayOf({0, 0, 5}, {0, 0, -1});
    expectRgb(traceOnce(sceneOf(red + green + "103 1 1 1\n"), ray, stats, settings), {1, 0, 0});
    expectRgb(traceOnce(sceneOf(green + red + "103 1 1 1\n"), ray, stats, settings), {0, 1, 0});
  }
}

// ---- The debug renders (notes 5.2): no lights, no recursion.

TEST(MaloneDebug, DepthColourNormal) {
  SceneFile f = readSceneFile(MALONE_SCENES "/doc-scene.mal");
  f.surfaces[0].colour = {0.5, 0.25, 1};
  f.surfaces[0].kd = 0.8;
  f.surfaces[0].ks = 0.5;  // would reflect in a normal render
  const Scene s = buildScene(f, "doc");
  auto render = [&](TraceSettings::Debug mode, int X, int Y, TraceStats& stats) {
    TraceSettings settings;
    settings.debug = mode;
    return Tracer(s, settings).pixel(X, Y, stats);
  };
  TraceStats stats;
  const double r13 = std::sqrt(13.0);
  // Depth: the centre hit at t = sqrt 13: grey 1/sqrt 13 = 0.27735.
  expectRgb(render(TraceSettings::Debug::Depth, 128, 128, stats), {1 / r13, 1 / r13, 1 / r13});
  // Colour: K_d = 0.8 (0.5, 0.25, 1) = (0.4, 0.2, 0.8).
  expectRgb(render(TraceSettings::Debug::Colour, 128, 128, stats), {0.4, 0.2, 0.8});
  // Normal: |n.i| = |(0,1,0).(0,-2,-3)/sqrt 13| = 2/sqrt 13 = 0.5547.
  expectRgb(render(TraceSettings::Debug::Normal, 128, 128, stats), {2 / r13, 2 / r13, 2 / r13});
  // A miss: the top row's centre looks up (f + y = (0, 1 - 2/sqrt 13, ...)): 0.
  for (auto mode :
       {TraceSettings::Debug::Depth, TraceSettings::Debug::Colour, TraceSettings::Debug::Normal})
    expectRgb(render(mode, 128, 0, stats), {0, 0, 0});
  EXPECT_EQ(stats.shadowRays, 0u);
  EXPECT_EQ(stats.reflectedRays, 0u);
  // Depth is clamped at 1: the 8 x 8 viewer at (0,0,10) looks down -z at pixel
  // (4,4); a plane at z = 9.5 is hit at t = 0.5 (1/0.5 = 2 -> 1), one at z = 6
  // at t = 4 (0.25).
  for (auto [z, grey] : {std::pair{9.5, 1.0}, std::pair{6.0, 0.25}}) {
    const Scene p = sceneOf("2 " + std::to_string(z) + " 0 0 1" + test::kSurface);
    TraceSettings settings;
    settings.debug = TraceSettings::Debug::Depth;
    TraceStats st;
    expectRgb(Tracer(p, settings).pixel(4, 4, st), {grey, grey, grey});
  }
}

TEST(MaloneSwitches, EachTermOff) {
  // SpecularOffTheMirror's scene: ambient (0.08,0.08,0.06), diffuse
  // (0.64,0.32,0.16), specular 0.4608 each.
  const Scene s = sceneOf(kPhongPlane + "101 0 8 6 100 100 100\n");
  TraceSettings settings;
  TraceStats stats;
  settings.ambient = false;
  expectRgb(traceOnce(s, kPhongRay, stats, settings), {1.1008, 0.7808, 0.6208});
  settings = {};
  settings.diffuse = false;
  expectRgb(traceOnce(s, kPhongRay, stats, settings), {0.5408, 0.5408, 0.5208});
  settings = {};
  settings.specular = false;
  expectRgb(traceOnce(s, kPhongRay, stats, settings), {0.72, 0.4, 0.22});
  settings = {};
  settings.ambient = settings.diffuse = settings.specular = false;
  expectRgb(traceOnce(s, kPhongRay, stats, settings), {0, 0, 0});
}

}  // namespace
}  // namespace prime::malone
