// 3-vectors as the listing uses them (Define.h: Vector, Point, RGB are double[3]).
#pragma once
#include <array>
#include <cmath>

namespace prime {

using Vec3 = std::array<double, 3>;
enum Axis { X = 0, Y = 1, Z = 2, W = 3 };

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator-(const Vec3& a) { return {-a[0], -a[1], -a[2]}; }
inline Vec3 operator*(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline Vec3 operator*(double s, const Vec3& a) { return a * s; }

// VectorDot (Matrix module): summed X, Y, Z in that order, as the listing does.
inline double dot(const Vec3& a, const Vec3& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i) d += a[i] * b[i];
  return d;
}

// VectorCross.
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[Y] * b[Z] - a[Z] * b[Y], a[Z] * b[X] - a[X] * b[Z], a[X] * b[Y] - a[Y] * b[X]};
}

// Sqr (MathFunc): x*x, with the listing's explicit zero case.
inline double sqr(double x) { return x == 0.0 ? 0.0 : x * x; }

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
