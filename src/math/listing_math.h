// MathFunc module of the listing (lines 5202-5340): degree trigonometry with the
// 7-digit `Radient` constant, and `Roundoff`, which snaps values near an integer.
#pragma once

namespace prime {

// Degrees per radian as the listing defines it (K3): 57.29578, not 180/pi.
inline constexpr double kRadient = 57.29578;

// Roundoff (K24, Q6): snaps to the nearest integer when within 1e-10 (positive
// numbers) or 1e-9/2e-9 (negative numbers, thresholds as printed); NaN and
// zero give 0.0.
double roundoff(double num);

double sinDeg(double degrees);   // Sin(): sin(num / Radient)
double cosDeg(double degrees);   // Cos()
double asinDeg(double x);        // ASin(): asin(x) * Radient
double acosDeg(double x);        // ACos()

}  // namespace prime
