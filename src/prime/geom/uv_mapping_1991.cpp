#include "src/prime/geom/uv_mapping_1991.h"

#include <cmath>

#include "src/prime/math/listing_math.h"
#include "src/prime/math/listing_vec.h"

namespace prime {

// GetUVSphere, lines 7351-7386.
UvSurface getUVSphere1991(const Vec3& n) {
  // `Vector cross = {0.0, 1.0, 0.0}; /* VectorCross(pole, equator, cross) */`
  const Vec3 crossPE = {0.0, 1.0, 0.0};
  UvSurface r;
  r.surface = 0;  // "Only one surface ie element 0"
  const double alpha = std::acos(roundoff(-n[Z]));
  // E53: `(*v = alpha * PiInv) == 0.0`. With the 9-digit PiInv, v is never
  // exactly 1.0 (alpha = pi gives 1 - 5.8e-10), so only the alpha = 0 pole
  // takes this branch.
  if (((r.v = alpha * kPiInv) == 0.0) || (r.v == 1.0)) {
    r.u = 0.0;
  } else {
    // Q5: `* 1.0 * PiInv` as printed (not TwoPiInv); C's sin() in radians.
    const double beta = std::acos(roundoff(n[X] / std::sin(alpha))) * 1.0 * kPiInv;
    if (dot(crossPE, n) > 0.0) {
      r.u = beta;
    } else {
      r.u = 1.0 - beta;  // K26: also for y == 0 exactly
    }
  }
  return r;
}

// GetUVCube, lines 7389-7441. K27: the first face in this order wins.
UvSurface getUVCube1991(const Vec3& n) {
  UvSurface r;  // E44: stays (0, 0, -1) when no face matches
  if (roundoff(n[X]) == 0.0) {
    r.u = 1.0 - n[Z];
    r.v = 1.0 - n[Y];
    r.surface = 3;
    return r;
  }
  if (roundoff(n[Y]) == 0.0) {
    r.u = n[X];
    r.v = n[Z];
    r.surface = 5;
    return r;
  }
  if (roundoff(n[Z]) == 0.0) {
    r.u = n[X];
    r.v = 1.0 - n[Y];
    r.surface = 0;
    return r;
  }
  if (roundoff(n[X]) == 1.0) {
    r.v = 1.0 - n[Y];
    r.u = n[Z];
    r.surface = 1;
    return r;
  }
  if (roundoff(n[Y]) == 1.0) {
    r.u = n[X];
    r.v = 1.0 - n[Z];
    r.surface = 4;
    return r;
  }
  if (roundoff(n[Z]) == 1.0) {
    r.u = 1.0 - n[X];
    r.v = 1.0 - n[Y];
    r.surface = 2;
    return r;
  }
  return r;
}

// GetUVCylinder, lines 7443-7486. K28: the caps divide by the radius, so the
// axis point gives acos(0/0) = NaN.
UvSurface getUVCylinder1991(const Vec3& n) {
  UvSurface r;
  if (roundoff(n[Z]) == 0.0) {
    r.surface = 1;
    r.v = std::sqrt(sqr(n[X]) + sqr(n[Y]));
    r.u = std::acos(n[X] / std::sqrt(sqr(n[X]) + sqr(n[Y]))) * kTwoPiInv;
    if (n[Y] < 0.0) {
      r.u = 1 - r.u;
    }
  } else {
    if (roundoff(n[Z]) == 1.0) {
      r.surface = 2;
      r.v = 1.0 - std::sqrt(sqr(n[X]) + sqr(n[Y]));
      r.u = std::acos(n[X] / std::sqrt(sqr(n[X]) + sqr(n[Y]))) * kTwoPiInv;
      if (n[Y] >= 0.0) {
        r.u = 1.0 - r.u;
      }
    } else {  // intersects main body
      r.surface = 0;
      r.v = n[Z];
      r.u = std::acos(roundoff(n[X])) * kTwoPiInv;
      if (n[Y] < 0.0) {
        r.u = 1.0 - r.u;
      }
    }
  }
  return r;
}

// GetUVCone, lines 7488-7532. The comment banner says "cylinder"; it is the
// cone (cap at z = 1, body x^2+y^2 = z^2).
UvSurface getUVCone1991(const Vec3& n) {
  UvSurface r;
  if (roundoff(n[Z]) == 1.0) {
    r.surface = 1;
    r.v = 1.0 - std::sqrt(sqr(n[X]) + sqr(n[Y]));
    r.u = 1.0 - std::acos(n[X] / std::sqrt(sqr(n[X]) + sqr(n[Y]))) * kTwoPiInv;
    if (n[Y] < 0.0) {
      r.u = 1 - r.u;
    }
  } else {  // intersects main body
    r.surface = 0;
    r.v = n[Z];
    if (n[Z] != 0.0) {
      r.u = std::acos(roundoff(n[X] / n[Z])) * kTwoPiInv;  // K28: x/z
    } else {
      r.u = 0.0;
    }
    if (n[Y] < 0.0) {
      r.u = 1.0 - r.u;
    }
  }
  return r;
}

// GetUVPyramid, lines 7534-7643 (E10: the printed `}` `}` after the back face
// closes nothing; the left face is part of the function).
UvSurface getUVPyramid1991(const Vec3& rI) {
  UvSurface r;  // E44: stays (0, 0, -1) when no face matches
  Polygon poly{};
  Vec3 n{};
  if (roundoff(rI[Y]) == 0.0) {  // base
    r.u = rI[X];
    r.v = rI[Z];
    r.surface = 4;
    return r;
  }
  // front
  if (roundoff((rI[Y] * kPyramidPlaneA) - (rI[Z] * kPyramidPlaneB)) == 0.0) {
    poly[0] = {0.0, 0.0, 0.0};
    poly[1] = {1.0, 0.0, 0.0};
    poly[2] = {0.5, 1.0, 0.5};
    n = {0.0, -kPyramidPlaneA, kPyramidPlaneB};
    unitVector(n, n);  // only the front face normalises its n (as printed)
    const UvPair uv = getUVPoly1991(n, 3, rI, poly);
    r.u = uv.u;
    r.v = uv.v;
    r.surface = 0;
    return r;
  }
  // right. shading.md S1: poly[1] is printed (1,1,0), which is not a vertex
  // of the pyramid (the face's other base corner is (1,0,1)); kept.
  if (roundoff((rI[X] * kPyramidPlaneB) + (rI[Y] * kPyramidPlaneA) - kPyramidPlaneB) == 0.0) {
    poly[0] = {1.0, 0.0, 0.0};
    poly[1] = {1.0, 1.0, 0.0};
    poly[2] = {0.5, 1.0, 0.5};
    n = {-kPyramidPlaneB, -kPyramidPlaneA, 0.0};
    const UvPair uv = getUVPoly1991(n, 3, rI, poly);
    r.u = uv.u;
    r.v = uv.v;
    r.surface = 1;
    return r;
  }
  // back
  if (roundoff((rI[Y] * kPyramidPlaneA) + (rI[Z] * kPyramidPlaneB) - kPyramidPlaneB) == 0.0) {
    poly[0] = {1.0, 0.0, 1.0};
    poly[1] = {0.0, 0.0, 1.0};
    poly[2] = {0.5, 1.0, 0.5};
    n = {0.0, -kPyramidPlaneA, -kPyramidPlaneB};
    const UvPair uv = getUVPoly1991(n, 3, rI, poly);
    r.u = uv.u;
    r.v = uv.v;
    r.surface = 2;
    return r;
  }
  // left
  if (roundoff((rI[X] * kPyramidPlaneB) - (rI[Y] * kPyramidPlaneA)) == 0.0) {
    poly[0] = {0.0, 0.0, 1.0};
    poly[1] = {0.0, 0.0, 0.0};
    poly[2] = {0.5, 1.0, 0.5};
    n = {kPyramidPlaneB, -kPyramidPlaneA, 0.0};
    const UvPair uv = getUVPoly1991(n, 3, rI, poly);
    r.u = uv.u;
    r.v = uv.v;
    r.surface = 3;
    return r;
  }
  return r;
}

// GetUVPoly, lines 7649-7759. PointVectorDot and VectorDot are the same
// X, Y, Z summation (Matrix module), i.e. dot().
UvPair getUVPoly1991(const Vec3& n, int numPoints, const Vec3& rI, Polygon poly) {
  UvPair out;
  if (numPoints == 3) {  // deal with triangular polygon
    for (int i = X; i < W; i++) poly[3][i] = poly[2][i];
  }
  Vec3 pA{}, pB{}, pC{}, pD{};
  for (int i = X; i < W; i++) {
    pA[i] = poly[0][i] - poly[1][i] + poly[2][i] - poly[3][i];
    pB[i] = poly[1][i] - poly[0][i];
    pC[i] = poly[3][i] - poly[0][i];
    pD[i] = poly[0][i];
  }

  // Get *u
  const Vec3 nA = cross(pA, n);
  const Vec3 nC = cross(pC, n);
  Vec3 dU{};
  dU[X] = dot(pD, nC);
  dU[Y] = dot(pD, nA) + dot(pB, nC);
  dU[Z] = dot(pB, nA);
  if (dU[Z] != 0.0) {  // polygon is NOT a parallelogram
    Vec3 qUX{}, qUY{};
    for (int i = X; i < W; i++) {
      qUX[i] = nA[i] / (2.0 * dU[Z]);
      qUY[i] = -nC[i] / dU[Z];
    }
    const double dUX = -dU[Y] / (2.0 * dU[Z]);
    const double dUY = dU[X] / dU[Z];
    const double kA = roundoff(dUX + (dot(rI, qUX)));
    const double kB = roundoff(dUY + (dot(rI, qUY)));
    const double tmp = std::sqrt(sqr(kA) - kB);
    if (((out.u = kA - tmp) > 1.0) || (out.u < 0.0)) {
      out.u = kA + tmp;
    }
  } else {  // polygon is a parallelogram
    out.u = (dot(rI, nC) - dU[X]) / (dU[Y] - (dot(rI, nA)));
  }

  // Get *v. E10: the printed `} }` after `kA = ...` belongs after the root
  // choice, so the `else` pairs with `if(dV[Z] != 0.0)` as in the u part.
  // E54: `v` -> `*v`. Unlike the u part, kA and kB are NOT Roundoff'ed here
  // (as printed; shading.md S3).
  const Vec3 nB = cross(pB, n);
  Vec3 dV{};
  dV[X] = dot(pD, nB);
  dV[Y] = dot(pD, nA) + dot(pC, nB);
  dV[Z] = dot(pC, nA);
  if (dV[Z] != 0.0) {  // polygon is NOT a parallelogram
    Vec3 qVX{}, qVY{};
    for (int i = X; i < W; i++) {
      qVX[i] = nA[i] / (2.0 * dV[Z]);
      qVY[i] = -nB[i] / dV[Z];
    }
    const double dVX = -dV[Y] / (2.0 * dV[Z]);
    const double dVY = dV[X] / dV[Z];
    const double kA = dVX + (dot(rI, qVX));
    const double kB = dVY + (dot(rI, qVY));
    const double tmp = std::sqrt(sqr(kA) - kB);
    if (((out.v = 1.0 - (kA - tmp)) > 1.0) || (out.v < 0.0)) {
      out.v = 1.0 - (kA + tmp);
    }
  } else {  // polygon is a parallelogram
    out.v = 1.0 - ((dot(rI, nB) - dV[X]) / (dV[Y] - (dot(rI, nA))));
  }
  return out;
}

// CastRay, lines 6815-6852, with E44.
InverseMapResult inverseMap1991(io::PrimType type, const Vec3& localHit) {
  UvSurface uvs;  // E44: u = v = 0.0, surface = -1 before the switch
  switch (type) {
    case io::PrimType::Sphere: {
      // `UnitVector(tmpV, n)`: a zero tmpV leaves CastRay's n as it was (a
      // stale normal); we start from tmpV itself, i.e. zero (shading.md S5).
      Vec3 n = localHit;
      unitVector(localHit, n);
      uvs = getUVSphere1991(n);
      break;
    }
    case io::PrimType::Cube:
      uvs = getUVCube1991(localHit);
      break;
    case io::PrimType::Pyramid:
      uvs = getUVPyramid1991(localHit);
      break;
    case io::PrimType::Cylinder:
      uvs = getUVCylinder1991(localHit);
      break;
    case io::PrimType::Cone:
      uvs = getUVCone1991(localHit);
      break;
  }
  InverseMapResult r;
  r.u = uvs.u;
  r.v = uvs.v;
  if (uvs.surface == -1) {  // E44: no face matched -> surface 0, u = v = 0
    r.surface = 0;
    r.noFaceMatched = true;
  } else {
    r.surface = uvs.surface;
  }
  return r;
}

}  // namespace prime
