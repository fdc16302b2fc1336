#include "src/prime/geom/primitives_modern.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prime {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Clips the running interval [lo, hi] by the half-space n.p <= c; the plane
// that moves a bound becomes that bound's normal.
bool clipHalfSpace(const Ray& r, const Vec3& n, double c, double& lo, double& hi, Vec3& nLo,
                   Vec3& nHi) {
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

// kNormals false: the same t's (and the same answer), the normals left zero.
template <bool kNormals = true>
bool convex(const Ray& r, const Vec3* normals, const double* offsets, int planes, PrimHit& out) {
  double lo = -kInf, hi = kInf;
  Vec3 nLo{}, nHi{};
  for (int i = 0; i < planes; ++i)
    if (!clipHalfSpace(r, normals[i], offsets[i], lo, hi, nLo, nHi)) return false;
  if (!(lo <= hi) || lo == -kInf || hi == kInf) return false;
  if constexpr (kNormals)
    out = {lo, hi, normalized(nLo), normalized(nHi)};
  else
    out = {lo, hi, {}, {}};
  return true;
}

// Clips [t0, t1] by the slab z0 <= z <= z1 with outward normals -z / +z.
bool clipSlabZ(const Ray& r, double z0, double z1, double& t0, double& t1, Vec3& n0, Vec3& n1) {
  return clipHalfSpace(r, {0, 0, -1}, -z0, t0, t1, n0, n1) &&
         clipHalfSpace(r, {0, 0, 1}, z1, t0, t1, n0, n1);
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

// The quadrics' kNormals = false forms give the same t's and the same
// answer without computing (normalising) the normals: for the tests that
// need only where a ray is inside (bounds, shadow rays, candidates).
template <bool kNormals>
static bool sphereAt(const Ray& r, PrimHit& out) {
  double t0, t1;
  const double a = dot(r.d, r.d), b = dot(r.o, r.d), c = dot(r.o, r.o) - 1.0;
  if (!solveQuadratic(a, b, c, t0, t1) || t0 == t1) return false;
  if constexpr (kNormals)
    out = {t0, t1, normalized(r.o + r.d * t0), normalized(r.o + r.d * t1)};
  else
    out = {t0, t1, {}, {}};
  return true;
}

template <bool kNormals>
static bool cylinderAt(const Ray& r, PrimHit& out) {
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
    if constexpr (kNormals) {
      const Vec3 p0 = r.o + r.d * s0, p1 = r.o + r.d * s1;
      n0 = normalized({p0[X], p0[Y], 0});
      n1 = normalized({p1[X], p1[Y], 0});
    }
  }
  if (!clipSlabZ(r, 0.0, 1.0, t0, t1, n0, n1) || !(t0 < t1)) return false;
  if constexpr (kNormals)
    out = {t0, t1, normalized(n0), normalized(n1)};
  else
    out = {t0, t1, {}, {}};
  return true;
}

template <bool kNormals>
static bool coneAt(const Ray& r, PrimHit& out) {
  // Solid: x^2 + y^2 <= z^2 with 0 <= z <= 1 (apex at the origin, cap z = 1).
  // f(t) = a t^2 + 2 b t + c; the upper nappe is convex, so the line meets
  // the solid in one interval.
  const double a = r.d[X] * r.d[X] + r.d[Y] * r.d[Y] - r.d[Z] * r.d[Z];
  const double b = r.o[X] * r.d[X] + r.o[Y] * r.d[Y] - r.o[Z] * r.d[Z];
  const double c = r.o[X] * r.o[X] + r.o[Y] * r.o[Y] - r.o[Z] * r.o[Z];
  double t0 = -kInf, t1 = kInf;
  Vec3 n0{}, n1{};
  auto bodyNormal = [&](double t) {
    if constexpr (!kNormals) return Vec3{};
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
  if constexpr (kNormals)
    out = {t0, t1, normalized(n0), normalized(n1)};
  else
    out = {t0, t1, {}, {}};
  return true;
}

namespace {

// The quadrics are solved from the point of the line nearest their centre,
// axis or apex (o' = o + s d), and s is added back to the roots. From there
// the coefficients are small where the roots are ill-conditioned (a line
// grazing the sphere or the cylinder, passing near the cone's apex), so a
// near-double root is found to O(u) instead of O(sqrt(u)) (Ray Tracing Gems
// ch. 7; the remaining error is the line's own position, u |o|).
template <class Solve>
bool shifted(const Ray& r, double num, double den, Solve solve, PrimHit& out) {
  // A line (nearly) parallel to the cylinder's axis has no useful nearest
  // point (den ~ 0): solved as it is.
  const double s = den > 1e-6 * dot(r.d, r.d) ? -num / den : 0.0;
  if (!std::isfinite(s) || s == 0.0) return solve(r, out);
  const Ray near{r.o + r.d * s, r.d};
  if (!solve(near, out)) return false;
  out.tIn += s;
  out.tOut += s;
  return out.tIn < out.tOut;
}

template <bool kNormals = true>
bool sphereWith(const Ray& r, PrimHit& out) {
  return shifted(r, dot(r.o, r.d), dot(r.d, r.d), sphereAt<kNormals>, out);
}
template <bool kNormals = true>
bool cylinderWith(const Ray& r, PrimHit& out) {
  return shifted(r, r.o[X] * r.d[X] + r.o[Y] * r.d[Y], r.d[X] * r.d[X] + r.d[Y] * r.d[Y],
                 cylinderAt<kNormals>, out);
}
template <bool kNormals = true>
bool coneWith(const Ray& r, PrimHit& out) {
  return shifted(r, dot(r.o, r.d), dot(r.d, r.d), coneAt<kNormals>, out);
}

}  // namespace

bool sphereModern(const Ray& r, PrimHit& out) {
  return sphereWith(r, out);
}

bool cylinderModern(const Ray& r, PrimHit& out) {
  return cylinderWith(r, out);
}

bool coneModern(const Ray& r, PrimHit& out) {
  return coneWith(r, out);
}

bool cubeModern(const Ray& r, PrimHit& out) {
  // convex() over the six faces -x <= 0, x <= 1, -y <= 0, ... in that order,
  // with each face's dot products written out: n.d and n.o are -d[i], -o[i]
  // or d[i], o[i] exactly (the other terms add a zero, and the sign of a zero
  // decides nothing below), so every t, every comparison and every normal
  // is convex()'s, bit for bit, at a third of the work.
  // The six divisions are made first, side by side (the same operands, so
  // the same quotients; a zero d's quotients are never read). On each axis
  // one face is entered and the other left: convex() takes the entered
  // one's t as a new lo only when it is larger, the left one's as a new hi
  // only when smaller (a tie keeps the earlier face), and returns false as
  // soon as lo > hi; lo only grows and hi only shrinks, so that test is made
  // once at the end.
  double tMinus[3], tPlus[3];
  for (int i = 0; i < 3; ++i) {
    tMinus[i] = (0.0 - (-r.o[i])) / (-r.d[i]);
    tPlus[i] = (1.0 - r.o[i]) / r.d[i];
  }
  double lo = -kInf, hi = kInf;
  int faceLo = -1, faceHi = -1;  // 2 i: the -axis face, 2 i + 1: the +axis face
  bool outside = false;          // parallel to a slab and outside it
  for (int i = 0; i < 3; ++i) {
    const double d = r.d[i], o = r.o[i];
    if (d == 0.0) {
      outside |= !(-o <= 0.0) || !(o <= 1.0);
      continue;
    }
    const bool up = d > 0.0;  // enters by the -axis face, leaves by the +axis one
    const double tIn = up ? tMinus[i] : tPlus[i], tOut = up ? tPlus[i] : tMinus[i];
    const int fIn = up ? 2 * i : 2 * i + 1, fOut = up ? 2 * i + 1 : 2 * i;
    if (tIn > lo) {
      lo = tIn;
      faceLo = fIn;
    }
    if (tOut < hi) {
      hi = tOut;
      faceHi = fOut;
    }
  }
  if (outside) return false;
  if (!(lo <= hi) || lo == -kInf || hi == kInf) return false;
  auto normal = [](int face) {
    Vec3 n{0, 0, 0};
    if (face >= 0) n[face / 2] = face % 2 == 0 ? -1.0 : 1.0;
    return n;
  };
  out = {lo, hi, normal(faceLo), normal(faceHi)};
  return true;
}

// The generic form cubeModern is checked against (tests).
bool cubeModernByPlanes(const Ray& r, PrimHit& out) {
  static const Vec3 n[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  static const double c[6] = {0, 1, 0, 1, 0, 1};
  return convex(r, n, c, 6, out);
}

bool pyramidModern(const Ray& r, PrimHit& out) {
  // Base y >= 0; four faces through the apex (0.5, 1, 0.5) and a base edge.
  static const Vec3 n[5] = {{0, -1, 0}, {0, 0.5, -1}, {0, 0.5, 1}, {-1, 0.5, 0}, {1, 0.5, 0}};
  static const double c[5] = {0, 0, 1, 0, 1};
  return convex(r, n, c, 5, out);
}

namespace {

constexpr double kUnit = std::numeric_limits<double>::epsilon() * 0.5;
constexpr double gammaN(int n) {
  return (n * kUnit) / (1 - n * kUnit);
}

// One constraint g(p) <= 0 of a solid, evaluated at p with its error bound.
struct Constraint {
  double g, err;
  Vec3 normal;  // outward (gradient direction)
};

Constraint plane(const Vec3& n, double c, const Vec3& p, const Vec3& e) {
  double g = -c, mag = std::abs(c), de = 0;
  for (int i = 0; i < 3; ++i) {
    g += n[i] * p[i];
    mag += std::abs(n[i] * p[i]);
    de += std::abs(n[i]) * e[i];
  }
  return {g, de + gammaN(4) * mag, n};
}

// g = s0 x^2 + s1 y^2 + s2 z^2 + k with signs s (a quadric through the origin's axes).
Constraint quadric(const Vec3& s, double k, const Vec3& p, const Vec3& e, const Vec3& grad) {
  double g = k, mag = std::abs(k), de = 0;
  for (int i = 0; i < 3; ++i) {
    if (s[i] == 0) continue;
    g += s[i] * p[i] * p[i];
    mag += p[i] * p[i];
    de += 2 * std::abs(p[i]) * e[i] + e[i] * e[i];
  }
  return {g, de + gammaN(5) * mag, grad};
}

}  // namespace

int nearSurfacesModern(io::PrimType type, const Vec3& p, const Vec3& e, Vec3* out, int max) {
  Constraint c[6];
  int n = 0;
  switch (type) {
    case io::PrimType::Sphere:
      c[n++] = quadric({1, 1, 1}, -1, p, e, p);
      break;
    case io::PrimType::Cube:
      for (int k = 0; k < 3; ++k) {
        Vec3 a{0, 0, 0};
        a[k] = -1;
        c[n++] = plane(a, 0, p, e);
        a[k] = 1;
        c[n++] = plane(a, 1, p, e);
      }
      break;
    case io::PrimType::Cylinder:
      c[n++] = quadric({1, 1, 0}, -1, p, e, {p[X], p[Y], 0});
      c[n++] = plane({0, 0, -1}, 0, p, e);
      c[n++] = plane({0, 0, 1}, 1, p, e);
      break;
    case io::PrimType::Cone:
      c[n++] = quadric({1, 1, -1}, 0, p, e, {p[X], p[Y], -p[Z]});
      c[n++] = plane({0, 0, -1}, 0, p, e);  // only the apex: z >= 0 touches the solid there
      c[n++] = plane({0, 0, 1}, 1, p, e);
      break;
    case io::PrimType::Pyramid: {
      static const Vec3 nn[5] = {{0, -1, 0}, {0, 0.5, -1}, {0, 0.5, 1}, {-1, 0.5, 0}, {1, 0.5, 0}};
      static const double cc[5] = {0, 0, 1, 0, 1};
      for (int k = 0; k < 5; ++k) c[n++] = plane(nn[k], cc[k], p, e);
      break;
    }
  }
  int count = 0;
  if (type == io::PrimType::Cone &&
      std::abs(p[X]) + std::abs(p[Y]) + std::abs(p[Z]) <= 4 * (e[X] + e[Y] + e[Z])) {
    // The apex: the body has no normal there. Its tangent planes at eight
    // azimuths (and the plane z = 0) stand in, so that a ray leaving the
    // apex steps to the right side of the cone whichever way it goes.
    if (c[0].g > 16 * c[0].err) return -1;
    static const double r = std::sqrt(0.5);
    for (int k = 0; k < 8 && count < max; ++k) {
      const double f = k * 0.7853981633974483;
      out[count++] = {r * std::cos(f), r * std::sin(f), -r};
    }
    if (count < max) out[count++] = {0, 0, -1};
    return count;
  }
  for (int k = 0; k < n; ++k) {
    // "Near" reaches 16 error bounds: stepping off one surface moves the
    // point by about one bound, which must not carry it across another
    // surface that was just outside the bound (the cone's rim).
    if (c[k].g > 16 * c[k].err) return -1;  // outside beyond doubt
    if (c[k].g >= -16 * c[k].err && count < max) {
      const Vec3 u = normalized(c[k].normal);
      if (dot(u, u) > 0) out[count++] = u;
    }
  }
  return count;
}

bool intersectModernT(io::PrimType type, const Ray& local, PrimHit& out) {
  switch (type) {
    case io::PrimType::Sphere:
      return sphereWith<false>(local, out);
    case io::PrimType::Cube:
      return cubeModern(local, out);  // its normals cost nothing
    case io::PrimType::Cylinder:
      return cylinderWith<false>(local, out);
    case io::PrimType::Cone:
      return coneWith<false>(local, out);
    case io::PrimType::Pyramid: {
      static const Vec3 n[5] = {{0, -1, 0}, {0, 0.5, -1}, {0, 0.5, 1}, {-1, 0.5, 0}, {1, 0.5, 0}};
      static const double c[5] = {0, 0, 1, 0, 1};
      return convex<false>(local, n, c, 5, out);
    }
  }
  return false;  // not reached
}

bool intersectModern(io::PrimType type, const Ray& local, PrimHit& out) {
  switch (type) {
    case io::PrimType::Sphere:
      return sphereModern(local, out);
    case io::PrimType::Cube:
      return cubeModern(local, out);
    case io::PrimType::Cylinder:
      return cylinderModern(local, out);
    case io::PrimType::Cone:
      return coneModern(local, out);
    case io::PrimType::Pyramid:
      return pyramidModern(local, out);
  }
  return false;  // not reached
}

}  // namespace prime
