// Modules Intersect (listing lines 4218-5142) and Bound (2518-3110) of the 1991
// listing. Every expression keeps the listing's operands and order of
// operations (Sqr() for squares, left-to-right sums) so results match the
// listing's double arithmetic. Structure follows errata E10 (braces rebuilt at
// the page breaks from the sibling functions). E20 (prototypes) and E23
// (IntersectPrim's locals) need no code here: C++ declares everything once.
//
// Division by zero / sqrt of a negative: every division in these functions is
// guarded by the listing itself (xD[k] != 0, a != 0, vD != 0, pt2.v != pt1.v)
// and sqrt() is only taken of a value > 0. The only unguarded division is the
// sphere's `/ a`, reached with a == 0 only when Sqr() of a direction component
// underflows; it then gives IEEE Inf/NaN (Q11, X2), as do non-finite inputs.
#include "src/prime/geom/primitives_1991.h"

#include <cmath>

#include "src/prime/math/listing_math.h"
#include "src/prime/math/listing_vec.h"

namespace prime {

using io::PrimType;

namespace {

constexpr int U = 0;  // Define.h: #define U 0
constexpr int V = 1;  // Define.h: #define V 1

// Does the ray meet this pyramid side face ahead? (`if(IntersectRayPlane(...))
// { ...; if(IntersectPoly(3, uVPoint, uVPoly)) ... }`, E25: `&t`.)
bool hitsPyramidFace(const Ray& ray, const PyramidFace1991& face, double& t) {
  Vec3 pt{};
  if (!intersectRayPlane1991(ray, face.plane, pt, t)) return false;
  const UV uvPoint{pt[face.uAxis], pt[face.vAxis]};
  return intersectPoly1991(3, uvPoint, face.poly);
}

// The square face of the cube (or the pyramid's base) on the plane
// coordinate[axis] = level: t = (level - o) / d, then the two other coordinates
// must lie in [0, 1] (inclusive). The listing writes `-ray->xO[k] / ray->xD[k]`
// for level 0 and `(1.0 - ray->xO[k]) / ray->xD[k]` for level 1; both are kept.
// The caller has already checked ray.d[axis] != 0.
bool hitsUnitSquare(const Ray& ray, int axis, bool levelOne, double& t) {
  t = levelOne ? (1.0 - ray.o[axis]) / ray.d[axis] : -ray.o[axis] / ray.d[axis];
  if (!(t > 0.0)) return false;
  const int a = axis == X ? Y : X;  // the listing's first in-face coordinate
  const int b = axis == Z ? Y : Z;  // and its second
  const double ca = ray.o[a] + t * ray.d[a];
  const double cb = ray.o[b] + t * ray.d[b];
  return (ca >= 0.0) && (ca <= 1.0) && (cb >= 0.0) && (cb <= 1.0);
}

// A cap of the cylinder / cone: the disc x^2 + y^2 <= 1 on z = 0 or z = 1.
// The caller has already checked ray.d[Z] != 0.
bool hitsUnitDisc(const Ray& ray, bool levelOne, double& t) {
  t = levelOne ? (1.0 - ray.o[Z]) / ray.d[Z] : -ray.o[Z] / ray.d[Z];
  if (!(t > 0.0)) return false;
  const double x = ray.o[X] + t * ray.d[X];
  const double y = ray.o[Y] + t * ray.d[Y];
  return (sqr(x) + sqr(y)) <= 1.0;
}

// The quadratic of the cylinder body (a, b, c as printed in IntersectCylinder
// 4361-4364 and BoundCylinder 3012-3015). Returns false when a == 0 or the
// discriminant is not > 0; otherwise t1 = (-b + sqrt(d)) / a (tested first) and
// t2 = (-b - sqrt(d)) / a (E22: `(d = sqrt(d))`).
bool cylinderRoots(const Ray& ray, double& t1, double& t2) {
  double a, b, c, d;
  if ((a = sqr(ray.d[X]) + sqr(ray.d[Y])) == 0.0) return false;
  b = ray.o[X] * ray.d[X] + ray.o[Y] * ray.d[Y];
  c = sqr(ray.o[X]) + sqr(ray.o[Y]) - 1.0;
  if (!((d = sqr(b) - (a * c)) > 0.0)) return false;
  d = std::sqrt(d);
  t1 = (-b + d) / a;
  t2 = (-b - d) / a;
  return true;
}

// The same for the cone body (IntersectCone 4456-4469, BoundCone 3074-3082).
// `a` may be negative (steep rays); then t1 is the smaller root.
bool coneRoots(const Ray& ray, double& t1, double& t2) {
  double a, b, c, d;
  if ((a = sqr(ray.d[X]) + sqr(ray.d[Y]) - sqr(ray.d[Z])) == 0.0) return false;
  b = ray.o[X] * ray.d[X] + ray.o[Y] * ray.d[Y] - ray.o[Z] * ray.d[Z];
  c = sqr(ray.o[X]) + sqr(ray.o[Y]) - sqr(ray.o[Z]);
  if (!((d = sqr(b) - (a * c)) > 0.0)) return false;
  d = std::sqrt(d);
  t1 = (-b + d) / a;
  t2 = (-b - d) / a;
  return true;
}

// The sphere's roots as IntersectSphere (4609-4616) and BoundSphere compute them.
bool sphereRoots(const Ray& ray, double& tIn, double& tOut) {
  const double a = sqr(ray.d[X]) + sqr(ray.d[Y]) + sqr(ray.d[Z]);
  const double b = ray.o[X] * ray.d[X] + ray.o[Y] * ray.d[Y] + ray.o[Z] * ray.d[Z];
  const double c = sqr(ray.o[X]) + sqr(ray.o[Y]) + sqr(ray.o[Z]) - 1.0;
  double tmp;
  if (!((tmp = sqr(b) - (a * c)) > 0.0)) return false;  // "two intersections occur"
  tmp = std::sqrt(tmp);
  tIn = (-b + tmp) / a;
  tOut = (-b - tmp) / a;
  return true;
}

bool inUnitRange(double z) {
  return (z <= 1.0) && (z >= 0.0);
}

}  // namespace

// ---------------------------------------------------------------- building blocks

bool swap1991(double t, const Vec3& n0, PrimHit& hit) {
  const Vec3 n1{-n0[X], -n0[Y], -n0[Z]};  // for(i = X; i < W; i++) n1[i] = -n0[i];
  if (hit.tIn == 0.0) {                   // "a value has not yet been placed in tIn"
    hit.tIn = t;
    hit.nIn = n0;
    hit.nOut = n1;
    return false;
  }
  if (t < hit.tIn) {
    hit.tOut = hit.tIn;
    hit.tIn = t;
    hit.nOut = hit.nIn;  // K6 (Q16: printed): the old ENTRY normal, pointing outward
    hit.nIn = n0;
  } else {  // "t > *tIn", but also t == *tIn (a face met at the same t: an edge)
    hit.tOut = t;
    hit.nOut = n1;  // K6: minus the face's outward normal, pointing inward
  }
  return true;
}

bool intersectRayPlane1991(const Ray& ray, const Plane4& plane, Vec3& pt, double& t) {
  const Vec3 n{plane[0], plane[1], plane[2]};  // PointVectorDot/PointDot use X..Z only
  double vD, vO;
  if ((vD = roundoff(dot(n, ray.d))) == 0.0) return false;  // K41: parallel (snapped)
  vO = -(roundoff(dot(n, ray.o)) + plane[3]);               // K41, E11: plane[3]
  if ((t = vO / vD) > 0.0) {                                // E24: `*t`
    for (int i = X; i < W; i++) pt[i] = ray.o[i] + t * ray.d[i];
    return true;
  }
  return false;  // intersection behind the ray
}

bool intersectLineYAxis1991(const UV& pt1, const UV& pt2) {
  if (pt2[1] != pt1[1]) {
    return (pt1[U] - pt1[V] * (pt2[U] - pt1[U]) / (pt2[V] - pt1[V])) > 0.0;
  }
  return false;
}

bool intersectPoly1991(int numPoints, const UV& point, std::array<UV, 4> poly) {
  if (numPoints < 1 || numPoints > 4) return false;  // uVPoly[4][2]; the listing passes 3
  int numIntersects = 0;
  for (int pt = 0; pt < numPoints; pt++) {
    poly[pt][U] -= point[U];
    poly[pt][V] -= point[V];
  }
  int sH = (poly[0][V] >= 0.0) ? 1 : -1;
  for (int pt = 0; pt < numPoints; pt++) {
    const int nextPt = (pt + 1) % numPoints;
    const int nSH = (poly[nextPt][V] >= 0.0) ? 1 : -1;
    if (sH != nSH) {
      if ((poly[pt][U] >= 0.0) && (poly[nextPt][U] >= 0.0)) {
        numIntersects++;
      } else if ((poly[pt][U] >= 0.0) || (poly[nextPt][U] >= 0.0)) {
        numIntersects += intersectLineYAxis1991(poly[pt], poly[nextPt]) ? 1 : 0;
      }
    }
    sH = nSH;
  }
  return numIntersects % 2 != 0;  // (int) fmod(numIntersects, 2.0); numIntersects >= 0
}

// ---------------------------------------------------------------- Intersect module

bool intersectSphere1991(const Ray& ray, PrimHit& hit) {
  // No `*tIn = 0.0` here: IntersectSphere writes tIn/tOut only when the
  // discriminant is > 0, and the normals only on a hit.
  if (!sphereRoots(ray, hit.tIn, hit.tOut)) return false;
  if (!((hit.tIn > 0.0) && (hit.tOut > 0.0))) return false;  // K7: both ahead
  if (hit.tOut < hit.tIn) {
    const double tmp = hit.tOut;  // swap tIn and tOut
    hit.tOut = hit.tIn;
    hit.tIn = tmp;
  }
  for (int i = X; i < W; i++) {                       // E18: `i < N` read as `i < W`
    hit.nIn[i] = ray.o[i] + hit.tIn * ray.d[i];       // the entry point (outward)
    hit.nOut[i] = -(ray.o[i] + hit.tOut * ray.d[i]);  // minus the exit point (inward, K6)
  }
  return true;
}

bool intersectCube1991(const Ray& ray, PrimHit& hit) {
  hit.tIn = 0.0;
  hit.tOut = 0.0;
  double t;
  // Faces in the listing's order x=0, x=1, y=0, y=1, z=0, z=1; both faces of an
  // axis inside `if(ray->xD[k] != 0.0)` (E10: the x=1 face was printed outside).
  for (int axis = X; axis <= Z; axis++) {
    if (ray.d[axis] == 0.0) continue;
    for (const bool levelOne : {false, true}) {
      if (hitsUnitSquare(ray, axis, levelOne, t)) {
        Vec3 n0{0.0, 0.0, 0.0};
        n0[axis] = levelOne ? 1.0 : -1.0;
        if (swap1991(t, n0, hit)) return true;  // K7: the second face ends the search
      }
    }
  }
  return false;  // NO intersection
}

bool intersectCylinder1991(const Ray& ray, PrimHit& hit) {
  hit.tIn = 0.0;
  hit.tOut = 0.0;
  double t, t1, t2;
  if (ray.d[Z] != 0.0) {
    if (hitsUnitDisc(ray, false, t) && swap1991(t, {0.0, 0.0, -1.0}, hit)) return true;
    if (hitsUnitDisc(ray, true, t) && swap1991(t, {0.0, 0.0, 1.0}, hit)) return true;
  }
  if (cylinderRoots(ray, t1, t2)) {  // E21 (`ray`), E22 (`d = sqrt(d)`)
    for (const double root : {t1, t2}) {
      if ((t = root) > 0.0) {
        const double z = ray.o[Z] + t * ray.d[Z];
        if ((z <= 1.0) && (z >= -0.0)) {  // printed `-0.0`; the same test as >= 0.0
          Vec3 n0{};
          for (int i = X; i < Z; i++) n0[i] = ray.o[i] + t * ray.d[i];
          n0[Z] = 0.0;
          if (swap1991(t, n0, hit)) return true;
        }
      }
    }
  }
  return false;
}

bool intersectCone1991(const Ray& ray, PrimHit& hit) {
  hit.tIn = 0.0;
  hit.tOut = 0.0;
  double t, t1, t2;
  // Only the z = 1 cap; the apex (z = 0) has none (K43).
  if (ray.d[Z] != 0.0) {
    if (hitsUnitDisc(ray, true, t) && swap1991(t, {0.0, 0.0, 1.0}, hit)) return true;
  }
  if (coneRoots(ray, t1, t2)) {
    for (const double root : {t1, t2}) {
      if ((t = root) > 0.0) {
        const double z = ray.o[Z] + t * ray.d[Z];
        // The 2nd root repeats this z test (K43); repeating it changes nothing.
        if (inUnitRange(z)) {
          const double x = ray.o[X] + t * ray.d[X];
          const double y = ray.o[Y] + t * ray.d[Y];
          if (swap1991(t, {x, y, -z}, hit)) return true;  // gradient/2, not unit (K5)
        }
      }
    }
  }
  return false;
}

bool intersectPyramid1991(const Ray& ray, PrimHit& hit) {
  // E08: these two assignments follow a `/*` left open by the OCR (4908); they are code.
  hit.tIn = 0.0;
  hit.tOut = 0.0;
  double t;
  // base (y = 0)
  if (ray.d[Y] != 0.0) {
    if (hitsUnitSquare(ray, Y, false, t) && swap1991(t, {0.0, -1.0, 0.0}, hit)) return true;
  }
  // front, right, back, left (E10: the base's stray `}` does not end the function)
  for (const PyramidFace1991& face : kPyramidFaces1991) {
    if (hitsPyramidFace(ray, face, t) && swap1991(t, face.normal, hit)) return true;
  }
  return false;
}

bool intersectPrimitive1991(PrimType type, const Ray& local, PrimHit& hit) {
  // The listing's default, Error("switch case fall to default ..."), cannot
  // happen: types are checked when the scene is loaded.
  switch (type) {
    case PrimType::Sphere:
      return intersectSphere1991(local, hit);
    case PrimType::Cube:
      return intersectCube1991(local, hit);
    case PrimType::Pyramid:
      return intersectPyramid1991(local, hit);
    case PrimType::Cylinder:
      return intersectCylinder1991(local, hit);
    case PrimType::Cone:
      return intersectCone1991(local, hit);
  }
  return false;  // not reached
}

// ---------------------------------------------------------------- Bound module

bool boundSphere1991(const Ray& ray) {
  double tIn = 0.0, tOut = 0.0;
  if (!sphereRoots(ray, tIn, tOut)) return false;
  return (tIn > 0.0) && (tOut > 0.0);  // K8: both roots ahead
}

bool boundCube1991(const Ray& ray) {
  double t;
  for (int axis = X; axis <= Z; axis++) {
    if (ray.d[axis] == 0.0) continue;
    if (hitsUnitSquare(ray, axis, false, t)) return true;  // K8: any face ahead
    if (hitsUnitSquare(ray, axis, true, t)) return true;
  }
  return false;  // NO intersection
}

bool boundCylinder1991(const Ray& ray) {
  double t, t1, t2;
  if (ray.d[Z] != 0.0) {  // E10: the z=1 cap belongs inside this `if` (2993-3011)
    if (hitsUnitDisc(ray, false, t)) return true;
    if (hitsUnitDisc(ray, true, t)) return true;
  }
  if (cylinderRoots(ray, t1, t2)) {
    if (t1 > 0.0 && inUnitRange(ray.o[Z] + t1 * ray.d[Z])) return true;
    if (t2 > 0.0 && inUnitRange(ray.o[Z] + t2 * ray.d[Z])) return true;
  }
  return false;
}

bool boundCone1991(const Ray& ray) {
  double t, t1, t2;
  if (ray.d[Z] != 0.0) {
    if (hitsUnitDisc(ray, true, t)) return true;
  }
  if (coneRoots(ray, t1, t2)) {
    if (t1 > 0.0 && inUnitRange(ray.o[Z] + t1 * ray.d[Z])) return true;
    if (t2 > 0.0 && inUnitRange(ray.o[Z] + t2 * ray.d[Z])) return true;
  }
  return false;
}

bool boundPyramid1991(const Ray& ray) {
  double t;
  if (ray.d[Y] != 0.0) {
    if (hitsUnitSquare(ray, Y, false, t)) return true;  // base
  }
  // E10: BoundPyramid's printed `}` after the base test (2856) is a page-break
  // artefact; the four side faces follow (E11: `double plane[4]`).
  for (const PyramidFace1991& face : kPyramidFaces1991) {
    if (hitsPyramidFace(ray, face, t)) return true;
  }
  return false;
}

bool boundHit1991(PrimType type, const Ray& local) {
  // The listing's default, Error("switch case fell to default ..."), cannot
  // happen: types are checked when the scene is loaded.
  switch (type) {
    case PrimType::Sphere:
      return boundSphere1991(local);
    case PrimType::Cube:
      return boundCube1991(local);
    case PrimType::Pyramid:
      return boundPyramid1991(local);
    case PrimType::Cylinder:
      return boundCylinder1991(local);
    case PrimType::Cone:
      return boundCone1991(local);
  }
  return false;  // not reached
}

}  // namespace prime
