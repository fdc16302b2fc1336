// Inverse texture mapping as the 1991 listing computes it (TextureMp module,
// lines 7168-7765: GetUVSphere, GetUVCube, GetUVCylinder, GetUVCone,
// GetUVPyramid, GetUVPoly) and the primitive-type switch of CastRay
// (lines 6815-6852) that calls them.
//
// Every routine works on the hit point in PRIMITIVE (local) space:
//   'S' sphere   unit sphere at the origin; GetUVSphere receives the hit point
//                normalised by CastRay (UnitVector(tmpV, n)).
//   'B' cube     [0,1]^3.
//   'C' cylinder x^2+y^2 <= 1, 0 <= z <= 1 (caps z=0 and z=1).
//   'N' cone     x^2+y^2 <= z^2, 0 <= z <= 1 (cap z=1 only, K43).
//   'Y' pyramid  base y=0 over [0,1]x[0,1] (x,z), apex (0.5, 1, 0.5).
// The routines are NOT corrected: the listing's face order (K27), its NaNs
// (K28), its constants (E47, Q5) and its Roundoff tests (K24) are kept.
// docs/prime/port-notes/shading.md lists every reading the errata do not cover.
#pragma once
#include <array>

#include "src/math/vec.h"
#include "src/prime/geom/primitives_1991.h"

namespace prime {

// TextureMp constants as printed (E47 repairs `-` to `=`). Neither is the
// full-precision 1/pi or 1/(2 pi): PiInv*pi = 1 - 5.8e-10 and
// TwoPiInv*2pi = 1 - 2.7e-7.
inline constexpr double kPiInv = 0.318309886;
inline constexpr double kTwoPiInv = 0.1591549;

// GetUVPyramid's plane coefficients are kPyramidPlaneA/B of primitives_1991.h.

// What a GetUV* routine leaves in CastRay's (u, v, surface). E44: CastRay's
// locals start as u = v = 0.0 and surface = -1, so a routine that matches no
// face (GetUVCube, GetUVPyramid) returns exactly this initial value.
struct UvSurface {
  double u = 0.0;
  double v = 0.0;
  int surface = -1;
};

// Listing `Polygon`: double[4][3]; a triangle repeats its apex in [3].
using Polygon = std::array<Vec3, 4>;

struct UvPair {
  double u = 0.0;
  double v = 0.0;
};

// GetUVSphere(n): n must already be the unit vector of the hit point.
// E53: v = alpha*PiInv; Q5: u = acos(...) * 1.0 * PiInv (printed); K26.
UvSurface getUVSphere1991(const Vec3& n);
// GetUVCube(p): faces in the order x=0, y=0, z=0, x=1, y=1, z=1 (K27);
// surface numbers 3, 5, 0, 1, 4, 2. No face -> surface -1 (E44).
UvSurface getUVCube1991(const Vec3& p);
// GetUVCylinder(p): z=0 cap (surface 1), z=1 cap (2), body (0). Caps give
// NaN u at the axis (K28). Always sets a surface.
UvSurface getUVCylinder1991(const Vec3& p);
// GetUVCone(p): z=1 cap (surface 1), body (0) with u from x/z (K28).
UvSurface getUVCone1991(const Vec3& p);
// GetUVPyramid(p): base (surface 4), front (0), right (1), back (2),
// left (3), in that order. No face -> surface -1 (E44).
UvSurface getUVPyramid1991(const Vec3& p);
// GetUVPoly(n, numPoints, rI, poly): bilinear inverse of a quadrilateral
// (numPoints == 3: a triangle, poly[3] := poly[2]). E10 (brace rebuild of
// the v part from its u sibling) and E54 (`*v`) applied.
UvPair getUVPoly1991(const Vec3& n, int numPoints, const Vec3& rI, Polygon poly);

// CastRay's switch (lines 6815-6852) plus E44, for a primitive type and the
// hit point in primitive space (tmpV).
struct InverseMapResult {
  double u = 0.0;
  double v = 0.0;
  int surface = 0;             // index into prim->map[surface][surfType]
  bool noFaceMatched = false;  // E44 event (X3 diagnostic): surface forced to 0
};
// The listing's fatal Error() for an unknown letter (line 6843) has no
// counterpart: types are checked when the scene is loaded (io::primType).
InverseMapResult inverseMap1991(io::PrimType type, const Vec3& localHit);

}  // namespace prime
