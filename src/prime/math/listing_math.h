// MathFunc module of the listing (lines 5202-5340): degree trigonometry with the
// 7-digit `Radient` constant, and `Roundoff`, which snaps values near an integer.
#pragma once
#include <cmath>

namespace prime {

// Degrees per radian as the listing defines it (K3): 57.29578, not 180/pi.
inline constexpr double kRadient = 57.29578;

// floor(x) without the libm call (baseline x86-64 has no rounding
// instruction, so std::floor is a function call): the same value for every
// x. Below 2^52 in magnitude, truncation through int64 is exact and one step
// down corrects negative non-integers; zero keeps its sign; larger values,
// infinities and NaN go to std::floor.
inline double floorExact(double x) {
  if (!(x > -4503599627370496.0 && x < 4503599627370496.0) || x == 0.0) return std::floor(x);
  const double t = static_cast<double>(static_cast<long long>(x));
  return t > x ? t - 1.0 : t;
}

// Roundoff (K24, Q6): snaps to the nearest integer when within 1e-10 (positive
// numbers) or 1e-9/2e-9 (negative numbers, thresholds as printed); NaN and
// zero give 0.0.
// Inline: the tracer calls it several times per hit (inverse mapping, the
// pyramid's planes, the texel index), where a call cost 3 % of a walk.
inline double roundoff(double num) {
  if (num > 0.0) {
    const double floorNum = floorExact(num);
    const double variance = num - floorNum;
    if (variance > 0.9999999999) return floorNum + 1.0;
    if (variance < 0.0000000001) return floorNum;
    return num;
  }
  if (num < 0.0) {
    const double floorNum = floorExact(-num);
    const double variance = -num - floorNum;
    if (variance > 0.999999998) return (floorNum + 1.0) * -1.0;
    if (variance < 0.000000001) return -floorNum;
    return num;
  }
  return 0.0;  // zero, and NaN (both comparisons false)
}

double sinDeg(double degrees);  // Sin(): sin(num / Radient)
double cosDeg(double degrees);  // Cos()
double asinDeg(double x);       // ASin(): asin(x) * Radient
double acosDeg(double x);       // ACos()

}  // namespace prime
