// Unit primitives and bounding volumes as the 1991 listing intersects them
// (src/prime/geom/primitives_1991.h). Every expectation is computed by hand from the
// listing's formulas or from the geometry of the unit primitive; the working is
// in the comment next to it. Quirks are named by their errata ids
// (docs/prime/listing-errata.md).
#include "src/prime/geom/primitives_1991.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prime {
namespace {

using io::PrimType;

Ray ray(const Vec3& o, const Vec3& d) {
  return Ray{o, d};
}

// The pyramid's plane constants as printed in the listing. p is ~5.0e-10 below
// 1/sqrt(5) and q is 2/sqrt(5) to 15 digits, so a plane hit found through them
// lies within ~1e-9 of the exact geometric one: hand values for the pyramid's
// side faces are checked with this tolerance.
constexpr double kPyrTol = 1e-9;

// ============================================================== Swap (K6)

TEST(Swap1991, FirstFaceOnlyRecordsEntryAndReturnsFalse) {
  PrimHit h;  // tIn == 0.0: "no value placed in tIn yet"
  EXPECT_FALSE(swap1991(2.0, {1.0, 0.0, 0.0}, h));
  EXPECT_EQ(h.tIn, 2.0);
  EXPECT_EQ(h.tOut, 0.0);
  EXPECT_EQ(h.nIn, (Vec3{1.0, 0.0, 0.0}));    // n0
  EXPECT_EQ(h.nOut, (Vec3{-1.0, 0.0, 0.0}));  // n1 = -n0
}

TEST(Swap1991, FartherSecondFaceGivesInwardExitNormal_K6) {
  PrimHit h;
  swap1991(2.0, {1.0, 0.0, 0.0}, h);
  EXPECT_TRUE(swap1991(3.0, {0.0, 1.0, 0.0}, h));
  // t = 3 > tIn = 2: tOut = 3, nOut = -n0 = (0,-1,0); the entry is unchanged.
  EXPECT_EQ(h.tIn, 2.0);
  EXPECT_EQ(h.tOut, 3.0);
  EXPECT_EQ(h.nIn, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, -1.0, 0.0}));
}

TEST(Swap1991, NearerSecondFaceHandsOldEntryNormalToExit_K6_Q16) {
  PrimHit h;
  swap1991(2.0, {1.0, 0.0, 0.0}, h);
  EXPECT_TRUE(swap1991(1.0, {0.0, 1.0, 0.0}, h));
  // t = 1 < tIn = 2: tOut = old tIn = 2, tIn = 1, nOut = old nIn = (1,0,0)
  // (the farther face's OUTWARD normal), nIn = n0.
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 1.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{1.0, 0.0, 0.0}));
}

TEST(Swap1991, EqualTTakesTheFartherBranch) {
  PrimHit h;
  swap1991(2.0, {1.0, 0.0, 0.0}, h);
  EXPECT_TRUE(swap1991(2.0, {0.0, 1.0, 0.0}, h));
  // `else /* t > *tIn */` also catches t == tIn: tOut = 2, nOut = -(0,1,0).
  EXPECT_EQ(h.tIn, 2.0);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, -1.0, 0.0}));
}

// ============================================ IntersectRayPlane (E24, K41)

TEST(RayPlane1991, PlainHit) {
  // Plane z = 0 as {0,0,1,0}; o = (1,2,-2), d = (0,0,1):
  // vD = Roundoff(1) = 1, vO = -(Roundoff(-2) + 0) = 2, t = 2, pt = (1,2,0).
  Vec3 pt{};
  double t = 0.0;
  ASSERT_TRUE(
      intersectRayPlane1991(ray({1.0, 2.0, -2.0}, {0.0, 0.0, 1.0}), {0.0, 0.0, 1.0, 0.0}, pt, t));
  EXPECT_EQ(t, 2.0);
  EXPECT_EQ(pt, (Vec3{1.0, 2.0, 0.0}));
}

TEST(RayPlane1991, BehindAndParallelAreMisses) {
  Vec3 pt{};
  double t = 0.0;
  // o = (0,0,2), d = (0,0,1): vO = -2, vD = 1, t = -2 -> behind.
  EXPECT_FALSE(
      intersectRayPlane1991(ray({0.0, 0.0, 2.0}, {0.0, 0.0, 1.0}), {0.0, 0.0, 1.0, 0.0}, pt, t));
  // d = (1,0,0) lies in the plane: vD = 0 -> parallel.
  EXPECT_FALSE(
      intersectRayPlane1991(ray({0.0, 0.0, -2.0}, {1.0, 0.0, 0.0}), {0.0, 0.0, 1.0, 0.0}, pt, t));
}

TEST(RayPlane1991, OriginDotSnappedToInteger_K41_K24) {
  // o.z = -0.99999999995: Roundoff(-0.99999999995): floor(0.99999999995) = 0,
  // variance 0.99999999995 > 0.999999998 -> -1. vO = -(-1 + 0) = 1, vD = 1,
  // so t = 1 exactly, not the geometric 0.99999999995.
  Vec3 pt{};
  double t = 0.0;
  ASSERT_TRUE(intersectRayPlane1991(ray({0.0, 0.0, -0.99999999995}, {0.0, 0.0, 1.0}),
                                    {0.0, 0.0, 1.0, 0.0}, pt, t));
  EXPECT_EQ(t, 1.0);
}

TEST(RayPlane1991, PlaneWithin1e9AheadIsNotSeen_K41_K24) {
  // o.z = -1e-11 (the plane is 1e-11 ahead): Roundoff(-1e-11) -> -0.0 (variance
  // 1e-11 < 1e-9), vO = -(-0.0 + 0.0) = -0.0, t = -0.0 / 1, not > 0 -> miss.
  Vec3 pt{};
  double t = 0.0;
  EXPECT_FALSE(
      intersectRayPlane1991(ray({0.0, 0.0, -1e-11}, {0.0, 0.0, 1.0}), {0.0, 0.0, 1.0, 0.0}, pt, t));
}

TEST(RayPlane1991, PyramidFrontFaceDirectionSnapsToParallel_K41_K24_Q6) {
  // Front plane {0, p, -q, 0}; d = (0,1,0.5) runs along the face (edge midpoint
  // (0.5,0,0) to apex (0.5,1,0.5)). n.d = p - 0.5q = 0.44721359499958 -
  // 0.447213595499958 = -5.00378e-10; Roundoff of a negative number snaps when
  // the variance is < 1e-9 -> -0.0 == 0.0 -> "parallel", whatever the origin.
  Vec3 pt{};
  double t = 0.0;
  EXPECT_FALSE(intersectRayPlane1991(ray({0.5, 0.0, -1.0}, {0.0, 1.0, 0.5}),
                                     {0.0, 0.44721359499958, -0.894427190999916, 0.0}, pt, t));
}

TEST(RayPlane1991, PyramidLeftFaceDirectionIsNotSnapped_K41_K24_Q6) {
  // Left plane {q, -p, 0, 0}; d = (0.5,1,0) runs along the face (origin to
  // apex). n.d = 0.5q - p = +5.00378e-10, but the POSITIVE threshold is 1e-10,
  // so it is not snapped. o = (-1,0,0.5): n.o = -q, vO = -(-q + 0) = q,
  // t = q / 5.00378e-10 = 1.78750303e9 (calculator) > 0 -> a hit far away.
  Vec3 pt{};
  double t = 0.0;
  ASSERT_TRUE(intersectRayPlane1991(ray({-1.0, 0.0, 0.5}, {0.5, 1.0, 0.0}),
                                    {0.894427190999916, -0.44721359499958, 0.0, 0.0}, pt, t));
  EXPECT_NEAR(t / 1.78750303e9, 1.0, 1e-6);
}

// ================================= IntersectPoly / IntersectLineYAxis (E19)

// The pyramid's front triangle in (u,v) = (x,y): apex (0.5,1), base (0,0),(1,0).
constexpr std::array<UV, 4> kFrontTri{{{0.5, 1.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}}};

TEST(IntersectPoly1991, InsideAndOutside) {
  // (0.5,0.5): shifted vertices (0,0.5), (-0.5,-0.5), (0.5,-0.5). Edge 0-1 changes
  // sign, u0 >= 0 > u1: LineYAxis u-intercept 0 - 0.5*(-0.5)/(-1) = -0.25 -> 0.
  // Edge 2-0 changes sign with both u >= 0 -> 1. Odd -> inside.
  EXPECT_TRUE(intersectPoly1991(3, {0.5, 0.5}, kFrontTri));
  // (2,0.5): all shifted u < 0 -> no crossing -> outside.
  EXPECT_FALSE(intersectPoly1991(3, {2.0, 0.5}, kFrontTri));
  // (-1,0.5): shifted (1.5,0.5), (1,-0.5), (2,-0.5): edges 0-1 and 2-0 both cross
  // with u >= 0 -> 2 crossings, even -> outside.
  EXPECT_FALSE(intersectPoly1991(3, {-1.0, 0.5}, kFrontTri));
  // (0.5,1.5): every shifted v < 0 -> no sign change -> outside.
  EXPECT_FALSE(intersectPoly1991(3, {0.5, 1.5}, kFrontTri));
}

TEST(IntersectPoly1991, EdgesAndVertexFollowTheCrossingRules) {
  // Base edge (0.5,0): shifted v = 1, 0, 0 are all ">= 0" -> no crossing -> outside.
  EXPECT_FALSE(intersectPoly1991(3, {0.5, 0.0}, kFrontTri));
  // Left slanted edge (0.25,0.5): shifted (0.25,0.5), (-0.25,-0.5), (0.75,-0.5).
  // Edge 0-1: intercept 0.25 - 0.5*(-0.5)/(-1) = 0 -> not > 0 -> 0; edge 2-0:
  // both u >= 0 -> 1. Odd -> inside.
  EXPECT_TRUE(intersectPoly1991(3, {0.25, 0.5}, kFrontTri));
  // Right slanted edge (0.75,0.5): shifted (-0.25,0.5), (-0.75,-0.5), (0.25,-0.5).
  // Edge 0-1: both u < 0 -> 0; edge 2-0: intercept 0.25 - (-0.5)*(-0.5)/1 = 0
  // -> 0. Even -> outside.
  EXPECT_FALSE(intersectPoly1991(3, {0.75, 0.5}, kFrontTri));
  // Apex (0.5,1): shifted (0,0), (-0.5,-1), (0.5,-1). Edge 0-1: intercept 0 -> 0;
  // edge 2-0: both u >= 0 -> 1. Odd -> inside.
  EXPECT_TRUE(intersectPoly1991(3, {0.5, 1.0}, kFrontTri));
}

TEST(IntersectPoly1991, QuadrilateralAndBadCounts) {
  const std::array<UV, 4> square{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};
  // (0.5,0.5): shifted (-.5,-.5), (.5,-.5), (.5,.5), (-.5,.5): edge 1-2 crosses
  // with both u >= 0 -> 1; edge 3-0 has both u < 0 -> 0. Odd -> inside.
  EXPECT_TRUE(intersectPoly1991(4, {0.5, 0.5}, square));
  EXPECT_FALSE(intersectPoly1991(4, {1.5, 0.5}, square));  // all shifted u < 0
  // Counts outside uVPoly[4][2] are refused rather than read out of bounds.
  EXPECT_FALSE(intersectPoly1991(0, {0.5, 0.5}, square));
  EXPECT_FALSE(intersectPoly1991(5, {0.5, 0.5}, square));
}

TEST(IntersectLineYAxis1991, InterceptMustBeStrictlyPositive) {
  // (1,-1)-(1,1): intercept 1 - (-1)*0/2 = 1 > 0.
  EXPECT_TRUE(intersectLineYAxis1991({1.0, -1.0}, {1.0, 1.0}));
  // (-1,-1)-(1,1): intercept -1 - (-1)*2/2 = 0 -> not > 0.
  EXPECT_FALSE(intersectLineYAxis1991({-1.0, -1.0}, {1.0, 1.0}));
  // (-2,-1)-(0,1): intercept -2 - (-1)*2/2 = -1.
  EXPECT_FALSE(intersectLineYAxis1991({-2.0, -1.0}, {0.0, 1.0}));
  // Equal v: no intersection (and no division).
  EXPECT_FALSE(intersectLineYAxis1991({1.0, 0.0}, {2.0, 0.0}));
}

// ============================================================ Sphere 'S'

TEST(Sphere1991, AlongEachAxis) {
  PrimHit h;
  // o = (-3,0,0), d = (1,0,0): a = 1, b = -3, c = 9 - 1 = 8, b^2 - ac = 1,
  // roots (3+1)/1 = 4 and (3-1)/1 = 2 -> swapped: tIn = 2, tOut = 4.
  // nIn = o + 2d = (-1,0,0); nOut = -(o + 4d) = -(1,0,0) (inward, K6).
  ASSERT_TRUE(intersectSphere1991(ray({-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 2.0);
  EXPECT_EQ(h.tOut, 4.0);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{-1.0, 0.0, 0.0}));
  // Same along +y.
  ASSERT_TRUE(intersectSphere1991(ray({0.0, -3.0, 0.0}, {0.0, 1.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 2.0);
  EXPECT_EQ(h.tOut, 4.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, -1.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, -1.0, 0.0}));
  // Along -z from (0,0,3): b = -3, c = 8: tIn = 2 at (0,0,1), tOut = 4 at
  // (0,0,-1): nIn = (0,0,1), nOut = -(0,0,-1) = (0,0,1).
  ASSERT_TRUE(intersectSphere1991(ray({0.0, 0.0, 3.0}, {0.0, 0.0, -1.0}), h));
  EXPECT_EQ(h.tIn, 2.0);
  EXPECT_EQ(h.tOut, 4.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 0.0, 1.0}));
}

TEST(Sphere1991, UnnormalisedDirectionScalesT_E55) {
  PrimHit h;
  // d = (2,0,0): a = 4, b = -6, c = 8, disc = 36 - 32 = 4 -> sqrt 2;
  // roots (6+2)/4 = 2, (6-2)/4 = 1 -> tIn = 1 (x = -1), tOut = 2 (x = 1).
  ASSERT_TRUE(intersectSphere1991(ray({-3.0, 0.0, 0.0}, {2.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{-1.0, 0.0, 0.0}));
}

TEST(Sphere1991, OffCentreChordHasInwardExitNormal_K6) {
  PrimHit h;
  // o = (-2,0,0.5), d = (1,0,0): b = -2, c = 4 + 0.25 - 1 = 3.25, disc = 0.75,
  // s = sqrt(0.75) = 0.8660254037844386: tIn = 2 - s, tOut = 2 + s.
  // Points (-s,0,0.5) and (s,0,0.5): nIn = (-s,0,0.5), nOut = (-s,0,-0.5),
  // i.e. minus the outward normal at the exit.
  const double s = 0.8660254037844386;
  ASSERT_TRUE(intersectSphere1991(ray({-2.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
  EXPECT_NEAR(h.tIn, 2.0 - s, 1e-15);
  EXPECT_NEAR(h.tOut, 2.0 + s, 1e-15);
  EXPECT_NEAR(h.nIn[X], -s, 1e-15);
  EXPECT_EQ(h.nIn[Z], 0.5);
  EXPECT_NEAR(h.nOut[X], -s, 1e-15);
  EXPECT_EQ(h.nOut[Z], -0.5);
}

TEST(Sphere1991, TangentRayIsAMiss) {
  PrimHit h;
  // o = (-2,1,0), d = (1,0,0): b = -2, c = 4 + 1 - 1 = 4, disc = 4 - 4 = 0,
  // not > 0 ("two intersections occur" is required).
  EXPECT_FALSE(intersectSphere1991(ray({-2.0, 1.0, 0.0}, {1.0, 0.0, 0.0}), h));
}

TEST(Sphere1991, Misses) {
  PrimHit h;
  // Passing outside: o = (-2,2,0): c = 7, disc = 4 - 7 < 0.
  EXPECT_FALSE(intersectSphere1991(ray({-2.0, 2.0, 0.0}, {1.0, 0.0, 0.0}), h));
  // Behind: o = (3,0,0), d = (1,0,0): b = 3, c = 8, roots (-3+1) = -2, -4.
  EXPECT_FALSE(intersectSphere1991(ray({3.0, 0.0, 0.0}, {1.0, 0.0, 0.0}), h));
  // Zero direction: a = 0, b = 0, disc = 0 - 0*c = 0 -> miss (no division).
  EXPECT_FALSE(intersectSphere1991(ray({3.0, 0.0, 0.0}, {0.0, 0.0, 0.0}), h));
}

TEST(Sphere1991, OriginInsideOrOnSurfaceIsNotSeen_K7) {
  PrimHit h;
  // o = 0: b = 0, c = -1, disc = 1, roots +1 and -1: not both > 0.
  EXPECT_FALSE(intersectSphere1991(ray({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}), h));
  // o = (0.5,0,0): b = 0.5, c = -0.75, disc = 1, roots 0.5 and -1.5.
  EXPECT_FALSE(intersectSphere1991(ray({0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}), h));
  // On the surface heading in: o = (1,0,0), d = (-1,0,0): b = -1, c = 0,
  // disc = 1, roots 2 and 0; 0 is not > 0.
  EXPECT_FALSE(intersectSphere1991(ray({1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}), h));
}

// ============================================================== Cube 'B'

struct CubeFaceCase {
  const char* face;
  Vec3 o, d;
  Vec3 nIn, nOut;
};

TEST(Cube1991, EveryFaceAsEntryWithItsOutwardNormal_K6) {
  // Perpendicular rays through the face centre, unit speed, one unit away:
  // entry at t = 1, exit through the opposite face at t = 2. Faces are tested
  // x=0, x=1, y=0, y=1, z=0, z=1 (only the axis with d != 0 is looked at).
  //  - entering at the 0-face: it is found first (nIn = its normal, -e), the
  //    1-face second and farther -> nOut = -(+e) = -e (inward).
  //  - entering at the 1-face: the 0-face (t = 2) is found first, the 1-face
  //    (t = 1) second and nearer -> nIn = +e, nOut = old nIn = -e (outward).
  // Either way nOut is the 0-face's outward normal.
  const CubeFaceCase cases[] = {
      {"x=0", {-1.0, 0.5, 0.5}, {1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}},
      {"x=1", {2.0, 0.5, 0.5}, {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}},
      {"y=0", {0.5, -1.0, 0.5}, {0.0, 1.0, 0.0}, {0.0, -1.0, 0.0}, {0.0, -1.0, 0.0}},
      {"y=1", {0.5, 2.0, 0.5}, {0.0, -1.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, -1.0, 0.0}},
      {"z=0", {0.5, 0.5, -1.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}, {0.0, 0.0, -1.0}},
      {"z=1", {0.5, 0.5, 2.0}, {0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.face);
    PrimHit h;
    ASSERT_TRUE(intersectCube1991(ray(c.o, c.d), h));
    EXPECT_EQ(h.tIn, 1.0);
    EXPECT_EQ(h.tOut, 2.0);
    EXPECT_EQ(h.nIn, c.nIn);
    EXPECT_EQ(h.nOut, c.nOut);
  }
}

TEST(Cube1991, ExitNormalFlipsWithTheOrderFacesAreFound_K6) {
  PrimHit h;
  // In at x=0, out at y=1: o = (-0.5,0.25,0.5), d = (1,1,0).
  // x=0: t = 0.5, y = 0.75 -> first (nIn = (-1,0,0)); x=1: t = 1.5, y = 1.75 no;
  // y=0: t = -0.25 no; y=1: t = 0.75, x = 0.25 -> farther: nOut = -(0,1,0).
  ASSERT_TRUE(intersectCube1991(ray({-0.5, 0.25, 0.5}, {1.0, 1.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 0.5);
  EXPECT_EQ(h.tOut, 0.75);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, -1.0, 0.0}));  // inward at y=1
  // The reverse path, in at y=1, out at x=0: o = (0.75,1.5,0.5), d = (-1,-1,0).
  // x=0: t = 0.75, y = 0.75 -> first (nIn = (-1,0,0)); x=1: t = -0.25 no;
  // y=0: t = 1.5, x = -0.75 no; y=1: t = 0.5, x = 0.25 -> nearer:
  // tIn = 0.5, nIn = (0,1,0), tOut = 0.75, nOut = old nIn = (-1,0,0).
  ASSERT_TRUE(intersectCube1991(ray({0.75, 1.5, 0.5}, {-1.0, -1.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 0.5);
  EXPECT_EQ(h.tOut, 0.75);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 1.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{-1.0, 0.0, 0.0}));  // outward at x=0
}

TEST(Cube1991, UnnormalisedDirectionAndMainDiagonal) {
  PrimHit h;
  // d = (4,0,0) from (-1,.5,.5): x=0 at t = 1/4, x=1 at t = 2/4.
  ASSERT_TRUE(intersectCube1991(ray({-1.0, 0.5, 0.5}, {4.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 0.25);
  EXPECT_EQ(h.tOut, 0.5);
  // Corner to corner: o = (-1,-1,-1), d = (1,1,1): x=0 at t = 1 (y = z = 0,
  // inclusive) first, x=1 at t = 2 (y = z = 1) second -> returns before y, z.
  ASSERT_TRUE(intersectCube1991(ray({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{-1.0, 0.0, 0.0}));
}

TEST(Cube1991, GrazingRays) {
  PrimHit h;
  // Sliding along the face y=0: o = (-1,0,0.5), d = (1,0,0). Bounds are
  // inclusive: x=0 at t = 1 (y = 0 >= 0), x=1 at t = 2 -> a hit.
  ASSERT_TRUE(intersectCube1991(ray({-1.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 2.0);
  // Touching only the edge x=0,y=0: o = (-1,1,0.5), d = (1,-1,0).
  // x=0: t = 1, y = 0 -> first; x=1: t = 2, y = -1 no; y=0: t = 1, x = 0 ->
  // t == tIn -> tOut = 1, nOut = -(0,-1,0): a zero-length hit.
  ASSERT_TRUE(intersectCube1991(ray({-1.0, 1.0, 0.5}, {1.0, -1.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 1.0);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 1.0, 0.0}));
  // Just outside that edge: o = (-1,0.9375,0.5): x=0 at t = 1 gives y = -0.0625
  // (no); x=1 at t = 2 gives y = -1.0625 (no); y=0 at t = 0.9375 gives
  // x = -0.0625 (no); y=1 at t = -0.0625 (no); d.z = 0 -> miss.
  EXPECT_FALSE(intersectCube1991(ray({-1.0, 0.9375, 0.5}, {1.0, -1.0, 0.0}), h));
}

TEST(Cube1991, EnteringThroughAnEdgeEndsAtTheEdge_K7) {
  PrimHit h;
  // o = (-0.5,-0.5,0), d = (1,1,1) enters at the edge point (0,0,0.5) (t = 0.5)
  // and really leaves through z=1 at (0.5,0.5,1) (t = 1). But x=0 (t = 0.5,
  // y = 0, z = 0.5) is found first, x=1 (t = 1.5, z = 1.5) fails, and y=0
  // (t = 0.5, x = 0, z = 0.5) is the second face: Swap returns 1 with
  // tIn == tOut == 0.5 before z=1 is ever tested.
  ASSERT_TRUE(intersectCube1991(ray({-0.5, -0.5, 0.0}, {1.0, 1.0, 1.0}), h));
  EXPECT_EQ(h.tIn, 0.5);
  EXPECT_EQ(h.tOut, 0.5);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 1.0, 0.0}));
}

TEST(Cube1991, OriginInsideOrOnAFaceIsNotSeen_K7) {
  PrimHit h;
  // From the centre along +x: x=0 at t = -0.5 (no), x=1 at t = 0.5: one face.
  EXPECT_FALSE(intersectCube1991(ray({0.5, 0.5, 0.5}, {1.0, 0.0, 0.0}), h));
  // From the face x=0 inward: x=0 at t = -0/1 = -0.0 (not > 0), x=1 at t = 1.
  EXPECT_FALSE(intersectCube1991(ray({0.0, 0.5, 0.5}, {1.0, 0.0, 0.0}), h));
}

TEST(Cube1991, Misses) {
  PrimHit h;
  // Beside: o = (-1,2,0.5), d = (1,0,0): x faces at y = 2 -> no; d.y = d.z = 0.
  EXPECT_FALSE(intersectCube1991(ray({-1.0, 2.0, 0.5}, {1.0, 0.0, 0.0}), h));
  // Behind: o = (2,0.5,0.5), d = (1,0,0): t = -2 and -1.
  EXPECT_FALSE(intersectCube1991(ray({2.0, 0.5, 0.5}, {1.0, 0.0, 0.0}), h));
  // Zero direction: every face is skipped by its `xD[k] != 0.0` guard.
  EXPECT_FALSE(intersectCube1991(ray({-1.0, 0.5, 0.5}, {0.0, 0.0, 0.0}), h));
}

// ========================================================== Cylinder 'C'

TEST(Cylinder1991, AlongTheAxisThroughBothCaps) {
  PrimHit h;
  // Up from (0,0,-1): z=0 cap at t = 1 (first, nIn = (0,0,-1)), z=1 cap at
  // t = 2 (farther, nOut = -(0,0,1)).
  ASSERT_TRUE(intersectCylinder1991(ray({0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 0.0, -1.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 0.0, -1.0}));
  // Down from (0,0,2): z=0 cap at t = 2 first, z=1 cap at t = 1 nearer:
  // nIn = (0,0,1), nOut = old nIn = (0,0,-1) (outward at the bottom).
  ASSERT_TRUE(intersectCylinder1991(ray({0.0, 0.0, 2.0}, {0.0, 0.0, -1.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 0.0, -1.0}));
}

TEST(Cylinder1991, AcrossTheBodyExitNormalIsOutward_K6) {
  PrimHit h;
  // o = (-2,0,0.5), d = (1,0,0): d.z = 0 (no caps). a = 1, b = -2, c = 3,
  // disc = 1. The listing tests (-b + 1)/a = 3 first (point (1,0,.5), n0 =
  // (1,0,0)), then (-b - 1)/a = 1 (point (-1,0,.5)), nearer: nIn = (-1,0,0),
  // nOut = old nIn = (1,0,0): OUTWARD, unlike the sphere's.
  ASSERT_TRUE(intersectCylinder1991(ray({-2.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 3.0);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{1.0, 0.0, 0.0}));
  // Reverse, o = (2,0,0.5), d = (-1,0,0): b = -2, c = 3: t = 3 at x = -1 first,
  // t = 1 at x = 1 nearer: nIn = (1,0,0), nOut = (-1,0,0), again outward.
  ASSERT_TRUE(intersectCylinder1991(ray({2.0, 0.0, 0.5}, {-1.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 3.0);
  EXPECT_EQ(h.nIn, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{-1.0, 0.0, 0.0}));
  // Along +y, o = (0,-2,0.5): same numbers with y: nIn = (0,-1,0), nOut = (0,1,0).
  ASSERT_TRUE(intersectCylinder1991(ray({0.0, -2.0, 0.5}, {0.0, 1.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 3.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, -1.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 1.0, 0.0}));
}

TEST(Cylinder1991, BodyAndCapNormalsFollowFaceOrder_K6) {
  PrimHit h;
  // In through the body, out through the top: o = (-1.5,0,0), d = (1,0,0.5).
  // z=0 cap: t = -0/0.5 = -0.0, no. z=1 cap: t = 2, x = 0.5 -> first (nIn =
  // (0,0,1)). Body: a = 1, b = -1.5, c = 1.25, disc = 2.25 - 1.25 = 1:
  // t = 2.5 -> z = 1.25 no; t = 0.5 -> z = 0.25, point (-1,0,.25) -> nearer:
  // nIn = (-1,0,0), nOut = old nIn = (0,0,1) (outward at the cap).
  ASSERT_TRUE(intersectCylinder1991(ray({-1.5, 0.0, 0.0}, {1.0, 0.0, 0.5}), h));
  EXPECT_EQ(h.tIn, 0.5);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 0.0, 1.0}));
  // In through the top, out through the body: o = (0,0,1.5), d = (1,0,-1).
  // z=0 cap: t = 1.5, x = 1.5 (2.25 > 1) no. z=1 cap: t = 0.5, x = 0.5 ->
  // first. Body: a = 1, b = 0, c = -1, disc = 1: t = 1, z = 0.5, point
  // (1,0,.5) -> farther: nOut = -(1,0,0) (inward).
  ASSERT_TRUE(intersectCylinder1991(ray({0.0, 0.0, 1.5}, {1.0, 0.0, -1.0}), h));
  EXPECT_EQ(h.tIn, 0.5);
  EXPECT_EQ(h.tOut, 1.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(h.nOut, (Vec3{-1.0, 0.0, 0.0}));
}

TEST(Cylinder1991, GrazingRays) {
  PrimHit h;
  // Tangent to the body: o = (-2,1,0.5): c = 4 + 1 - 1 = 4, disc = 4 - 4 = 0.
  EXPECT_FALSE(intersectCylinder1991(ray({-2.0, 1.0, 0.5}, {1.0, 0.0, 0.0}), h));
  // Up along the side line x = 1: caps at t = 1 and 2 with x^2 + y^2 = 1 <= 1;
  // the body is skipped (a = 0).
  ASSERT_TRUE(intersectCylinder1991(ray({1.0, 0.0, -1.0}, {0.0, 0.0, 1.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 2.0);
  // In the plane of the top cap: o = (-2,0,1), d = (1,0,0): body roots 3 and 1
  // with z = 1 <= 1 -> a hit (same normals as the mid-height ray).
  ASSERT_TRUE(intersectCylinder1991(ray({-2.0, 0.0, 1.0}, {1.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 3.0);
  EXPECT_EQ(h.nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(h.nOut, (Vec3{1.0, 0.0, 0.0}));
  // In the plane of the bottom: z = 0 passes `z >= -0.0` -> a hit.
  EXPECT_TRUE(intersectCylinder1991(ray({-2.0, 0.0, 0.0}, {1.0, 0.0, 0.0}), h));
}

TEST(Cylinder1991, OriginInsideIsNotSeen_K7) {
  PrimHit h;
  // o = (0,0,0.5), d = (1,0,0): roots t = 1 (ahead) and -1: one face only.
  EXPECT_FALSE(intersectCylinder1991(ray({0.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
  // o = (0,0,0.5), d = (0,0,1): z=0 cap at t = -0.5 no, z=1 cap at 0.5: one face.
  EXPECT_FALSE(intersectCylinder1991(ray({0.0, 0.0, 0.5}, {0.0, 0.0, 1.0}), h));
}

TEST(Cylinder1991, Misses) {
  PrimHit h;
  // Outside the radius: o = (-2,2,0.5): c = 7, disc = 4 - 7 < 0.
  EXPECT_FALSE(intersectCylinder1991(ray({-2.0, 2.0, 0.5}, {1.0, 0.0, 0.0}), h));
  // Above: o = (-2,0,1.5): roots 1 and 3 but z = 1.5 > 1.
  EXPECT_FALSE(intersectCylinder1991(ray({-2.0, 0.0, 1.5}, {1.0, 0.0, 0.0}), h));
  // Parallel to the axis outside: o = (1.5,0,-1): caps at x^2 = 2.25 > 1, a = 0.
  EXPECT_FALSE(intersectCylinder1991(ray({1.5, 0.0, -1.0}, {0.0, 0.0, 1.0}), h));
  // Behind: o = (2,0,0.5), d = (1,0,0): b = 2, roots -1 and -3.
  EXPECT_FALSE(intersectCylinder1991(ray({2.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
}

// ============================================================== Cone 'N'

TEST(Cone1991, AcrossTheBodyAtHalfHeight_K5_K6) {
  PrimHit h;
  // o = (-2,0,0.5), d = (1,0,0): no cap (d.z = 0). a = 1, b = -2 - 0 = -2,
  // c = 4 - 0.25 = 3.75, disc = 4 - 3.75 = 0.25, sqrt 0.5. First root
  // (2 + 0.5)/1 = 2.5: point (0.5,0,0.5), n0 = (x,y,-z) = (0.5,0,-0.5). Second
  // 1.5: point (-0.5,0,0.5), n0 = (-0.5,0,-0.5), nearer -> nOut = old nIn.
  // Both are outward and of length 0.707 (not unit, K5).
  ASSERT_TRUE(intersectCone1991(ray({-2.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.5);
  EXPECT_EQ(h.tOut, 2.5);
  EXPECT_EQ(h.nIn, (Vec3{-0.5, 0.0, -0.5}));
  EXPECT_EQ(h.nOut, (Vec3{0.5, 0.0, -0.5}));
  // Same along +y from (0,-2,0.5).
  ASSERT_TRUE(intersectCone1991(ray({0.0, -2.0, 0.5}, {0.0, 1.0, 0.0}), h));
  EXPECT_EQ(h.tIn, 1.5);
  EXPECT_EQ(h.tOut, 2.5);
  EXPECT_EQ(h.nIn, (Vec3{0.0, -0.5, -0.5}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 0.5, -0.5}));
}

TEST(Cone1991, DownThroughTheCapOutThroughTheBody_K6) {
  PrimHit h;
  // o = (0.5,0,2), d = (0,0,-1). Cap: t = (1-2)/-1 = 1, x = 0.5 -> first
  // (nIn = (0,0,1)). Body: a = -1, b = -(2)(-1) = 2, c = 0.25 - 4 = -3.75,
  // disc = 4 - 3.75 = 0.25, sqrt 0.5: (-2 + 0.5)/-1 = 1.5 -> z = 0.5, point
  // (0.5,0,0.5), n0 = (0.5,0,-0.5) -> farther: nOut = (-0.5,0,0.5) (inward).
  ASSERT_TRUE(intersectCone1991(ray({0.5, 0.0, 2.0}, {0.0, 0.0, -1.0}), h));
  EXPECT_EQ(h.tIn, 1.0);
  EXPECT_EQ(h.tOut, 1.5);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(h.nOut, (Vec3{-0.5, 0.0, 0.5}));
}

TEST(Cone1991, UpFromBelowCrossesZ0WithoutACap_K43) {
  PrimHit h;
  // o = (0.5,0,-1), d = (0,0,1) crosses z = 0 at (0.5,0,0), where there is
  // nothing (no apex cap; the cone is a point there). Cap z=1: t = 2 -> first.
  // Body: a = -1, b = 1, c = 0.25 - 1 = -0.75, disc = 1 - 0.75 = 0.25:
  // (-1 + 0.5)/-1 = 0.5 -> z = -0.5 (lower nappe) rejected; (-1 - 0.5)/-1 = 1.5
  // -> z = 0.5, n0 = (0.5,0,-0.5), nearer: nOut = old nIn = (0,0,1).
  ASSERT_TRUE(intersectCone1991(ray({0.5, 0.0, -1.0}, {0.0, 0.0, 1.0}), h));
  EXPECT_EQ(h.tIn, 1.5);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{0.5, 0.0, -0.5}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, 0.0, 1.0}));
}

TEST(Cone1991, RaysThroughTheApexMiss_K43_K7) {
  PrimHit h;
  // Along the axis from below: cap at t = 2 (one face). Body: a = -1, b = 1,
  // c = -1, disc = 1 - 1 = 0, not > 0 (the apex is a double root).
  EXPECT_FALSE(intersectCone1991(ray({0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}), h));
  // Along the axis from above: cap at t = 1; a = -1, b = 2, c = -4, disc = 0.
  EXPECT_FALSE(intersectCone1991(ray({0.0, 0.0, 2.0}, {0.0, 0.0, -1.0}), h));
  // Obliquely through the apex: o = (-0.25,0,-1), d = (0.25,0,1) passes (0,0,0)
  // at t = 1 and (0.25,0,1) at t = 2 (cap, x^2 = 0.0625 <= 1: one face).
  // a = 0.0625 - 1 = -0.9375, b = -0.0625 + 1 = 0.9375, c = -0.9375,
  // disc = 0.87890625 - 0.87890625 = 0.
  EXPECT_FALSE(intersectCone1991(ray({-0.25, 0.0, -1.0}, {0.25, 0.0, 1.0}), h));
}

TEST(Cone1991, LowerNappeIsRejected) {
  PrimHit h;
  // o = (-2,0,-0.5), d = (1,0,0): the double cone x^2 + y^2 = z^2 is met at
  // t = 1.5 and 2.5, but z = -0.5 fails z >= 0.
  EXPECT_FALSE(intersectCone1991(ray({-2.0, 0.0, -0.5}, {1.0, 0.0, 0.0}), h));
}

TEST(Cone1991, OriginInsideIsNotSeen_K7) {
  PrimHit h;
  // o = (0,0,0.5), d = (1,0,0): a = 1, b = 0, c = -0.25, disc = 0.25: roots
  // +0.5 and -0.5 -> one face ahead.
  EXPECT_FALSE(intersectCone1991(ray({0.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
}

TEST(Cone1991, Misses) {
  PrimHit h;
  // o = (-2,2,0.5): c = 4 + 4 - 0.25 = 7.75, disc = 4 - 7.75 < 0.
  EXPECT_FALSE(intersectCone1991(ray({-2.0, 2.0, 0.5}, {1.0, 0.0, 0.0}), h));
  // Tangent: o = (-3,0.5,0.5): b = -3, c = 9 + 0.25 - 0.25 = 9, disc = 0.
  EXPECT_FALSE(intersectCone1991(ray({-3.0, 0.5, 0.5}, {1.0, 0.0, 0.0}), h));
  // Above the cap: o = (-2,0,1.5): roots at z = 1.5 > 1.
  EXPECT_FALSE(intersectCone1991(ray({-2.0, 0.0, 1.5}, {1.0, 0.0, 0.0}), h));
}

// =========================================================== Pyramid 'Y'

// Listing constants: p = 0.44721359499958 (~1/sqrt5), q = 0.894427190999916
// (~2/sqrt5). Faces are tested base (y=0), front (z=0 side, plane
// {0,p,-q,0}), right (x=1 side, {q,p,0,-q}), back (z=1 side, {0,p,q,-q}),
// left (x=0 side, {q,-p,0,0}); Swap gets the unnormalised outward normals
// (0,-1,0), (0,.5,-1), (1,.5,0), (0,.5,1), (-1,.5,0). At height y the solid
// spans x, z in [y/2, 1 - y/2].

struct PyramidCase {
  const char* face;
  Vec3 o, d;
  double tIn, tOut;
  Vec3 nIn, nOut;
};

TEST(Pyramid1991, EveryFaceAsEntryWithItsOutwardNormal_K6) {
  const PyramidCase cases[] = {
      // base: o = (0.5,-1,0.25), d = +y. Base at t = 1 (x = .5, z = .25) first.
      // Front: vD = p, vO = p + 0.25q, t = 1 + 0.25q/p ~ 1.5 (exactly 1.5 with
      // 1/sqrt5, 2/sqrt5), point (0.5,0.5,0.25) inside -> farther: nOut =
      // -(0,.5,-1).
      {"base", {0.5, -1.0, 0.25}, {0.0, 1.0, 0.0}, 1.0, 1.5, {0.0, -1.0, 0.0}, {0.0, -0.5, 1.0}},
      // front: o = (0.5,0.5,-1), d = +z. Front: vD = -q, vO = -(0.5p + q),
      // t = 1 + 0.5p/q ~ 1.25, point (0.5,0.5,0.25) first. Right/left: n.d = 0.
      // Back: vD = q, vO = 2q - 0.5p, t ~ 1.75, point (.5,.5,.75) -> farther:
      // nOut = -(0,.5,1).
      {"front", {0.5, 0.5, -1.0}, {0.0, 0.0, 1.0}, 1.25, 1.75, {0.0, 0.5, -1.0}, {0.0, -0.5, -1.0}},
      // right: o = (2,0.5,0.5), d = -x. Right: vD = -q, vO = -(q + 0.5p),
      // t ~ 1.25 at x = 0.75, first. Left: vD = -q, vO = -(2q - 0.5p), t ~ 1.75
      // at x = 0.25 -> farther: nOut = -(-1,.5,0).
      {"right", {2.0, 0.5, 0.5}, {-1.0, 0.0, 0.0}, 1.25, 1.75, {1.0, 0.5, 0.0}, {1.0, -0.5, 0.0}},
      // back: o = (0.5,0.5,2), d = -z. Front found first (t ~ 1.75 at z = .25),
      // back (t ~ 1.25 at z = .75) nearer: nIn = (0,.5,1), nOut = (0,.5,-1).
      {"back", {0.5, 0.5, 2.0}, {0.0, 0.0, -1.0}, 1.25, 1.75, {0.0, 0.5, 1.0}, {0.0, 0.5, -1.0}},
      // left: o = (-1,0.5,0.5), d = +x. Right found first (t ~ 1.75 at x = .75),
      // left (t ~ 1.25 at x = .25) nearer: nIn = (-1,.5,0), nOut = (1,.5,0).
      {"left", {-1.0, 0.5, 0.5}, {1.0, 0.0, 0.0}, 1.25, 1.75, {-1.0, 0.5, 0.0}, {1.0, 0.5, 0.0}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.face);
    PrimHit h;
    ASSERT_TRUE(intersectPyramid1991(ray(c.o, c.d), h));
    EXPECT_NEAR(h.tIn, c.tIn, kPyrTol);
    EXPECT_NEAR(h.tOut, c.tOut, kPyrTol);
    EXPECT_EQ(h.nIn, c.nIn);
    EXPECT_EQ(h.nOut, c.nOut);
  }
}

TEST(Pyramid1991, LeavingThroughTheBaseGivesOutwardExitNormal_K6) {
  PrimHit h;
  // o = (0.5,2,0.25), d = -y (the base case reversed). Base: t = -2/-1 = 2
  // (x = .5, z = .25) first. Front: vD = -p, vO = -(2p - 0.25q),
  // t = 2 - 0.25q/p ~ 1.5 -> nearer: nIn = (0,.5,-1), nOut = old nIn = (0,-1,0).
  ASSERT_TRUE(intersectPyramid1991(ray({0.5, 2.0, 0.25}, {0.0, -1.0, 0.0}), h));
  EXPECT_NEAR(h.tIn, 1.5, kPyrTol);
  EXPECT_EQ(h.tOut, 2.0);
  EXPECT_EQ(h.nIn, (Vec3{0.0, 0.5, -1.0}));
  EXPECT_EQ(h.nOut, (Vec3{0.0, -1.0, 0.0}));
}

TEST(Pyramid1991, PrintedPlaneConstantIsKept) {
  PrimHit h;
  // The 'base' case above: tOut = vO / vD = (p + 0.25q) / p. With the printed
  // p = 0.44721359499958 (not 1/sqrt5 = 0.4472135954999579...) this is, by
  // 30-digit decimal arithmetic, 1.500000000559439612; with exact constants it
  // would be 1.5. Double rounding of the three operations is below 1e-15.
  ASSERT_TRUE(intersectPyramid1991(ray({0.5, -1.0, 0.25}, {0.0, 1.0, 0.0}), h));
  EXPECT_NEAR(h.tOut, 1.500000000559439612, 1e-14);
  EXPECT_NE(h.tOut, 1.5);
}

TEST(Pyramid1991, RaySlidingOnTheBasePlaneMisses) {
  PrimHit h;
  // o = (-1,0,0.5), d = +x in the plane y = 0. Base: d.y = 0, skipped.
  // Front/back: n.d = 0. Right: vD = q, vO = -(-q - q) = 2q, t = 2, point
  // (1,0,0.5) -> (u,v) = (y,z) = (0,0.5) on the triangle's base edge: shifted
  // (1,0), (0,-0.5), (0,0.5): two crossings with u >= 0 -> outside. Left:
  // t = q/q = 1, (u,v) = (0,0.5): shifted (1,0), (0,0.5), (0,-0.5): two
  // crossings -> outside. (The cube's face-sliding ray, by contrast, hits.)
  EXPECT_FALSE(intersectPyramid1991(ray({-1.0, 0.0, 0.5}, {1.0, 0.0, 0.0}), h));
}

TEST(Pyramid1991, OriginInsideIsNotSeen_K7) {
  PrimHit h;
  // o = (0.5,0.25,0.5), d = +x: base skipped, front/back parallel. Right:
  // vO = 0.5q - 0.25p, t = 0.5 - 0.25p/q ~ 0.375 at x = 0.875 (2x + y = 2),
  // (u,v) = (0.25,0.5) inside -> one face. Left: t ~ -0.375, behind.
  EXPECT_FALSE(intersectPyramid1991(ray({0.5, 0.25, 0.5}, {1.0, 0.0, 0.0}), h));
}

TEST(Pyramid1991, Misses) {
  PrimHit h;
  // Above the apex: o = (0.5,1.5,-1), d = +z: front at t ~ 1.75 and back at
  // t ~ 1.25, both at (u,v) = (0.5,1.5): every shifted v < 0 -> outside.
  EXPECT_FALSE(intersectPyramid1991(ray({0.5, 1.5, -1.0}, {0.0, 0.0, 1.0}), h));
  // Beside: o = (2,0.5,-1), d = +z: front/back planes at (u,v) = (2,0.5),
  // all shifted u < 0 -> outside.
  EXPECT_FALSE(intersectPyramid1991(ray({2.0, 0.5, -1.0}, {0.0, 0.0, 1.0}), h));
  // Behind: o = (0.5,0.5,2), d = +z: front t = (2q - 0.5p)/(-q) < 0, back
  // t = -(0.5p + q)/q < 0.
  EXPECT_FALSE(intersectPyramid1991(ray({0.5, 0.5, 2.0}, {0.0, 0.0, 1.0}), h));
  // Below the base going down: base t = -(-1)/(-1) = -1.
  EXPECT_FALSE(intersectPyramid1991(ray({0.5, -1.0, 0.5}, {0.0, -1.0, 0.0}), h));
}

// ============================================================== dispatch

TEST(IntersectPrimitive1991, DispatchesOnTheType) {
  // One ray for all five: o = (-3,0.5,0.5), d = +x.
  const Ray r = ray({-3.0, 0.5, 0.5}, {1.0, 0.0, 0.0});
  PrimHit h;
  // 'S': b = -3, c = 9 + .25 + .25 - 1 = 8.5, disc = 0.5: tIn = 3 - sqrt(0.5).
  ASSERT_TRUE(intersectPrimitive1991(PrimType::Sphere, r, h));
  EXPECT_NEAR(h.tIn, 3.0 - 0.7071067811865476, 1e-15);
  // 'B': x=0 at t = 3, x=1 at t = 4.
  ASSERT_TRUE(intersectPrimitive1991(PrimType::Cube, r, h));
  EXPECT_EQ(h.tIn, 3.0);
  EXPECT_EQ(h.tOut, 4.0);
  // 'C': c = 9 + .25 - 1 = 8.25, disc = 0.75: tIn = 3 - sqrt(0.75), z = .5.
  ASSERT_TRUE(intersectPrimitive1991(PrimType::Cylinder, r, h));
  EXPECT_NEAR(h.tIn, 3.0 - 0.8660254037844386, 1e-15);
  // 'N': tangent to the cone (radius 0.5 at z = 0.5): disc = 9 - 9 = 0.
  EXPECT_FALSE(intersectPrimitive1991(PrimType::Cone, r, h));
  // 'Y': right at t = 4 - 0.5p/q ~ 3.75 first, left at 3 + 0.5p/q ~ 3.25.
  ASSERT_TRUE(intersectPrimitive1991(PrimType::Pyramid, r, h));
  EXPECT_NEAR(h.tIn, 3.25, kPyrTol);
  EXPECT_NEAR(h.tOut, 3.75, kPyrTol);
}

// ============================================================ Bound (K8)

TEST(Bound1991, InsideOriginSeesEveryBoundButTheSphere_K8) {
  // o = (0.25,0.25,0.5) is inside all five solids (sphere: .375 < 1; cylinder:
  // .125 <= 1; cone: .125 < z^2 = .25; pyramid: x, z in [.125,.875] at y = .25).
  // d = +x.
  const Ray r = ray({0.25, 0.25, 0.5}, {1.0, 0.0, 0.0});
  // Sphere: b = .25, c = -.625, disc = .6875: roots -.25 +- .83, one negative.
  EXPECT_FALSE(boundSphere1991(r));
  // Cube: x=1 at t = 0.75 (y = .25, z = .5).
  EXPECT_TRUE(boundCube1991(r));
  // Cylinder: a = 1, b = .25, c = -.875, disc = .9375: t = -.25 + .968 > 0, z = .5.
  EXPECT_TRUE(boundCylinder1991(r));
  // Cone: a = 1, b = .25, c = -.125, disc = .1875: t = -.25 + .433 > 0, z = .5.
  EXPECT_TRUE(boundCone1991(r));
  // Pyramid: right face at t = 0.75 - 0.25p/q ~ 0.625, (u,v) = (.25,.5) inside.
  EXPECT_TRUE(boundPyramid1991(r));
  // ...while none of the primitives report this ray (K7: one face ahead).
  PrimHit h;
  for (const PrimType type :
       {PrimType::Sphere, PrimType::Cube, PrimType::Cylinder, PrimType::Cone, PrimType::Pyramid}) {
    SCOPED_TRACE(static_cast<char>(type));
    EXPECT_FALSE(intersectPrimitive1991(type, r, h));
    EXPECT_EQ(boundHit1991(type, r), type != PrimType::Sphere);
  }
}

TEST(Bound1991, Sphere) {
  EXPECT_TRUE(boundSphere1991(ray({-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0})));   // roots 2, 4
  EXPECT_FALSE(boundSphere1991(ray({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0})));   // roots +-1
  EXPECT_FALSE(boundSphere1991(ray({-2.0, 1.0, 0.0}, {1.0, 0.0, 0.0})));  // disc 0
  EXPECT_FALSE(boundSphere1991(ray({3.0, 0.0, 0.0}, {1.0, 0.0, 0.0})));   // roots -2, -4
}

TEST(Bound1991, CubeAcceptsAnyFaceAhead) {
  // From the centre each of the six directions meets exactly one face ahead
  // (t = 0.5), found by each of BoundCube's six tests in turn.
  const Vec3 dirs[] = {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},  {0.0, -1.0, 0.0},
                       {0.0, 1.0, 0.0},  {0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}};
  for (const Vec3& d : dirs) EXPECT_TRUE(boundCube1991(ray({0.5, 0.5, 0.5}, d)));
  EXPECT_TRUE(boundCube1991(ray({-1.0, 0.5, 0.5}, {1.0, 0.0, 0.0})));   // from outside
  EXPECT_TRUE(boundCube1991(ray({0.0, 0.5, 0.5}, {1.0, 0.0, 0.0})));    // on x=0: x=1 at t=1
  EXPECT_FALSE(boundCube1991(ray({-1.0, 2.0, 0.5}, {1.0, 0.0, 0.0})));  // beside (y = 2)
  EXPECT_FALSE(boundCube1991(ray({2.0, 0.5, 0.5}, {1.0, 0.0, 0.0})));   // behind
}

TEST(Bound1991, Cylinder) {
  // Inside, up: z=0 cap t = -0.5 no, z=1 cap t = 0.5 (r = 0) -> true.
  EXPECT_TRUE(boundCylinder1991(ray({0.0, 0.0, 0.5}, {0.0, 0.0, 1.0})));
  // Inside, down: z=0 cap t = -0.5/-1 = 0.5 -> true.
  EXPECT_TRUE(boundCylinder1991(ray({0.0, 0.0, 0.5}, {0.0, 0.0, -1.0})));
  // Inside, sideways: body root t = 1 at z = 0.5 -> true.
  EXPECT_TRUE(boundCylinder1991(ray({0.0, 0.0, 0.5}, {1.0, 0.0, 0.0})));
  // Outside through the body: roots 1, 3.
  EXPECT_TRUE(boundCylinder1991(ray({-2.0, 0.0, 0.5}, {1.0, 0.0, 0.0})));
  EXPECT_FALSE(boundCylinder1991(ray({-2.0, 2.0, 0.5}, {1.0, 0.0, 0.0})));  // disc < 0
  EXPECT_FALSE(boundCylinder1991(ray({-2.0, 0.0, 1.5}, {1.0, 0.0, 0.0})));  // z = 1.5
  EXPECT_FALSE(boundCylinder1991(ray({2.0, 0.0, 0.5}, {1.0, 0.0, 0.0})));   // roots -1, -3
}

TEST(Bound1991, Cone) {
  // Up the axis from below: the cap (t = 2, r = 0) is enough for the bound,
  // although IntersectCone rejects this ray (body disc = 0, one face).
  EXPECT_TRUE(boundCone1991(ray({0.0, 0.0, -1.0}, {0.0, 0.0, 1.0})));
  // Inside, sideways: roots +-0.5, t = 0.5 at z = 0.5 -> true.
  EXPECT_TRUE(boundCone1991(ray({0.0, 0.0, 0.5}, {1.0, 0.0, 0.0})));
  // Inside, down the axis to the apex: cap t = (1 - .5)/-1 < 0; body a = -1,
  // b = 0.5, c = -0.25, disc = 0.25 - 0.25 = 0 -> false.
  EXPECT_FALSE(boundCone1991(ray({0.0, 0.0, 0.5}, {0.0, 0.0, -1.0})));
  // Outside through the body (roots 1.5, 2.5 at z = 0.5).
  EXPECT_TRUE(boundCone1991(ray({-2.0, 0.0, 0.5}, {1.0, 0.0, 0.0})));
  EXPECT_FALSE(boundCone1991(ray({-2.0, 2.0, 0.5}, {1.0, 0.0, 0.0})));   // disc < 0
  EXPECT_FALSE(boundCone1991(ray({-2.0, 0.0, -0.5}, {1.0, 0.0, 0.0})));  // lower nappe
}

TEST(Bound1991, PyramidTestsEveryFace_E10) {
  // From o = (0.5,0.25,0.5) each direction meets one face ahead; every face
  // test must be reachable (E10: the printed `}` after the base test does not
  // end BoundPyramid).
  const Vec3 o{0.5, 0.25, 0.5};
  // base: t = -0.25/-1 = 0.25 at (0.5,0,0.5).
  EXPECT_TRUE(boundPyramid1991(ray(o, {0.0, -1.0, 0.0})));
  // front (d = -z): vD = q, vO = -(0.25p - 0.5q), t = 0.5 - 0.25p/q ~ 0.375
  // at z = 0.125 (y = 2z), (u,v) = (x,y) = (0.5,0.25) inside.
  EXPECT_TRUE(boundPyramid1991(ray(o, {0.0, 0.0, -1.0})));
  // right (d = +x): t ~ 0.375 at x = 0.875, (u,v) = (0.25,0.5) inside.
  EXPECT_TRUE(boundPyramid1991(ray(o, {1.0, 0.0, 0.0})));
  // back (d = +z): front t < 0; back vD = q, vO = 0.5q - 0.25p, t ~ 0.375.
  EXPECT_TRUE(boundPyramid1991(ray(o, {0.0, 0.0, 1.0})));
  // left (d = -x): right t < 0; left vD = -q, vO = -(0.5q - 0.25p), t ~ 0.375.
  EXPECT_TRUE(boundPyramid1991(ray(o, {-1.0, 0.0, 0.0})));
  // From outside (the 'left' case of the primitive test).
  EXPECT_TRUE(boundPyramid1991(ray({-1.0, 0.5, 0.5}, {1.0, 0.0, 0.0})));
  // Misses: above the apex, beside, and sliding on the base plane.
  EXPECT_FALSE(boundPyramid1991(ray({0.5, 1.5, -1.0}, {0.0, 0.0, 1.0})));
  EXPECT_FALSE(boundPyramid1991(ray({2.0, 0.5, -1.0}, {0.0, 0.0, 1.0})));
  EXPECT_FALSE(boundPyramid1991(ray({-1.0, 0.0, 0.5}, {1.0, 0.0, 0.0})));
}

TEST(Bound1991, DispatchMatchesTheTypeFunctions) {
  // o = (-3,0.5,0.5), d = +x: sphere (disc 0.5), cube, cylinder, pyramid are
  // hit; the cone is tangent (disc 0).
  const Ray r = ray({-3.0, 0.5, 0.5}, {1.0, 0.0, 0.0});
  EXPECT_TRUE(boundHit1991(PrimType::Sphere, r));
  EXPECT_TRUE(boundHit1991(PrimType::Cube, r));
  EXPECT_TRUE(boundHit1991(PrimType::Cylinder, r));
  EXPECT_FALSE(boundHit1991(PrimType::Cone, r));
  EXPECT_TRUE(boundHit1991(PrimType::Pyramid, r));
}

}  // namespace
}  // namespace prime
