// The stress suite's measurement (measurer.h).
#include "src/prime/stress/measurer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "src/prime/geom/uv_mapping_1991.h"

namespace prime::stress {

namespace {

LD normInf(const Vec3& v) {
  return std::max({std::abs(LD(v[0])), std::abs(LD(v[1])), std::abs(LD(v[2]))});
}

LD angleBetween(const V3<LD>& a, const V3<LD>& b) {
  const V3<LD> c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(dot3(c, c)), dot3(a, b));
}

bool finiteV(const Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

bool debugOn() {
  static const bool on = std::getenv("PRIME_STRESS_DEBUG") != nullptr;
  return on;
}
void debugRay(const char* what, const std::string& types, const Ray& ray, double pt, long double rt,
              bool listing) {
  if (!debugOn()) return;
  std::fprintf(stderr,
               "%s %s [%s] o=(%.17g,%.17g,%.17g) d=(%.17g,%.17g,%.17g) p.t=%.17g r.t=%.17Lg\n",
               what, listing ? "1991" : "modern", types.c_str(), ray.o[0], ray.o[1], ray.o[2],
               ray.d[0], ray.d[1], ray.d[2], pt, rt);
}

// The reference for `ray` (design semantics for the 1991 profile when k7).
RefResult Measurer::reference(const Ray& ray, bool k7, Figures& f) const {
  RefResult ld = refNearest(s_, s_.refLd, ray, k7);
  if (!quad_) return ld;
  RefResult q = refNearest(s_, s_.refQ, ray, k7);
  const LD scale = std::abs(q.t) + LD(s_.size);
  if (ld.hit != q.hit || (q.hit && (ld.exit != q.exit || std::abs(ld.t - q.t) > 1e-12L * scale))) {
    ++f.refDisagree;
    return q;
  }
  return ld;
}

// Tolerance (local units of prim k) at parameter t of the world ray.
LD Measurer::tolerance(int k, const Ray& ray, LD t, const V3<LD>& pl) const {
  const RefPrim<LD>& rp = s_.refLd[static_cast<std::size_t>(k)];
  const LD tr = std::max({std::abs(rp.tr[0]), std::abs(rp.tr[1]), std::abs(rp.tr[2])});
  const LD world = normInf(ray.o) + std::abs(t) * normInf(ray.d) + tr;
  const LD local = 1 + std::max({std::abs(pl[0]), std::abs(pl[1]), std::abs(pl[2])});
  return LD(c_) * LD(kU) * (world * rp.invNorm + local);
}

// Signed distance in tolerances of the object's solid at ray(t).
LD Measurer::objectNsdf(int obj, const Ray& ray, LD t) const {
  const RefRay<LD> w{cast3<LD>(ray.o), cast3<LD>(ray.d)};
  const V3<LD> pw = w.at(t);
  const auto& e = s_.scene.objects[static_cast<std::size_t>(obj)].entries;
  return nsdf(e, 0, pw, ray, t, 0);
}

LD Measurer::sceneNsdf(const Ray& ray, LD t) const {
  LD best = std::numeric_limits<LD>::infinity();
  for (int o = 0; o < static_cast<int>(s_.scene.objects.size()); ++o) {
    const LD v = objectNsdf(o, ray, t);
    if (std::abs(v) < std::abs(best)) best = v;
  }
  return best;
}

// The extreme (min when `inside`, else max) of the object's normalised
// signed distance along [a, b] of the ray: sampled, then refined by
// ternary search around the best sample.
LD Measurer::extreme(int obj, const Ray& ray, LD a, LD b, bool inside) const {
  const LD sign = inside ? 1 : -1;
  auto f = [&](LD t) { return sign * objectNsdf(obj, ray, t); };
  constexpr int n = 16;
  LD best = std::numeric_limits<LD>::infinity();
  int bi = 0;
  for (int i = 0; i <= n; ++i) {
    const LD v = f(a + (b - a) * i / n);
    if (v < best) best = v, bi = i;
  }
  LD lo = a + (b - a) * std::max(0, bi - 1) / n, hi = a + (b - a) * std::min(n, bi + 1) / n;
  for (int it = 0; it < 40; ++it) {
    const LD m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    const LD v1 = f(m1), v2 = f(m2);
    best = std::min({best, v1, v2});
    if (v1 < v2)
      hi = m2;
    else
      lo = m1;
  }
  return sign * best;
}

// True when the object's solid along [a, b] is nowhere deeper than one tolerance.
bool Measurer::thin(int obj, const Ray& ray, LD a, LD b) const {
  a = std::max(a, LD(0));
  if (!(b > a)) return true;
  return extreme(obj, ray, a, b, true) >= -1;
}

// Backward error of a hit at tp where the reference has its nearest
// boundary at tr: the profile's point lies on the boundary within the
// tolerance (a near touch, when tp < tr), and when tp > tr the stretch the
// profile skipped is within the tolerance of the boundary too.
bool Measurer::explainable(int obj, const Ray& ray, LD tp, LD tr, bool refEnters) const {
  if (std::abs(objectNsdf(obj, ray, tp)) > 1) return false;
  if (tp < tr) return true;  // a near touch before the reference's boundary
  const LD a = std::min(tp, tr), b = std::max(tp, tr);
  // Entering at tr: inside after tr, outside before; leaving: the opposite.
  const bool insideBetween = (tp > tr) == refEnters;
  const LD e = extreme(obj, ray, a, b, insideBetween);
  return insideBetween ? e >= -1 : e <= 1;
}

// Compares a profile's answer with the reference; returns true when the
// decisions agree without ambiguity (a clean hit, usable for secondaries).
bool Measurer::compare(const ProfileHit& p, const RefResult& r, const Ray& ray, bool listing,
                       Figures& f) const {
  ++f.rays;
  if (r.hit) ++f.refHits;
  if (!sameHitDecisions(p, r, ray, listing, f)) return false;
  const RefPoint at = refPointAt(r, ray);
  const LD dt = std::abs(LD(p.t) - r.t);
  if (!sameSurface(p, r, ray, at, dt, listing, f)) return false;
  ++f.compared;
  f.tRel.add(double(dt / std::max(std::abs(r.t), LD(s_.size))));
  measureNormal(p, r, ray, at, listing, f);
  measureUv(p, r, at, f);
  return true;
}

Measurer::RefPoint Measurer::refPointAt(const RefResult& r, const Ray& ray) const {
  const RefPrim<LD>& rp = s_.refLd[static_cast<std::size_t>(r.prim)];
  const RefRay<LD> w{cast3<LD>(ray.o), cast3<LD>(ray.d)};
  const RefRay<LD> l{rp.toLocalPoint(w.o), rp.toLocalVector(w.d)};
  const V3<LD> pl = l.at(r.t);
  return {&rp, l, pl, tolerance(r.prim, ray, r.t, pl)};
}

// Both hit, both finite, both entering or both leaving: there is a hit to
// measure. A disagreement is counted, as wrong or (within the tolerance)
// ambiguous; NaN/Inf in the profile's hit is counted apart; two misses
// count nothing.
bool Measurer::sameHitDecisions(const ProfileHit& p, const RefResult& r, const Ray& ray,
                                bool listing, Figures& f) const {
  if (p.hit && (!std::isfinite(p.t) || !finiteV(p.point) || !finiteV(p.normal))) {
    ++f.nanInf;
    return false;
  }
  if (p.hit != r.hit) {
    bool amb;
    if (p.hit)
      amb = std::abs(sceneNsdf(ray, p.t)) <= 1;
    else
      amb = thin(r.obj, ray, r.exit ? 0 : r.a, r.b);
    ++(amb ? f.ambiguousHitMiss : f.wrongHitMiss);
    if (!amb)
      debugRay("wrong-hit/miss", describe(), ray, p.hit ? p.t : -1, r.hit ? r.t : -1, listing);
    return false;
  }
  if (!p.hit) return false;
  if (p.exit != r.exit) {
    const bool amb = std::abs(sceneNsdf(ray, 0)) <= 1 || thin(r.obj, ray, r.exit ? 0 : r.a, r.b) ||
                     std::abs(sceneNsdf(ray, p.t)) <= 1;
    ++(amb ? f.ambiguousInOut : f.wrongInOut);
    if (!amb) debugRay("wrong-in/out", describe(), ray, p.t, r.t, listing);
    return false;
  }
  return true;
}

// Is the profile's hit the reference's nearest surface: within the tolerance
// of it, or the same primitive at nearly the same t? Another surface is
// counted, as wrong or ambiguous.
bool Measurer::sameSurface(const ProfileHit& p, const RefResult& r, const Ray& ray,
                           const RefPoint& at, LD dt, bool listing, Figures& f) const {
  const LD dLen = std::sqrt(dot3(at.local.d, at.local.d));
  const bool samePrimitive = p.prim == r.prim && dt <= 1e-6L * std::max(std::abs(r.t), LD(s_.size));
  if (dt * dLen > at.tol && !samePrimitive) {  // not the reference's nearest surface
    const bool amb = (p.obj == r.obj && explainable(r.obj, ray, p.t, r.t, !r.exit)) ||
                     (LD(p.t) > r.t && thin(r.obj, ray, r.exit ? 0 : r.a, r.b)) ||
                     std::abs(sceneNsdf(ray, 0)) <= 1;
    ++(amb ? f.ambiguousSurface : f.wrongSurface);
    if (!amb && debugOn()) {
      debugRay("wrong-surface", describe(), ray, p.t, r.t, listing);
      const LD a = std::min(LD(p.t), r.t), b = std::max(LD(p.t), r.t);
      std::fprintf(
          stderr, "  nsdf(p.t) %.3Lg nsdf(r.t) %.3Lg min %.3Lg max %.3Lg exit %d prim %d/%d\n",
          objectNsdf(r.obj, ray, p.t), objectNsdf(r.obj, ray, r.t), extreme(r.obj, ray, a, b, true),
          extreme(r.obj, ray, a, b, false), r.exit, p.prim, r.prim);
    }
    return false;
  }
  return true;
}

// The normal's angle to the nearest of every face within the tolerance of the
// reference point (up to sign for the 1991 profile); the 1991 profile's
// semantic differences (K31 and kin, K4) are counted apart.
void Measurer::measureNormal(const ProfileHit& p, const RefResult& r, const Ray& ray,
                             const RefPoint& at, bool listing, Figures& f) const {
  const RefPrim<LD>& rp = *at.prim;
  const V3<LD>& pl = at.p;
  const LD tol = at.tol;
  std::vector<V3<LD>> cands = refNormals(rp.type, pl, tol);
  if (!cands.empty()) {
    const V3<LD> d = unit3(cast3<LD>(ray.d));
    const V3<LD> pn = unit3(cast3<LD>(p.normal));
    LD best = std::numeric_limits<LD>::infinity();
    for (const V3<LD>& c : cands) {
      const V3<LD> cw = listing ? rp.normalByForward(c) : rp.normalToWorld(c);
      LD a = angleBetween(pn, cw);
      if (listing || std::abs(dot3(cw, d)) < 1e-6L)
        a = std::min(a, kPi - a);  // up to sign
      else if (dot3(cw, d) > 0)
        a = kPi - a;  // the profile faces it to the ray
      best = std::min(best, a);
    }
    if (listing && best > 1e-6L &&
        s_.scene.objects[static_cast<std::size_t>(r.obj)].entries.size() > 1) {
      // K31 and kin: the printed operators hand on another node's normal.
      const ProfileHit d = listingOnReference(s_, ray);
      if (d.hit && d.prim == p.prim) {
        const LD a = angleBetween(unit3(cast3<LD>(d.normal)), pn);
        if (std::min(a, kPi - a) < 1e-6L) {
          ++f.semanticCsg;
          best = -1;
        }
      }
    }
    if (best >= 0) f.normalAngle.add(double(best));
    if (best > 1e-6L && debugOn()) {
      debugRay("normal", describe(), ray, double(best), r.t, listing);
      const V3<LD> cw = listing ? rp.normalByForward(cands[0]) : rp.normalToWorld(cands[0]);
      std::fprintf(stderr,
                   "  p.prim %d r.prim %d exit %d/%d pn (%.6Lg %.6Lg %.6Lg) cand (%.6Lg %.6Lg "
                   "%.6Lg) n=%zu\n",
                   p.prim, r.prim, p.exit, r.exit, pn[0], pn[1], pn[2], cw[0], cw[1], cw[2],
                   cands.size());
    }
    if (listing) {
      const LD k4 = angleBetween(rp.normalByForward(cands[0]), rp.normalToWorld(cands[0]));
      if (std::min(k4, kPi - k4) > 1e-6L) ++f.semanticK4;
    }
  }
}

// (u, v) by the listing's inverse mapping at both local points, on the
// reference's primitive only.
void Measurer::measureUv(const ProfileHit& p, const RefResult& r, const RefPoint& at,
                         Figures& f) const {
  if (p.prim != r.prim) return;
  const RefPrim<LD>& rp = *at.prim;
  const V3<LD>& pl = at.p;
  const Vec3 refLocal{double(pl[0]), double(pl[1]), double(pl[2])};
  const io::PrimType type = s_.scene.prims[static_cast<std::size_t>(r.prim)].type;
  const InverseMapResult a = inverseMap1991(type, p.local), b = inverseMap1991(type, refLocal);
  if (!std::isfinite(a.u) || !std::isfinite(a.v)) {
    ++f.uvNan;
  } else if (a.surface != b.surface) {
    ++f.uvFaceChanges;
  } else if (std::isfinite(b.u) && std::isfinite(b.v)) {
    double du = std::abs(a.u - b.u);
    if ((rp.type == 'S' || ((rp.type == 'C' || rp.type == 'N') && a.surface == 0)) && du > 0.5)
      du = std::abs(du - 1);
    f.uv.add(std::max(du, std::abs(a.v - b.v)));
  }
}

// World unit normals of every face of the reference hit's primitive within
// the tolerance of the reference hit point.
std::vector<Vec3> Measurer::worldNormalsAt(const RefResult& r, const Ray& ray) const {
  std::vector<Vec3> out;
  if (!r.hit) return out;
  const RefPoint at = refPointAt(r, ray);
  for (const V3<LD>& c : refNormals(at.prim->type, at.p, at.tol)) {
    const V3<LD> n = at.prim->normalToWorld(c);
    out.push_back({double(n[0]), double(n[1]), double(n[2])});
  }
  return out;
}

std::string Measurer::describe() const {
  std::string d;
  for (const auto& p : s_.scene.prims) d += static_cast<char>(p.type);
  for (const auto& o : s_.scene.objects) d += std::string(" ") + o.entries[0].op;
  return d;
}

LD Measurer::nsdf(const std::vector<CsgEntry>& e, int node, const V3<LD>& pw, const Ray& ray, LD t,
                  int depth) const {
  if (node < 0 || node >= static_cast<int>(e.size()) || depth > static_cast<int>(e.size()))
    return 1e30L;
  const CsgEntry& c = e[static_cast<std::size_t>(node)];
  if (c.op == 'P') {
    const RefPrim<LD>& rp = s_.refLd[static_cast<std::size_t>(c.l)];
    const V3<LD> pl = rp.toLocalPoint(pw);
    return refSdf(rp.type, pl) / tolerance(c.l, ray, t, pl);
  }
  const LD a = nsdf(e, c.l, pw, ray, t, depth + 1), b = nsdf(e, c.r, pw, ray, t, depth + 1);
  switch (c.op) {
    case '+':
      return std::min(a, b);
    case '&':
      return std::max(a, b);
    default:
      return std::max(a, -b);
  }
}

}  // namespace prime::stress
