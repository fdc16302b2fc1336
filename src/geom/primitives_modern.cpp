#include "src/geom/primitives_modern.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prime {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3 normalized(const Vec3& v) {
  const double len = std::sqrt(dot(v, v));
  return len > 0.0 ? v * (1.0 / len) : v;
}

// Clips the running interval [lo, hi] by the half-space n.p <= c; the plane
// that moves a bound becomes that bound's normal.
bool clipHalfSpace(const Ray& r, const Vec3& n, double c, double& lo, double& hi, Vec3& nLo, Vec3& nHi) {
  const double nd = dot(n, r.d), no = dot(n, r.o);
  if (nd == 0.0) return no <= c;  // parallel: inside the plane's half-space or not at all
  const double t = (c - no) / nd;
  if (nd > 0.0) {  // leaving the half-space at t
    if (t < hi) {
      hi = t;
      nHi = n;
    }
  } else if (t > lo) {  // entering at t
    lo = t;
    nLo = n;
  }
  return lo <= hi;
}

bool convex(const Ray& r, const Vec3* normals, const double* offsets, int planes, Interval& out) {
  double lo = -kInf, hi = kInf;
  Vec3 nLo{}, nHi{};
  for (int i = 0; i < planes; ++i)
    if (!clipHalfSpace(r, normals[i], offsets[i], lo, hi, nLo, nHi)) return false;
  if (!(lo <= hi) || lo == -kInf || hi == kInf) return false;
  out = {lo, hi, normalized(nLo), normalized(nHi)};
  return true;
}

// Clips [t0, t1] by the slab z0 <= z <= z1 with outward normals -z / +z.
bool clipSlabZ(const Ray& r, double z0, double z1, double& t0, double& t1, Vec3& n0, Vec3& n1) {
  return clipHalfSpace(r, {0, 0, -1}, -z0, t0, t1, n0, n1) && clipHalfSpace(r, {0, 0, 1}, z1, t0, t1, n0, n1);
}

}  // namespace

bool solveQuadratic(double a, double b, double c, double& t0, double& t1) {
  if (a == 0.0) return false;
  // Discriminant of the half-b form, b^2 - a c, with one rounding less where
  // fma is exact enough: plain products are fine at double precision here.
  const double disc = b * b - a * c;
  if (disc < 0.0) return false;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) {  // b = 0 and disc = 0: a double root at 0
    t0 = t1 = 0.0;
    return true;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

bool sphereModern(const Ray& r, Interval& out) {
  double t0, t1;
  const double a = dot(r.d, r.d), b = dot(r.o, r.d), c = dot(r.o, r.o) - 1.0;
  if (!solveQuadratic(a, b, c, t0, t1) || t0 == t1) return false;
  out = {t0, t1, normalized(r.o + r.d * t0), normalized(r.o + r.d * t1)};
  return true;
}

bool cylinderModern(const Ray& r, Interval& out) {
  double t0 = -kInf, t1 = kInf;
  Vec3 n0{}, n1{};
  const double a = r.d[X] * r.d[X] + r.d[Y] * r.d[Y];
  const double b = r.o[X] * r.d[X] + r.o[Y] * r.d[Y];
  const double c = r.o[X] * r.o[X] + r.o[Y] * r.o[Y] - 1.0;
  if (a == 0.0) {
    if (c > 0.0) return false;  // parallel to the axis, outside
  } else {
    double s0, s1;
    if (!solveQuadratic(a, b, c, s0, s1) || s0 == s1) return false;
    t0 = s0;
    t1 = s1;
    const Vec3 p0 = r.o + r.d * s0, p1 = r.o + r.d * s1;
    n0 = normalized({p0[X], p0[Y], 0});
    n1 = normalized({p1[X], p1[Y], 0});
  }
  if (!clipSlabZ(r, 0.0, 1.0, t0, t1, n0, n1) || !(t0 < t1)) return false;
  out = {t0, t1, normalized(n0), normalized(n1)};
  return true;
}

bool coneModern(const Ray& r, Interval& out) {
  // Solid: x^2 + y^2 <= z^2 with 0 <= z <= 1 (apex at the origin, cap z = 1).
  // f(t) = a t^2 + 2 b t + c; the upper nappe is convex, so the line meets
  // the solid in one interval.
  const double a = r.d[X] * r.d[X] + r.d[Y] * r.d[Y] - r.d[Z] * r.d[Z];
  const double b = r.o[X] * r.d[X] + r.o[Y] * r.d[Y] - r.o[Z] * r.d[Z];
  const double c = r.o[X] * r.o[X] + r.o[Y] * r.o[Y] - r.o[Z] * r.o[Z];
  double t0 = -kInf, t1 = kInf;
  Vec3 n0{}, n1{};
  auto bodyNormal = [&](double t) {
    const Vec3 p = r.o + r.d * t;
    if (p[X] == 0.0 && p[Y] == 0.0 && p[Z] == 0.0) return Vec3{0, 0, -1};  // the apex
    return normalized({p[X], p[Y], -p[Z]});
  };
  double s0, s1;
  if (a == 0.0) {
    // One nappe's generator direction: f is linear, 2 b t + c <= 0.
    if (b == 0.0) {
      if (c > 0.0) return false;
    } else {
      const double t = -c / (2.0 * b);
      if (b > 0.0) {
        t1 = t;
        n1 = bodyNormal(t);
      } else {
        t0 = t;
        n0 = bodyNormal(t);
      }
    }
  } else if (!solveQuadratic(a, b, c, s0, s1)) {
    if (a > 0.0) return false;  // never inside the double cone
  } else if (a > 0.0) {         // inside between the roots (one nappe or the other)
    t0 = s0;
    t1 = s1;
    n0 = bodyNormal(s0);
    n1 = bodyNormal(s1);
  } else if (r.d[Z] > 0.0) {  // a < 0: inside beyond the roots; the upper nappe is where z grows
    t0 = s1;
    n0 = bodyNormal(s1);
  } else {
    t1 = s0;
    n1 = bodyNormal(s0);
  }
  if (!clipSlabZ(r, 0.0, 1.0, t0, t1, n0, n1) || !(t0 < t1)) return false;
  // The slab clip keeps z >= 0 at both ends, so the part kept is on the
  // upper nappe (the lower one lies at z <= 0).
  const double zMid = r.o[Z] + r.d[Z] * (0.5 * (t0 + t1));
  if (zMid < 0.0) return false;
  out = {t0, t1, normalized(n0), normalized(n1)};
  return true;
}

bool cubeModern(const Ray& r, Interval& out) {
  static const Vec3 n[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  static const double c[6] = {0, 1, 0, 1, 0, 1};
  return convex(r, n, c, 6, out);
}

bool pyramidModern(const Ray& r, Interval& out) {
  // Base y >= 0; four faces through the apex (0.5, 1, 0.5) and a base edge.
  static const Vec3 n[5] = {{0, -1, 0}, {0, 0.5, -1}, {0, 0.5, 1}, {-1, 0.5, 0}, {1, 0.5, 0}};
  static const double c[5] = {0, 0, 1, 0, 1};
  return convex(r, n, c, 5, out);
}

bool intersectModern(char type, const Ray& local, Interval& out) {
  switch (type) {
    case 'S': return sphereModern(local, out);
    case 'B': return cubeModern(local, out);
    case 'C': return cylinderModern(local, out);
    case 'N': return coneModern(local, out);
    case 'Y': return pyramidModern(local, out);
    default: return false;
  }
}

}  // namespace prime
