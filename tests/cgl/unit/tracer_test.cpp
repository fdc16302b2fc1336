// Trace and Shade (src/cgl/tracer.h; Sweeney 1985 sections 8.3-8.5 and 9,
// Figure 41): depth, the background at the limit, shadows (opaque objects
// only, in-scene lights stopping at the light), the ambience, Lambert and
// Phong terms, reflection, refraction with 1/index on the way out, total
// internal reflection. Scenes are small enough to work out by hand.
#include "src/cgl/tracer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/cgl/unit/scene_text.h"

namespace prime::cgl {
namespace {

using test::flat;

// A floor (y = 0, x and z in -1..1; its N_E1 x N_E2 normal is +y) with
// surface 1, and optionally a sphere with surface 2; one light at infinity
// straight above, flat 100, dw 0.01; no ambience.
SceneFile floorScene(const SurfaceRecord& floor, const SurfaceRecord* ball = nullptr,
                     Vec3 centre = {0, 0.5, 0}, double radius = 0.2) {
  SceneFile f = test::emptyScene();
  f.vertices = test::floorVertices();
  f.surfaces.push_back(floor);
  if (ball) {
    f.surfaces.push_back(*ball);
    f.nodes.push_back(test::polygon(1, 2, 1, {1, 2, 3, 4}));
    f.nodes.push_back(test::sphere(2, 0, 2, centre, radius));
  } else {
    f.nodes.push_back(test::polygon(1, 0, 1, {1, 2, 3, 4}));
  }
  f.lights.push_back(test::infinityLight({0, 1, 0}, 0.01, flat(100.0)));
  f.numbers.root = 1;
  return f;
}

// From (0,1,3) to the floor's centre: D = (0,-1,-3)/sqrt(10). It passes the
// sphere at (0,0.5,0) at 0.474 from its centre (closest at s = 0.95 along
// (0,1-s,3-3s)), so it meets only the floor, at the origin.
const Ray kToFloor{{0, 1, 3}, normalized(Vec3{0, -1, -3})};

void expectFlat(const Spectrum& z, double value, double tolerance = 1e-12) {
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_NEAR(z[k], value, tolerance) << "sample " << k;
}

TEST(CglShadows, OpaqueBlocksTransparentDoesNot) {
  // Lambert floor k_d 2, D = 0.5; N = L = (0,1,0): k_d (N.L) D I dw =
  // 2 * 1 * 0.5 * 100 * 0.01 = 1.0 at every sample; shadowed: 0 (no ambience).
  const SurfaceRecord floor = test::lambert(2.0, 0.5);
  const SurfaceRecord opaque = test::lambert(1.0, 1.0);
  const Scene s = buildScene(floorScene(floor, &opaque));
  TraceSettings settings;
  settings.shadows = true;
  TraceStats stats;
  ProbeReport probe;
  expectFlat(Tracer(s, settings).trace(kToFloor, 0, RayKind::Primary, stats, &probe), 0.0);
  EXPECT_EQ(stats.rays.shadowRays, 1u);
  ASSERT_EQ(probe.rays.size(), 1u);
  ASSERT_EQ(probe.rays[0].lights.size(), 1u);
  EXPECT_EQ(probe.rays[0].lights[0].skipped, "shadowed");
  EXPECT_EQ(probe.rays[0].lights[0].shadowedBy, 1);  // the sphere, second in the list
  EXPECT_EQ(probe.rays[0].object, 0);

  settings.shadows = false;
  TraceStats off;
  expectFlat(Tracer(s, settings).trace(kToFloor, 0, RayKind::Primary, off, nullptr), 1.0);
  EXPECT_EQ(off.rays.shadowRays, 0u);

  // Section 9.3: a transparent object (k_t > 0) casts no shadow.
  const SurfaceRecord glass = test::lambert(1.0, 1.0, 0.0, 0.5, 1.5);
  const Scene g = buildScene(floorScene(floor, &glass));
  settings.shadows = true;
  TraceStats gs;
  expectFlat(Tracer(g, settings).trace(kToFloor, 0, RayKind::Primary, gs, nullptr), 1.0);
  EXPECT_EQ(gs.rays.shadowRays, 1u);
}

TEST(CglShadows, InSceneLightStopsAtTheLight) {
  const SurfaceRecord floor = test::lambert(2.0, 0.5);
  const SurfaceRecord opaque = test::lambert(1.0, 1.0);
  SceneFile f = floorScene(floor, &opaque);  // the sphere spans y 0.3..0.7 over the origin
  f.lights[0].kind = LightKind::InScene;
  TraceSettings settings;
  settings.shadows = true;
  // Above the sphere: shadowed.
  f.lights[0].xyz = {0, 2, 0};
  TraceStats a;
  expectFlat(Tracer(buildScene(f), settings).trace(kToFloor, 0, RayKind::Primary, a, nullptr), 0.0);
  // Between the floor and the sphere (y = 0.2 < 0.3): t_min = |l - I| = 0.2
  // and the sphere beyond it does not count; L = (0,1,0) again: 1.0.
  f.lights[0].xyz = {0, 0.2, 0};
  TraceStats b;
  expectFlat(Tracer(buildScene(f), settings).trace(kToFloor, 0, RayKind::Primary, b, nullptr), 1.0);
}

TEST(CglShade, AmbienceTermAndFacing) {
  // Section 9.6: k_a((N.V) + 0.5) I_a pi D with k_a 0.001, I_a flat 100,
  // D 0.5, N.V = (0,1,0).(0,1,3)/sqrt(10) = 0.316228: (0.316228 + 0.5) *
  // 0.001 pi 100 * 0.5 = 0.128213. No lights.
  SceneFile f = floorScene(test::lambert(2.0, 0.5));
  f.lights.clear();
  f.ambience.ka = 0.001;
  f.ambience.colour = flat(100.0);
  const Scene s = buildScene(f);
  TraceStats stats;
  const Tracer tracer(s, {});
  expectFlat(tracer.trace(kToFloor, 0, RayKind::Primary, stats, nullptr), 0.128213, 1e-6);
  // From below the floor the normal is turned to face the viewer: the same.
  const Ray fromBelow{{0, -1, 3}, normalized(Vec3{0, 1, -3})};
  ProbeReport probe;
  expectFlat(tracer.trace(fromBelow, 0, RayKind::Primary, stats, &probe), 0.128213, 1e-6);
  EXPECT_DOUBLE_EQ(probe.rays[0].normal[1], -1.0);
  EXPECT_EQ(stats.shadeCalls[0], 2u);  // Lambert
}

TEST(CglShade, PhongHighlightAndItsNegativeSide) {
  // Phong k_s 1, e 1, k_d 0, straight down from (0,3,0): V = N = L = (0,1,0),
  // P = 2N - L/(N.L) = (0,1,0), (P.V)^e = 1: k_s I dw = 100 * 0.01 = 1.0.
  SceneFile f = floorScene(test::phong(0.0, 1.0, 1.0, 0.5));
  const Ray down{{0, 3, 0}, {0, -1, 0}};
  TraceStats stats;
  ProbeReport probe;
  expectFlat(Tracer(buildScene(f), {}).trace(down, 0, RayKind::Primary, stats, &probe), 1.0);
  EXPECT_DOUBLE_EQ(probe.rays[0].lights[0].specular, 1.0);
  EXPECT_EQ(stats.shadeCalls[1], 1u);
  // L = (1,1,0)/sqrt2, V = (2,1,0)/sqrt5: N.L = 0.707 > 0, P = (0,2,0) -
  // (1,1,0) = (-1,1,0)/sqrt2, P.V = -1/sqrt10 < 0. With e = 2 the printed
  // formula would give (P.V)^2 = 0.1; CGL-Q51 gives no highlight.
  f.surfaces[0].exponent = 2.0;
  f.lights[0].xyz = {1, 1, 0};
  const Ray slanted{{2, 1, 0}, normalized(Vec3{-2, -1, 0})};
  expectFlat(Tracer(buildScene(f), {}).trace(slanted, 0, RayKind::Primary, stats, nullptr), 0.0);
  // A light under the surface (N.L < 0) is skipped.
  f.surfaces[0] = test::lambert(2.0, 0.5);
  f.lights[0].xyz = {0, -1, 0};
  ProbeReport under;
  expectFlat(Tracer(buildScene(f), {}).trace(down, 0, RayKind::Primary, stats, &under), 0.0);
  EXPECT_EQ(under.rays[0].lights[0].skipped, "N.L < 0");
}

TEST(CglDepth, ZeroCastsNoSecondaryRaysAndAddsTheBackground) {
  // A mirror floor (k_r 1, k_d 0) and a Lambert ball at (0,0.5,-1.5) r 0.2
  // with k_r 0.5: kToFloor hits the origin and reflects along (0,1,-3),
  // through the ball's centre (s = 0.5 on (0, s, -3s)).
  SurfaceRecord mirror = test::lambert(0.0, 0.0, 1.0);
  const SurfaceRecord ball = test::lambert(2.0, 0.5, 0.5);
  const Scene s = buildScene(floorScene(mirror, &ball, {0, 0.5, -1.5}, 0.2));
  TraceSettings settings;
  settings.background = {60, 90, 120};
  settings.depth = 0;
  const Tracer d0(s, settings);
  const Spectrum bg = d0.backgroundSpectrum();
  EXPECT_EQ(bg, rgbToSpectrum(Rgb8{60, 90, 120}, Phosphors::Electrohome));
  // Depth 0: only the primary ray; Shade adds k_r * background (Figure 41).
  TraceStats st0;
  const Spectrum z0 = d0.trace(kToFloor, 0, RayKind::Primary, st0, nullptr);
  EXPECT_EQ(st0.rays.reflectedRays, 0u);
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_DOUBLE_EQ(z0[k], bg[k]);

  // Depth 1: one reflected ray, which hits the ball at the limit: the ball's
  // colour includes 0.5 * background for its own (uncast) reflection.
  settings.depth = 1;
  const Tracer d1(s, settings);
  TraceStats st1;
  ProbeReport probe;
  const Spectrum z1 = d1.trace(kToFloor, 0, RayKind::Primary, st1, &probe);
  EXPECT_EQ(st1.rays.reflectedRays, 1u);
  ASSERT_EQ(probe.rays.size(), 2u);
  EXPECT_EQ(probe.rays[1].kind, RayKind::Reflected);
  EXPECT_EQ(probe.rays[1].level, 1);
  EXPECT_TRUE(probe.rays[1].atDepthLimit);
  EXPECT_EQ(probe.rays[1].object, 1);
  // The reflected direction is (0,1,-3)/sqrt10 (Omega + 2N, normalised).
  EXPECT_NEAR(probe.rays[1].direction[1], 1 / std::sqrt(10.0), 1e-15);
  // The same ray with the ball's k_r set to 0 loses exactly 0.5 * background.
  SceneFile plain = floorScene(mirror, &ball, {0, 0.5, -1.5}, 0.2);
  plain.surfaces[1].reflect = 0.0;
  const Scene p = buildScene(plain);
  TraceStats st2;
  const Spectrum z2 = Tracer(p, settings).trace(kToFloor, 0, RayKind::Primary, st2, nullptr);
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_NEAR(z1[k] - z2[k], 0.5 * bg[k], 1e-12);
  // The reflected ray meets the ball's underside, where N.L < 0: unlit.
  EXPECT_DOUBLE_EQ(z2[17], 0.0);
}

TEST(CglRefraction, SnellThroughWhittedsFormula) {
  const Vec3 n{0, 1, 0};
  Vec3 out{};
  // Entering (D.N < 0) at 30 degrees, index 1.5: sin = 0.5/1.5 = 1/3,
  // cos = 0.942809.
  ASSERT_TRUE(refractDirection({0.5, -std::sqrt(0.75), 0}, n, 1.5, out));
  EXPECT_NEAR(out[0], 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(out[1], -0.942809, 1e-6);
  // Leaving (D.N > 0) at 30 degrees: 1/index, so sin = 0.5 * 1.5 = 0.75,
  // cos = 0.661438 (CGL-Q45).
  ASSERT_TRUE(refractDirection({0.5, std::sqrt(0.75), 0}, n, 1.5, out));
  EXPECT_NEAR(out[0], 0.75, 1e-15);
  EXPECT_NEAR(out[1], 0.661438, 1e-6);
  // Leaving at 45 degrees: sin 45 * 1.5 = 1.06 > 1, total internal reflection.
  EXPECT_FALSE(refractDirection(normalized(Vec3{1, 1, 0}), n, 1.5, out));
  // Reflection: D = (1,-1,0)/sqrt2 off N = (0,1,0): Omega = (1,-1,0),
  // Omega + 2N = (1,1,0), normalised.
  const Vec3 r = reflectDirection(normalized(Vec3{1, -1, 0}), n);
  EXPECT_NEAR(r[0], 1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(r[1], 1 / std::sqrt(2.0), 1e-15);
}

SceneFile glassBall() {
  SceneFile f = test::emptyScene();
  f.surfaces.push_back(test::lambert(0.0, 0.0, 0.0, 1.0, 1.5));
  f.nodes.push_back(test::sphere(1, 0, 1, {0, 0, 0}, 1.0));
  f.numbers.root = 1;
  return f;
}

TEST(CglRefraction, ThroughAGlassBallAndTotalInternalReflection) {
  const Scene s = buildScene(glassBall());
  TraceSettings settings;
  settings.depth = 2;
  settings.background = {60, 90, 120};
  const Tracer tracer(s, settings);
  // Half a radius above the axis: in at 30 degrees (sin 1/3 inside), out at
  // sin = (1/3) * 1.5 = 0.5: deviation 2 (30 - 19.4712) = 21.0576 degrees,
  // the exit direction (0.933220, -0.359306, 0). Using 1.5 again on the way
  // out would give sin 0.222 and another direction.
  TraceStats stats;
  ProbeReport probe;
  const Spectrum z = tracer.trace({{-3, 0.5, 0}, {1, 0, 0}}, 0, RayKind::Primary, stats, &probe);
  EXPECT_EQ(stats.rays.transmittedRays, 2u);
  EXPECT_EQ(stats.totalInternalReflections, 0u);
  ASSERT_EQ(probe.rays.size(), 3u);
  EXPECT_NEAR(probe.rays[2].direction[0], 0.933220, 1e-6);
  EXPECT_NEAR(probe.rays[2].direction[1], -0.359306, 1e-6);
  EXPECT_FALSE(probe.rays[2].hit);
  // k_t 1 twice over the background: the background.
  const Spectrum& bg = tracer.backgroundSpectrum();
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_NEAR(z[k], bg[k], 1e-12);

  // From inside at (0,0.8,0) along +x: out through (0.6,0.8,0), cos = D.N =
  // 0.6, sin 0.8 > 1/1.5: total internal reflection, no refracted ray, the
  // background in its place.
  TraceStats tir;
  const Spectrum zt = tracer.trace({{0, 0.8, 0}, {1, 0, 0}}, 0, RayKind::Primary, tir, nullptr);
  EXPECT_EQ(tir.totalInternalReflections, 1u);
  EXPECT_EQ(tir.rays.transmittedRays, 0u);
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_DOUBLE_EQ(zt[k], bg[k]);
}

TEST(CglShade, TextureTexelIsRowFromTheTopColumnFromTheLeft) {
  // The floor (vertices 1 2 3 4: V0 = (-1,0,-1), E1 = (0,0,2), N_E1 =
  // (2,0,0)) textured: u = (z + 1)/2, v = (x + 1)/2. Straight down onto
  // (0.5, 0, -0.5): u = 0.25, v = 0.75, u_i = 128, v_i = 384 (CGL-Q50: row
  // 128 from the top, column 384 from the left). The map is red in its top
  // right quarter (rows 0-255, columns 256-511) and grey elsewhere, so rows
  // counted from the bottom would give grey.
  SurfaceRecord floor = test::lambert(2.0, 0.0);
  floor.textured = true;
  floor.texture = "quarters";
  SceneFile f = floorScene(floor);
  Frame map;
  for (int row = 0; row < Frame::kSize; ++row)
    for (int col = 0; col < Frame::kSize; ++col)
      map.words[static_cast<std::size_t>(row) * Frame::kSize + col] =
          row < 256 && col >= 256 ? packPixel(200, 0, 0) : packPixel(90, 90, 90);
  BuildOptions options;
  options.textures.emplace_back("quarters", map);
  const Scene s = buildScene(f, options);
  TraceStats stats;
  ProbeReport probe;
  const Spectrum z =
      Tracer(s, {}).trace({{0.5, 3, -0.5}, {0, -1, 0}}, 0, RayKind::Primary, stats, &probe);
  ASSERT_TRUE(probe.rays.at(0).textured);
  EXPECT_EQ(probe.rays[0].ui, 128);
  EXPECT_EQ(probe.rays[0].vi, 384);
  // Z = k_d (N.L) D I dw = 2 * 1 * D * 100 * 0.01 = 2 D, D the red texel's
  // spectrum: only its 450, 550 and 600 nm samples (indices 7, 17, 22).
  const Spectrum red = rgbToSpectrum(Rgb8{200, 0, 0}, Phosphors::Electrohome);
  for (int k = 0; k < kSpectrumSamples; ++k) {
    const bool kept = k == 7 || k == 17 || k == 22;
    EXPECT_NEAR(z[k], kept ? 2.0 * red[k] : 0.0, 1e-12) << "sample " << k;
  }
  EXPECT_NE(red[22], 0.0);
}

TEST(CglTracer, SuperBoxSkipsItsContents) {
  // A box around two spheres at x = 0 and 1 (radius 0.5), and a sphere at
  // x = 5. A ray at x = 5 misses the box: 1 box test, 0 box hits, and only
  // the third sphere tested; a ray at x = 0 enters it: all three tested.
  SceneFile f = test::emptyScene();
  f.surfaces.push_back(test::lambert(1, 1));
  f.nodes.push_back(test::node(1, NodeKind::Box, 2, 4));
  f.nodes.push_back(test::sphere(2, 3, 1, {0, 0, 0}, 0.5));
  f.nodes.push_back(test::sphere(3, 0, 1, {1, 0, 0}, 0.5));
  f.nodes.push_back(test::sphere(4, 0, 1, {5, 0, 0}, 0.5));
  f.numbers.root = 1;
  const Scene s = buildScene(f);
  TraceSettings list;
  list.linearSearch = true;  // the document's object list (the BVH has no super boxes)
  const Tracer tracer(s, list);
  TraceStats outside;
  Tracer::Hit hit;
  ASSERT_TRUE(tracer.intersect({{5, 0, 5}, {0, 0, -1}}, 1e10, hit, outside));
  EXPECT_EQ(hit.object, 3);
  EXPECT_EQ(outside.boxTests, 1u);
  EXPECT_EQ(outside.boxHits, 0u);
  EXPECT_EQ(outside.tests[0], 1u);
  TraceStats inside;
  ASSERT_TRUE(tracer.intersect({{0, 0, 5}, {0, 0, -1}}, 1e10, hit, inside));
  EXPECT_EQ(hit.object, 1);
  EXPECT_DOUBLE_EQ(hit.t, 4.5);
  EXPECT_EQ(inside.boxHits, 1u);
  EXPECT_EQ(inside.tests[0], 3u);
  EXPECT_EQ(inside.hits[0], 1u);
}

TEST(CglTracer, PrimaryMissIsTheBackgroundExactly) {
  // CGL-Q49: a primary ray that meets nothing gives the background RGB as
  // given, not ToRGB of its spectrum (which need not round-trip).
  const Scene s = buildScene(glassBall());
  TraceSettings settings;
  settings.background = {61, 92, 123};
  const Tracer tracer(s, settings);
  TraceStats stats;
  ProbeReport probe;
  const Rgb8 c = tracer.screenPoint(0, 0, stats, &probe);  // the corner: misses
  EXPECT_EQ(c, (Rgb8{61, 92, 123}));
  EXPECT_TRUE(probe.background);
  EXPECT_EQ(stats.rays.primaryRays, 1u);
  EXPECT_EQ(stats.rays.hits, 0u);
}

}  // namespace
}  // namespace prime::cgl
