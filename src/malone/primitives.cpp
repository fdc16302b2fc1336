#include "src/malone/primitives.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "src/malone/quartic.h"

namespace prime::malone {

namespace {

Vec3 mul(const Mat3& m, const Vec3& v) {
  return {dot(m[0], v), dot(m[1], v), dot(m[2], v)};
}

// The document's quadratic formula, t = (-b +- sqrt(b^2 - 4ac)) / 2a, both
// roots in ascending order (a may be negative for the cone).
int quadraticRoots(double a, double b, double c, double r[2]) {
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  const double s = std::sqrt(disc);
  r[0] = (-b - s) / (2 * a);
  r[1] = (-b + s) / (2 * a);
  if (r[0] > r[1]) std::swap(r[0], r[1]);
  return 2;
}

bool accept(double t, double eps, double length) {
  return t > eps && t < length;
}

// The plane n.x = D: t = (D - n.o) / (n.d), no hit when n.d = 0 (section 2.2).
bool planeT(const Vec3& n, double D, const MRay& ray, double& t) {
  const double nd = dot(n, ray.d);
  if (nd == 0.0) return false;
  t = (D - dot(n, ray.o)) / nd;
  return true;
}

// Barycentric test of section 2.4 (times det, no division).
void barycentric(const Primitive& p, const Vec3& x, double& alpha, double& beta) {
  const Vec3 w = x - p.c;
  const double aw = dot(p.a, w), bw = dot(p.b, w);
  alpha = p.bb * aw - p.ab * bw;
  beta = -p.ab * aw + p.aa * bw;
}

bool insidePolygon(const Scene& scene, const Primitive& p, const Vec3& x) {
  const int i0 = (p.dropAxis + 1) % 3, i1 = (p.dropAxis + 2) % 3;
  bool inside = false;
  for (int i = 0, j = p.count - 1; i < p.count; j = i++) {
    const Vec3& a = scene.polygonVertices[p.first + i];
    const Vec3& b = scene.polygonVertices[p.first + j];
    // On an edge counts as inside.
    const double ex = b[i0] - a[i0], ey = b[i1] - a[i1];
    const double px = x[i0] - a[i0], py = x[i1] - a[i1];
    const double crossp = ex * py - ey * px;
    const double len2 = ex * ex + ey * ey;
    if (std::fabs(crossp) <= 1e-12 * len2 && px * ex + py * ey >= 0 && px * ex + py * ey <= len2)
      return true;
    if ((a[i1] > x[i1]) != (b[i1] > x[i1]) &&
        x[i0] < (b[i0] - a[i0]) * (x[i1] - a[i1]) / (b[i1] - a[i1]) + a[i0])
      inside = !inside;
  }
  return inside;
}

// The nearest root of the quadric pair r[0..1] whose point lies within the
// range lo <= (x - c).axis / |axis|^2 <= hi; the far root is tried when the
// near one is clipped (section 2.7).
bool clippedRoot(const Primitive& p, const MRay& ray, double eps, const double* r, int n,
                 double& t) {
  for (int i = 0; i < n; ++i) {
    if (!accept(r[i], eps, ray.length)) continue;
    const Vec3 x = ray.o + ray.d * r[i];
    const double along = dot(x - p.c, p.axis) / p.axis2;
    if (along >= p.lo && along <= p.hi) {
      t = r[i];
      return true;
    }
  }
  return false;
}

}  // namespace

bool intersect(const Scene& scene, const Primitive& p, const MRay& ray, double eps, double& t) {
  switch (p.id) {
    case ObjectId::Sphere: {
      // t^2 + 2t (o - c).d + (o - c)^2 - r^2 = 0 (section 2.2), d unit.
      const Vec3 oc = ray.o - p.c;
      double r[2];
      if (quadraticRoots(1.0, 2 * dot(oc, ray.d), dot(oc, oc) - p.r2, r) == 0) return false;
      for (double root : r)
        if (accept(root, eps, ray.length)) {
          t = root;
          return true;
        }
      return false;
    }
    case ObjectId::Plane:
      return planeT(p.n, p.D, ray, t) && accept(t, eps, ray.length);
    case ObjectId::Disk:
    case ObjectId::Annulus: {
      if (!planeT(p.n, p.D, ray, t) || !accept(t, eps, ray.length)) return false;
      const Vec3 w = ray.o + ray.d * t - p.c;
      const double d2 = dot(w, w);
      return d2 <= p.r2 && (p.id == ObjectId::Disk || d2 > p.rIn2);
    }
    case ObjectId::Triangle:
    case ObjectId::Parallelogram: {
      if (!planeT(p.n, p.D, ray, t) || !accept(t, eps, ray.length)) return false;
      double alpha, beta;
      barycentric(p, ray.o + ray.d * t, alpha, beta);
      if (p.id == ObjectId::Triangle) return alpha >= 0 && beta >= 0 && alpha + beta <= p.det;
      return alpha >= 0 && alpha <= p.det && beta >= 0 && beta <= p.det;
    }
    case ObjectId::Polygon:
      return planeT(p.n, p.D, ray, t) && accept(t, eps, ray.length) &&
             insidePolygon(scene, p, ray.o + ray.d * t);
    case ObjectId::Cone: {
      // A t^2 + B t + C = 0 with the constant term corrected (MAL-E3).
      const Vec3 q = ray.o - p.c;
      const double da = dot(ray.d, p.u), qa = dot(q, p.u);
      const double A = p.alpha2 - da * da;
      const double B = 2 * (p.alpha2 * dot(q, ray.d) - da * qa);
      const double C = p.alpha2 * dot(q, q) - qa * qa;
      double r[2];
      int n = 0;
      if (A == 0.0) {
        if (B == 0.0) return false;
        r[0] = -C / B;
        n = 1;
      } else {
        n = quadraticRoots(A, B, C, r);
      }
      return clippedRoot(p, ray, eps, r, n, t);
    }
    case ObjectId::Cylinder: {
      const Vec3 q = ray.o - p.c;
      const double da = dot(ray.d, p.u), qa = dot(q, p.u);
      const double A = 1 - da * da;
      if (A == 0.0) return false;  // along the axis: no hit (MAL-Q5)
      const double B = 2 * (dot(q, ray.d) - qa * da);
      const double C = dot(q, q) - qa * qa - p.r2;
      double r[2];
      const int n = quadraticRoots(A, B, C, r);
      return clippedRoot(p, ray, eps, r, n, t);
    }
    case ObjectId::Torus: {
      // (|x|^2 + R^2 - r^2)^2 = 4 R^2 (|x|^2 - (x.a)^2), x = o - c + t d.
      const Vec3 q = ray.o - p.c;
      const double b = dot(q, ray.d), qq = dot(q, q);
      const double qd = dot(ray.d, p.u), s = dot(q, p.u);
      // The torus lies within the sphere |x - c| <= R + r and the slab
      // |(x - c).u| <= r: a ray that misses either, or meets both only
      // outside (eps, length), cannot hit it, and skips the quartic (the
      // same pixels: the margin 1e-9 keeps every root the quartic finds).
      const double outer = (p.R + p.r) * (1 + 1e-9), slab = p.r * (1 + 1e-9);
      const double disc = b * b - (qq - outer * outer);
      if (disc < 0) return false;
      const double root = std::sqrt(disc);
      double t0 = -b - root, t1 = -b + root;
      if (qd != 0) {
        double ta = (-slab - s) / qd, tb = (slab - s) / qd;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
      } else if (std::fabs(s) > slab) {
        return false;
      }
      if (t0 > t1 || t1 <= eps || t0 >= ray.length) return false;
      const double k = qq + p.R * p.R - p.r * p.r;
      const double R2 = p.R * p.R;
      return firstQuarticRoot(4 * b, 4 * b * b + 2 * k - 4 * R2 * (1 - qd * qd),
                              4 * b * k - 8 * R2 * (b - s * qd), k * k - 4 * R2 * (qq - s * s), eps,
                              ray.length, t);
    }
    case ObjectId::Affine: {
      // M(o - O) + t' Md/|Md|, t' = t |Md| (section 2.6).
      const Affine& f = scene.affines[p.affine];
      const Vec3 md = mul(f.m, ray.d);
      const double scale = length(md);
      if (!(scale > 0)) return false;
      MRay local;
      local.o = mul(f.m, ray.o - p.c);
      local.d = md * (1.0 / scale);
      local.length = ray.length == kInfinite ? kInfinite : ray.length * scale;
      double tl = 0;
      if (!intersect(scene, scene.embedded[f.inner], local, eps, tl)) return false;
      t = tl / scale;
      return t < ray.length;
    }
    default:
      return false;
  }
}

Vec3 normal(const Scene& scene, const Primitive& p, const Vec3& x) {
  switch (p.id) {
    case ObjectId::Sphere:
      return normalized(x - p.c);
    case ObjectId::Plane:
    case ObjectId::Disk:
    case ObjectId::Annulus:
    case ObjectId::Triangle:
    case ObjectId::Parallelogram:
    case ObjectId::Polygon:
      return p.n;
    case ObjectId::Cone: {
      // n = w - (|w|^2 / (w.a)) a, outward on both nappes (MAL-E4).
      const Vec3 w = x - p.c;
      const double wa = dot(w, p.u);
      // At the apex itself (w = 0) no normal is defined: -u, not 0/0 = NaN.
      if (wa == 0.0) return dot(w, w) > 0 ? normalized(w) : p.u * -1.0;
      return normalized(w - p.u * (dot(w, w) / wa));
    }
    case ObjectId::Cylinder: {
      const Vec3 w = x - p.c;
      return normalized(w - p.u * dot(w, p.u));
    }
    case ObjectId::Torus: {
      const Vec3 w = x - p.c;
      const Vec3 radial = w - p.u * dot(w, p.u);
      const double len = length(radial);
      if (!(len > 0)) return normalized(w);
      return normalized(w - radial * (p.R / len));
    }
    case ObjectId::Affine: {
      // M^T n_local(M(x - O)), translation included (MAL-E5).
      const Affine& f = scene.affines[p.affine];
      const Vec3 local = mul(f.m, x - p.c);
      return normalized(mul(f.mT, normal(scene, scene.embedded[f.inner], local)));
    }
    default:
      return {0, 0, 1};
  }
}

Aabb bounds(const Scene& scene, const Primitive& p) {
  Aabb box;
  // The extent of a circle of radius r about the unit axis u, per axis.
  auto disc = [&](const Vec3& centre, const Vec3& u, double r) {
    for (int s = -1; s <= 1; s += 2) {
      Vec3 corner = centre;
      for (int k = 0; k < 3; ++k) corner[k] += s * r * std::sqrt(std::max(0.0, 1 - u[k] * u[k]));
      box.add(corner);
    }
  };
  switch (p.id) {
    case ObjectId::Plane:
      return Aabb{};
    case ObjectId::Sphere:
      box.add(p.c - Vec3{p.r, p.r, p.r});
      box.add(p.c + Vec3{p.r, p.r, p.r});
      break;
    case ObjectId::Disk:
    case ObjectId::Annulus:
      disc(p.c, p.n, p.r);
      break;
    case ObjectId::Triangle:
      box.add(p.c);
      box.add(p.c + p.a);
      box.add(p.c + p.b);
      break;
    case ObjectId::Parallelogram:
      box.add(p.c);
      box.add(p.c + p.a);
      box.add(p.c + p.b);
      box.add(p.c + p.a + p.b);
      break;
    case ObjectId::Polygon:
      for (int i = 0; i < p.count; ++i) box.add(scene.polygonVertices[p.first + i]);
      break;
    case ObjectId::Cylinder:
      disc(p.c + p.axis * p.lo, p.u, p.r);
      disc(p.c + p.axis * p.hi, p.u, p.r);
      break;
    case ObjectId::Cone: {
      // The radius at axis parameter v is |v| |axis| tan(theta).
      const double tanTheta = std::sqrt(1 - p.alpha2) / p.alpha;
      const double len = std::sqrt(p.axis2);
      for (double v : {p.lo, p.hi}) disc(p.c + p.axis * v, p.u, std::fabs(v) * len * tanTheta);
      if (p.lo < 0 && p.hi > 0) box.add(p.c);
      break;
    }
    case ObjectId::Torus:
      disc(p.c + p.u * p.r, p.u, p.R + p.r);
      disc(p.c - p.u * p.r, p.u, p.R + p.r);
      break;
    case ObjectId::Affine: {
      const Affine& f = scene.affines[p.affine];
      const Aabb inner = bounds(scene, scene.embedded[f.inner]);
      if (inner.empty()) return Aabb{};  // an affine plane is still unbounded
      // World = O + (X Y Z) local: the corners of the local box.
      const Mat3& cols = f.mInv;
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local{corner & 1 ? inner.hi[0] : inner.lo[0],
                         corner & 2 ? inner.hi[1] : inner.lo[1],
                         corner & 4 ? inner.hi[2] : inner.lo[2]};
        box.add(p.c + mul(cols, local));
      }
      break;
    }
    default:
      return Aabb{};
  }
  // Padded so that rounding in the tests above can never put a hit outside.
  double extent = 0;
  for (int k = 0; k < 3; ++k)
    extent = std::max({extent, std::fabs(box.lo[k]), std::fabs(box.hi[k]), box.hi[k] - box.lo[k]});
  const double pad = 1e-7 * extent + 1e-9;
  box.lo = box.lo - Vec3{pad, pad, pad};
  box.hi = box.hi + Vec3{pad, pad, pad};
  return box;
}

}  // namespace prime::malone
