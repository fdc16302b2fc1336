// Axis-aligned boxes and the ray/box slab test, for any system: a ray that
// misses a box cannot hit what the box encloses. A system pads its boxes so
// that rounding in its own intersection tests can never put a reported hit
// outside its box (PRIME: src/prime/scene/prim_boxes.h).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "src/geom/ray.h"

namespace prime {

// 1/d per component, as Aabb::entry wants it (infinite for a zero component).
inline Vec3 reciprocal(const Vec3& d) {
  return {1.0 / d[0], 1.0 / d[1], 1.0 / d[2]};
}

// A ray prepared once for many box tests: 1/d, and per axis whether the
// slab's high plane is met first. `simple` when every 1/d is finite and
// non-zero, the case the branch-free test handles.
struct BoxRay {
  explicit BoxRay(const Ray& r) : ray(r), inv(reciprocal(r.d)) {
    for (int i = 0; i < 3; ++i) {
      neg[i] = inv[i] < 0.0;
      simple = simple && std::isfinite(inv[i]) && inv[i] != 0.0;
    }
  }
  Ray ray;
  Vec3 inv;
  std::array<bool, 3> neg{};
  bool simple = true;
};

struct Aabb {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};

  bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
  void add(const Vec3& p) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  void add(const Aabb& b) {
    add(b.lo);
    add(b.hi);
  }
  Aabb intersected(const Aabb& b) const {
    Aabb r;
    for (int i = 0; i < 3; ++i) {
      r.lo[i] = std::max(lo[i], b.lo[i]);
      r.hi[i] = std::min(hi[i], b.hi[i]);
    }
    return r;
  }
  Vec3 centre() const { return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}; }

  // Entry parameter of the ray into the box for t >= 0 (0 when the origin is
  // inside), or +infinity when the ray misses it ahead. `inv` = 1/d.
  double entry(const Ray& ray, const Vec3& inv) const {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      if (ray.d[i] == 0.0) {
        if (ray.o[i] < lo[i] || ray.o[i] > hi[i]) return std::numeric_limits<double>::infinity();
        continue;
      }
      double a = (lo[i] - ray.o[i]) * inv[i], b = (hi[i] - ray.o[i]) * inv[i];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
      if (!(t0 <= t1)) return std::numeric_limits<double>::infinity();
    }
    return t0;
  }

  // The same value as entry(r.ray, r.inv). For a simple ray and a box with
  // lo <= hi on every axis (so no NaN): (lo - o)/d <= (hi - o)/d when d > 0
  // and the reverse when d < 0, rounding being monotonic, so taking the
  // planes in sign order is entry()'s swap, and since t0 only grows and t1
  // only shrinks, one test at the end rejects whatever the per-axis tests do.
  double entry(const BoxRay& r) const {
    if (!r.simple || !(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]))
      return entry(r.ray, r.inv);
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const double a = ((r.neg[i] ? hi[i] : lo[i]) - r.ray.o[i]) * r.inv[i];
      const double b = ((r.neg[i] ? lo[i] : hi[i]) - r.ray.o[i]) * r.inv[i];
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    return t0 <= t1 ? t0 : std::numeric_limits<double>::infinity();
  }
};

}  // namespace prime
