// The stress suite's reference: the five unit solids of PRIME and the ray
// transform re-implemented once more, templated on the float type, so that
// every ray the profiles trace in double can be traced again in long double
// and in __float128 (binary128) from the SAME double inputs (the ray, and
// the primitive's FORWARD matrix M as the database stores it).
//
// The reference inverts M itself (3x3 cofactors in T), so the double
// inverse of the database (the listing's unpivoted Gauss-Jordan, K42) is
// part of what is measured, not part of the reference. Every function gives
// the whole-line interval [tIn, tOut] with OUTWARD unit normals, like the
// modern profile, but nothing here is shared with either profile's code.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "src/math/matrix.h"

#if defined(PRIME_HAVE_QUADMATH)
#include <quadmath.h>
#endif

namespace prime::stress {

#if defined(__SIZEOF_FLOAT128__)
using Quad = __float128;
inline constexpr bool kHaveQuad = true;
#else
using Quad = long double;
inline constexpr bool kHaveQuad = false;
#endif

template <class T>
using V3 = std::array<T, 3>;

template <class T>
T refAbs(T x) {
  return x < T(0) ? -x : x;
}

template <class T>
T refSqrt(T x) {
  if constexpr (std::is_same_v<T, long double> || std::is_same_v<T, double>) {
    return std::sqrt(x);
  } else {
#if defined(PRIME_HAVE_QUADMATH)
    return sqrtq(x);
#else
    // Two Newton steps from the long double root: 64 -> 128 bits.
    if (!(x > T(0))) return x == T(0) ? x : T(std::numeric_limits<long double>::quiet_NaN());
    T r = T(std::sqrt(static_cast<long double>(x)));
    r = (r + x / r) / T(2);
    r = (r + x / r) / T(2);
    return r;
#endif
  }
}

template <class T>
T dot3(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
V3<T> unit3(const V3<T>& v) {
  const T l = refSqrt(dot3(v, v));
  if (!(l > T(0))) return v;
  return {v[0] / l, v[1] / l, v[2] / l};
}
template <class T, class U>
V3<T> cast3(const std::array<U, 3>& v) {
  return {T(v[0]), T(v[1]), T(v[2])};
}

// One primitive: p_world = p_local A + tr (row vectors, as the listing).
template <class T>
struct RefPrim {
  char type = 'S';
  T a[3][3]{}, inv[3][3]{}, tr[3]{};
  long double invNorm = 0;  // |A^-1| (max row sum), for the tolerance

  static RefPrim make(char type, const Matrix4& m) {
    RefPrim p;
    p.type = type;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) p.a[i][j] = T(m[i][j]);
      p.tr[i] = T(m[3][i]);
    }
    const T(&a)[3][3] = p.a;
    T c[3][3];  // cofactors
    c[0][0] = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    c[0][1] = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    c[0][2] = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    c[1][0] = a[0][2] * a[2][1] - a[0][1] * a[2][2];
    c[1][1] = a[0][0] * a[2][2] - a[0][2] * a[2][0];
    c[1][2] = a[0][1] * a[2][0] - a[0][0] * a[2][1];
    c[2][0] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
    c[2][1] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
    c[2][2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    const T det = a[0][0] * c[0][0] + a[0][1] * c[0][1] + a[0][2] * c[0][2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) p.inv[i][j] = c[j][i] / det;
    for (int i = 0; i < 3; ++i) {
      long double s = 0;
      for (int j = 0; j < 3; ++j) s += static_cast<long double>(refAbs(p.inv[i][j]));
      p.invNorm = std::max(p.invNorm, s);
    }
    return p;
  }
  template <class U>
  RefPrim<U> as() const {
    RefPrim<U> r;
    r.type = type;
    r.invNorm = invNorm;
    for (int i = 0; i < 3; ++i) {
      r.tr[i] = U(tr[i]);
      for (int j = 0; j < 3; ++j) {
        r.a[i][j] = U(a[i][j]);
        r.inv[i][j] = U(inv[i][j]);
      }
    }
    return r;
  }
  V3<T> toLocalPoint(const V3<T>& w) const {
    const V3<T> q{w[0] - tr[0], w[1] - tr[1], w[2] - tr[2]};
    return toLocalVector(q);
  }
  V3<T> toLocalVector(const V3<T>& w) const {
    V3<T> l;
    for (int j = 0; j < 3; ++j) l[j] = w[0] * inv[0][j] + w[1] * inv[1][j] + w[2] * inv[2][j];
    return l;
  }
  // A local outward normal in the world: by the inverse transpose.
  V3<T> normalToWorld(const V3<T>& n) const {
    V3<T> w;
    for (int j = 0; j < 3; ++j) w[j] = n[0] * inv[j][0] + n[1] * inv[j][1] + n[2] * inv[j][2];
    return unit3(w);
  }
  // The same by the FORWARD matrix, as the listing does it (K4).
  V3<T> normalByForward(const V3<T>& n) const {
    V3<T> w;
    for (int j = 0; j < 3; ++j) w[j] = n[0] * a[0][j] + n[1] * a[1][j] + n[2] * a[2][j];
    return unit3(w);
  }
};

template <class T>
struct RefRay {
  V3<T> o{}, d{};
  V3<T> at(T t) const { return {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]}; }
};

template <class T>
struct RefInterval {
  T tIn{}, tOut{};
  V3<T> nIn{}, nOut{};  // outward unit normals (local)
};

namespace detail {

template <class T>
bool clipPlane(const RefRay<T>& r, const V3<T>& n, T c, T& lo, T& hi, V3<T>& nLo, V3<T>& nHi,
               bool& loSet, bool& hiSet) {
  const T nd = dot3(n, r.d), no = dot3(n, r.o);
  if (nd == T(0)) return no <= c;
  const T t = (c - no) / nd;
  if (nd > T(0)) {
    if (!hiSet || t < hi) {
      hi = t;
      nHi = n;
      hiSet = true;
    }
  } else if (!loSet || t > lo) {
    lo = t;
    nLo = n;
    loSet = true;
  }
  return !(loSet && hiSet) || lo <= hi;
}

// Roots of a t^2 + 2 b t + c, ordered; false when none.
template <class T>
bool quadratic(T a, T b, T c, T& t0, T& t1) {
  if (a == T(0)) return false;
  const T disc = b * b - a * c;
  if (disc < T(0)) return false;
  const T s = refSqrt(disc);
  const T q = b >= T(0) ? -(b + s) : -(b - s);
  if (q == T(0)) {
    t0 = t1 = T(0);
    return true;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace detail

// The unit solid `type` along the whole line of `r` (local frame).
template <class T>
bool refIntersect(char type, const RefRay<T>& r, RefInterval<T>& out) {
  using detail::clipPlane;
  T lo{}, hi{};
  V3<T> nLo{}, nHi{};
  bool loSet = false, hiSet = false;
  auto finish = [&]() {
    if (!loSet || !hiSet || !(lo < hi)) return false;
    out = {lo, hi, unit3(nLo), unit3(nHi)};
    return true;
  };
  auto slabZ = [&]() {
    return clipPlane(r, V3<T>{0, 0, -1}, T(0), lo, hi, nLo, nHi, loSet, hiSet) &&
           clipPlane(r, V3<T>{0, 0, 1}, T(1), lo, hi, nLo, nHi, loSet, hiSet);
  };
  switch (type) {
    case 'B': {
      static const int axes[3] = {0, 1, 2};
      for (int k : axes) {
        V3<T> n{0, 0, 0};
        n[k] = T(-1);
        if (!clipPlane(r, n, T(0), lo, hi, nLo, nHi, loSet, hiSet)) return false;
        n[k] = T(1);
        if (!clipPlane(r, n, T(1), lo, hi, nLo, nHi, loSet, hiSet)) return false;
      }
      return finish();
    }
    case 'Y': {
      const V3<T> n[5] = {
          {0, -1, 0}, {0, T(0.5), -1}, {0, T(0.5), 1}, {-1, T(0.5), 0}, {1, T(0.5), 0}};
      const T c[5] = {0, 0, 1, 0, 1};
      for (int i = 0; i < 5; ++i)
        if (!clipPlane(r, n[i], c[i], lo, hi, nLo, nHi, loSet, hiSet)) return false;
      return finish();
    }
    case 'S': {
      T t0, t1;
      if (!detail::quadratic(dot3(r.d, r.d), dot3(r.o, r.d), dot3(r.o, r.o) - T(1), t0, t1) ||
          !(t0 < t1))
        return false;
      out = {t0, t1, unit3(r.at(t0)), unit3(r.at(t1))};
      return true;
    }
    case 'C': {
      const T a = r.d[0] * r.d[0] + r.d[1] * r.d[1];
      const T b = r.o[0] * r.d[0] + r.o[1] * r.d[1];
      const T c = r.o[0] * r.o[0] + r.o[1] * r.o[1] - T(1);
      if (a == T(0)) {
        if (c > T(0)) return false;
      } else {
        T s0, s1;
        if (!detail::quadratic(a, b, c, s0, s1) || !(s0 < s1)) return false;
        const V3<T> p0 = r.at(s0), p1 = r.at(s1);
        lo = s0;
        hi = s1;
        loSet = hiSet = true;
        nLo = unit3(V3<T>{p0[0], p0[1], 0});
        nHi = unit3(V3<T>{p1[0], p1[1], 0});
      }
      if (!slabZ()) return false;
      return finish();
    }
    case 'N': {
      const T a = r.d[0] * r.d[0] + r.d[1] * r.d[1] - r.d[2] * r.d[2];
      const T b = r.o[0] * r.d[0] + r.o[1] * r.d[1] - r.o[2] * r.d[2];
      const T c = r.o[0] * r.o[0] + r.o[1] * r.o[1] - r.o[2] * r.o[2];
      auto body = [&](T t) {
        const V3<T> p = r.at(t);
        if (p[0] == T(0) && p[1] == T(0) && p[2] == T(0)) return V3<T>{0, 0, -1};
        return unit3(V3<T>{p[0], p[1], -p[2]});
      };
      T s0, s1;
      if (a == T(0)) {
        if (b == T(0)) {
          if (c > T(0)) return false;
        } else {
          const T t = -c / (T(2) * b);
          if (b > T(0)) {
            hi = t, hiSet = true, nHi = body(t);
          } else {
            lo = t, loSet = true, nLo = body(t);
          }
        }
      } else if (!detail::quadratic(a, b, c, s0, s1)) {
        if (a > T(0)) return false;
      } else if (a > T(0)) {
        lo = s0, hi = s1, loSet = hiSet = true;
        nLo = body(s0);
        nHi = body(s1);
      } else if (r.d[2] > T(0)) {
        lo = s1, loSet = true, nLo = body(s1);
      } else {
        hi = s0, hiSet = true, nHi = body(s0);
      }
      if (!slabZ()) return false;
      if (!loSet || !hiSet || !(lo < hi)) return false;
      if (r.o[2] + r.d[2] * ((lo + hi) / T(2)) < T(0)) return false;  // the lower nappe
      return finish();
    }
    default:
      return false;
  }
}

// Signed distance (or a tight lower bound outside edges) of a local point
// from the unit solid's surface: negative inside.
template <class T>
T refSdf(char type, const V3<T>& p) {
  auto mx = [](T a, T b) { return a > b ? a : b; };
  switch (type) {
    case 'S':
      return refSqrt(dot3(p, p)) - T(1);
    case 'B': {
      T q[3], out = 0, in = T(-1e300L);
      for (int i = 0; i < 3; ++i) {
        q[i] = refAbs(p[i] - T(0.5)) - T(0.5);
        if (q[i] > T(0)) out += q[i] * q[i];
        in = mx(in, q[i]);
      }
      return out > T(0) ? refSqrt(out) : in;
    }
    case 'C': {
      const T dr = refSqrt(p[0] * p[0] + p[1] * p[1]) - T(1);
      const T dz = refAbs(p[2] - T(0.5)) - T(0.5);
      if (dr > T(0) && dz > T(0)) return refSqrt(dr * dr + dz * dz);
      return mx(dr, dz);
    }
    case 'N': {
      const T r = refSqrt(p[0] * p[0] + p[1] * p[1]);
      return mx(mx((r - p[2]) / refSqrt(T(2)), p[2] - T(1)), -p[2]);
    }
    case 'Y': {
      const T s5 = refSqrt(T(1.25));
      T d = -p[1];
      d = mx(d, (T(0.5) * p[1] - p[2]) / s5);
      d = mx(d, (T(0.5) * p[1] + p[2] - T(1)) / s5);
      d = mx(d, (T(0.5) * p[1] - p[0]) / s5);
      d = mx(d, (T(0.5) * p[1] + p[0] - T(1)) / s5);
      return d;
    }
    default:
      return T(0);
  }
}

// The outward unit normals (local) of every surface of the solid that lies
// within `tol` of the local point p: one at a face, two at an edge, more at
// a vertex. Empty at the cone's apex (any normal of its cone is right).
template <class T>
std::vector<V3<T>> refNormals(char type, const V3<T>& p, T tol) {
  std::vector<V3<T>> n;
  auto near = [&](T d) { return refAbs(d) <= tol; };
  switch (type) {
    case 'S':
      n.push_back(unit3(p));
      break;
    case 'B':
      for (int k = 0; k < 3; ++k) {
        V3<T> e{0, 0, 0};
        if (near(p[k])) e[k] = T(-1), n.push_back(e);
        e = {0, 0, 0};
        if (near(p[k] - T(1))) e[k] = T(1), n.push_back(e);
      }
      break;
    case 'C': {
      const T r = refSqrt(p[0] * p[0] + p[1] * p[1]);
      if (near(r - T(1)) && r > T(0)) n.push_back({p[0] / r, p[1] / r, 0});
      if (near(p[2])) n.push_back({0, 0, -1});
      if (near(p[2] - T(1))) n.push_back({0, 0, 1});
      break;
    }
    case 'N': {
      const T r = refSqrt(p[0] * p[0] + p[1] * p[1]);
      if (refSqrt(dot3(p, p)) <= tol) return {};  // the apex
      if (near((r - p[2]) / refSqrt(T(2))) && r > T(0))
        n.push_back(unit3(V3<T>{p[0] / r, p[1] / r, T(-1)}));
      if (near(p[2] - T(1))) n.push_back({0, 0, 1});
      break;
    }
    case 'Y': {
      const V3<T> ns[5] = {
          {0, -1, 0}, {0, T(0.5), -1}, {0, T(0.5), 1}, {-1, T(0.5), 0}, {1, T(0.5), 0}};
      const T c[5] = {0, 0, 1, 0, 1};
      for (int i = 0; i < 5; ++i) {
        const T len = refSqrt(dot3(ns[i], ns[i]));
        if (near((dot3(ns[i], p) - c[i]) / len)) n.push_back(unit3(ns[i]));
      }
      break;
    }
    default:
      break;
  }
  return n;
}

// ---- Interval lists and set operations in T (regularised, exact compares).

template <class T>
struct RefNode {
  T t{};
  int prim = -1;
  V3<T> n{};  // outward normal of the RESULT solid there (local frame of prim)
};

template <class T>
struct RefSpan {
  RefNode<T> in, out;
};

template <class T>
using RefList = std::vector<RefSpan<T>>;

template <class T>
RefList<T> refCombine(char op, const RefList<T>& a, const RefList<T>& b) {
  struct Ev {
    T t;
    int side;  // 0 = a, 1 = b
    bool enter;
    RefNode<T> node;
  };
  std::vector<Ev> ev;
  for (const auto& s : a)
    ev.push_back({s.in.t, 0, true, s.in}), ev.push_back({s.out.t, 0, false, s.out});
  for (const auto& s : b)
    ev.push_back({s.in.t, 1, true, s.in}), ev.push_back({s.out.t, 1, false, s.out});
  std::stable_sort(ev.begin(), ev.end(), [](const Ev& x, const Ev& y) { return x.t < y.t; });
  auto comp = [&](bool ia, bool ib) {
    switch (op) {
      case '+':
        return ia || ib;
      case '&':
        return ia && ib;
      default:
        return ia && !ib;
    }
  };
  bool ia = false, ib = false;
  RefList<T> out;
  RefNode<T> open{};
  for (std::size_t i = 0; i < ev.size();) {
    const bool before = comp(ia, ib);
    std::size_t j = i;
    for (; j < ev.size() && ev[j].t == ev[i].t; ++j) (ev[j].side == 0 ? ia : ib) = ev[j].enter;
    const bool after = comp(ia, ib);
    if (before != after) {
      // The node of an operand whose own change goes the composite's way.
      const Ev* pick = &ev[i];
      for (std::size_t k = i; k < j; ++k) {
        const bool flips = op == '-' && ev[k].side == 1;
        if ((ev[k].enter != flips) == after) {
          pick = &ev[k];
          break;
        }
      }
      RefNode<T> node = pick->node;
      if (op == '-' && pick->side == 1) node.n = {-node.n[0], -node.n[1], -node.n[2]};
      if (after) {
        open = node;
      } else {
        out.push_back({open, node});
      }
    }
    i = j;
  }
  return out;
}

}  // namespace prime::stress
