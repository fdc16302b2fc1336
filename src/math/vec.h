// 3-vectors shared by every system: points, directions and colours as three
// doubles (PRIME's Define.h: Vector, Point, RGB are double[3]). No system's
// quirks live here; PRIME's Sqr, UnitVector (E28) and Distance are in
// src/prime/math/listing_vec.h.
#pragma once
#include <array>
#include <cmath>

namespace prime {

using Vec3 = std::array<double, 3>;
enum Axis { X = 0, Y = 1, Z = 2, W = 3 };

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator-(const Vec3& a) {
  return {-a[0], -a[1], -a[2]};
}
inline Vec3 operator*(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
inline Vec3 operator*(double s, const Vec3& a) {
  return a * s;
}

// Dot product, summed X, Y, Z in that order (PRIME's VectorDot sums the same way).
inline double dot(const Vec3& a, const Vec3& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i) d += a[i] * b[i];
  return d;
}

inline double length(const Vec3& v) {
  return std::sqrt(dot(v, v));
}
// v / |v|, computed as v * (1 / |v|); a zero vector is returned as it is.
// (PRIME's listing has its own UnitVector, E28, in src/prime/math/listing_vec.h.)
inline Vec3 normalized(const Vec3& v) {
  const double len = length(v);
  return len > 0.0 ? v * (1.0 / len) : v;
}

// Cross product (PRIME's VectorCross).
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[Y] * b[Z] - a[Z] * b[Y], a[Z] * b[X] - a[X] * b[Z], a[X] * b[Y] - a[Y] * b[X]};
}

}  // namespace prime
