// The listing's own vector helpers (MathFunc and Matrix modules), kept with
// their exact arithmetic: Sqr's explicit zero case, UnitVector as repaired by
// E28, and Distance through pow(..., 2).
#pragma once
#include <cmath>

#include "src/math/vec.h"

namespace prime {

// Sqr (MathFunc): x*x, with the listing's explicit zero case.
inline double sqr(double x) {
  return x == 0.0 ? 0.0 : x * x;
}

// UnitVector as repaired by errata E28: divides by the length; a zero vector
// is left as the caller's `out` was (the listing leaves xUnit untouched).
inline void unitVector(const Vec3& v, Vec3& out) {
  double len = sqr(v[X]) + sqr(v[Y]) + sqr(v[Z]);
  if ((len = std::sqrt(len)) != 0.0)
    for (int i = 0; i < 3; ++i) out[i] = v[i] / len;
}

// Distance (Matrix module): sqrt of pow(...,2) sums, as printed.
inline double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt(std::pow(b[X] - a[X], 2.0) + std::pow(b[Y] - a[Y], 2.0) +
                   std::pow(b[Z] - a[Z], 2.0));
}

}  // namespace prime
