// Floating-point arithmetic with known error, for the modern profile's
// geometry: the error bound of n roundings, an accurate inverse of an affine
// transform, and a ray origin moved off its surface by more than its error
// bound.
#pragma once
#include <limits>

#include "src/math/matrix.h"
#include "src/math/vec.h"

namespace prime {

// pbrt's gamma(n) = n u / (1 - n u): the relative error bound of n
// roundings, u the unit roundoff.
constexpr double gamma(int n) {
  constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
  return (n * u) / (1 - n * u);
}

// The inverse of an affine row-vector transform, accurate to about one
// rounding per entry (long double cofactors and one Newton step), instead of
// the database's unpivoted Gauss-Jordan inverse (K42, M18: good to 1.5e-9
// only for a 90-degree rotation). A singular matrix gives prime::inverse's.
Matrix4 accurateInverse(const Matrix4& m);

// A point moved off its surface along `n` (the side the new ray leaves on)
// by more than its error bound, so the new ray cannot re-hit the surface it
// starts on (Ray Tracing Gems ch. 6 / pbrt-v4 OffsetRayOrigin).
Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pError, const Vec3& n, const Vec3& w);

}  // namespace prime
