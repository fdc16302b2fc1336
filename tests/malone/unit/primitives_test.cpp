// The intersection and normal functions of Malone's primitives
// (src/malone/primitives.h) against hits and normals worked out by hand
// (each arithmetic in a comment): the notes' section 2 formulas, the EPS rule
// (eps < t < length), the boundaries and the vertex order. The torus is in
// quartic_test.cpp.
#include "src/malone/primitives.h"

#include <gtest/gtest.h>

#include <optional>

#include "tests/malone/unit/scene_text.h"

namespace prime::malone {
namespace {

using test::rayOf;
using test::sceneOf;
using test::unitVec;

constexpr double kEps = 1e-6;

std::optional<double> hitT(const Scene& s, const MRay& ray, int i = 0) {
  double t = 0;
  if (!intersect(s, s.primitives[i], ray, kEps, t)) return std::nullopt;
  return t;
}

Vec3 normalAt(const Scene& s, const MRay& ray, double t, int i = 0) {
  return normal(s, s.primitives[i], ray.o + ray.d * t);
}

void expectVecNear(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

// Hits at t (within tol) with the given normal.
void expectHit(const Scene& s, const MRay& ray, double t, const Vec3& n, int i = 0,
               double tol = 1e-12) {
  const auto got = hitT(s, ray, i);
  ASSERT_TRUE(got.has_value());
  EXPECT_NEAR(*got, t, tol * std::max(1.0, t));
  expectVecNear(normalAt(s, ray, *got, i), n, 1e-9);
}

// ---- Sphere (section 2.1): the unit sphere around the origin [L372-377].

const std::string kUnitSphere = "1 1 0 0 0" + test::kSurface;

TEST(MaloneSphere, FromOutside) {
  const Scene s = sceneOf(kUnitSphere);
  // o = (0,0,5), d = (0,0,-1): |o + t d| = 1 at t = 4 and 6; nearest 4 at (0,0,1).
  expectHit(s, rayOf({0, 0, 5}, {0, 0, -1}), 4.0, {0, 0, 1});
  // Oblique: o = (3,4,0) toward the centre, |o| = 5: t = 5 - 1 = 4 at (0.6, 0.8, 0).
  expectHit(s, rayOf({3, 4, 0}, {-3, -4, 0}), 4.0, {0.6, 0.8, 0});
  // Pointing away: both roots negative.
  EXPECT_FALSE(hitT(s, rayOf({0, 0, 5}, {0, 0, 1})));
}

TEST(MaloneSphere, FromInside) {
  const Scene s = sceneOf(kUnitSphere);
  // From the centre the roots are -1 and 1: the far one, outward normal (1,0,0).
  expectHit(s, rayOf({0, 0, 0}, {1, 0, 0}), 1.0, {1, 0, 0});
  // From (0.5,0,0) along -x: roots -0.5 and 1.5, hit (-1,0,0), normal (-1,0,0).
  expectHit(s, rayOf({0.5, 0, 0}, {-1, 0, 0}), 1.5, {-1, 0, 0});
}

TEST(MaloneSphere, Grazing) {
  const Scene s = sceneOf(kUnitSphere);
  // o = (1,0,5), d = (0,0,-1): b = 2 (o.d) = -10, c = 26 - 1 = 25, b^2 - 4c = 0:
  // the double root t = 5 at (1,0,0), normal (1,0,0).
  expectHit(s, rayOf({1, 0, 5}, {0, 0, -1}), 5.0, {1, 0, 0});
  // Just outside the silhouette: b^2 - 4c = 100 - 4 (1.001^2 + 24) < 0.
  EXPECT_FALSE(hitT(s, rayOf({1.001, 0, 5}, {0, 0, -1})));
}

TEST(MaloneSphere, EpsRejection) {
  const Scene s = sceneOf(kUnitSphere);
  // From the surface point (0,0,1) outward: roots -2 and 0, and 0 <= eps.
  EXPECT_FALSE(hitT(s, rayOf({0, 0, 1}, {0, 0, 1})));
  // From (0,0,1) inward: roots 0 (rejected) and 2 (the far side).
  expectHit(s, rayOf({0, 0, 1}, {0, 0, -1}), 2.0, {0, 0, -1});
  // A root at 5e-7 < eps = 1e-6 is rejected, the next one (2 + 5e-7) taken.
  expectHit(s, rayOf({0, 0, 1 + 5e-7}, {0, 0, -1}), 2 + 5e-7, {0, 0, -1}, 0, 1e-9);
  // A root at 2e-6 > eps is kept.
  expectHit(s, rayOf({0, 0, 1 + 2e-6}, {0, 0, -1}), 2e-6, {0, 0, 1}, 0, 1e-9);
}

TEST(MaloneSphere, RayLength) {
  const Scene s = sceneOf(kUnitSphere);
  // The hit at t = 4 needs length > 4 (eps < t < length).
  EXPECT_FALSE(hitT(s, rayOf({0, 0, 5}, {0, 0, -1}, 4.0)));
  EXPECT_TRUE(hitT(s, rayOf({0, 0, 5}, {0, 0, -1}, 4.0 + 1e-9)));
}

// ---- Plane (section 2.2): n.x = D.

TEST(MalonePlane, NormalisedD) {
  // "2 5 0 0 2": (0,0,2).x = 5, i.e. z = 2.5; read time divides D by |n| = 2.
  const Scene s = sceneOf("2 5 0 0 2" + test::kSurface);
  EXPECT_DOUBLE_EQ(s.primitives[0].D, 2.5);
  expectVecNear(s.primitives[0].n, {0, 0, 1});
  // o = (1,2,10), d = (0,0,-1): t = (D - n.o)/(n.d) = (2.5 - 10)/(-1) = 7.5.
  expectHit(s, rayOf({1, 2, 10}, {0, 0, -1}), 7.5, {0, 0, 1});
  // From below the normal is still (0,0,1) (the outward one; shading flips it).
  expectHit(s, rayOf({0, 0, 0}, {0, 0, 1}), 2.5, {0, 0, 1});
  // The document's example [L391-396]: "5 0 0 1" passes through (3,4,5).
  const Scene doc = sceneOf("2 5 0 0 1" + test::kSurface);
  // From (3,4,9) down: t = (5 - 9)/(-1) = 4, the point (3,4,5).
  expectHit(doc, rayOf({3, 4, 9}, {0, 0, -1}), 4.0, {0, 0, 1});
  // A slanted normal (3,4,0)/5 with D = 10 / 5 = 2: from the origin along
  // (0.6,0.8,0), t = 2.
  const Scene slant = sceneOf("2 10 3 4 0" + test::kSurface);
  expectHit(slant, rayOf({0, 0, 0}, {3, 4, 0}), 2.0, {0.6, 0.8, 0});
}

TEST(MalonePlane, ParallelRayMisses) {
  const Scene s = sceneOf("2 5 0 0 2" + test::kSurface);
  // n.d = 0: no hit, even on the plane itself.
  EXPECT_FALSE(hitT(s, rayOf({0, 0, 1}, {1, 0, 0})));
  EXPECT_FALSE(hitT(s, rayOf({0, 0, 2.5}, {0, 1, 0})));
  // Behind the origin: t < 0.
  EXPECT_FALSE(hitT(s, rayOf({0, 0, 10}, {0, 0, 1})));
}

// ---- Disk and annulus (section 2.3): |x - p|^2 <= r^2, annulus also > r_in^2.

TEST(MaloneDisk, Boundary) {
  // Centre origin, normal (0,0,1), radius 2; rays straight down from z = 1, t = 1.
  const Scene s = sceneOf("3 0 0 0 0 0 1 2" + test::kSurface);
  expectHit(s, rayOf({1, 1, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({2, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});  // |x|^2 = 4 <= 4: on the rim
  expectHit(s, rayOf({0, -2, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  EXPECT_FALSE(hitT(s, rayOf({2.000001, 0, 1}, {0, 0, -1})));
  EXPECT_FALSE(hitT(s, rayOf({1.5, 1.5, 1}, {0, 0, -1})));  // 4.5 > 4
  // The normal is normalised: the document's disk [L410-416], normal (4,3,-1).
  const Scene doc = sceneOf("3 1 1 1 4 3 -1 2.5" + test::kSurface);
  const double len = std::sqrt(26.0);  // |(4,3,-1)|
  // From c + 2 n_hat toward the centre: t = 2, normal (4,3,-1)/sqrt(26).
  const Vec3 n{4 / len, 3 / len, -1 / len};
  expectHit(doc, rayOf(Vec3{1, 1, 1} + n * 2.0, n * -1.0), 2.0, n);
}

TEST(MaloneAnnulus, Boundary) {
  // Radius 2, r_in 1: r_in^2 < |x|^2 <= r^2.
  const Scene s = sceneOf("4 0 0 0 0 0 1 2 1" + test::kSurface);
  expectHit(s, rayOf({1.5, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({2, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});  // outer rim: <=, a hit
  EXPECT_FALSE(hitT(s, rayOf({1, 0, 1}, {0, 0, -1})));         // inner rim: 1 > 1 false
  EXPECT_FALSE(hitT(s, rayOf({0, -1, 1}, {0, 0, -1})));
  expectHit(s, rayOf({1.000001, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  EXPECT_FALSE(hitT(s, rayOf({0.5, 0, 1}, {0, 0, -1})));  // in the hole
  EXPECT_FALSE(hitT(s, rayOf({0, 0, 1}, {0, 0, -1})));    // the centre
  EXPECT_FALSE(hitT(s, rayOf({2.5, 0, 1}, {0, 0, -1})));  // outside
}

// ---- Triangle (section 2.4) and parallelogram (section 2.5).

TEST(MaloneTriangle, InsideOutsideEdges) {
  // v0 (0,0,0), v1 (1,0,0), v2 (0,1,0): a x b = (0,0,1).
  const Scene s = sceneOf("5 0 0 0 1 0 0 0 1 0" + test::kSurface);
  expectHit(s, rayOf({0.25, 0.25, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  EXPECT_FALSE(hitT(s, rayOf({0.6, 0.6, 1}, {0, 0, -1})));   // alpha + beta = 1.2 > 1
  EXPECT_FALSE(hitT(s, rayOf({-0.1, 0.5, 1}, {0, 0, -1})));  // alpha < 0
  EXPECT_FALSE(hitT(s, rayOf({0.5, -0.1, 1}, {0, 0, -1})));  // beta < 0
  // On the edges (all three tests are inclusive): alpha + beta = det = 1,
  // beta = 0, alpha = 0, and the vertices.
  expectHit(s, rayOf({0.5, 0.5, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({0.5, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({0, 0.5, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({1, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({0, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
}

TEST(MaloneTriangle, VertexOrderSetsTheNormal) {
  // v0, v2, v1: a x b = (0,1,0) x (1,0,0) = (0,0,-1).
  const Scene s = sceneOf("5 0 0 0 0 1 0 1 0 0" + test::kSurface);
  expectHit(s, rayOf({0.25, 0.25, 1}, {0, 0, -1}), 1.0, {0, 0, -1});
  // The document's triangle [L452-456]: (1,0,0), (0,1,0), (0,0,1):
  // a = (-1,1,0), b = (-1,0,1), a x b = (1,1,1) -> (1,1,1)/sqrt(3), D = 1/sqrt(3).
  const Scene doc = sceneOf("5 1 0 0 0 1 0 0 0 1" + test::kSurface);
  const double r3 = 1 / std::sqrt(3.0);
  // From the origin along (1,1,1): the centroid (1/3,1/3,1/3) at t = 1/sqrt(3).
  expectHit(doc, rayOf({0, 0, 0}, {1, 1, 1}), r3, {r3, r3, r3});
}

TEST(MaloneParallelogram, InsideOutsideEdges) {
  // vertex (0,0,0), edges (2,0,0), (0,1,0): det = 4 * 1 - 0 = 4.
  const Scene s = sceneOf("6 0 0 0 2 0 0 0 1 0" + test::kSurface);
  // (1,0.5): alpha' = b.b (a.w) = 2, beta' = a.a (b.w) = 4 * 0.5 = 2: inside.
  expectHit(s, rayOf({1, 0.5, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  // The far corner (2,1): alpha' = 4 <= 4, beta' = 4 <= 4.
  expectHit(s, rayOf({2, 1, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({0, 0, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
  expectHit(s, rayOf({2, 0.5, 1}, {0, 0, -1}), 1.0, {0, 0, 1});  // on an edge
  EXPECT_FALSE(hitT(s, rayOf({2.01, 0.5, 1}, {0, 0, -1})));      // alpha' = 4.02 > 4
  EXPECT_FALSE(hitT(s, rayOf({1, 1.01, 1}, {0, 0, -1})));
  EXPECT_FALSE(hitT(s, rayOf({-0.01, 0.5, 1}, {0, 0, -1})));
  // Beyond the triangle's hypotenuse, still in the parallelogram.
  expectHit(s, rayOf({1.9, 0.9, 1}, {0, 0, -1}), 1.0, {0, 0, 1});
}

TEST(MaloneParallelogram, VertexOrderSetsTheNormal) {
  // Edges swapped: (0,1,0) x (2,0,0) = (0,0,-2) -> (0,0,-1).
  const Scene s = sceneOf("6 0 0 0 0 1 0 2 0 0" + test::kSurface);
  expectHit(s, rayOf({1, 0.5, 1}, {0, 0, -1}), 1.0, {0, 0, -1});
  // The document's printed square [L468-472]: vertex (1,1,0), edges (0,-1,0),
  // (0,0,-1): the unit square in the plane x = 1 (not the caption's z = 0
  // square, notes section 7 item 19); normal (0,-1,0) x (0,0,-1) = (1,0,0).
  const Scene doc = sceneOf("6 1 1 0 0 -1 0 0 0 -1" + test::kSurface);
  expectHit(doc, rayOf({4, 0.5, -0.5}, {-1, 0, 0}), 3.0, {1, 0, 0});
  EXPECT_FALSE(hitT(doc, rayOf({4, 0.5, 0.5}, {-1, 0, 0})));
}

// ---- Polygon: Newell normal, even-odd, on an edge counts as inside.

TEST(MalonePolygon, ConvexSquare) {
  // (0,0,0) (1,0,0) (1,1,0) (0,1,0), counter-clockwise about +z: Newell (0,0,2) -> (0,0,1).
  const Scene s = sceneOf("11 4 0 0 0 1 0 0 1 1 0 0 1 0" + test::kSurface);
  expectHit(s, rayOf({0.5, 0.5, 2}, {0, 0, -1}), 2.0, {0, 0, 1});
  expectHit(s, rayOf({0.5, 0, 2}, {0, 0, -1}), 2.0, {0, 0, 1});  // on an edge
  expectHit(s, rayOf({1, 1, 2}, {0, 0, -1}), 2.0, {0, 0, 1});    // a vertex
  EXPECT_FALSE(hitT(s, rayOf({1.1, 0.5, 2}, {0, 0, -1})));
  EXPECT_FALSE(hitT(s, rayOf({0.5, -0.1, 2}, {0, 0, -1})));
  // Clockwise: the normal flips.
  const Scene cw = sceneOf("11 4 0 0 0 0 1 0 1 1 0 1 0 0" + test::kSurface);
  expectHit(cw, rayOf({0.5, 0.5, 2}, {0, 0, -1}), 2.0, {0, 0, -1});
}

TEST(MalonePolygon, NonConvexStar) {
  // A four-pointed star in the plane z = 1: tips at distance 2 on the axes,
  // notches at distance 0.5 on the diagonals (h = 0.5 / sqrt 2 = 0.353553...).
  const double h = 0.5 / std::sqrt(2.0);
  auto v = [](double x, double y) {
    return " " + std::to_string(x) + " " + std::to_string(y) + " 1";
  };
  const Scene s = sceneOf("11 8" + v(2, 0) + v(h, h) + v(0, 2) + v(-h, h) + v(-2, 0) + v(-h, -h) +
                          v(0, -2) + v(h, -h) + test::kSurface);
  auto down = [](double x, double y) { return rayOf({x, y, 3}, {0, 0, -1}); };
  expectHit(s, down(0, 0), 2.0, {0, 0, 1});      // the centre
  expectHit(s, down(1.5, 0), 2.0, {0, 0, 1});    // in the +x arm
  expectHit(s, down(0, -1.8), 2.0, {0, 0, 1});   // in the -y arm
  expectHit(s, down(0.2, 0.2), 2.0, {0, 0, 1});  // 0.283 < 0.5 along the diagonal
  // The arm at x = 1.5 is h (2 - 1.5)/(2 - h) = 0.1074 wide each side: 0.2 is out.
  EXPECT_FALSE(hitT(s, down(1.5, 0.2)));
  EXPECT_FALSE(hitT(s, down(1, 1)));       // in a notch, beyond the inner vertex
  EXPECT_FALSE(hitT(s, down(-0.5, 0.5)));  // 0.707 > 0.5 along the diagonal
}

TEST(MalonePolygon, EvenOdd) {
  // A pentagram (vertices 0, 2, 4, 1, 3 of a regular pentagon of radius 1,
  // the first at 90 degrees): even-odd leaves the inner pentagon (covered
  // twice) outside, and the tips (covered once) inside.
  std::string text = "11 5";
  for (int k = 0; k < 5; ++k) {
    const double a = (90.0 + 144.0 * k) * 3.14159265358979323846 / 180.0;
    text += " " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0";
  }
  const Scene s = sceneOf(text + test::kSurface);
  auto down = [](double x, double y) { return rayOf({x, y, 1}, {0, 0, -1}); };
  // The centre: winding number 2, even: no hit.
  EXPECT_FALSE(hitT(s, down(0, 0)));
  EXPECT_FALSE(hitT(s, down(0.1, -0.1)));
  // The top tip: the inner pentagon's top edge is at y = 0.382 cos 36 = 0.309;
  // (0, 0.8) lies in the tip triangle.
  ASSERT_TRUE(hitT(s, down(0, 0.8)));
  EXPECT_NEAR(*hitT(s, down(0, 0.8)), 1.0, 1e-12);
  EXPECT_FALSE(hitT(s, down(0, 1.1)));  // beyond the tip
}

// ---- Cone (section 2.7): the document's example, alpha 0.9, range 0 2,
// apex (0,2,0), axis (0,-5,0): y from 2 down to 2 - 2 * 5 = -8.

const double kSinT = std::sqrt(1 - 0.81);  // sin(theta), cos(theta) = 0.9
const double kTanT = kSinT / 0.9;          // 0.484322... (notes: 0.48432)

TEST(MaloneCone, DocumentExample) {
  const Scene s = sceneOf("8 0.9 0 2 0 2 0 0 -5 0" + test::kSurface);
  // A horizontal ray at y = 0, 2 below the apex: radius 2 tan(theta) = 0.968644.
  const double rad = 2 * kTanT;
  // From (5,0,0) along -x: t = 5 - rad; the outward normal is perpendicular to
  // the generator (sin, -cos) in the x-y plane and away from the axis:
  // (cos(theta), sin(theta), 0).
  expectHit(s, rayOf({5, 0, 0}, {-1, 0, 0}), 5 - rad, {0.9, kSinT, 0});
  // From the other side: (-cos, sin, 0).
  expectHit(s, rayOf({-5, 0, 0}, {1, 0, 0}), 5 - rad, {-0.9, kSinT, 0});
  // At y = -8 (the end of the range, 10 below the apex): radius 10 tan.
  expectHit(s, rayOf({0, -8, 20}, {0, 0, -1}), 20 - 10 * kTanT, {0, kSinT, 0.9}, 0, 1e-10);
  // Below y = -8: clipped (the cone is open, no cap), both roots out of range.
  EXPECT_FALSE(hitT(s, rayOf({0, -8.5, 20}, {0, 0, -1})));
  // The range picks the nappe: at y = 4 (2 above the apex, range -0.4) no hit.
  EXPECT_FALSE(hitT(s, rayOf({5, 4, 0}, {-1, 0, 0})));
}

TEST(MaloneCone, BothNappesNormalsPointAwayFromTheAxis) {
  // The same cone with range -2 2: y from 12 down to -8, both nappes.
  const Scene s = sceneOf("8 0.9 -2 2 0 2 0 0 -5 0" + test::kSurface);
  // Upper nappe at y = 4, radius 2 tan(theta): the generator is (sin, cos), the
  // normal away from the axis (cos(theta), -sin(theta), 0).
  const double rad = 2 * kTanT;
  expectHit(s, rayOf({5, 4, 0}, {-1, 0, 0}), 5 - rad, {0.9, -kSinT, 0});
  expectHit(s, rayOf({0, 4, -5}, {0, 0, 1}), 5 - rad, {0, -kSinT, -0.9});
  // Lower nappe as before.
  expectHit(s, rayOf({5, 0, 0}, {-1, 0, 0}), 5 - rad, {0.9, kSinT, 0});
  // Range given in the other order: the same cone.
  const Scene swapped = sceneOf("8 0.9 2 -2 0 2 0 0 -5 0" + test::kSurface);
  expectHit(swapped, rayOf({5, 4, 0}, {-1, 0, 0}), 5 - rad, {0.9, -kSinT, 0});
  // A vertical ray at x = 0.5 through both nappes: |y - 2| = 0.5 / tan(theta) =
  // 1.032380; from below the first hit is the lower nappe (y = 0.967620),
  // from above the upper one (y = 3.032380).
  const double dy = 0.5 / kTanT;
  expectHit(s, rayOf({0.5, -5, 0}, {0, 1, 0}), 7 - dy, {0.9, kSinT, 0}, 0, 1e-11);
  expectHit(s, rayOf({0.5, 9, 0}, {0, -1, 0}), 7 - dy, {0.9, -kSinT, 0}, 0, 1e-11);
}

TEST(MaloneCone, NearRootClippedFarAccepted) {
  const Scene s = sceneOf("8 0.9 0 2 0 2 0 0 -5 0" + test::kSurface);
  // o = (-12,-20,0), d = (1,1,0)/sqrt 2: points (-12 + u, -20 + u) for u = t / sqrt 2.
  // Left wall x = -(2 - y) tan: -12 + u = -tan (22 - u) -> u1 = (12 - 22 tan)/(1 - tan)
  // = 2.61 (y = -17.39, below the end -8: clipped). Right wall x = (2 - y) tan:
  // u2 = (12 + 22 tan)/(1 + tan) = 15.26 (y = -4.74: in range, accepted).
  const double u1 = (12 - 22 * kTanT) / (1 - kTanT);
  const double u2 = (12 + 22 * kTanT) / (1 + kTanT);
  EXPECT_LT(-20 + u1, -8.0);
  EXPECT_GT(-20 + u2, -8.0);
  expectHit(s, rayOf({-12, -20, 0}, {1, 1, 0}), u2 * std::sqrt(2.0), {0.9, kSinT, 0}, 0, 1e-11);
}

TEST(MaloneCone, RayAlongAGenerator) {
  // A = alpha^2 - (d.a)^2 = 0 for d along a generator: the linear case. The
  // ray parallel to the right generator (sin, -cos) of the doc cone, offset
  // to x = -1 at y = 2: it meets the left wall once. Line: (-1 + s sin, 2 - s cos);
  // left wall x = -(2 - y) tan: -1 + s sin = -s cos tan = -s sin -> s = 1 / (2 sin).
  const Scene s = sceneOf("8 0.9 0 2 0 2 0 0 -5 0" + test::kSurface);
  const double sHit = 1 / (2 * kSinT);
  // The direction as is (unit by construction), so that A is exactly 0.
  const auto t = hitT(s, MRay{{-1, 2, 0}, {kSinT, -0.9, 0}, kInfinite});
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, sHit, 1e-9);
}

TEST(MaloneCone, ApexNormalIsFinite) {
  // A ray through the apex (0,2,0) from outside: q = o - c = -t0 d makes the
  // quadratic (t - t0)^2 (alpha^2 - (d.a)^2): a double root at the apex, range
  // parameter 0, accepted. There w = x - c = 0 and no normal is defined; the
  // one returned must still be a unit vector (a NaN would blacken the pixel).
  const Scene s = sceneOf("8 0.9 0 2 0 2 0 0 -5 0" + test::kSurface);
  const MRay ray = rayOf({5, 2, 0}, {-1, 0, 0});
  const auto t = hitT(s, ray);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 5, 1e-6);  // a double root: about sqrt(machine epsilon) * 5
  // Exactly at the apex: -u = (0,1,0) (a point of the other nappe's axis side).
  const Vec3 n = normal(s, s.primitives[0], Vec3{0, 2, 0});
  EXPECT_NEAR(dot(n, n), 1, 1e-12);
  expectVecNear(n, {0, 1, 0});
}

// ---- Cylinder (section 2.8): the document's radius 0.5, range 0 10, point
// (0,2,0), axis (0,-1,0): y from 2 down to -8.

TEST(MaloneCylinder, DocumentExample) {
  const Scene s = sceneOf("9 0.5 0 10 0 2 0 0 -1 0" + test::kSurface);
  expectHit(s, rayOf({5, 0, 0}, {-1, 0, 0}), 4.5, {1, 0, 0});
  expectHit(s, rayOf({0, -3, 5}, {0, 0, -1}), 4.5, {0, 0, 1});
  // From inside (on the axis): roots -0.5 and 0.5, the far one, normal outward.
  expectHit(s, rayOf({0, 0, 0}, {-1, 0, 0}), 0.5, {-1, 0, 0});
  // The range ends: y = 2 and y = -8 are in (<=), beyond is not.
  expectHit(s, rayOf({5, 2, 0}, {-1, 0, 0}), 4.5, {1, 0, 0});
  expectHit(s, rayOf({5, -8, 0}, {-1, 0, 0}), 4.5, {1, 0, 0});
  EXPECT_FALSE(hitT(s, rayOf({5, 2.01, 0}, {-1, 0, 0})));
  EXPECT_FALSE(hitT(s, rayOf({5, -8.01, 0}, {-1, 0, 0})));
  // Oblique, normal by hand: from (3,0,4) toward the axis point (0,0,0):
  // |(x,z)| = 5 - t = 0.5 -> t = 4.5 at (0.3, 0, 0.4), normal (0.6, 0, 0.8).
  expectHit(s, rayOf({3, 0, 4}, {-3, 0, -4}), 4.5, {0.6, 0, 0.8});
  // The near root clipped, the far one accepted: from (-0.8,-8.8,0) along
  // (1,2,0)/sqrt 5, points (-0.8 + u, -8.8 + 2u): x = -0.5 at u = 0.3, y = -8.2
  // (below -8: clipped); x = 0.5 at u = 1.3, y = -6.2 (in range): t = 1.3 sqrt 5,
  // the wall seen from inside, outward normal (1,0,0).
  expectHit(s, rayOf({-0.8, -8.8, 0}, {1, 2, 0}), 1.3 * std::sqrt(5.0), {1, 0, 0}, 0, 1e-11);
  // Both roots clipped: the same line from (-0.8,-10.8,0) meets the wall at
  // y = -10.2 and y = -8.2: no hit.
  EXPECT_FALSE(hitT(s, rayOf({-0.8, -10.8, 0}, {1, 2, 0})));
}

TEST(MaloneCylinder, RangeEitherOrder) {
  const Scene a = sceneOf("9 0.5 0 10 0 2 0 0 -1 0" + test::kSurface);
  const Scene b = sceneOf("9 0.5 10 0 0 2 0 0 -1 0" + test::kSurface);
  for (double y : {2.5, 1.0, -3.0, -8.0, -8.5}) {
    const MRay ray = rayOf({5, y, 0}, {-1, 0, 0});
    EXPECT_EQ(hitT(a, ray).has_value(), hitT(b, ray).has_value()) << y;
    EXPECT_EQ(hitT(a, ray).has_value(), y <= 2 && y >= -8) << y;
  }
  // A long axis (0,-2,0): the range is in axis lengths, 0 5 is y from 2 to -8.
  const Scene c = sceneOf("9 0.5 5 0 0 2 0 0 -2 0" + test::kSurface);
  EXPECT_TRUE(hitT(c, rayOf({5, -7.9, 0}, {-1, 0, 0})));
  EXPECT_FALSE(hitT(c, rayOf({5, -8.1, 0}, {-1, 0, 0})));
}

TEST(MaloneCylinder, RayAlongTheAxisMisses) {
  const Scene s = sceneOf("9 0.5 0 10 0 2 0 0 -1 0" + test::kSurface);
  EXPECT_FALSE(hitT(s, rayOf({0, 5, 0}, {0, -1, 0})));    // on the axis
  EXPECT_FALSE(hitT(s, rayOf({0.5, 5, 0}, {0, -1, 0})));  // on the wall itself
  EXPECT_FALSE(hitT(s, rayOf({0.2, -5, 0}, {0, 1, 0})));  // inside, parallel
}

// ---- Affine (section 2.6): the document's ellipsoid. O = 0, X = (1,0,0),
// Y = (0,2,0), Z = (0,0,2) around a sphere of radius 0.5 at (0,0.5,0): in the
// world (x/0.5)^2 + (y-1)^2 + z^2 = 1, centre (0,1,0), semi-axes (0.5,1,1).

const std::string kEllipsoid = "7 0 0 0 1 0 0 0 2 0 0 0 2 1 0.5 0 0.5 0" + test::kSurface;

TEST(MaloneAffine, DocumentEllipsoid) {
  const Scene s = sceneOf(kEllipsoid);
  expectHit(s, rayOf({5, 1, 0}, {-1, 0, 0}), 4.5, {1, 0, 0});   // x = 0.5
  expectHit(s, rayOf({0, 5, 0}, {0, -1, 0}), 3.0, {0, 1, 0});   // y = 2
  expectHit(s, rayOf({0, -5, 0}, {0, 1, 0}), 5.0, {0, -1, 0});  // y = 0
  expectHit(s, rayOf({0, 1, 5}, {0, 0, -1}), 4.0, {0, 0, 1});   // z = 1
  EXPECT_FALSE(hitT(s, rayOf({0.6, 5, 0}, {0, -1, 0})));        // x = 0.6 > 0.5
  // Oblique from the centre along (1,0,1)/sqrt 2: 4 x^2 + z^2 = 5 u^2 / 2 = 1
  // -> u = sqrt(2/5); the gradient (8x, 2(y-1), 2z) is along (4,0,1):
  // normal (4,0,1)/sqrt 17 (not the sphere's radial (1,0,1)/sqrt 2).
  const double r17 = std::sqrt(17.0);
  expectHit(s, rayOf({0, 1, 0}, {1, 0, 1}), std::sqrt(0.4), {4 / r17, 0, 1 / r17});
  // Along (0,1,1) from the centre: (y-1)^2 + z^2 = u^2 = 1: t = 1, normal (0,1,1)/sqrt 2.
  const double r2 = 1 / std::sqrt(2.0);
  expectHit(s, rayOf({0, 1, 0}, {0, 1, 1}), 1.0, {0, r2, r2});
}

TEST(MaloneAffine, TranslatedNormalIncludesO) {
  // O = (10,0,0): the same ellipsoid centred at (10,1,0). The document's normal
  // formula M^T n(M x) leaves O out; with it the normals are those above.
  const Scene s = sceneOf("7 10 0 0 1 0 0 0 2 0 0 0 2 1 0.5 0 0.5 0" + test::kSurface);
  expectHit(s, rayOf({15, 1, 0}, {-1, 0, 0}), 4.5, {1, 0, 0});
  expectHit(s, rayOf({5, 1, 0}, {1, 0, 0}), 4.5, {-1, 0, 0});
  const double r17 = std::sqrt(17.0);
  expectHit(s, rayOf({10, 1, 0}, {1, 0, 1}), std::sqrt(0.4), {4 / r17, 0, 1 / r17});
  expectHit(s, rayOf({10, 1, 0}, {-1, 0, -1}), std::sqrt(0.4), {-4 / r17, 0, -1 / r17});
}

TEST(MaloneAffine, FiniteRayLength) {
  // Shadow rays: the hit at world t = 4.5 (x = 0.5) needs length > 4.5; along
  // y the local scale is |M d| = 1/2 and the hit is at world t = 3 (y = 2).
  const Scene s = sceneOf(kEllipsoid);
  EXPECT_FALSE(hitT(s, rayOf({5, 1, 0}, {-1, 0, 0}, 4.4)));
  EXPECT_TRUE(hitT(s, rayOf({5, 1, 0}, {-1, 0, 0}, 4.6)));
  EXPECT_FALSE(hitT(s, rayOf({0, 5, 0}, {0, -1, 0}, 2.9)));
  ASSERT_TRUE(hitT(s, rayOf({0, 5, 0}, {0, -1, 0}, 3.1)));
  EXPECT_NEAR(*hitT(s, rayOf({0, 5, 0}, {0, -1, 0}, 3.1)), 3.0, 1e-12);
  // A rotated and sheared frame: X = (0,1,0), Y = (-3,0,0), Z = (0,0,1), unit
  // sphere at the local origin, O = (1,1,1): world {O + x X + y Y + z Z}, an
  // ellipse with semi-axis 1 along world y and 3 along world x. From (10,1,1)
  // along -x: hit at x = 1 + 3 = 4, t = 6, normal (1,0,0).
  const Scene r = sceneOf("7 1 1 1 0 1 0 -3 0 0 0 0 1 1 1 0 0 0" + test::kSurface);
  expectHit(r, rayOf({10, 1, 1}, {-1, 0, 0}), 6.0, {1, 0, 0});
  EXPECT_FALSE(hitT(r, rayOf({10, 1, 1}, {-1, 0, 0}, 5.9)));
  expectHit(r, rayOf({1, 10, 1}, {0, -1, 0}), 8.0, {0, 1, 0});
}

TEST(MaloneAffine, EpsInEmbeddedSpace) {
  // EPS applies in the embedded primitive's space: a root 1.5e-6 world units
  // along y (above eps in the world) is 7.5e-7 local units (|M d| = 1/2),
  // below eps: rejected, and the far side (y = 0) is the hit.
  const Scene s = sceneOf(kEllipsoid);
  const auto t = hitT(s, rayOf({0, 2 + 1.5e-6, 0}, {0, -1, 0}));
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 2 + 1.5e-6, 1e-9);
  // Along x the scale is 1: a root 1.5e-6 away is kept.
  const auto tx = hitT(s, rayOf({0.5 + 1.5e-6, 1, 0}, {-1, 0, 0}));
  ASSERT_TRUE(tx.has_value());
  EXPECT_NEAR(*tx, 1.5e-6, 1e-12);
}

TEST(MaloneBounds, ContainEveryHit) {
  // The padded boxes of the BVH contain the hit points found above.
  const Scene s =
      sceneOf("8 0.9 -2 2 0 2 0 0 -5 0" + test::kSurface + kEllipsoid + "9 0.5 0 10 0 2 0 0 -1 0" +
              test::kSurface + "2 0 0 1 0" + test::kSurface);
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(bounds(s, s.primitives[i]).empty());
  EXPECT_TRUE(bounds(s, s.primitives[3]).empty());  // the plane is unbounded
  const Aabb cone = bounds(s, s.primitives[0]);
  // y from 12 to -8, radius 10 tan(theta) = 4.84 at both ends.
  EXPECT_NEAR(cone.hi[1], 12, 1e-5);
  EXPECT_NEAR(cone.lo[1], -8, 1e-5);
  EXPECT_NEAR(cone.hi[0], 10 * kTanT, 1e-5);
  const Aabb ell = bounds(s, s.primitives[1]);
  EXPECT_NEAR(ell.lo[0], -0.5, 1e-6);
  EXPECT_NEAR(ell.hi[1], 2, 1e-6);
  EXPECT_NEAR(ell.hi[2], 1, 1e-6);
}

}  // namespace
}  // namespace prime::malone
