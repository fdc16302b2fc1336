// Inverse mapping (TextureMp GetUV*, listing lines 7351-7759) and CastRay's
// switch with E44. Every expected value below was worked out by hand from the
// printed code; where it involves acos, the closed form is written with the
// listing's constants (PiInv = 0.318309886, TwoPiInv = 0.1591549) and the
// decimal value is given in the comment.
#include "src/prime/geom/uv_mapping_1991.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace prime {
namespace {

using io::PrimType;

constexpr double kPi = std::numbers::pi;  // == acos(-1.0) == 2*acos(0.0)
// The listing's constants, as printed (E47). Written out here rather than
// taken from the header, so that a changed constant fails the tests.
constexpr double kPiInv1991 = 0.318309886;
constexpr double kTwoPiInv1991 = 0.1591549;
// TwoPiInv * pi/2 = 0.24999993231... (not 0.25: TwoPiInv is 7 digits).
const double kQuarter = (kPi / 2) * kTwoPiInv1991;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

void expectUvs(const UvSurface& got, double u, double v, int surface, double tol = 0.0) {
  EXPECT_EQ(got.surface, surface);
  if (tol == 0.0) {
    EXPECT_DOUBLE_EQ(got.u, u);
    EXPECT_DOUBLE_EQ(got.v, v);
  } else {
    EXPECT_NEAR(got.u, u, tol);
    EXPECT_NEAR(got.v, v, tol);
  }
}

TEST(UvConstants, AsPrinted) {
  EXPECT_EQ(kPiInv, kPiInv1991);
  EXPECT_EQ(kTwoPiInv, kTwoPiInv1991);
  EXPECT_EQ(kPyramidPlaneA, 0.44721359499958);
  EXPECT_EQ(kPyramidPlaneB, 0.894427190999916);
}

// ---------------------------------------------------------------- sphere (S)

TEST(UvSphere, FrontPoleFacingTheCameraIsVZeroUZero) {
  // n = (0,0,-1): alpha = acos(Roundoff(1)) = 0, v = 0 -> u = 0 (E53 branch).
  const UvSurface r = getUVSphere1991({0.0, 0.0, -1.0});
  EXPECT_EQ(r.surface, 0);
  EXPECT_EQ(r.u, 0.0);
  EXPECT_EQ(r.v, 0.0);
}

TEST(UvSphere, BackPoleNeverGivesVOneBecausePiInvIsShort) {
  // n = (0,0,1): alpha = acos(-1) = pi; v = pi*0.318309886 = 0.9999999994226
  // != 1.0, so the else branch runs: sin(pi) = 1.22e-16, 0/1.22e-16 = 0,
  // beta = acos(0)*PiInv = 0.4999999997113; VectorDot((0,1,0), n) = 0 is not
  // > 0, so u = 1 - beta = 0.5000000002887.
  const UvSurface r = getUVSphere1991({0.0, 0.0, 1.0});
  EXPECT_EQ(r.surface, 0);
  EXPECT_DOUBLE_EQ(r.v, kPi * kPiInv1991);
  EXPECT_NE(r.v, 1.0);
  EXPECT_DOUBLE_EQ(r.u, 1.0 - (kPi / 2) * kPiInv1991);
  EXPECT_NEAR(r.u, 0.5000000002887, 1e-12);
}

TEST(UvSphere, EquatorPoints) {
  const double vEq = (kPi / 2) * kPiInv1991;  // alpha = acos(Roundoff(-0.0)) = pi/2
  // (1,0,0): sin(pi/2) = 1, acos(Roundoff(1)) = 0 -> beta 0; y = 0 is not
  // > 0, so u = 1 - 0 = 1 (K26: the y <= 0 side is mirrored).
  expectUvs(getUVSphere1991({1.0, 0.0, 0.0}), 1.0, vEq, 0);
  // (0,1,0): beta = acos(0)*PiInv = 0.4999999997; y > 0 -> u = beta. Q5: a
  // quarter turn is u ~ 0.5, not 0.25 (PiInv, not TwoPiInv).
  expectUvs(getUVSphere1991({0.0, 1.0, 0.0}), (kPi / 2) * kPiInv1991, vEq, 0);
  // (-1,0,0): beta = pi*PiInv = 0.99999999942; u = 1 - beta = 5.77e-10.
  expectUvs(getUVSphere1991({-1.0, 0.0, 0.0}), 1.0 - kPi * kPiInv1991, vEq, 0);
  // (0,-1,0): u = 1 - 0.4999999997 = 0.5000000003.
  expectUvs(getUVSphere1991({0.0, -1.0, 0.0}), 1.0 - (kPi / 2) * kPiInv1991, vEq, 0);
}

TEST(UvSphere, GeneralPointBothSidesOfY) {
  // n = (0.48, 0.64, -0.6) (unit: .2304+.4096+.36 = 1). alpha = acos(0.6),
  // v = acos(0.6)*PiInv = 0.29516723513; sin(alpha) = 0.8, 0.48/0.8 = 0.6,
  // beta = acos(0.6)*PiInv; y > 0 -> u = beta.
  const double b = std::acos(0.6) * kPiInv1991;
  expectUvs(getUVSphere1991({0.48, 0.64, -0.6}), b, b, 0, 1e-12);
  expectUvs(getUVSphere1991({0.48, -0.64, -0.6}), 1.0 - b, b, 0, 1e-12);
}

TEST(UvSphere, CastRayNormalisesTheHitPointInsideOrOutside) {
  // 'S': UnitVector(tmpV, n) first, so (0,0,-2) and (0,0,-0.5) map as (0,0,-1).
  for (const Vec3& p : {Vec3{0.0, 0.0, -2.0}, Vec3{0.0, 0.0, -0.5}}) {
    const auto r = inverseMap1991(PrimType::Sphere, p);
    EXPECT_EQ(r.u, 0.0);
    EXPECT_EQ(r.v, 0.0);
    EXPECT_EQ(r.surface, 0);
    EXPECT_FALSE(r.noFaceMatched);
  }
  const auto r = inverseMap1991(PrimType::Sphere, {0.96, 1.28, -1.2});  // 2 * (0.48, 0.64, -0.6)
  EXPECT_NEAR(r.u, std::acos(0.6) * kPiInv1991, 1e-12);
  EXPECT_NEAR(r.v, std::acos(0.6) * kPiInv1991, 1e-12);
}

TEST(UvSphere, RoundoffSnapsNearThePole) {
  // (1e-6, 0, -1) normalised: -n[Z] = 1/sqrt(1+1e-12) = 1 - 5e-13, which
  // Roundoff snaps to 1 (K24): alpha = 0, v = 0, u = 0.
  const auto r = inverseMap1991(PrimType::Sphere, {1e-6, 0.0, -1.0});
  EXPECT_EQ(r.v, 0.0);
  EXPECT_EQ(r.u, 0.0);
}

// ------------------------------------------------------------------ cube (B)

TEST(UvCube, EveryFace) {
  // p = (x, y, z) with two of 0.25/0.75 on the face; see GetUVCube's table.
  expectUvs(getUVCube1991({0.0, 0.25, 0.75}), 1.0 - 0.75, 1.0 - 0.25, 3);  // x=0
  expectUvs(getUVCube1991({0.25, 0.0, 0.75}), 0.25, 0.75, 5);              // y=0
  expectUvs(getUVCube1991({0.25, 0.75, 0.0}), 0.25, 1.0 - 0.75, 0);        // z=0
  expectUvs(getUVCube1991({1.0, 0.25, 0.75}), 0.75, 1.0 - 0.25, 1);        // x=1: u=z
  expectUvs(getUVCube1991({0.25, 1.0, 0.75}), 0.25, 1.0 - 0.75, 4);        // y=1
  expectUvs(getUVCube1991({0.25, 0.75, 1.0}), 1.0 - 0.25, 1.0 - 0.75, 2);  // z=1
}

TEST(UvCube, EdgesAndCornersTakeTheFirstFaceInListingOrder) {
  // K27: x=0, y=0, z=0, x=1, y=1, z=1.
  expectUvs(getUVCube1991({0.0, 0.0, 0.5}), 0.5, 1.0, 3);  // x=0 before y=0
  expectUvs(getUVCube1991({0.5, 0.0, 0.0}), 0.5, 0.0, 5);  // y=0 before z=0
  expectUvs(getUVCube1991({1.0, 0.0, 0.5}), 1.0, 0.5, 5);  // y=0 before x=1
  expectUvs(getUVCube1991({0.5, 1.0, 0.0}), 0.5, 0.0, 0);  // z=0 before y=1
  expectUvs(getUVCube1991({1.0, 1.0, 0.5}), 0.5, 0.0, 1);  // x=1 before y=1
  expectUvs(getUVCube1991({1.0, 0.5, 1.0}), 1.0, 0.5, 1);  // x=1 before z=1
  expectUvs(getUVCube1991({0.5, 1.0, 1.0}), 0.5, 0.0, 4);  // y=1 before z=1
  expectUvs(getUVCube1991({0.0, 0.0, 0.0}), 1.0, 1.0, 3);  // corner: x=0
  expectUvs(getUVCube1991({1.0, 1.0, 1.0}), 1.0, 0.0, 1);  // corner: x=1
}

TEST(UvCube, RoundoffWindowsOfTheFaceTests) {
  // Positive side snaps within 1e-10, negative side within 1e-9 (K24, Q6);
  // u and v use the raw coordinates.
  expectUvs(getUVCube1991({5e-11, 0.5, 0.5}), 0.5, 0.5, 3);
  expectUvs(getUVCube1991({-5e-10, 0.5, 0.5}), 0.5, 0.5, 3);
  expectUvs(getUVCube1991({1.0 + 5e-11, 0.5, 0.25}), 0.25, 0.5, 1);
  expectUvs(getUVCube1991({1.0 - 5e-11, 0.5, 0.25}), 0.25, 0.5, 1);
  // 5e-10 above 0 and 5e-10 below 1 are not snapped: no face (E44).
  expectUvs(getUVCube1991({5e-10, 0.5, 0.5}), 0.0, 0.0, -1);
  expectUvs(getUVCube1991({1.0 - 5e-10, 0.5, 0.5}), 0.0, 0.0, -1);
}

TEST(UvCube, InsideAndOutsidePoints) {
  // Interior and off-face points match no face: (0, 0, -1) (E44).
  expectUvs(getUVCube1991({0.5, 0.5, 0.5}), 0.0, 0.0, -1);
  expectUvs(getUVCube1991({2.0, 0.5, 0.5}), 0.0, 0.0, -1);
  // A point in a face's plane but outside the square is still mapped.
  expectUvs(getUVCube1991({0.5, 0.0, 2.0}), 0.5, 2.0, 5);
  // Roundoff(NaN) = 0 (K24): a NaN x is "on" the x=0 face.
  expectUvs(getUVCube1991({kNaN, 0.5, 0.25}), 0.75, 0.5, 3);
}

TEST(UvCube, CastRayAppliesE44WhenNoFaceMatches) {
  const auto r = inverseMap1991(PrimType::Cube, {0.5, 0.5, 0.5});
  EXPECT_EQ(r.surface, 0);
  EXPECT_EQ(r.u, 0.0);
  EXPECT_EQ(r.v, 0.0);
  EXPECT_TRUE(r.noFaceMatched);
  const auto f = inverseMap1991(PrimType::Cube, {0.25, 0.75, 1.0});
  EXPECT_EQ(f.surface, 2);
  EXPECT_DOUBLE_EQ(f.u, 0.75);
  EXPECT_DOUBLE_EQ(f.v, 0.25);
  EXPECT_FALSE(f.noFaceMatched);
}

// -------------------------------------------------------------- cylinder (C)

TEST(UvCylinder, Body) {
  // u = acos(Roundoff(x))*TwoPiInv, 1-u when y < 0; v = z; surface 0.
  expectUvs(getUVCylinder1991({1.0, 0.0, 0.5}), 0.0, 0.5, 0);
  expectUvs(getUVCylinder1991({0.0, 1.0, 0.25}), kQuarter, 0.25, 0);              // 0.2499999323
  expectUvs(getUVCylinder1991({-1.0, 0.0, 0.75}), kPi * kTwoPiInv1991, 0.75, 0);  // 0.49999986
  expectUvs(getUVCylinder1991({0.0, -1.0, 0.5}), 1.0 - kQuarter, 0.5, 0);         // 0.7500000677
  // (0.6,-0.8): 1 - acos(0.6)*TwoPiInv = 0.85241642231.
  expectUvs(getUVCylinder1991({0.6, -0.8, 0.5}), 1.0 - std::acos(0.6) * kTwoPiInv1991, 0.5, 0);
}

TEST(UvCylinder, TwoPiInvShowsInTheQuarterTurn) {
  // acos(0)*0.1591549 = 1.5707963267949*0.1591549 = 0.2499999323114, and
  // pi*0.1591549 = 0.4999998646228: a quarter and a half turn fall short.
  EXPECT_NEAR(getUVCylinder1991({0.0, 1.0, 0.5}).u, 0.2499999323114, 1e-12);
  EXPECT_NEAR(getUVCylinder1991({-1.0, 0.0, 0.5}).u, 0.4999998646228, 1e-12);
}

TEST(UvCylinder, BodyInsideAndOutside) {
  // Interior point: the body formula still applies: acos(0.5)*TwoPiInv.
  expectUvs(getUVCylinder1991({0.5, 0.0, 0.5}), (kPi / 3) * kTwoPiInv1991, 0.5, 0, 1e-15);
  // x = 1 + 5e-11 is snapped to 1 by Roundoff: u = 0.
  expectUvs(getUVCylinder1991({1.0 + 5e-11, 0.0, 0.5}), 0.0, 0.5, 0);
  // x = 1 + 1e-9 or 1.5 (outside): acos(>1) = NaN.
  for (double x : {1.0 + 1e-9, 1.5}) {
    const UvSurface r = getUVCylinder1991({x, 0.0, 0.5});
    EXPECT_EQ(r.surface, 0);
    EXPECT_TRUE(std::isnan(r.u));
    EXPECT_EQ(r.v, 0.5);
  }
}

TEST(UvCylinder, BottomCap) {
  // Roundoff(z) == 0: v = r, u = acos(x/r)*TwoPiInv, 1-u when y < 0; surface 1.
  expectUvs(getUVCylinder1991({0.5, 0.0, 0.0}), 0.0, 0.5, 1);
  expectUvs(getUVCylinder1991({0.0, 0.5, 0.0}), kQuarter, 0.5, 1);
  expectUvs(getUVCylinder1991({0.0, -0.5, 0.0}), 1.0 - kQuarter, 0.5, 1);
  expectUvs(getUVCylinder1991({-0.5, 0.0, 0.0}), kPi * kTwoPiInv1991, 0.5, 1);
  // z within the negative Roundoff window still counts as the cap.
  expectUvs(getUVCylinder1991({0.5, 0.0, -5e-10}), 0.0, 0.5, 1);
  // ... but z = 5e-10 is body.
  expectUvs(getUVCylinder1991({1.0, 0.0, 5e-10}), 0.0, 5e-10, 0);
}

TEST(UvCylinder, TopCap) {
  // Roundoff(z) == 1: v = 1 - r, u = acos(x/r)*TwoPiInv, 1-u when y >= 0.
  expectUvs(getUVCylinder1991({0.5, 0.0, 1.0}), 1.0, 0.5, 2);
  expectUvs(getUVCylinder1991({0.0, 0.5, 1.0}), 1.0 - kQuarter, 0.5, 2);
  expectUvs(getUVCylinder1991({0.0, -0.5, 1.0}), kQuarter, 0.5, 2);
  expectUvs(getUVCylinder1991({-0.5, 0.0, 1.0}), 1.0 - kPi * kTwoPiInv1991, 0.5, 2);
}

TEST(UvCylinder, RimEdgesBelongToTheCaps) {
  expectUvs(getUVCylinder1991({1.0, 0.0, 0.0}), 0.0, 1.0, 1);
  expectUvs(getUVCylinder1991({0.0, -1.0, 0.0}), 1.0 - kQuarter, 1.0, 1);
  expectUvs(getUVCylinder1991({1.0, 0.0, 1.0}), 1.0, 0.0, 2);
}

TEST(UvCylinder, CapCentresGiveNaNu) {
  // K28: acos(0/sqrt(0)) = acos(NaN).
  const UvSurface bottom = getUVCylinder1991({0.0, 0.0, 0.0});
  EXPECT_EQ(bottom.surface, 1);
  EXPECT_EQ(bottom.v, 0.0);
  EXPECT_TRUE(std::isnan(bottom.u));
  const UvSurface top = getUVCylinder1991({0.0, 0.0, 1.0});
  EXPECT_EQ(top.surface, 2);
  EXPECT_EQ(top.v, 1.0);
  EXPECT_TRUE(std::isnan(top.u));  // 1 - NaN
}

TEST(UvCylinder, NaNzIsTheBottomCap) {
  // Roundoff(NaN) = 0 (K24).
  expectUvs(getUVCylinder1991({0.5, 0.0, kNaN}), 0.0, 0.5, 1);
}

// ------------------------------------------------------------------ cone (N)

TEST(UvCone, Cap) {
  // Roundoff(z) == 1: v = 1 - r, u = 1 - acos(x/r)*TwoPiInv, 1-u when y < 0.
  expectUvs(getUVCone1991({0.5, 0.0, 1.0}), 1.0, 0.5, 1);
  expectUvs(getUVCone1991({0.0, 0.5, 1.0}), 1.0 - kQuarter, 0.5, 1);
  expectUvs(getUVCone1991({0.0, -0.5, 1.0}), 1.0 - (1.0 - kQuarter), 0.5, 1);
  expectUvs(getUVCone1991({-0.5, 0.0, 1.0}), 1.0 - kPi * kTwoPiInv1991, 0.5, 1);
  expectUvs(getUVCone1991({1.0, 0.0, 1.0}), 1.0, 0.0, 1);          // rim: cap wins
  expectUvs(getUVCone1991({0.5, 0.0, 1.0 - 5e-11}), 1.0, 0.5, 1);  // snapped
  const UvSurface centre = getUVCone1991({0.0, 0.0, 1.0});
  EXPECT_EQ(centre.surface, 1);
  EXPECT_EQ(centre.v, 1.0);
  EXPECT_TRUE(std::isnan(centre.u));  // K28
}

TEST(UvCone, Body) {
  // v = z; u = acos(Roundoff(x/z))*TwoPiInv (z != 0), 1-u when y < 0.
  expectUvs(getUVCone1991({0.5, 0.0, 0.5}), 0.0, 0.5, 0);
  expectUvs(getUVCone1991({0.0, 0.25, 0.25}), kQuarter, 0.25, 0);
  expectUvs(getUVCone1991({-0.25, 0.0, 0.25}), kPi * kTwoPiInv1991, 0.25, 0);
  expectUvs(getUVCone1991({0.0, -0.5, 0.5}), 1.0 - kQuarter, 0.5, 0);
  // 0.3/0.5 = 0.6 exactly (0.6 is twice 0.3 in binary): 1 - acos(0.6)*TwoPiInv.
  expectUvs(getUVCone1991({0.3, -0.4, 0.5}), 1.0 - std::acos(0.6) * kTwoPiInv1991, 0.5, 0);
}

TEST(UvCone, ApexAndZeroHeight) {
  expectUvs(getUVCone1991({0.0, 0.0, 0.0}), 0.0, 0.0, 0);  // z == 0: u = 0
  // z == 0 off the axis (outside the cone): u = 0, then 1 - 0 because y < 0.
  expectUvs(getUVCone1991({0.5, -0.5, 0.0}), 1.0, 0.0, 0);
}

TEST(UvCone, InsideAndOutside) {
  // Interior: x/z = 0.5 -> acos(0.5)*TwoPiInv.
  expectUvs(getUVCone1991({0.25, 0.0, 0.5}), (kPi / 3) * kTwoPiInv1991, 0.5, 0, 1e-15);
  // Outside: x/z = 2 -> NaN (K28).
  const UvSurface r = getUVCone1991({1.0, 0.0, 0.5});
  EXPECT_EQ(r.surface, 0);
  EXPECT_EQ(r.v, 0.5);
  EXPECT_TRUE(std::isnan(r.u));
}

// --------------------------------------------------------------- pyramid (Y)
//
// Hit points lie on the listing's own planes (those IntersectPyramid uses):
// front z = rho*y, right x = 1 - rho*y, back z = 1 - rho*y, left x = rho*y,
// with rho = 0.44721359499958 / 0.894427190999916 = 0.5 - 5.6e-10.
// Worked by hand (with rho = 0.5; the printed constants move the results by
// ~1e-9, hence the 1e-8 tolerance), GetUVPoly gives for the four triangles:
//   front: u = (x - y/2)/(1 - y), v = 1 - y          (u: parallelogram branch,
//   back:  u = (1 - x - y/2)/(1 - y), v = 1 - y       v: quadratic branch with
//   left:  u = (1 - z - y/2)/(1 - y), v = 1 - y       kA = (1+y)/2, kB = y)
//   right (printed polygon (1,0,0),(1,1,0),apex, shading.md S1):
//          u = 1.25 (z - y/2)/(z - 0.5), v = 1 - 2z for z < 0.5
//          (kA = 0.5 + z, kB = 2z).
const double kRho = kPyramidPlaneA / kPyramidPlaneB;
constexpr double kUvPyrTol = 1e-8;

TEST(UvPyramid, Base) {
  expectUvs(getUVPyramid1991({0.25, 0.0, 0.75}), 0.25, 0.75, 4);
  expectUvs(getUVPyramid1991({1.0, 0.0, 1.0}), 1.0, 1.0, 4);
  expectUvs(getUVPyramid1991({0.5, 0.0, 0.0}), 0.5, 0.0, 4);  // base/front edge: base
  expectUvs(getUVPyramid1991({2.0, 0.0, 2.0}), 2.0, 2.0, 4);  // outside, in the plane
}

TEST(UvPyramid, Front) {
  // (0.5, 0.5, 0.5rho): u = (0.5-0.25)/0.5 = 0.5, v = 0.5.
  expectUvs(getUVPyramid1991({0.5, 0.5, 0.5 * kRho}), 0.5, 0.5, 0, kUvPyrTol);
  // (0.25, 0.25, 0.25rho): u = 0.125/0.75 = 1/6, v = 0.75.
  expectUvs(getUVPyramid1991({0.25, 0.25, 0.25 * kRho}), 1.0 / 6.0, 0.75, 0, kUvPyrTol);
}

TEST(UvPyramid, RightAsPrinted) {
  // (1-0.5rho, 0.5, 0.3): u = 1.25*0.05/(-0.2) = -0.3125; v: kA = 0.8,
  // kB = 0.6, tmp = 0.2, v = 1 - 0.6 = 0.4.
  expectUvs(getUVPyramid1991({1.0 - 0.5 * kRho, 0.5, 0.3}), -0.3125, 0.4, 1, kUvPyrTol);
  // (1-0.25rho, 0.25, 0.2): u = 1.25*(0.2-0.125)/(-0.3) = -0.3125; v = 0.6.
  expectUvs(getUVPyramid1991({1.0 - 0.25 * kRho, 0.25, 0.2}), -0.3125, 0.6, 1, kUvPyrTol);
}

TEST(UvPyramid, Back) {
  // (0.5, 0.5, 1-0.5rho): u = (1-0.5-0.25)/0.5 = 0.5, v = 0.5.
  expectUvs(getUVPyramid1991({0.5, 0.5, 1.0 - 0.5 * kRho}), 0.5, 0.5, 2, kUvPyrTol);
  // (0.75, 0.25, 1-0.25rho): u = 0.125/0.75 = 1/6, v = 0.75.
  expectUvs(getUVPyramid1991({0.75, 0.25, 1.0 - 0.25 * kRho}), 1.0 / 6.0, 0.75, 2, kUvPyrTol);
}

TEST(UvPyramid, Left) {
  // (0.5rho, 0.5, 0.5): u = (1-0.5-0.25)/0.5 = 0.5, v = 0.5.
  expectUvs(getUVPyramid1991({0.5 * kRho, 0.5, 0.5}), 0.5, 0.5, 3, kUvPyrTol);
  // (0.25rho, 0.25, 0.25): u = 0.625/0.75 = 5/6, v = 0.75.
  expectUvs(getUVPyramid1991({0.25 * kRho, 0.25, 0.25}), 5.0 / 6.0, 0.75, 3, kUvPyrTol);
}

TEST(UvPyramid, SlantEdgesTakeTheFirstFaceInListingOrder) {
  // front/right: front. u = (0.75-0.25)/0.5 = 1, v = 0.5.
  expectUvs(getUVPyramid1991({1.0 - 0.5 * kRho, 0.5, 0.5 * kRho}), 1.0, 0.5, 0, kUvPyrTol);
  // right/back: right. u = 1.25*(0.75-0.25)/0.25 = 2.5 (v is ~0 there: the
  // quadratic's two candidates meet, so its sign is a rounding matter).
  const UvSurface rb = getUVPyramid1991({1.0 - 0.5 * kRho, 0.5, 1.0 - 0.5 * kRho});
  EXPECT_EQ(rb.surface, 1);
  EXPECT_NEAR(rb.u, 2.5, kUvPyrTol);
  // back/left: back. u = (1-0.25-0.25)/0.5 = 1, v = 0.5.
  expectUvs(getUVPyramid1991({0.5 * kRho, 0.5, 1.0 - 0.5 * kRho}), 1.0, 0.5, 2, kUvPyrTol);
  // left/front: front. u = (0.25-0.25)/0.5 = 0, v = 0.5.
  expectUvs(getUVPyramid1991({0.5 * kRho, 0.5, 0.5 * kRho}), 0.0, 0.5, 0, kUvPyrTol);
  // apex: the front test (0.5a - 0.5b = -2.5e-10, inside the negative
  // Roundoff window) wins; u there is 0/0.
  EXPECT_EQ(getUVPyramid1991({0.5, 1.0, 0.5}).surface, 0);
}

TEST(UvPyramid, PrintedConstantMakesTheExactLeftPlaneMissAboveY02) {
  // shading.md S2: on the exact plane x = y/2, x*b - y*a = y*(b/2 - a)
  // = y * 5.0e-10, which is > 1e-10 (positive Roundoff window) for y > 0.2.
  expectUvs(getUVPyramid1991({0.25, 0.5, 0.5}), 0.0, 0.0, -1);
  // At y = 0.1 it is 5.0e-11: matched.
  EXPECT_EQ(getUVPyramid1991({0.05, 0.1, 0.5}).surface, 3);
  // The exact front plane z = y/2 gives y*(a - b/2) = -5.0e-10*y, inside
  // the NEGATIVE window (1e-9): matched even at y = 1.
  EXPECT_EQ(getUVPyramid1991({0.5, 0.5, 0.25}).surface, 0);
}

TEST(UvPyramid, InsideAndOutsideMatchNoFace) {
  expectUvs(getUVPyramid1991({0.5, 0.5, 0.5}), 0.0, 0.0, -1);
  expectUvs(getUVPyramid1991({0.5, -1.0, 0.5}), 0.0, 0.0, -1);
  const auto r = inverseMap1991(PrimType::Pyramid, {0.5, 0.5, 0.5});
  EXPECT_EQ(r.surface, 0);
  EXPECT_TRUE(r.noFaceMatched);
  EXPECT_EQ(r.u, 0.0);
  EXPECT_EQ(r.v, 0.0);
}

// ------------------------------------------------------------------ GetUVPoly

TEST(UvPoly, UnitSquareIsParallelogramBranch) {
  // pA = 0, nA = 0, nC = (1,0,0), nB = (0,-1,0): u = x, v = 1 - y.
  const Polygon sq = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}};
  const UvPair uv = getUVPoly1991({0, 0, 1}, 4, {0.25, 0.75, 0}, sq);
  EXPECT_DOUBLE_EQ(uv.u, 0.25);
  EXPECT_DOUBLE_EQ(uv.v, 0.25);
}

TEST(UvPoly, QuadraticVWithRootSwitch) {
  // (0,0,0),(2,0,0),(1,1,0),(0,1,0), n = (0,0,1): dU[Z] = 0 -> u = x/(2-y);
  // dV = (0,-2,1): kA = 1 + y/2, kB = 2y.
  const Polygon trap = {Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}};
  // (0.75,0.5): u = 0.75/1.5 = 0.5; kA = 1.25, kB = 1, tmp = 0.75, v = 0.5.
  UvPair uv = getUVPoly1991({0, 0, 1}, 4, {0.75, 0.5, 0}, trap);
  EXPECT_DOUBLE_EQ(uv.u, 0.5);
  EXPECT_DOUBLE_EQ(uv.v, 0.5);
  // (0.5,3): u = 0.5/(2-3) = -0.5; kA = 2.5, kB = 6, tmp = 0.5:
  // 1-(kA-tmp) = -1 < 0 -> v = 1-(kA+tmp) = -2.
  uv = getUVPoly1991({0, 0, 1}, 4, {0.5, 3, 0}, trap);
  EXPECT_DOUBLE_EQ(uv.u, -0.5);
  EXPECT_DOUBLE_EQ(uv.v, -2.0);
}

TEST(UvPoly, QuadraticUWithRootSwitch) {
  // (0,0,0),(1,0,0),(1,1,0),(0,2,0): dU = (0,2,-1) -> kA = Roundoff(1+x/2),
  // kB = Roundoff(2x); dV[Z] = 0 -> v = 1 - y/(2-x).
  const Polygon trap = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 2, 0}};
  // (0.5,0.75): kA 1.25, kB 1, tmp 0.75 -> u = 0.5; v = 1 - 0.75/1.5 = 0.5.
  UvPair uv = getUVPoly1991({0, 0, 1}, 4, {0.5, 0.75, 0}, trap);
  EXPECT_DOUBLE_EQ(uv.u, 0.5);
  EXPECT_DOUBLE_EQ(uv.v, 0.5);
  // (3,0): kA 2.5, kB 6, tmp 0.5: 2 > 1 -> u = 3; v = 1 - 0/1 = 1.
  uv = getUVPoly1991({0, 0, 1}, 4, {3, 0, 0}, trap);
  EXPECT_DOUBLE_EQ(uv.u, 3.0);
  EXPECT_DOUBLE_EQ(uv.v, 1.0);
  // (-1,0): kA 0.5, kB -2, tmp 1.5: -1 < 0 -> u = 2.
  uv = getUVPoly1991({0, 0, 1}, 4, {-1, 0, 0}, trap);
  EXPECT_DOUBLE_EQ(uv.u, 2.0);
  EXPECT_DOUBLE_EQ(uv.v, 1.0);
}

TEST(UvPoly, OnlyTheUPartRoundsItsCoefficients) {
  // u part (trapezoid with dU = (0,2,-1)) at (2e-11, 0): kA = Roundoff(1 +
  // 1e-11) = 1, kB = Roundoff(4e-11) = 0, tmp = 1, u = 1 - 1 = 0 exactly
  // (unrounded it would be 2e-11).
  const Polygon trapU = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 2, 0}};
  EXPECT_EQ(getUVPoly1991({0, 0, 1}, 4, {2e-11, 0, 0}, trapU).u, 0.0);
  // v part (trapezoid with dV = (0,-2,1)) at (0, 2e-11): kA = 1 + 1e-11 and
  // kB = 4e-11 are NOT rounded (as printed), tmp = sqrt(1 - 2e-11)
  // = 1 - 1e-11, v = 1 - 2e-11 (rounded coefficients would give exactly 1).
  const Polygon trapV = {Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}};
  const double v = getUVPoly1991({0, 0, 1}, 4, {0, 2e-11, 0}, trapV).v;
  EXPECT_NE(v, 1.0);
  EXPECT_NEAR(v, 1.0 - 2e-11, 1e-14);
}

TEST(UvPoly, TriangleCopiesTheApexIntoTheFourthVertex) {
  // (0,0,0),(1,0,0),(0,1,0), poly[3] ignored (set from poly[2]):
  // u = x/(1-y); kA = (1+y)/2, kB = y -> v = 1 - y. (0.25,0.5): u = 0.5,
  // kA = 0.75, tmp = sqrt(0.5625-0.5) = 0.25, v = 0.5.
  const Polygon tri = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{9, 9, 9}};
  const UvPair uv = getUVPoly1991({0, 0, 1}, 3, {0.25, 0.5, 0}, tri);
  EXPECT_DOUBLE_EQ(uv.u, 0.5);
  EXPECT_DOUBLE_EQ(uv.v, 0.5);
}

// ------------------------------------------------------------- the dispatcher

TEST(InverseMap, DispatchesOnTheType) {
  const auto c = inverseMap1991(PrimType::Cylinder, {0.0, 1.0, 0.25});
  EXPECT_EQ(c.surface, 0);
  EXPECT_DOUBLE_EQ(c.u, kQuarter);
  EXPECT_DOUBLE_EQ(c.v, 0.25);
  const auto n = inverseMap1991(PrimType::Cone, {0.5, 0.0, 1.0});
  EXPECT_EQ(n.surface, 1);
  EXPECT_DOUBLE_EQ(n.u, 1.0);
  EXPECT_DOUBLE_EQ(n.v, 0.5);
  const auto y = inverseMap1991(PrimType::Pyramid, {0.25, 0.0, 0.75});
  EXPECT_EQ(y.surface, 4);
  EXPECT_FALSE(y.noFaceMatched);
}

}  // namespace
}  // namespace prime
