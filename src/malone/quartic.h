// Real roots of polynomials of degree less than 5 (Malone's feature list:
// "Code for solving polynomials of degree less than 5"), for the torus. The
// closed forms (Cardano, Ferrari) lose digits on near-double roots and
// grazing rays, so every root is polished by Newton's method on the
// original polynomial, evaluated in long double, and roots that polishing
// shows to be spurious are dropped.
#pragma once
#include <array>

namespace prime::malone {

// Roots of a x^2 + b x + c (a != 0), ascending; returns how many (0..2).
int solveQuadratic(double a, double b, double c, std::array<double, 2>& roots);
// Real roots of x^3 + a x^2 + b x + c, ascending; returns how many (1..3).
int solveCubic(double a, double b, double c, std::array<double, 3>& roots);
// Real roots of x^4 + a x^3 + b x^2 + c x + d, ascending, polished; returns
// how many (0..4).
int solveQuartic(double a, double b, double c, double d, std::array<double, 4>& roots);
// The smallest root of solveQuartic's in (lo, hi), polishing only the
// candidates up to it (ascending); false when there is none.
bool firstQuarticRoot(double a, double b, double c, double d, double lo, double hi, double& x);

}  // namespace prime::malone
