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

// Newton steps from x; stops when the step no longer shrinks. The steps
// far from the root are taken in double (cheap), the last ones in long
// double.
double polish(double x0, double a, double b, double c, double d, bool& converged) {
  converged = false;
  double xd = x0, lastD = HUGE_VAL;
  for (int i = 0; i < 8; ++i) {
    const double f = (((xd + a) * xd + b) * xd + c) * xd + d;
    const double slope = ((4.0 * xd + 3.0 * a) * xd + 2.0 * b) * xd + c;
    if (f == 0 || slope == 0) break;
    const double step = f / slope;
    if (!(std::fabs(step) < lastD)) break;
    if (!(std::fabs(step) > 1e-9 * (1 + std::fabs(xd)))) break;  // near: long double from here
    xd -= step;
    lastD = std::fabs(step);
  }
  long double x = xd, lastStep = HUGE_VALL;
  for (int i = 0; i < 8; ++i) {
    long double slope = 0;
    const long double f = quarticAt(x, a, b, c, d, slope);
    if (f == 0 || slope == 0) break;
    const long double step = f / slope;
    if (!(std::fabs(step) < lastStep)) break;  // diverging or stalled: keep the best
    x -= step;
    lastStep = std::fabs(step);
    // Converged: the next step (quadratic convergence) is below the last
    // bits of a long double, far below a double's.
    if (lastStep <= 0x1p-40L * std::fabs(x)) {
      converged = true;
      break;
    }
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

namespace {

// The largest real root of x^3 + a x^2 + b x + c: solveCubic's last, computed
// the same way but without the other two of three real roots.
double largestCubicRoot(double a, double b, double c) {
  const double a3 = a / 3;
  const double p = b - a * a3;
  const double q = 2 * a3 * a3 * a3 - a3 * b + c;
  const double h = q * q / 4 + p * p * p / 27;
  if (h > 0) {
    const double s = std::sqrt(h);
    const double u = std::cbrt(-q / 2 - std::copysign(s, q));
    return (u != 0 ? u - p / (3 * u) : 0.0) - a3;
  }
  if (p == 0) return -a3;
  const double m = 2 * std::sqrt(-p / 3);
  const double arg = std::clamp(3 * q / (p * m), -1.0, 1.0);
  return m * std::cos(std::acos(arg) / 3) - a3;  // k = 0: theta in [0, pi/3]
}

}  // namespace

int solveCubic(double a, double b, double c, std::array<double, 3>& roots) {
  // x = y - a/3: y^3 + p y + q = 0.
  const double a3 = a / 3;
  const double p = b - a * a3;
  const double q = 2 * a3 * a3 * a3 - a3 * b + c;
  const double h = q * q / 4 + p * p * p / 27;
  int n = 0;
  if (h > 0) {
    const double s = std::sqrt(h);
    // One cube root: u = cbrt(-q/2 -+ s) without cancellation, and
    // v = -p/(3u) since u v = cbrt(q^2/4 - h) = -p/3.
    const double u = std::cbrt(-q / 2 - std::copysign(s, q));
    roots[n++] = (u != 0 ? u - p / (3 * u) : 0.0) - a3;
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

namespace {

// The closed form's candidates (Ferrari), unpolished, unsorted.
int quarticCandidates(double a, double b, double c, double d, std::array<double, 4>& y) {
  // Ferrari: x = y - a/4 gives y^4 + p y^2 + q y + r = 0.
  const double a4 = a / 4;
  const double a2 = a4 * a4;
  const double p = b - 6 * a2;
  const double q = c - 2 * b * a4 + 8 * a2 * a4;
  const double r = d - c * a4 + b * a2 - 3 * a2 * a2;
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
    const double z0 = largestCubicRoot(2 * p, p * p - 4 * r, -q * q);  // > 0: -q^2 < 0
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
  for (int i = 0; i < n; ++i) y[i] -= a4;  // back to x
  return n;
}

// A candidate polished on the original polynomial; false when polishing
// could not bring it near zero (an artefact of a negative discriminant lost
// to rounding: dropped).
bool polished(double y, double a, double b, double c, double d, double& x) {
  bool converged = false;
  x = polish(y, a, b, c, d, converged);
  // Newton converging quadratically leaves f(x) far below the threshold.
  if (converged) return std::isfinite(x);
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
  return std::isfinite(x) && !(std::fabs(f) > 1e-10L * bound);
}

}  // namespace

int solveQuartic(double a, double b, double c, double d, std::array<double, 4>& roots) {
  std::array<double, 4> y{};
  const int n = quarticCandidates(a, b, c, d, y);
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    double x = 0;
    if (polished(y[i], a, b, c, d, x)) roots[kept++] = x;
  }
  std::sort(roots.begin(), roots.begin() + kept);
  return kept;
}

bool firstQuarticRoot(double a, double b, double c, double d, double lo, double hi, double& x) {
  std::array<double, 4> y{};
  const int n = quarticCandidates(a, b, c, d, y);
  for (int i = 1; i < n; ++i)  // ascending (insertion: at most four)
    for (int j = i; j > 0 && y[j] < y[j - 1]; --j) std::swap(y[j], y[j - 1]);
  // Polishing moves a candidate by far less than the gap to its neighbours
  // but for a near-double root, whose two polished values then agree: the
  // first accepted polished candidate is solveQuartic's first in (lo, hi).
  for (int i = 0; i < n; ++i) {
    double r = 0;
    if (!polished(y[i], a, b, c, d, r)) continue;
    if (r > lo && r < hi) {
      x = r;
      return true;
    }
  }
  return false;
}

}  // namespace prime::malone
