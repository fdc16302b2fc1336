#include "src/malone/quartic.h"

#include <algorithm>
#include <cmath>

namespace prime::malone {

namespace {

constexpr double kPi = 3.14159265358979323846;

long double quarticAt(long double x, double a, double b, double c, double d, long double& slope) {
  const long double p = (((x + a) * x + b) * x + c) * x + d;
  slope = ((4.0L * x + 3.0L * a) * x + 2.0L * b) * x + c;
  return p;
}

// Newton steps in long double from x; stops when the step no longer shrinks.
double polish(double x0, double a, double b, double c, double d) {
  long double x = x0, lastStep = HUGE_VALL;
  for (int i = 0; i < 8; ++i) {
    long double slope = 0;
    const long double f = quarticAt(x, a, b, c, d, slope);
    if (f == 0 || slope == 0) break;
    const long double step = f / slope;
    if (!(std::fabs(step) < lastStep)) break;  // diverging or stalled: keep the best
    x -= step;
    lastStep = std::fabs(step);
  }
  return static_cast<double>(x);
}

}  // namespace

int solveQuadratic(double a, double b, double c, std::array<double, 2>& roots) {
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  // The cancellation-free pair: q = -(b + sign(b) sqrt(disc)) / 2.
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double r0 = q / a, r1 = q != 0 ? c / q : r0;
  if (r0 > r1) std::swap(r0, r1);
  roots = {r0, r1};
  return disc == 0 ? 1 : 2;
}

int solveCubic(double a, double b, double c, std::array<double, 3>& roots) {
  // x = y - a/3: y^3 + p y + q = 0.
  const double a3 = a / 3;
  const double p = b - a * a3;
  const double q = 2 * a3 * a3 * a3 - a3 * b + c;
  const double h = q * q / 4 + p * p * p / 27;
  int n = 0;
  if (h > 0) {
    const double s = std::sqrt(h);
    roots[n++] = std::cbrt(-q / 2 + s) + std::cbrt(-q / 2 - s) - a3;
  } else if (p == 0) {
    roots[n++] = -a3;
  } else {
    // Three real roots (trigonometric form).
    const double m = 2 * std::sqrt(-p / 3);
    const double arg = std::clamp(3 * q / (p * m), -1.0, 1.0);
    const double theta = std::acos(arg) / 3;
    for (int k = 0; k < 3; ++k) roots[n++] = m * std::cos(theta - 2 * kPi * k / 3) - a3;
  }
  std::sort(roots.begin(), roots.begin() + n);
  return n;
}

int solveQuartic(double a, double b, double c, double d, std::array<double, 4>& roots) {
  // Ferrari: x = y - a/4 gives y^4 + p y^2 + q y + r = 0.
  const double a4 = a / 4;
  const double a2 = a4 * a4;
  const double p = b - 6 * a2;
  const double q = c - 2 * b * a4 + 8 * a2 * a4;
  const double r = d - c * a4 + b * a2 - 3 * a2 * a2;
  std::array<double, 4> y{};
  int n = 0;
  std::array<double, 2> two{};
  if (std::fabs(q) <= 1e-14 * (std::fabs(p) * std::fabs(p) + std::fabs(r) + 1e-300)) {
    // Biquadratic: z = y^2, z^2 + p z + r = 0.
    const int m = solveQuadratic(1, p, r, two);
    for (int i = 0; i < m; ++i) {
      if (two[i] < 0) continue;
      const double s = std::sqrt(two[i]);
      y[n++] = -s;
      y[n++] = s;
    }
  } else {
    // The resolvent cubic z^3 + 2p z^2 + (p^2 - 4r) z - q^2 = 0 has a
    // positive root z; then y^2 + p/2 + z/2 = +-sqrt(z) (y - q / (2z)).
    std::array<double, 3> z{};
    const int m = solveCubic(2 * p, p * p - 4 * r, -q * q, z);
    const double z0 = z[m - 1];  // the largest, positive since -q^2 < 0
    if (z0 > 0) {
      const double s = std::sqrt(z0);
      const double t = q / (2 * s);
      // y^2 - s y + (p + z0)/2 + t = 0 and y^2 + s y + (p + z0)/2 - t = 0.
      const int m1 = solveQuadratic(1, -s, (p + z0) / 2 + t, two);
      for (int i = 0; i < m1; ++i) y[n++] = two[i];
      const int m2 = solveQuadratic(1, s, (p + z0) / 2 - t, two);
      for (int i = 0; i < m2; ++i) y[n++] = two[i];
    }
  }
  // Back to x, polished on the original polynomial.
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    const double x = polish(y[i] - a4, a, b, c, d);
    long double slope = 0;
    const long double f = quarticAt(x, a, b, c, d, slope);
    // A root of the closed form that polishing could not bring near zero is
    // an artefact of a negative discriminant lost to rounding: dropped. Near
    // zero means within what the rounding of the double coefficients allows
    // at x: a small multiple of eps * sum |coefficient| |x|^i (a bound that
    // grew with |d| let points far off the torus through on grazing rays).
    const long double ax = std::fabs((long double)x);
    const long double bound =
        (((ax + std::fabs(a)) * ax + std::fabs(b)) * ax + std::fabs(c)) * ax + std::fabs(d);
    if (!std::isfinite(x) || std::fabs(f) > 1e-10L * bound) continue;
    roots[kept++] = x;
  }
  std::sort(roots.begin(), roots.begin() + kept);
  return kept;
}

}  // namespace prime::malone
