// Cook-Torrance (src/cgl/cook.h; Sweeney 1985 section 9.9): D, G, the
// Fresnel row and Psi worked out by hand at three geometries, the Fresnel
// table against the Fresnel equations, the generator against the document's
// copper, its descriptor read back strictly, and a rendered Cook sphere's
// highlight where H = N.
#include "src/cgl/cook.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/cgl/colour.h"
#include "src/cgl/pov_export.h"
#include "src/cgl/render.h"
#include "tests/cgl/unit/scene_text.h"

namespace prime::cgl {
namespace {

using test::flat;
constexpr double kPi = std::numbers::pi;

double deg(double d) {
  return d * kPi / 180.0;
}

// A table whose row j is flat(j / 100), so a Psi shows the row it used.
std::vector<Spectrum> rowTable() {
  std::vector<Spectrum> t;
  for (int j = 0; j < kFresnelAngles; ++j) t.push_back(flat(j / 100.0));
  return t;
}

const Vec3 kN{0, 0, 1};

TEST(CglCook, NormalIncidence) {
  // V = L = N: H = N, N.H = V.H = N.V = N.L = 1. m = 0.3:
  // D = exp(-tan^2(0)/m^2) / (m^2 * 1^4) = 1/0.09 = 11.1111;
  // G = min{1, 2*1*1/1, 2*1*1/1} = 1; theta = arccos(1) = 0: row 0;
  // S/F = D G / (pi * 1 * 1) = 11.1111/pi = 3.536777.
  const CookTerms t = cookTerms(kN, kN, kN, 0.3);
  EXPECT_NEAR(t.d, 11.111111, 1e-6);
  EXPECT_DOUBLE_EQ(t.g, 1.0);
  EXPECT_EQ(t.fresnel, 0);
  EXPECT_NEAR(t.s, 3.536777, 1e-6);
  EXPECT_NEAR(t.specular, 3.536777, 1e-6);
  // Psi with I = 1, dw = 1, k_s = 1, k_d = 0.5, F = 0.07 (the copper's row 0
  // at 380 nm), D_lambda = 0.0223: 1*1*(1*0.07*3.536777 + 0.5*1*0.0223) =
  // 0.247574 + 0.01115 = 0.258724.
  std::vector<Spectrum> f(kFresnelAngles, flat(0.5));
  f[0] = flat(0.07);
  Spectrum z{};
  addPsi(z, flat(1.0), 1.0, t, 1.0, 0.5, flat(0.0223), f);
  EXPECT_NEAR(z[0], 0.258724, 1e-6);
  EXPECT_NEAR(z[32], 0.258724, 1e-6);
}

TEST(CglCook, MirrorAtThirtyDegrees) {
  // V and L at 30 degrees either side of N: H = N, N.H = 1, V.H = N.V = N.L
  // = cos 30 = 0.866025. D = 1/m^2 = 11.1111 (m = 0.3); G = min{1, 2, 2} = 1;
  // theta = 30 degrees: int(pi/6 * 130/pi) = int(21.67) = row 21;
  // S/F = 11.1111 / (pi * 0.75) = 4.715702; (N.L) S/F = 11.1111 / (pi *
  // 0.866025) = 4.083918.
  const Vec3 v{std::sin(deg(30)), 0, std::cos(deg(30))};
  const Vec3 l{-std::sin(deg(30)), 0, std::cos(deg(30))};
  const CookTerms t = cookTerms(kN, v, l, 0.3);
  EXPECT_NEAR(t.nh, 1.0, 1e-12);
  EXPECT_NEAR(t.d, 11.111111, 1e-6);
  EXPECT_DOUBLE_EQ(t.g, 1.0);
  EXPECT_EQ(t.fresnel, 21);
  EXPECT_NEAR(t.s, 4.715702, 1e-6);
  EXPECT_NEAR(t.specular, 4.083918, 1e-6);
  // Psi with I = 2, dw = 0.5, k_s = 1, k_d = 0.5, F = row 21 = 0.21,
  // D_lambda = 0.1: 2*0.5*(0.21*4.083918 + 0.5*0.866025*0.1) = 0.857623 +
  // 0.043301 = 0.900924.
  Spectrum z{};
  addPsi(z, flat(2.0), 0.5, t, 1.0, 0.5, flat(0.1), rowTable());
  EXPECT_NEAR(z[10], 0.900924, 1e-6);
}

TEST(CglCook, OffSpecularAtSeventyDegrees) {
  // L = N, V at 70 degrees: H halfway, 35 degrees from both. N.V = cos 70 =
  // 0.342020, N.H = V.H = cos 35 = 0.819152, N.L = 1.
  // D: tan 35 = 0.700208, (0.700208/0.3)^2 = 5.447672, exp(-5.447672) =
  // 0.0043032; m^2 (N.H)^4 = 0.09 * 0.450237 = 0.0405213; D = 0.106269.
  // G = min{1, 2*0.819152*0.342020/0.819152 = 0.684040, 2*1 = 2} = 0.684040:
  // masking of the view.
  // theta = 35 degrees: int(35/180 * 130) = int(25.28) = row 25.
  // S/F = D G / (pi (N.L)(N.V)) = 0.106269*0.684040/(pi*0.342020) = 2D/pi =
  // 0.0676527 (here G/(N.V) = 2).
  const Vec3 v{std::sin(deg(70)), 0, std::cos(deg(70))};
  const CookTerms t = cookTerms(kN, v, kN, 0.3);
  EXPECT_NEAR(t.nh, 0.819152, 1e-6);
  EXPECT_NEAR(t.vh, 0.819152, 1e-6);
  EXPECT_NEAR(t.d, 0.106269, 1e-6);
  EXPECT_NEAR(t.g, 0.684040, 1e-6);
  EXPECT_EQ(t.fresnel, 25);
  EXPECT_NEAR(t.s, 0.0676527, 1e-7);
  EXPECT_NEAR(t.specular, 0.0676527, 1e-7);
  // Psi with I = 1, dw = 1, k_s = 1, k_d = 0.2, F = row 25 = 0.25, D_lambda
  // = 0.3: 0.25*0.0676527 + 0.2*1*0.3 = 0.0169132 + 0.06 = 0.0769132.
  Spectrum z{};
  addPsi(z, flat(1.0), 1.0, t, 1.0, 0.2, flat(0.3), rowTable());
  EXPECT_NEAR(z[20], 0.0769132, 1e-7);
}

TEST(CglCook, EdgeCases) {
  // CGL-Q105: a light below the surface (N.L < 0) adds nothing.
  const Vec3 below{0.6, 0, -0.8};
  Spectrum z{};
  addPsi(z, flat(1.0), 1.0, cookTerms(kN, kN, below, 0.3), 1.0, 1.0, flat(0.5), rowTable());
  EXPECT_EQ(z[0], 0.0);
  // CGL-Q104: N.V = 0 (V in the surface) with L = N: G/(N.V) has the limit
  // 2(N.H)/(V.H); H at 45 degrees, N.H = V.H = 0.707107, D = exp(-1/0.09) /
  // (0.09 * 0.25) = 6.6654e-4, so (N.L) S/F = 2D/pi = 4.2433e-4, finite.
  const CookTerms t = cookTerms(kN, Vec3{1, 0, 0}, kN, 0.3);
  EXPECT_NEAR(t.specular, 2.0 * std::exp(-1.0 / 0.09) / (0.09 * 0.25) / kPi, 1e-12);
  EXPECT_EQ(t.s, 0.0);
  EXPECT_EQ(t.fresnel, 32);  // theta = 45 degrees: int(45/180 * 130) = int(32.5)
  // V = -L: no half-vector, no highlight.
  const CookTerms opposite = cookTerms(kN, kN, Vec3{0, 0, -1}, 0.3);
  EXPECT_EQ(opposite.specular, 0.0);
  // The index: 90 degrees is row 65, and it never leaves 0..65.
  EXPECT_EQ(fresnelIndex(0.0), 65);
  EXPECT_EQ(fresnelIndex(1.0), 0);
  EXPECT_EQ(fresnelIndex(-0.5), 65);
  // theta_j = j * 90/65 degrees falls in row j (within rounding: +1e-9).
  for (int j = 0; j < kFresnelAngles; ++j)
    EXPECT_EQ(fresnelIndex(std::cos(fresnelAngle(j) + 1e-9)), j) << j;
}

// The unpolarised reflectance from Snell's law and the s and p amplitude
// reflectances, independently of cook.cpp's form.
double fresnelBySnell(double n, double theta) {
  const double ci = std::cos(theta);
  const double st = std::sin(theta) / n;
  const double ct = std::sqrt(1.0 - st * st);
  const double rs = (ci - n * ct) / (ci + n * ct);
  const double rp = (ct - n * ci) / (ct + n * ci);
  return 0.5 * (rs * rs + rp * rp);
}

TEST(CglCookFresnel, TableReproducesTheFresnelEquations) {
  // R = 0.04: n = (1 + 0.2)/(1 - 0.2) = 1.5 (glass).
  EXPECT_NEAR(effectiveIndex(0.04), 1.5, 1e-12);
  // By hand at 45 degrees, n = 1.5: cos i = 0.707107, sin t = 0.707107/1.5 =
  // 0.471405, cos t = 0.881917. r_s = (0.707107 - 1.322876)/(0.707107 +
  // 1.322876) = -0.303337, R_s = 0.092013; r_p = (0.881917 - 1.060660)/
  // (0.881917 + 1.060660) = -0.092013, R_p = 0.0084664; F = 0.050240.
  EXPECT_NEAR(fresnelReflectance(1.5, std::cos(deg(45))), 0.050240, 1e-6);
  Spectrum r{};
  for (int k = 0; k < kSpectrumSamples; ++k) r[k] = 0.01 + 0.028 * k;  // 0.01 .. 0.906
  const std::vector<Spectrum> table = fresnelTable(r);
  ASSERT_EQ(table.size(), 66u);
  for (int k = 0; k < kSpectrumSamples; ++k) {
    // theta = 0: F = ((n-1)/(n+1))^2 = R (the normal reflectance back).
    EXPECT_NEAR(table[0][k], r[k], 1e-12) << k;
    // theta = 90 degrees: F = 1.
    EXPECT_NEAR(table[65][k], 1.0, 1e-12) << k;
    for (int j = 1; j < 65; ++j)
      EXPECT_NEAR(table[j][k], fresnelBySnell(effectiveIndex(r[k]), fresnelAngle(j)), 1e-12)
          << "row " << j << " sample " << k;
  }
  // The unpolarised mean dips before grazing for a large index (R = 0.906:
  // n = 19.4), as the p reflectance's pseudo-Brewster minimum pulls it down.
  EXPECT_LT(table[60][32], table[50][32]);
  r[5] = 1.0;
  EXPECT_THROW(fresnelTable(r), std::invalid_argument);
}

// Appendix 1 section 8's copper, as printed: the normal-colour-vector and the
// first Fresnel vector (the second is the same).
const Spectrum kCopperColour{0.0223, 0.0242, 0.0261, 0.0280, 0.0302, 0.0337, 0.0372, 0.0407, 0.0446,
                             0.0497, 0.0547, 0.0602, 0.0653, 0.0700, 0.0748, 0.0796, 0.0844, 0.0955,
                             0.1066, 0.1311, 0.1560, 0.1757, 0.1958, 0.2044, 0.2133, 0.2174, 0.2219,
                             0.2263, 0.2308, 0.2330, 0.2355, 0.2381, 0.2403};
const Spectrum kCopperFresnel0{
    0.0700, 0.0760, 0.0820, 0.0880, 0.0950, 0.1060, 0.1170, 0.1280, 0.1400, 0.1560, 0.1720,
    0.1890, 0.2050, 0.2200, 0.2350, 0.2500, 0.2650, 0.3000, 0.3350, 0.4120, 0.4900, 0.5520,
    0.6150, 0.6420, 0.6700, 0.6830, 0.6970, 0.7110, 0.7250, 0.7320, 0.7400, 0.7480, 0.7550};

TEST(CglCookFresnel, GeneratorReprintsTheDocumentsCopper) {
  // CGL-Q106: the printed normal-colour-vector is the printed first Fresnel
  // vector over pi, to 4 places, at all 33 wavelengths; the second vector
  // (theta = 90/65 = 1.385 degrees) equals the first to 4 places.
  CookDescriptor d;
  d.count = 1;
  d.reflect = 0.8;
  d.reflectance = kCopperFresnel0;
  d.name = "reflective copper";
  const std::string text = cookDescriptorText(d);
  // Read back strictly in a one-sphere scene.
  const std::string scene = "* cook descriptor round trip\n0 0 0 1 1 1 1\n" + text +
                            "* ambience\n0.0\n" + colourVectorText(flat(0.0)) +
                            "1 infinity 0 0 1 0.01\n" + colourVectorText(flat(100.0)) +
                            "1 sphere 0 0 1 0 0 0 0.5 x y\n";
  const SceneFile f = readScene(scene, "round-trip.cgl");
  ASSERT_EQ(f.surfaces.size(), 1u);
  const SurfaceRecord& s = f.surfaces[0];
  EXPECT_EQ(s.model, ShadingModel::Cook);
  EXPECT_DOUBLE_EQ(s.reflect, 0.8);
  EXPECT_DOUBLE_EQ(s.specular, 1.0);
  EXPECT_DOUBLE_EQ(s.m, 0.3);
  ASSERT_EQ(s.fresnel.size(), 66u);
  for (int k = 0; k < kSpectrumSamples; ++k) {
    EXPECT_DOUBLE_EQ(s.colour[k], kCopperColour[k]) << k;
    EXPECT_DOUBLE_EQ(s.fresnel[0][k], kCopperFresnel0[k]) << k;
    EXPECT_DOUBLE_EQ(s.fresnel[1][k], kCopperFresnel0[k]) << k;
    EXPECT_DOUBLE_EQ(s.fresnel[65][k], 1.0) << k;
  }
  const Scene built = buildScene(f);
  ASSERT_EQ(built.surfaces.size(), 1u);
  EXPECT_EQ(built.surfaces[0].fresnel.size(), 66u);
  EXPECT_DOUBLE_EQ(built.surfaces[0].m, 0.3);
}

TEST(CglCookRender, HighlightWhereHEqualsN) {
  // A Cook sphere (k_d 0, k_s 1, m 0.1, flat Fresnel 0.5) of radius 1 at the
  // origin under the default camera (eye (0, 0, 3.5)), one light at infinity
  // towards (1, 1, 1). The brightest pixel is where the sphere's normal is
  // the half-vector of V (to the eye) and L, within about a pixel's turn of
  // the normal (0.5-1 degree here; 1.5 allowed), and far from the point
  // where N = L (the diffuse peak): about 27 degrees away.
  SceneFile f = test::emptyScene();
  SurfaceRecord s;
  s.model = ShadingModel::Cook;
  s.specular = 1.0;
  s.m = 0.1;
  s.colour = flat(0.0);
  s.fresnel.assign(kFresnelAngles, flat(0.5));
  s.where = test::at(100);
  f.surfaces.push_back(s);
  f.nodes.push_back(test::sphere(1, 0, 1, {0, 0, 0}, 1.0));
  f.lights.push_back(test::infinityLight({1, 1, 1}, 0.01, flat(100.0)));
  f.numbers.root = 1;
  const Scene scene = buildScene(f);
  // Every pixel corner's colour-vector, unclipped (the picture saturates).
  RenderSettings rs;
  rs.program.aalevel = 0;
  const Tracer tracer(scene, traceSettings(rs));
  TraceStats stats;
  int bestX = -1, bestY = -1;
  double best = -1;
  for (int y = 0; y < 512; ++y)
    for (int x = 0; x < 512; ++x) {
      const Spectrum z =
          tracer.trace(scene.camera.primaryRay(x, y), 0, RayKind::Primary, stats, nullptr);
      double sum = 0;
      for (double c : z) sum += c;
      if (sum > best) {
        best = sum;
        bestX = x;
        bestY = y;
      }
    }
  ASSERT_GT(best, 0.0);
  const ProbeReport pr = probe(scene, rs, bestX, bestY);
  ASSERT_TRUE(pr.rays[0].hit);
  const Vec3 n = pr.rays[0].normal;
  const Vec3 v = -pr.rays[0].direction;
  const Vec3 l = normalized(Vec3{1, 1, 1});
  const Vec3 h = normalized(v + l);
  EXPECT_GT(dot(n, h), std::cos(deg(1.5)));
  EXPECT_LT(dot(n, l), std::cos(deg(20)));
  ASSERT_EQ(pr.rays[0].lights.size(), 1u);
  EXPECT_TRUE(pr.rays[0].lights[0].cook);
  EXPECT_EQ(stats.shadeCalls[2], stats.rays.hits);  // every hit shaded by Cook
}

TEST(CglCookTrace, TheReflectedRayIsALight) {
  // A Cook floor (y = 0, N = +y; k_r 0.8, k_s 1, k_d 0, m 0.5, row j's F =
  // j/100) seen from (0, 1, 3) at its centre; the light straight above is
  // shadowed by an opaque ball at (0, 0.5, 0), which the reflected ray
  // misses (it passes 0.47 from the ball's centre); the background is white,
  // the ambience 0. So Z = Psi(R, D_reflect, k_r) with R = the background's
  // colour-vector: V = (0, 1, 3)/sqrt 10, N.V = 0.316228 = N.L, H = N, D =
  // 1/m^2 = 4, G = 1, theta = arccos(0.316228) = 71.565 degrees: row
  // int(71.565/180 * 130) = int(51.69) = 51, F = 0.51; Psi = R * 0.8 * 1 *
  // 0.51 * 4 / (pi * 0.316228) = R * 1.642747. The same at the depth limit
  // (depth 0: R is the background from the same direction, CGL-Q107).
  SceneFile f = test::emptyScene();
  f.vertices = test::floorVertices();
  SurfaceRecord floor;
  floor.model = ShadingModel::Cook;
  floor.reflect = 0.8;
  floor.specular = 1.0;
  floor.m = 0.5;
  floor.colour = flat(0.2);
  floor.fresnel = rowTable();
  floor.where = test::at(100);
  f.surfaces.push_back(floor);
  f.surfaces.push_back(test::lambert(1.0, 1.0));
  f.nodes.push_back(test::polygon(1, 2, 1, {1, 2, 3, 4}));
  f.nodes.push_back(test::sphere(2, 0, 2, {0, 0.5, 0}, 0.2));
  f.lights.push_back(test::infinityLight({0, 1, 0}, 0.01, flat(100.0)));
  f.numbers.root = 1;
  const Scene scene = buildScene(f);
  const Ray toFloor{{0, 1, 3}, normalized(Vec3{0, -1, -3})};
  for (int depth : {1, 0}) {
    TraceSettings settings;
    settings.depth = depth;
    settings.shadows = true;
    settings.background = {255, 255, 255};
    const Tracer tracer(scene, settings);
    TraceStats stats;
    ProbeReport probe;
    const Spectrum z = tracer.trace(toFloor, 0, RayKind::Primary, stats, &probe);
    const Spectrum& b = tracer.backgroundSpectrum();
    ASSERT_GT(b[17], 0.0);
    for (int k = 0; k < kSpectrumSamples; ++k)
      EXPECT_NEAR(z[k], b[k] * 1.642747, 1e-5 * std::abs(b[k]) + 1e-12) << depth << " " << k;
    ASSERT_EQ(probe.rays[0].lights.size(), 2u);
    EXPECT_EQ(probe.rays[0].lights[0].light, ProbeLight::kReflectedLight);
    EXPECT_EQ(probe.rays[0].lights[0].fresnel, 51);
    EXPECT_EQ(probe.rays[0].lights[1].skipped, "shadowed");
    EXPECT_EQ(stats.rays.reflectedRays, depth == 1 ? 1u : 0u);
  }
}

TEST(CglCookTrace, TheTransmittedRayIsALight) {
  // The floor of the test above with k_r 0, k_t 0.5, index 1.5, k_d 0.5,
  // D 0.2: the transmitted ray leaves downwards and meets nothing, so T is
  // the background; the light is shadowed. By Snell: sin i = 3/sqrt 10 =
  // 0.948683, sin t = 0.632456, cos t = 0.774597; L = -D_refract = (0,
  // 0.774597, 0.632456), N.L = 0.774597. H = normalise(V + L) = (0, 0.567868,
  // 0.823129): N.H = 0.567868, V.H = 0.960455 (16.19 degrees: row int(11.69)
  // = 11, F = 0.11). G = min{1, 2*0.567868*0.316228/0.960455 = 0.373939,
  // 2*0.567868*0.774597/0.960455 = 0.915955} = 0.373939. D = exp(-(1 -
  // 0.322474)/0.322474/0.25) / (0.25 * 0.103990) = 8.6144e-3. Psi = T * 0.5 *
  // (1 * 0.11 * 8.6144e-3 * 0.373939/(pi * 0.316228) + 0.5 * 0.774597 * 0.2)
  // = T * 0.5 * (3.5667e-4 + 0.0774597) = T * 0.0389082.
  SceneFile f = test::emptyScene();
  f.vertices = test::floorVertices();
  SurfaceRecord floor;
  floor.model = ShadingModel::Cook;
  floor.refract = 0.5;
  floor.index = 1.5;
  floor.diffuse = 0.5;
  floor.specular = 1.0;
  floor.m = 0.5;
  floor.colour = flat(0.2);
  floor.fresnel = rowTable();
  floor.where = test::at(100);
  f.surfaces.push_back(floor);
  f.surfaces.push_back(test::lambert(1.0, 1.0));
  f.nodes.push_back(test::polygon(1, 2, 1, {1, 2, 3, 4}));
  f.nodes.push_back(test::sphere(2, 0, 2, {0, 0.5, 0}, 0.2));
  f.lights.push_back(test::infinityLight({0, 1, 0}, 0.01, flat(100.0)));
  f.numbers.root = 1;
  const Scene scene = buildScene(f);
  TraceSettings settings;
  settings.depth = 1;
  settings.shadows = true;
  settings.background = {255, 255, 255};
  const Tracer tracer(scene, settings);
  TraceStats stats;
  ProbeReport probe;
  const Spectrum z =
      tracer.trace({{0, 1, 3}, normalized(Vec3{0, -1, -3})}, 0, RayKind::Primary, stats, &probe);
  const Spectrum& b = tracer.backgroundSpectrum();
  for (int k = 0; k < kSpectrumSamples; ++k)
    EXPECT_NEAR(z[k], b[k] * 0.0389082, 1e-5 * std::abs(b[k]) + 1e-12) << k;
  ASSERT_EQ(probe.rays[0].lights.size(), 2u);
  EXPECT_EQ(probe.rays[0].lights[0].light, ProbeLight::kTransmittedLight);
  EXPECT_NEAR(probe.rays[0].lights[0].nl, 0.774597, 1e-6);
  EXPECT_EQ(probe.rays[0].lights[0].fresnel, 11);
  EXPECT_EQ(stats.rays.transmittedRays, 1u);
}

TEST(CglCookPov, MetallicHighlightAndColouredReflection) {
  // CGL-D101: m = 0.3 gives specular k_s/m^2 = 1/0.09 = 11.1111 and
  // roughness m^2/(2 - 4m^2) = 0.09/1.64 = 0.0548780; reflect 0.8 with F_0 =
  // 0.5 everywhere and k_d 0: the weight 0.8 * 0.5/(pi * 0.09) = 1.414711 at
  // every wavelength, which under any light is that grey: rgb 1.414711 each.
  SceneFile f = test::emptyScene();
  SurfaceRecord s;
  s.model = ShadingModel::Cook;
  s.reflect = 0.8;
  s.specular = 1.0;
  s.m = 0.3;
  s.colour = flat(0.5 / kPi);
  s.fresnel.assign(kFresnelAngles, flat(0.5));
  s.where = test::at(100);
  f.surfaces.push_back(s);
  f.nodes.push_back(test::sphere(1, 0, 1, {0, 0, 0}, 1.0));
  f.lights.push_back(test::infinityLight({1, 1, 1}, 0.01, test::d6500()));
  f.numbers.root = 1;
  const Scene scene = buildScene(f);
  const PovExportOptions options;
  const std::string pov = exportPov(scene, options).pov;
  EXPECT_NE(pov.find("specular 11.1111"), std::string::npos) << pov;
  EXPECT_NE(pov.find("roughness 0.054878"), std::string::npos) << pov;
  EXPECT_NE(pov.find("metallic"), std::string::npos) << pov;
  EXPECT_NE(pov.find("reflection { rgb <1.41471"), std::string::npos) << pov;
}

}  // namespace
}  // namespace prime::cgl
