// The stress suite's subjects (one primitive, or two under a CSG operator,
// as a Scene and as the reference's primitives), the reference's nearest
// boundary along a ray, and each profile's answer for the same ray.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/scene/scene.h"
#include "src/prime/stress/common.h"
#include "src/prime/stress/reference.h"

namespace prime::stress {

// ------------------------------------------------------------------ subjects

struct Subject {
  Scene scene;
  std::vector<RefPrim<LD>> refLd;
  std::vector<RefPrim<Quad>> refQ;
  double size = 1;  // world size of the solids (for the self-intersection distance)
};

// Transform(s, t, pivot 0, r) as the listing builds a primitive's matrix.
Matrix4 listingTransform(const Vec3& s, const Vec3& t, const Vec3& r);
// The same with EXACT quarter turns (r in multiples of 90 degrees).
Matrix4 exactQuarterTransform(const Vec3& s, const Vec3& t, const std::array<int, 3>& quarters);
Matrix4 mul(Matrix4 a, const Matrix4& b);  // a * b (row vectors: a first)

struct PrimSpec {
  char type;
  Matrix4 m;
};

Subject makeSubject(const std::vector<PrimSpec>& prims,
                    const std::vector<std::vector<CsgEntry>>& objects);

// ------------------------------------------------------------------ reference evaluation

struct RefResult {
  bool hit = false, exit = false;
  LD t = 0, a = 0, b = 0;  // the nearest boundary ahead, and its solid span [a, b]
  int obj = -1, prim = -1;
  V3<LD> n{};  // outward normal of the result solid there (local frame of prim)
};

template <class T>
RefList<T> refObject(const std::vector<CsgEntry>& e, int node,
                     const std::vector<std::optional<RefInterval<T>>>& iv, int depth = 0) {
  if (node < 0 || node >= static_cast<int>(e.size()) || depth > static_cast<int>(e.size()))
    return {};
  const CsgEntry& c = e[static_cast<std::size_t>(node)];
  if (c.op == 'P') {
    const auto& h = iv[static_cast<std::size_t>(c.l)];
    if (!h) return {};
    return {{{h->tIn, c.l, h->nIn}, {h->tOut, c.l, h->nOut}}};
  }
  RefList<T> a = refObject(e, c.l, iv, depth + 1);
  if (a.empty() && (c.op == '-' || c.op == '&')) return a;
  return refCombine(c.op, a, refObject(e, c.r, iv, depth + 1));
}

template <class T>
RefResult refNearest(const Subject& s, const std::vector<RefPrim<T>>& prims, const Ray& ray,
                     bool k7) {
  std::vector<std::optional<RefInterval<T>>> iv(prims.size());
  const RefRay<T> w{cast3<T>(ray.o), cast3<T>(ray.d)};
  for (std::size_t k = 0; k < prims.size(); ++k) {
    const RefRay<T> l{prims[k].toLocalPoint(w.o), prims[k].toLocalVector(w.d)};
    RefInterval<T> in;
    if (refIntersect(prims[k].type, l, in) && (!k7 || in.tIn > T(0))) iv[k] = in;
  }
  RefResult r;
  for (std::size_t o = 0; o < s.scene.objects.size(); ++o) {
    const RefList<T> list = refObject(s.scene.objects[o].entries, 0, iv);
    for (const auto& span : list) {
      const bool entry = span.in.t > T(0);
      if (!entry && !(span.out.t > T(0))) continue;
      const RefNode<T>& node = entry ? span.in : span.out;
      if (!r.hit || LD(node.t) < r.t) {
        r.hit = true, r.exit = !entry, r.t = LD(node.t), r.a = LD(span.in.t), r.b = LD(span.out.t);
        r.obj = static_cast<int>(o), r.prim = node.prim, r.n = cast3<LD>(node.n);
      }
      break;
    }
  }
  return r;
}

// ------------------------------------------------------------------ the profiles

struct ProfileHit {
  bool hit = false, exit = false, error = false;
  double t = 0;
  int obj = -1, prim = -1;
  Vec3 point{}, local{}, normal{}, pointError{};
  SurfaceHit surf;  // the modern profile's whole answer (spawnOrigin needs it)
};

// The modern profile's nearest hit (TracerModern::nearestHit).
ProfileHit modernHit(const TracerModern& tracer, const Ray& ray);
// CastRay's nearest-object search of the 1991 profile (tracer_1991.cpp),
// over the object list in order, without bounds (the stress scenes have none).
ProfileHit listingHit(const Scene& scene, const Ray& rayIn);
// What csg1991 makes of the REFERENCE intervals (K7-filtered, rounded to
// double): separates the printed operators' set errors (semantic) from
// rounding.
ProfileHit listingOnReference(const Subject& s, const Ray& ray);

}  // namespace prime::stress
