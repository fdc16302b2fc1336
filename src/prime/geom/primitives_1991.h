// The five unit primitives of PRIME (thesis Sec. 5.3.1) intersected exactly as
// the 1991 listing does it: module Intersect (listing lines 4218-5142) for the
// primitive hits, module Bound (2518-3110) for the bounding-volume tests.
//
// Every function takes a ray ALREADY in primitive space (TransformRay, E55: the
// direction is not normalised, so t is the same parameter as in world space).
//
//   'S' sphere   unit sphere at the origin
//   'B' cube     [0,1]^3
//   'C' cylinder radius 1 about +Z, z in [0,1], both caps
//   'N' cone     apex at the origin, radius-1 cap at z = 1, no apex cap (K43)
//   'Y' pyramid  base 1x1 on y = 0 (x, z in [0,1]), apex (0.5, 1, 0.5)
//
// 1991 behaviour kept on purpose (see docs/prime/port-notes/primitives.md):
//  - K7: a hit is only reported when two surfaces lie ahead (t > 0); a ray that
//    starts inside (or on) a primitive does not see it.
//  - K6: nIn/nOut are the raw face normals as Swap() hands them out, so the exit
//    normal points inward or outward depending on the order the faces are
//    tested in. Cone and pyramid normals are not unit length (K5).
//  - K8: the bounding sphere needs both roots > 0, the other bounds accept any
//    face ahead.
//  - K41: the pyramid's plane tests Roundoff() their dot products.
// All functions are pure: no I/O, no globals, no heap.
#pragma once
#include <array>

#include "legacy_io/prime/records.h"
#include "src/geom/ray.h"
#include "src/math/vec.h"
#include "src/prime/geom/prim_hit.h"

namespace prime {

// The pyramid's side-face plane coefficients as printed everywhere in the
// listing (BoundPyramid, IntersectPyramid, GetUVPyramid; all 16 occurrences
// agree). kPyramidPlaneA is NOT 1/sqrt(5) = 0.4472135954999579: it is about
// 5.0e-10 smaller (a digit was dropped by the author, not by the OCR), while
// kPyramidPlaneB is 2/sqrt(5) to 15 digits. Kept as printed (primitives.md P1,
// shading.md S2).
inline constexpr double kPyramidPlaneA = 0.44721359499958;
inline constexpr double kPyramidPlaneB = 0.894427190999916;

// IntersectPrim's switch. Returns true on a hit and fills `hit` completely.
// On false, `hit` holds whatever partial state the listing's function left in
// it (callers must not use it). The listing's Error() for an unknown letter
// has no counterpart: a type byte is checked once, when the scene is loaded
// (io::primType).
bool intersectPrimitive1991(io::PrimType type, const Ray& local, PrimHit& hit);

bool intersectSphere1991(const Ray& local, PrimHit& hit);    // IntersectSphere
bool intersectCube1991(const Ray& local, PrimHit& hit);      // IntersectCube
bool intersectCylinder1991(const Ray& local, PrimHit& hit);  // IntersectCylinder
bool intersectCone1991(const Ray& local, PrimHit& hit);      // IntersectCone
bool intersectPyramid1991(const Ray& local, PrimHit& hit);   // IntersectPyramid

// IntersectObjBound's switch (without the file reading).
bool boundHit1991(io::PrimType type, const Ray& local);

bool boundSphere1991(const Ray& local);    // BoundSphere (K8: both roots > 0)
bool boundCube1991(const Ray& local);      // BoundCube (any face ahead)
bool boundCylinder1991(const Ray& local);  // BoundCylinder
bool boundCone1991(const Ray& local);      // BoundCone
bool boundPyramid1991(const Ray& local);   // BoundPyramid

// ---- The listing's building blocks, exposed for tests ----

// Swap (4790-4839, K6). The first face found (hit.tIn == 0.0) sets tIn = t,
// nIn = n0, nOut = -n0 and returns false. A later face returns true: if nearer
// (t < tIn) it becomes the entry and the OLD nIn becomes nOut; otherwise
// (t >= tIn, including t == tIn) tOut = t and nOut = -n0.
bool swap1991(double t, const Vec3& n0, PrimHit& hit);

// A plane a*x + b*y + c*z + d = 0 as {a, b, c, d} (E11: `double plane[4]`).
using Plane4 = std::array<double, 4>;

// IntersectRayPlane (4841-4877, E24, K41): vD = Roundoff(n.dir), parallel when
// vD == 0; vO = -(Roundoff(n.origin) + d); t = vO / vD. Returns true when
// t > 0 and then sets pt = o + t*dir. `t` is written whenever vD != 0.
bool intersectRayPlane1991(const Ray& ray, const Plane4& plane, Vec3& pt, double& t);

// A point of a 2-D (u, v) mapping, as the listing's `double[2]`.
using UV = std::array<double, 2>;

// One side face of the pyramid, shared by the scalar functions and the packet
// path (primitives_1991_packet.h): its plane, its triangle in the (u, v) plane
// obtained by dropping one coordinate, which coordinates become u and v, and
// the (unnormalised, outward) normal handed to Swap.
struct PyramidFace1991 {
  Plane4 plane;
  std::array<UV, 4> poly;  // uVPoly[4][2]; only the first 3 are used
  int uAxis;
  int vAxis;
  Vec3 normal;
};

// In the order the listing tests them: front, right, back, left
// (IntersectPyramid 4932-5045, BoundPyramid 2864-2946).
inline constexpr std::array<PyramidFace1991, 4> kPyramidFaces1991{{
    // front (z = 0 side), drop Z
    {{0.0, kPyramidPlaneA, -kPyramidPlaneB, 0.0},
     {{{0.5, 1.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}}},
     X,
     Y,
     {0.0, 0.5, -1.0}},
    // right (x = 1 side), drop X
    {{kPyramidPlaneB, kPyramidPlaneA, 0.0, -kPyramidPlaneB},
     {{{1.0, 0.5}, {0.0, 0.0}, {0.0, 1.0}, {0.0, 0.0}}},
     Y,
     Z,
     {1.0, 0.5, 0.0}},
    // back (z = 1 side), drop Z
    {{0.0, kPyramidPlaneA, kPyramidPlaneB, -kPyramidPlaneB},
     {{{0.5, 1.0}, {1.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}}},
     X,
     Y,
     {0.0, 0.5, 1.0}},
    // left (x = 0 side), drop X
    {{kPyramidPlaneB, -kPyramidPlaneA, 0.0, 0.0},
     {{{1.0, 0.5}, {0.0, 1.0}, {0.0, 0.0}, {0.0, 0.0}}},
     Y,
     Z,
     {-1.0, 0.5, 0.0}},
}};

// IntersectPoly (5050-5114, E19): crossing-number test of `point` against the
// first `numPoints` vertices of `poly` (points with v == 0 count as v >= 0).
// `poly` is taken by value because the listing shifts it in place.
// numPoints outside 1..4 returns false (the listing only ever passes 3).
bool intersectPoly1991(int numPoints, const UV& point, std::array<UV, 4> poly);

// IntersectLineYAxis (5116-5132): true when the segment pt1-pt2 meets v = 0 at
// u > 0 (strictly); false for a segment with pt1.v == pt2.v.
bool intersectLineYAxis1991(const UV& pt1, const UV& pt2);

}  // namespace prime
