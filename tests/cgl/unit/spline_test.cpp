// The CGL B-spline surfaces (src/cgl/spline.h; Sweeney 1985 section 6): the
// basis, the extended graph, Oslo refinement against Table 2, the counts of
// Table 3, hand-worked surface points, Newton against an independent dense
// search in long double, false hits and holes.
#include "src/cgl/spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "legacy_io/cgl/scene_file.h"
#include "src/cgl/scene.h"
#include "tests/cgl/unit/scene_text.h"

namespace prime::cgl {
namespace {

// A 4 x 4 graph x = i, z = j on the plane y = height(i, j).
std::vector<Vec3> grid(int nu, int nv, double (*height)(int, int)) {
  std::vector<Vec3> c;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) c.push_back({double(i), height(i, j), double(j)});
  return c;
}
double zero(int, int) {
  return 0.0;
}
double squares(int i, int j) {
  return double(i * i + j * j);
}
double bumpHeight(int i, int j) {
  return (i == 1 || i == 2) && (j == 1 || j == 2) ? 1.2 : 0.0;
}

TEST(CglSplineBasis, SegmentsSumToOneAndMatchSection61) {
  double w[4], dw[4];
  // u = 0: b_3 = 1/6, b_2 = 4/6, b_1 = 1/6, b_0 = 0.
  bsplineWeights(0.0, w, dw);
  EXPECT_DOUBLE_EQ(w[0], 1.0 / 6);
  EXPECT_DOUBLE_EQ(w[1], 4.0 / 6);
  EXPECT_DOUBLE_EQ(w[2], 1.0 / 6);
  EXPECT_DOUBLE_EQ(w[3], 0.0);
  // u = 1/2: 1/48, 23/48, 23/48, 1/48; derivatives -1/8, -5/8, 5/8, 1/8.
  bsplineWeights(0.5, w, dw);
  EXPECT_DOUBLE_EQ(w[0], 1.0 / 48);
  EXPECT_DOUBLE_EQ(w[1], 23.0 / 48);
  EXPECT_DOUBLE_EQ(w[3], 1.0 / 48);
  EXPECT_DOUBLE_EQ(dw[0], -1.0 / 8);
  EXPECT_DOUBLE_EQ(dw[1], -5.0 / 8);
  EXPECT_DOUBLE_EQ(dw[2], 5.0 / 8);
  for (double u : {0.1, 0.37, 0.9}) {
    bsplineWeights(u, w, dw);
    EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-15);  // property (C)
    EXPECT_NEAR(dw[0] + dw[1] + dw[2] + dw[3], 0.0, 1e-15);
  }
}

TEST(CglSplineGraph, TripledAndWrappedExtensions) {
  // Open: U_{-4} = U_{-3} = U_{-2} = the first vertex, likewise at the end.
  EXPECT_EQ(extendedIndices(4, EndCondition::Triple), (std::vector<int>{0, 0, 0, 1, 2, 3, 3, 3}));
  // Closed, the donut's period 5: U_{-4} = U_1, ..., U_{-1} = U_4, U_0 = U_5.
  EXPECT_EQ(extendedIndices(5, EndCondition::Closed),
            (std::vector<int>{1, 2, 3, 4, 0, 1, 2, 3, 4}));
}

TEST(CglSplineRefinement, OsloAlphasAreTable2) {
  // Table 2 as reconstructed: divisions 2, m = 2, p = 6; rows i, columns r.
  ASSERT_EQ(refinedLast(2, 2), 6);
  const std::vector<double> a = osloAlphas(2, 2);
  auto alpha = [&](int i, int r) { return a[static_cast<std::size_t>((r + 4) * 7 + (i + 4))]; };
  const double table[7][11] = {
      {1, 1.0 / 6, 0, 0, 0, 0, 0, 0, 0, 0, 0},
      {0, 5.0 / 6, 0.5, 1.0 / 8, 0, 0, 0, 0, 0, 0, 0},
      {0, 0, 0.5, 0.75, 0.5, 1.0 / 8, 0, 0, 0, 0, 0},
      {0, 0, 0, 1.0 / 8, 0.5, 0.75, 0.5, 1.0 / 8, 0, 0, 0},
      {0, 0, 0, 0, 0, 1.0 / 8, 0.5, 0.75, 0.5, 0, 0},
      {0, 0, 0, 0, 0, 0, 0, 1.0 / 8, 0.5, 5.0 / 6, 0},
      {0, 0, 0, 0, 0, 0, 0, 0, 0, 1.0 / 6, 1},
  };
  for (int i = -4; i <= 2; ++i)
    for (int r = -4; r <= 6; ++r)
      EXPECT_NEAR(alpha(i, r), table[i + 4][r + 4], 1e-15) << "i " << i << " r " << r;
}

TEST(CglSplineRefinement, RefinedCountsAreTable3s) {
  // The inference (extend by 4, m = nu - 1): (nu + 1) divisions + 3 per
  // direction: bump 43^2 = 1849, donut 99^2 = 9801, mask 87^2 = 7569.
  std::vector<Vec3> bump = grid(4, 4, zero), donut = grid(5, 5, zero), mask = grid(41, 41, zero);
  const SplineSurface b =
      buildSpline(bump, 4, 4, EndCondition::Triple, EndCondition::Triple, 8, 0.5);
  const SplineSurface d =
      buildSpline(donut, 5, 5, EndCondition::Closed, EndCondition::Closed, 16, 0.75);
  const SplineSurface m =
      buildSpline(mask, 41, 41, EndCondition::Triple, EndCondition::Triple, 2, 0.55);
  EXPECT_EQ(b.mu * b.mv, 64);
  EXPECT_EQ(d.mu * d.mv, 81);
  EXPECT_EQ(m.mu * m.mv, 2025);
  EXPECT_EQ(b.pu * b.pv, 1849);
  EXPECT_EQ(d.pu * d.pv, 9801);
  EXPECT_EQ(m.pu * m.pv, 7569);
  // One leaf per refined knot pair in the parameter range (CGL-Q145): the
  // triple bump's range [-1, 4] holds 5 * 8 + 1 = 41 knots per direction.
  EXPECT_EQ(b.leaves, 41 * 41);
  EXPECT_EQ(d.leaves, (5 * 16 + 1) * (5 * 16 + 1));
}

TEST(CglSplineRefinement, TriplingIsKeptAndTheSurfaceIsUnchanged) {
  std::vector<Vec3> c = grid(4, 4, bumpHeight);
  const SplineSurface s = buildSpline(c, 4, 4, EndCondition::Triple, EndCondition::Triple, 2, 0.5);
  auto w = [&](int r, int t) { return s.w[static_cast<std::size_t>((r + 4) + (t + 4) * s.pu)]; };
  auto u = [&](int i, int j) { return s.u[static_cast<std::size_t>((i + 4) + (j + 4) * s.mu)]; };
  // Section 6.4: W_{-4} = W_{-3} = W_{-2} = U_{-4}, W_{-1} = U_{-3}/8 + 3U_{-2}/4 + U_{-1}/8.
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(w(-3, 0)[k], w(-4, 0)[k]);
    EXPECT_DOUBLE_EQ(w(-2, 0)[k], w(-4, 0)[k]);
  }
  const Vec3 expect = (u(-3, 2) * 0.125 + u(-2, 2) * 0.75 + u(-1, 2) * 0.125);
  // (column t = 2 of the refined graph is a combination of columns j; check x.)
  EXPECT_NEAR(w(-1, 2)[0], expect[0], 1e-12);
  // The refined graph describes the same surface: at an interior refined
  // knot (uniform spacing h = 1/2) Q(w_{r+2}, t_{s+2}) is the (1, 4, 1)/6
  // tensor average of W around W_{r,s}.
  for (int r = 0; r <= 3; ++r)
    for (int t = 0; t <= 3; ++t) {
      Vec3 avg{0, 0, 0};
      const double k[3] = {1.0 / 6, 4.0 / 6, 1.0 / 6};
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) avg = avg + w(r - 1 + a, t - 1 + b) * (k[a] * k[b]);
      const SplinePoint q = evaluate(s, refinedKnot(r + 2, s.m, 2), refinedKnot(t + 2, s.n, 2));
      for (int c3 = 0; c3 < 3; ++c3) EXPECT_NEAR(q.q[c3], avg[c3], 1e-12) << r << " " << t;
    }
}

TEST(CglSplineSurface, FlatAndQuadraticPatchesByHand) {
  // Single ends: the range [1, m - 1] = [1, 2] is the one segment of the
  // user's 4 x 4 vertices. Linear precision: x = 1 + u, so Q(1.5, 1.5) =
  // (1.5, 0, 1.5) on the flat patch, normal +-y.
  const SplineSurface flat =
      buildSpline(grid(4, 4, zero), 4, 4, EndCondition::Single, EndCondition::Single, 2, 0.5);
  EXPECT_DOUBLE_EQ(flat.umin, 1.0);
  EXPECT_DOUBLE_EQ(flat.umax, 2.0);
  const SplinePoint p = evaluate(flat, 1.5, 1.5);
  EXPECT_NEAR(p.q[0], 1.5, 1e-15);
  EXPECT_NEAR(p.q[1], 0.0, 1e-15);
  EXPECT_NEAR(p.q[2], 1.5, 1e-15);
  EXPECT_NEAR(std::fabs(splineNormal(flat, 1.5, 1.5)[1]), 1.0, 1e-15);
  // y = i^2 + j^2: with weights (1, 23, 23, 1)/48 at u = 1/2, sum i^2 w =
  // (0 + 23 + 92 + 9)/48 = 124/48 = 1.5^2 + 1/3, so Q_y(1.5, 1.5) = 4.5 + 2/3.
  const SplinePoint q = evaluate(
      buildSpline(grid(4, 4, squares), 4, 4, EndCondition::Single, EndCondition::Single, 2, 0.5),
      1.5, 1.5);
  EXPECT_NEAR(q.q[1], 4.5 + 2.0 / 3.0, 1e-14);
  // dy/du = 2x = 3 there.
  EXPECT_NEAR(q.qu[1], 3.0, 1e-14);
}

TEST(CglSplineSurface, TripleInterpolatesCornersDoubleAndClosedAsSection64) {
  std::vector<Vec3> c = grid(4, 4, bumpHeight);
  const SplineSurface t = buildSpline(c, 4, 4, EndCondition::Triple, EndCondition::Triple, 2, 0.5);
  const SplinePoint corner = evaluate(t, t.umin, t.vmin);
  EXPECT_NEAR(corner.q[0], 0.0, 1e-15);
  EXPECT_NEAR(corner.q[2], 0.0, 1e-15);
  // Double: at u = 0 the edge is (U_{-3} + 4U_{-2} + U_{-1})/6 = (5 P_0 + P_1)/6 in x: 1/6.
  const SplineSurface d = buildSpline(c, 4, 4, EndCondition::Double, EndCondition::Double, 2, 0.5);
  EXPECT_NEAR(evaluate(d, d.umin, 1.0).q[0], 1.0 / 6, 1e-15);
  // Closed: the surface closes on itself with matching tangents.
  std::vector<Vec3> ring;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i) {
      const double a = 2 * M_PI * i / 5;
      ring.push_back({std::cos(a), double(j), std::sin(a)});
    }
  const SplineSurface cl =
      buildSpline(ring, 5, 3, EndCondition::Closed, EndCondition::Triple, 2, 0.5);
  EXPECT_DOUBLE_EQ(cl.umin, -1.0);
  EXPECT_DOUBLE_EQ(cl.umax, 4.0);  // five segments, each once (CGL-Q141)
  const SplinePoint a = evaluate(cl, cl.umin, 0.3), b = evaluate(cl, cl.umax, 0.3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(a.q[k], b.q[k], 1e-14);
    EXPECT_NEAR(a.qu[k], b.qu[k], 1e-14);
  }
}

// The bump of Figures 28-30, seen from above and to the side.
SplineSurface bump(double overlap) {
  return buildSpline(grid(4, 4, bumpHeight), 4, 4, EndCondition::Triple, EndCondition::Triple, 8,
                     overlap);
}

// An independent hit: the smallest distance from Q to the ray over a dense
// (u, v) grid in long double, then the nearest t among points within `tol`.
bool denseHit(const SplineSurface& s, const Ray& ray, long double& tHit) {
  const int n = 600;
  bool found = false;
  long double best = 1e30L;
  long double o[3] = {ray.o[0], ray.o[1], ray.o[2]}, d[3] = {ray.d[0], ray.d[1], ray.d[2]};
  for (int b = 0; b <= n; ++b)
    for (int a = 0; a <= n; ++a) {
      const long double u = s.umin + (s.umax - s.umin) * a / (long double)n;
      const long double v = s.vmin + (s.vmax - s.vmin) * b / (long double)n;
      long double q[3];
      evaluateLong(s, u, v, q);
      long double t = 0;
      for (int k = 0; k < 3; ++k) t += (q[k] - o[k]) * d[k];
      long double dist2 = 0;
      for (int k = 0; k < 3; ++k) {
        const long double e = q[k] - o[k] - t * d[k];
        dist2 += e * e;
      }
      // The grid spacing is ~ 5/600 in u: points within 0.01 of the ray.
      if (dist2 < 1e-4L && t > 0 && t < best) {
        best = t;
        found = true;
      }
    }
  tHit = best;
  return found;
}

TEST(CglSplineNewton, ConvergesOnTheDenseReferencesHit) {
  const SplineSurface s = bump(0.5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> xz(0.3, 2.7);
  int hits = 0;
  for (int k = 0; k < 12; ++k) {
    const Vec3 target{xz(rng), 0.5, xz(rng)};
    const Vec3 eye{1.5, 5.0, 6.0};
    const Ray ray{eye, normalized(target - eye)};
    long double tRef = 0;
    const bool ref = denseHit(s, ray, tRef);
    SplineHit h;
    SplineCounters c;
    const bool got = intersectSpline(s, ray, 1e-6, 1e10, h, c);
    ASSERT_EQ(got, ref) << k;
    if (!got) continue;
    ++hits;
    // The dense grid finds the hit to within its spacing (~0.01 along the ray).
    EXPECT_NEAR(h.t, static_cast<double>(tRef), 0.05) << k;
    // Newton's point is on the ray to the tolerance (1e-9 of the size).
    const Vec3 p = evaluate(s, h.u, h.v).q, on = ray.o + ray.d * h.t;
    EXPECT_LT(length(p - on), 1e-8) << k;
    EXPECT_GE(h.iterations, 1);
  }
  EXPECT_GE(hits, 10);
}

TEST(CglSplineNewton, DocumentPlanesDegenerateThePortsDoNot) {
  // CGL-Q142: N_1 = O x D vanishes for an eye at the origin (and E_k scale
  // with |O|), so every ray from there fails; the port's planes do not.
  std::vector<Vec3> c = grid(4, 4, bumpHeight);
  for (Vec3& v : c) v = v + Vec3{-1.5, -3.0, -1.5};  // below the origin
  const SplineSurface s = buildSpline(c, 4, 4, EndCondition::Triple, EndCondition::Triple, 8, 0.5);
  const Ray ray{{0, 0, 0}, normalized(Vec3{0.1, -1.0, 0.05})};
  NewtonOptions o;
  o.tolerance = 1.0;  // the document's
  const NewtonResult doc = newton(s, documentRayPlanes(ray), ray, 1.5, 1.5, o);
  EXPECT_FALSE(doc.hit);
  o.tolerance = s.tolerance;
  const NewtonResult port = newton(s, rayPlanes(ray), ray, 1.5, 1.5, o);
  ASSERT_TRUE(port.hit);
  const Vec3 p = evaluate(s, port.u, port.v).q;
  EXPECT_LT(length(p - ray.d * port.t), 1e-8);
  // From an eye off the origin the document's tolerance 1.0 in unnormalised
  // units accepts points far from the ray: |E_1| + |E_2| < 1 with |N_1| ~ 1.5.
  const Ray off{{2.0, 0.0, 0.0}, normalized(Vec3{-0.5, -1.0, 0.05})};
  const NewtonResult loose = newton(s, documentRayPlanes(off), off, 1.5, 1.5, {1.0, 16});
  const NewtonResult tight = newton(s, rayPlanes(off), off, 1.5, 1.5, {s.tolerance, 16});
  ASSERT_TRUE(loose.hit);
  ASSERT_TRUE(tight.hit);
  EXPECT_GT(std::fabs(loose.t - tight.t), 1e-4);  // the document's stops early
}

TEST(CglSplineIntersect, NoFalseHitInAMillionRandomRays) {
  const SplineSurface s = bump(0.5);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> in(-1.0, 4.0), dir(-1.0, 1.0);
  SplineCounters c;
  int hits = 0;
  for (int k = 0; k < 1000000; ++k) {
    const Vec3 o{in(rng), 1.0 + 3.0 * (in(rng) + 1.0) / 5.0, in(rng)};
    Vec3 d{dir(rng), dir(rng), dir(rng)};
    if (length(d) < 1e-3) continue;
    d = normalized(d);
    SplineHit h;
    if (!intersectSpline(s, {o, d}, 1e-6, 1e10, h, c)) continue;
    ++hits;
    // Every hit is a point of the surface, in range, on the ray, ahead.
    ASSERT_TRUE(h.u >= s.umin && h.u <= s.umax && h.v >= s.vmin && h.v <= s.vmax) << k;
    ASSERT_GT(h.t, 1e-6);
    const Vec3 p = evaluate(s, h.u, h.v).q;
    ASSERT_LT(length(p - (o + d * h.t)), 1e-8) << k;
  }
  EXPECT_GT(hits, 50000);  // 65,023 with this seed
}

// The control vertices of a vase of spline-vases.cgl (8 around, 6 up).
std::vector<Vec3> vaseControls() {
  std::vector<Vec3> c;
  const double profile[6][2] = {{0, 0.16},    {0.12, 0.30}, {0.32, 0.34},
                                {0.55, 0.16}, {0.72, 0.10}, {0.85, 0.17}};
  for (const auto& ring : profile)
    for (int i = 0; i < 8; ++i) {
      const double a = 2 * M_PI * (i + 0.5) / 8;
      c.push_back({ring[1] * std::cos(a), ring[0], ring[1] * std::sin(a)});
    }
  return c;
}

TEST(CglSplineHoles, GenerousOverlapHasNoneFigure55sHas) {
  // Primary-like rays over the bump from above: with overlap 1.0 the Newton
  // path finds every hit the reference finds; the vases' 0.2 misses some.
  auto holes = [](const SplineSurface& s, const Vec3& eye, const Vec3& at, double span) {
    HoleCount count;
    for (int y = 0; y < 60; ++y)
      for (int x = 0; x < 60; ++x) {
        const Vec3 target = at + Vec3{span * (x / 59.0 - 0.5), span * (y / 59.0 - 0.5), 0.0};
        countHoles(s, {eye, normalized(target - eye)}, 1e-6, count);
      }
    return count;
  };
  const HoleCount generous = holes(bump(1.0), {1.5, 5.0, 6.0}, {1.5, 0.0, 1.5}, 4.0);
  EXPECT_GT(generous.referenceHits, 1000u);
  EXPECT_EQ(generous.holes, 0u);
  EXPECT_EQ(generous.extra, 0u);
  // A vase of spline-vases.cgl at overlap 0.2.
  const SplineSurface vase =
      buildSpline(vaseControls(), 8, 6, EndCondition::Closed, EndCondition::Double, 2, 0.2);
  const HoleCount v = holes(vase, {0.0, 0.5, 3.2}, {0.0, 0.45, 0.0}, 0.8);
  EXPECT_GT(v.referenceHits, 1000u);
  EXPECT_GT(v.holes, v.referenceHits / 10);
}

// CGL-D180: the modern intersector (--profile modern) against the dense
// reference and the document's walk, on a vase at Figure 55's overlap 0.2
// (where the document's walk misses more than a tenth) and at 1.0: every
// hit is a point of the surface, none lies beyond the reference's hit (to
// Newton's tolerance: two runs may stop at two points of one piece of
// surface within it), it has no more holes than the document's walk, and at
// 0.2 under a twentieth of them; a shadow segment just past each hit is
// blocked.
TEST(CglSplineModern, FewerHolesThanTheDocumentsWalkAndEveryHitOnTheSurface) {
  const std::vector<Vec3> c = vaseControls();
  for (const double overlap : {0.2, 1.0}) {
    SplineSurface vase =
        buildSpline(c, 8, 6, EndCondition::Closed, EndCondition::Double, 2, overlap);
    HoleCount document;
    const Vec3 eye{0.0, 0.5, 3.2}, at{0.0, 0.45, 0.0};
    std::vector<Ray> rays;
    for (int y = 0; y < 60; ++y)
      for (int x = 0; x < 60; ++x) {
        const Vec3 target = at + Vec3{0.8 * (x / 59.0 - 0.5), 0.8 * (y / 59.0 - 0.5), 0.0};
        rays.push_back({eye, normalized(target - eye)});
        countHoles(vase, rays.back(), 1e-6, document);
      }
    buildModernCells(vase);
    ASSERT_FALSE(vase.cells.empty());
    HoleCount modern;
    for (const Ray& ray : rays) {
      countHoles(vase, ray, 1e-6, modern);  // the modern path now: the surface has cells
      SplineHit ref, hit;
      SplineCounters counters;
      const bool r = intersectSplineReference(vase, ray, 1e-6, 1e100, ref);
      const bool m = intersectSplineModern(vase, BoxRay(ray), 1e-6, 1e100, hit, counters);
      if (!m) continue;
      if (r) {
        EXPECT_LE(hit.t, ref.t + 10 * vase.tolerance);
      }
      const SplinePoint p = evaluate(vase, hit.u, hit.v);
      EXPECT_LT(length(p.q - (ray.o + ray.d * hit.t)), 1e-6);
      SplineCounters sc;
      EXPECT_TRUE(occludesSplineModern(vase, BoxRay(ray), 1e-6, hit.t * 1.001, sc));
    }
    EXPECT_EQ(modern.referenceHits, document.referenceHits);
    EXPECT_GT(modern.referenceHits, 1000u);
    EXPECT_EQ(modern.farther, 0u);
    EXPECT_LE(modern.holes, document.holes) << overlap;
    if (overlap == 0.2) {
      EXPECT_GT(document.holes, document.referenceHits / 10);
      EXPECT_LT(modern.holes * 20, document.holes) << modern.holes << " of " << document.holes;
    }
  }
}

// CGL-D180's cells: over each knot cell the surface is the bicubic Bezier
// patch of the cell's 16 points (sampled and converted), at the ends of a
// triple-ended bump (where the refined knots change spacing) and around a
// closed vase alike: the patch and the surface agree at points between the
// samples, and every surface point lies in the points' box.
TEST(CglSplineModern, CellsAreTheSurfacesBezierPatches) {
  auto bernstein = [](double t, int k) {
    const double s = 1 - t;
    const double b[4] = {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
    return b[k];
  };
  for (SplineSurface surface : {bump(0.5), buildSpline(vaseControls(), 8, 6, EndCondition::Closed,
                                                       EndCondition::Double, 2, 0.5)}) {
    buildModernCells(surface);
    ASSERT_GT(surface.cells.size(), 10u);
    double worst = 0;
    for (const SplineCell& c : surface.cells) {
      Aabb box;
      for (const Vec3& p : c.bezier) box.add(p);
      for (const double a : {0.1, 0.45, 0.8})
        for (const double b : {0.05, 0.5, 0.95}) {
          const Vec3 q = evaluate(surface, c.u0 + (c.u1 - c.u0) * a, c.v0 + (c.v1 - c.v0) * b).q;
          Vec3 patch{0, 0, 0};
          for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
              patch = patch + c.bezier[static_cast<std::size_t>(j * 4 + i)] *
                                  (bernstein(a, i) * bernstein(b, j));
          worst = std::max(worst, length(patch - q));
          for (int k = 0; k < 3; ++k) {
            EXPECT_GE(q[k], box.lo[k] - 1e-12);
            EXPECT_LE(q[k], box.hi[k] + 1e-12);
          }
        }
    }
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(CglSplineSurface, TextureIndicesFromTheParameters) {
  // Section 6.9: u = (u-bar - u_min)/(u_max - u_min). The triple bump's range
  // is [-1, 4]: u-bar = 1.5 gives 2.5/5 = 0.5, v-bar = -1 gives 0.
  const SplineSurface s =
      buildSpline(grid(4, 4, zero), 4, 4, EndCondition::Triple, EndCondition::Triple, 2, 0.5);
  double u = 0, v = 0;
  splineTexture(s, 1.5, -1.0, u, v);
  EXPECT_DOUBLE_EQ(u, 0.5);
  EXPECT_DOUBLE_EQ(v, 0.0);
  splineTexture(s, 4.0, 0.25, u, v);
  EXPECT_DOUBLE_EQ(u, 1.0);
  EXPECT_DOUBLE_EQ(v, 0.25);
}

TEST(CglSplineBezier, PatchesAreTheSurfaceExactly) {
  // The triple bump: 5 x 5 knot intervals, 25 patches; each Bezier patch
  // evaluated by de Casteljau's Bernstein weights equals Q on its interval.
  const SplineSurface s = bump(0.5);
  const auto patches = bezierPatches(s);
  ASSERT_EQ(patches.size(), 25u);
  auto bern = [](double t, double b[4]) {
    const double r = 1 - t;
    b[0] = r * r * r;
    b[1] = 3 * t * r * r;
    b[2] = 3 * t * t * r;
    b[3] = t * t * t;
  };
  for (int k : {0, 7, 12, 24})
    for (double lu : {0.0, 0.3, 1.0})
      for (double lv : {0.0, 0.6, 1.0}) {
        double bu[4], bv[4];
        bern(lu, bu);
        bern(lv, bv);
        Vec3 p{0, 0, 0};
        for (int b = 0; b < 4; ++b)
          for (int a = 0; a < 4; ++a)
            p = p + patches[static_cast<std::size_t>(k)][static_cast<std::size_t>(b * 4 + a)] *
                        (bu[a] * bv[b]);
        const double u = s.umin + k % 5 + lu, v = s.vmin + k / 5 + lv;
        const Vec3 q = evaluate(s, u, v).q;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], q[c], 1e-14) << k << " " << lu << " " << lv;
      }
}

TEST(CglSplineScene, TooFewVerticesForTheEndConditionAreRefusedAtTheNode) {
  // Single ends need 3 vertices (the range [u_1, u_{m-1}] must hold an
  // interval); the reader allows nu = 2.
  SceneFile f = test::emptyScene();
  f.surfaces.push_back(test::lambert(1, 1));
  NodeRecord n;
  n.number = 1;
  n.kind = NodeKind::Spline;
  n.surface = 1;
  n.nu = 2;
  n.nv = 3;
  n.uEnd = EndCondition::Single;
  n.vEnd = EndCondition::Triple;
  n.divisions = 2;
  n.overlap = 0.5;
  n.controls.assign(6, Vec3{0, 0, 0});
  n.where.file = "t.cgl";
  n.where.line = 42;
  f.nodes.push_back(n);
  f.numbers.root = 1;
  try {
    buildScene(f);
    FAIL() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().line, 42);
    EXPECT_NE(std::string(e.what()).find("at least 3"), std::string::npos) << e.what();
  }
  f.nodes[0].uEnd = EndCondition::Double;  // [u_0, u_1]: one interval
  EXPECT_EQ(buildScene(f).splines.size(), 1u);
}

TEST(CglSplineScene, TheDocumentsTubeReadsAndRenders) {
  const SceneFile f = readSceneFile(CGL_SCENES "/doc-spline-tube.cgl");
  const Scene s = buildScene(f);
  ASSERT_EQ(s.splines.size(), 1u);
  const SplineSurface& tube = s.splines[0];
  // 4 closed x 5 double, divisions 8: (4 + 1) 8 + 3 = 43 by (5 + 1) 8 + 3 = 51.
  EXPECT_EQ(tube.pu, 43);
  EXPECT_EQ(tube.pv, 51);
  EXPECT_DOUBLE_EQ(tube.umin, -1.0);
  EXPECT_DOUBLE_EQ(tube.umax, 3.0);
  EXPECT_DOUBLE_EQ(tube.vmin, 0.0);
  EXPECT_DOUBLE_EQ(tube.vmax, 4.0);
  EXPECT_NE(describeObjects(s).find("spline (node 4)"), std::string::npos) << describeObjects(s);
}

// CGL-D170: the packet walk returns the document's walk's hit bit for bit,
// and the shadow query answers as the nearest-hit search does, on every
// shipped spline scene: the primary rays of every 3rd pixel (the vases'
// holes included), rays from the hit points towards the light and random
// rays through the surface's box from every side. The counts of hits are
// printed by the failure messages; the assertion is the exact equality.
// CGL-D172: the vector evaluation is the scalar sum over Vec3 that it
// replaced (rows from zero in u, then weighted into sums from zero in v),
// to the last bit, at random parameters and at every knot of each shipped
// surface (the Newton iterates, and so the pictures, depend on these bits).
SplinePoint scalarEvaluate(const SplineSurface& s, double u, double v) {
  const int i = std::clamp(static_cast<int>(std::floor(u)), -1, s.m);
  const int j = std::clamp(static_cast<int>(std::floor(v)), -1, s.n);
  double wu[4], dwu[4], wv[4], dwv[4];
  bsplineWeights(u - i, wu, dwu);
  bsplineWeights(v - j, wv, dwv);
  SplinePoint out;
  for (int b = 0; b < 4; ++b) {
    Vec3 row{0, 0, 0}, drow{0, 0, 0};
    const std::size_t base = static_cast<std::size_t>((i + 1) + (j + 1 + b) * s.mu);
    for (int a = 0; a < 4; ++a) {
      const Vec3& c = s.u[base + static_cast<std::size_t>(a)];
      row = row + c * wu[a];
      drow = drow + c * dwu[a];
    }
    out.q = out.q + row * wv[b];
    out.qu = out.qu + drow * wv[b];
    out.qv = out.qv + row * dwv[b];
  }
  return out;
}

TEST(CglSplineSurface, VectorEvaluationIsTheScalarSumBitForBit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uint64_t points = 0;
  for (const char* name : {"spline-bump-single", "spline-donut", "spline-mask", "spline-vases"}) {
    const Scene scene = buildScene(readSceneFile(std::string(CGL_SCENES) + "/" + name + ".cgl"));
    for (const SplineSurface& s : scene.splines) {
      std::vector<std::pair<double, double>> at;
      for (int k = 0; k < 5000; ++k)
        at.push_back(
            {s.umin + (s.umax - s.umin) * unit(rng), s.vmin + (s.vmax - s.vmin) * unit(rng)});
      for (const SplineLeaf& leaf : s.leafData) at.push_back({leaf.u0, leaf.v0});
      for (const auto& [u, v] : at) {
        const SplinePoint a = evaluate(s, u, v), b = scalarEvaluate(s, u, v);
        for (int c = 0; c < 3; ++c) {
          // Bit for bit: EXPECT_EQ on doubles is exact equality (and +0 vs -0
          // would pass it, so the sign bits are compared too).
          ASSERT_EQ(a.q[c], b.q[c]) << name << " (" << u << ", " << v << ")";
          ASSERT_EQ(a.qu[c], b.qu[c]) << name << " (" << u << ", " << v << ")";
          ASSERT_EQ(a.qv[c], b.qv[c]) << name << " (" << u << ", " << v << ")";
          ASSERT_EQ(std::signbit(a.q[c]), std::signbit(b.q[c])) << name;
          ASSERT_EQ(std::signbit(a.qu[c]), std::signbit(b.qu[c])) << name;
          ASSERT_EQ(std::signbit(a.qv[c]), std::signbit(b.qv[c])) << name;
        }
        ++points;
      }
      // The leaf records' saved starts (CGL-D170) are these evaluations too.
      for (const SplineLeaf& leaf : s.leafData) {
        const SplinePoint b = scalarEvaluate(s, leaf.u0, leaf.v0);
        ASSERT_EQ(leaf.start.q, b.q) << name;
        ASSERT_EQ(leaf.start.qu, b.qu) << name;
        ASSERT_EQ(leaf.start.qv, b.qv) << name;
      }
    }
  }
  EXPECT_GT(points, 20000u);
}

// The same hit to the bit: t, the parameters, Newton's start and its
// iteration count (the packet walk against the document's walk).
void expectSameHit(const SplineHit& a, const SplineHit& b, const std::string& name, std::size_t r) {
  ASSERT_EQ(a.t, b.t) << name << " ray " << r;
  ASSERT_EQ(a.u, b.u) << name << " ray " << r;
  ASSERT_EQ(a.v, b.v) << name << " ray " << r;
  ASSERT_EQ(a.u0, b.u0) << name << " ray " << r;
  ASSERT_EQ(a.v0, b.v0) << name << " ray " << r;
  ASSERT_EQ(a.iterations, b.iterations) << name << " ray " << r;
}

TEST(CglSplineIntersect, PacketWalkIsTheDocumentsWalkBitForBit) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const char* name : {"spline-bump-single", "spline-bump-double", "spline-bump-triple",
                           "spline-donut", "spline-mask", "spline-vases", "doc-spline-tube"}) {
    const SceneFile f = readSceneFile(std::string(CGL_SCENES) + "/" + name + ".cgl");
    const Scene scene = buildScene(f);
    ASSERT_FALSE(scene.splines.empty()) << name;
    std::vector<Ray> rays;
    const auto& p = f.program;
    for (int y = p.ylow; y <= p.yhigh; y += 3)
      for (int x = p.xleft; x <= p.xright; x += 3) rays.push_back(scene.camera.primaryRay(x, y));
    std::uint64_t hits = 0, shadowHits = 0, tried = 0;
    for (const SplineSurface& s : scene.splines) {
      const Vec3 c = s.hull.centre(), e = s.hull.hi - s.hull.lo;
      for (int k = 0; k < 20000; ++k) {
        // From a point outside the box towards a point inside it.
        Vec3 a{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5}, b = a;
        for (int i = 0; i < 3; ++i) {
          a[i] = c[i] + 3.0 * e[i] * a[i] + (i == k % 3 ? (k % 2 ? 2.0 : -2.0) * e[i] : 0.0);
          b[i] = c[i] + e[i] * (unit(rng) - 0.5);
        }
        rays.push_back({a, normalized(b - a)});
      }
      const std::size_t primaryAndRandom = rays.size();
      for (std::size_t r = 0; r < primaryAndRandom; ++r) {
        const Ray& ray = rays[r];
        SplineHit a, b;
        SplineCounters ca, cb;
        const bool fa = intersectSplineDocument(s, ray, 1e-6, 1e10, a, ca);
        const bool fb = intersectSpline(s, ray, 1e-6, 1e10, b, cb);
        ++tried;
        ASSERT_EQ(fa, fb) << name << " ray " << r;
        EXPECT_EQ(fb, occludesSpline(s, ray, 1e-6, 1e10, cb)) << name << " ray " << r;
        // Never fewer Newton runs than the document's walk (it runs a superset).
        ASSERT_GE(cb.newtonCalls, ca.newtonCalls) << name << " ray " << r;
        if (!fa) continue;
        ++hits;
        ASSERT_NO_FATAL_FAILURE(expectSameHit(a, b, name, r));
        // CGL-D173: the normal from Newton's last Q_u, Q_v is the normal
        // evaluated afresh at (u, v), to the bit.
        ASSERT_EQ(splineNormal(s, b), splineNormal(s, b.u, b.v)) << name << " ray " << r;
        // A segment ending just short of the hit, and one just past it:
        // the shadow query against the nearest-hit search with tMax.
        const Ray toward{ray.o, ray.d};
        for (const double tMax : {a.t * 0.999, a.t * 1.001}) {
          SplineHit h;
          SplineCounters c;
          const bool near = intersectSplineDocument(s, toward, 1e-6, tMax, h, c);
          const bool occ = occludesSpline(s, toward, 1e-6, tMax, c);
          ASSERT_EQ(near, occ) << name << " ray " << r << " tMax " << tMax;
          shadowHits += occ;
        }
      }
      rays.resize(primaryAndRandom - 20000);
    }
    // Each scene gives both kinds of answers.
    EXPECT_GT(hits, 1000u) << name << " of " << tried;
    EXPECT_GT(shadowHits, 0u) << name;
  }
}

// CGL-D175: Auto keeps the grouping the surface area heuristic prefers; the
// document grouping's cost comes from the tree without building its packets
// (documentPacketCost), and must be the built packets' cost to the bit, so
// that Auto chooses as it did when it built both.
TEST(CglSplineIntersect, AutoLayoutIsTheCheaperGroupingByTheSameCosts) {
  int spatial = 0, document = 0;
  for (const char* name : {"spline-bump-single", "spline-bump-double", "spline-bump-triple",
                           "spline-donut", "spline-mask", "spline-vases", "doc-spline-tube"}) {
    const SceneFile f = readSceneFile(std::string(CGL_SCENES) + "/" + name + ".cgl");
    const Scene scene = buildScene(f);
    ASSERT_FALSE(scene.splines.empty()) << name;
    for (const SplineSurface& original : scene.splines) {
      SplineSurface d = original, sp = original, a = original;
      buildTraversal(d, PacketLayout::Document);
      buildTraversal(sp, PacketLayout::Spatial);
      buildTraversal(a, PacketLayout::Auto);
      const double fromTree = documentPacketCost(d), built = packetCost(d);
      ASSERT_EQ(std::memcmp(&fromTree, &built, sizeof built), 0)
          << name << ": " << fromTree << " against " << built;
      ASSERT_GT(built, 0.0) << name;
      const bool spatialWins = packetCost(sp) < built;
      (spatialWins ? spatial : document)++;
      const SplineSurface& expected = spatialWins ? sp : d;
      ASSERT_EQ(a.packets.size(), expected.packets.size()) << name;
      for (std::size_t k = 0; k < a.packets.size(); ++k) {
        const SplinePacket &x = a.packets[k], &y = expected.packets[k];
        ASSERT_EQ(x.count, y.count) << name << " packet " << k;
        ASSERT_EQ(x.plain, y.plain) << name << " packet " << k;
        for (int lane = 0; lane < 4; ++lane) {
          ASSERT_EQ(x.ref[lane], y.ref[lane]) << name << " packet " << k;
          for (int axis = 0; axis < 3; ++axis) {
            ASSERT_EQ(x.lo[axis][lane], y.lo[axis][lane]) << name << " packet " << k;
            ASSERT_EQ(x.hi[axis][lane], y.hi[axis][lane]) << name << " packet " << k;
          }
        }
      }
      ASSERT_EQ(a.leafData.size(), expected.leafData.size()) << name;
      for (std::size_t k = 0; k < a.leafData.size(); ++k)
        ASSERT_EQ(a.leafData[k].node, expected.leafData[k].node) << name << " leaf " << k;
    }
  }
  // CGL-D175's measurements: space for the donut, bump-single, bump-triple
  // and the vases; knot rectangles for bump-double and the mask.
  EXPECT_GT(spatial, 0);
  EXPECT_GT(document, 0);
}

// CGL-D175: whatever the grouping of the leaves into packets, the walk lists
// the same leaves with the same entries, so its hits are the document's.
TEST(CglSplineIntersect, EveryPacketLayoutIsTheDocumentsWalkBitForBit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uint64_t hits = 0;
  for (const char* name : {"spline-bump-single", "spline-bump-triple", "spline-donut",
                           "spline-mask", "spline-vases", "doc-spline-tube"}) {
    const SceneFile f = readSceneFile(std::string(CGL_SCENES) + "/" + name + ".cgl");
    const Scene scene = buildScene(f);
    ASSERT_FALSE(scene.splines.empty()) << name;
    const auto& p = f.program;
    for (const SplineSurface& original : scene.splines) {
      for (const PacketLayout layout : {PacketLayout::Document, PacketLayout::Spatial}) {
        SplineSurface s = original;
        buildTraversal(s, layout);
        ASSERT_EQ(s.leafData.size(), static_cast<std::size_t>(s.leaves)) << name;
        // Every leaf once.
        std::vector<int> seen(s.nodes.size(), 0);
        for (const SplineLeaf& leaf : s.leafData) ++seen[static_cast<std::size_t>(leaf.node)];
        for (std::size_t k = 0; k < s.nodes.size(); ++k)
          ASSERT_EQ(seen[k], s.nodes[k].count == 0 ? 1 : 0) << name << " node " << k;
        std::vector<Ray> rays;
        for (int y = p.ylow; y <= p.yhigh; y += 5)
          for (int x = p.xleft; x <= p.xright; x += 5)
            rays.push_back(scene.camera.primaryRay(x, y));
        const Vec3 c = s.hull.centre(), e = s.hull.hi - s.hull.lo;
        for (int k = 0; k < 5000; ++k) {
          Vec3 a{}, b{};
          for (int i = 0; i < 3; ++i) {
            a[i] = c[i] + 3.0 * e[i] * (unit(rng) - 0.5) +
                   (i == k % 3 ? (k % 2 ? 2.0 : -2.0) * e[i] : 0.0);
            b[i] = c[i] + e[i] * (unit(rng) - 0.5);
          }
          rays.push_back({a, normalized(b - a)});
        }
        for (std::size_t r = 0; r < rays.size(); ++r) {
          SplineHit a, b;
          SplineCounters ca, cb;
          const bool fa = intersectSplineDocument(s, rays[r], 1e-6, 1e10, a, ca);
          const bool fb = intersectSpline(s, rays[r], 1e-6, 1e10, b, cb);
          ASSERT_EQ(fa, fb) << name << " ray " << r;
          ASSERT_EQ(fb, occludesSpline(s, rays[r], 1e-6, 1e10, cb)) << name << " ray " << r;
          if (!fa) continue;
          ++hits;
          ASSERT_NO_FATAL_FAILURE(expectSameHit(a, b, name, r));
        }
      }
    }
  }
  EXPECT_GT(hits, 10000u);
}

}  // namespace
}  // namespace prime::cgl
