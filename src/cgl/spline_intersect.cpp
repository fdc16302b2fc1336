// B-spline surfaces: evaluation, Newton's iteration and the walks of the box
// tree (sections 6.5 to 6.8): the document's heap walk, the packet walks,
// occlusion, the dense reference. The hot walk and Newton stay in this one
// translation unit, so that their kernels inline as measured
// (docs/cgl/benchmarks.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "src/cgl/spline.h"
#include "src/cgl/spline_kernels.h"

namespace prime::cgl {

using namespace spline_detail;

namespace {

// Q, Q_u, Q_v as the scalar loop over Vec3 computed them (rows summed from
// zero in a, then weighted into the sums from zero in b), lane by lane
// (CGL-D172).
[[gnu::always_inline]] inline SplinePoint evaluateImpl(const SplineSurface& s, double u, double v) {
  double lu = 0, lv = 0;
  const int i = interval(u, s.m, lu), j = interval(v, s.n, lv);
  double wu[4], dwu[4], wv[4], dwv[4];
  basisWeights(lu, wu, dwu);
  basisWeights(lv, wv, dwv);
  const V4 zero = {0.0, 0.0, 0.0, 0.0};
  V4 q = zero, qu = zero, qv = zero;
  for (int b = 0; b < 4; ++b) {
    V4 row = zero, drow = zero;
    const double* base = s.u4.data() + 4 * static_cast<std::size_t>((i + 1) + (j + 1 + b) * s.mu);
    for (int a = 0; a < 4; ++a) {
      V4 c;
      load4(c, base + 4 * a);
      row = row + c * wu[a];
      drow = drow + c * dwu[a];
    }
    q = q + row * wv[b];
    qu = qu + drow * wv[b];
    qv = qv + row * dwv[b];
  }
  SplinePoint out;
  out.q = {q[0], q[1], q[2]};
  out.qu = {qu[0], qu[1], qu[2]};
  out.qv = {qv[0], qv[1], qv[2]};
  return out;
}

}  // namespace

PRIME_SPLINE_CLONES SplinePoint evaluate(const SplineSurface& s, double u, double v) {
  return evaluateImpl(s, u, v);
}

void evaluateLong(const SplineSurface& s, long double u, long double v, long double out[3]) {
  auto weights = [](long double t, long double w[4]) {
    const long double r = 1.0L - t;
    w[0] = r * r * r / 6.0L;
    w[1] = (4.0L - 6.0L * t * t + 3.0L * t * t * t) / 6.0L;
    w[2] = (1.0L + 3.0L * t + 3.0L * t * t - 3.0L * t * t * t) / 6.0L;
    w[3] = t * t * t / 6.0L;
  };
  int i = std::clamp(static_cast<int>(std::floor(u)), -1, s.m);
  int j = std::clamp(static_cast<int>(std::floor(v)), -1, s.n);
  long double wu[4], wv[4];
  weights(u - i, wu);
  weights(v - j, wv);
  out[0] = out[1] = out[2] = 0.0L;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const Vec3& c = s.u[static_cast<std::size_t>((i + 1 + a) + (j + 1 + b) * s.mu)];
      for (int k = 0; k < 3; ++k) out[k] += static_cast<long double>(c[k]) * wu[a] * wv[b];
    }
}

RayPlanes rayPlanes(const Ray& ray) {
  RayPlanes p;
  const Vec3& d = ray.d;
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(d[a]) < std::fabs(d[k])) k = a;
  Vec3 e{0, 0, 0};
  e[k] = 1.0;
  const Vec3 n1 = cross(d, e);
  const double l1 = length(n1);
  if (!(l1 > 0.0)) return p;
  p.n1 = n1 * (1.0 / l1);
  const Vec3 n2 = cross(p.n1, d);
  const double l2 = length(n2);
  if (!(l2 > 0.0)) return p;
  p.n2 = n2 * (1.0 / l2);
  p.a1 = dot(p.n1, ray.o);
  p.a2 = dot(p.n2, ray.o);
  p.ok = true;
  return p;
}

RayPlanes documentRayPlanes(const Ray& ray) {
  RayPlanes p;
  p.n1 = cross(ray.o, ray.d);
  p.n2 = cross(p.n1, ray.d);
  p.a1 = dot(p.n1, ray.o);
  p.a2 = dot(p.n2, ray.o);
  p.ok = true;  // degenerate (N_1 = 0) when O = 0 or O || D: Newton's Jacobian is then singular
  return p;
}

namespace {

[[gnu::always_inline]] inline NewtonResult newtonImpl(const SplineSurface& s,
                                                      const RayPlanes& planes, const Ray& ray,
                                                      double u0, double v0,
                                                      const SplinePoint& start,
                                                      const NewtonOptions& options) {
  NewtonResult res;
  if (!planes.ok) return res;
  double u = u0, v = v0;
  SplinePoint sp = start;
  // (6.8.1) with the basis factor B_{i,4}(u) B_{j,4}(v) (CGL-E140).
  double e1 = dot(planes.n1, sp.q) - planes.a1, e2 = dot(planes.n2, sp.q) - planes.a2;
  double err = std::fabs(e1) + std::fabs(e2);
  for (int it = 1; it <= options.maxIterations; ++it) {
    const double j11 = dot(planes.n1, sp.qu), j12 = dot(planes.n1, sp.qv);
    const double j21 = dot(planes.n2, sp.qu), j22 = dot(planes.n2, sp.qv);
    const double det = j11 * j22 - j12 * j21;
    res.iterations = it;
    if (!(det != 0.0) || !std::isfinite(det)) return res;
    const double du = (e1 * j22 - e2 * j12) / det, dv = (j11 * e2 - j21 * e1) / det;
    u -= du;
    v -= dv;
    // Failure: the iterate leaves the parameter range ...
    if (!(u >= s.umin && u <= s.umax && v >= s.vmin && v <= s.vmax)) return res;
    sp = evaluateImpl(s, u, v);
    e1 = dot(planes.n1, sp.q) - planes.a1;
    e2 = dot(planes.n2, sp.q) - planes.a2;
    const double next = std::fabs(e1) + std::fabs(e2);
    if (next < options.tolerance) {
      const Vec3 od = sp.q - ray.o;
      res.hit = true;
      res.u = u;
      res.v = v;
      res.t = dot(od, ray.d) / dot(ray.d, ray.d);  // CGL-E141
      res.qu = sp.qu;
      res.qv = sp.qv;
      return res;
    }
    // ... or |E_1| + |E_2| increased.
    if (next > err) return res;
    err = next;
  }
  return res;  // CGL-Q144: the iteration cap
}

}  // namespace

PRIME_SPLINE_CLONES NewtonResult newton(const SplineSurface& s, const RayPlanes& planes,
                                        const Ray& ray, double u0, double v0,
                                        const NewtonOptions& options) {
  if (!planes.ok) return {};
  return newtonImpl(s, planes, ray, u0, v0, evaluateImpl(s, u0, v0), options);
}

PRIME_SPLINE_CLONES NewtonResult newtonFrom(const SplineSurface& s, const RayPlanes& planes,
                                            const Ray& ray, double u0, double v0,
                                            const SplinePoint& start,
                                            const NewtonOptions& options) {
  return newtonImpl(s, planes, ray, u0, v0, start, options);
}

SplineCounters& SplineCounters::operator+=(const SplineCounters& o) {
  calls += o.calls;
  boxes += o.boxes;
  newtonCalls += o.newtonCalls;
  iterations += o.iterations;
  hits += o.hits;
  return *this;
}

namespace {

struct Active {
  double d;
  int node;
};
// Min-heap order on (distance, node): deterministic for ties.
bool later(const Active& a, const Active& b) {
  return a.d > b.d || (a.d == b.d && a.node > b.node);
}

// The per-thread active list (section 6.7): reserved once for the largest
// tree the thread meets, so a ray never allocates (each node enters the list
// at most once, so the size never exceeds the node count).
thread_local std::vector<Active> tActive;

}  // namespace

bool intersectSplineDocument(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                             SplineHit& hit, SplineCounters& counters,
                             std::vector<NewtonStart>* record) {
  ++counters.calls;
  if (s.nodes.empty()) return false;
  std::vector<Active>& active = tActive;
  if (active.capacity() < s.nodes.size()) active.reserve(s.nodes.size());
  active.clear();
  const BoxRay boxRay(ray);
  ++counters.boxes;
  const double d0 = s.nodes[0].box.entry(boxRay);
  if (!(d0 < tMax)) return false;
  active.push_back({d0, 0});
  const RayPlanes planes = rayPlanes(ray);
  NewtonOptions options;
  options.tolerance = s.tolerance;
  double best = tMax;
  bool found = false;
  while (!active.empty()) {
    std::pop_heap(active.begin(), active.end(), later);
    const Active a = active.back();
    active.pop_back();
    // Success: the hit is nearer than the first node on the list.
    if (!(a.d < best)) break;
    const SplineNode& n = s.nodes[static_cast<std::size_t>(a.node)];
    if (n.count == 0) {
      ++counters.newtonCalls;
      if (record) record->push_back({n.u0, n.v0});
      const NewtonResult r = newton(s, planes, ray, n.u0, n.v0, options);
      counters.iterations += static_cast<std::uint64_t>(r.iterations);
      if (r.hit && r.t > tMin && r.t < best) {
        best = r.t;
        found = true;
        hit = {r.t, r.u, r.v, n.u0, n.v0, r.iterations, r.qu, r.qv};
      }
      continue;
    }
    for (int c = 0; c < n.count; ++c) {
      const int ci = n.first + c;
      ++counters.boxes;
      const double d = s.nodes[static_cast<std::size_t>(ci)].box.entry(boxRay);
      if (d < best) {
        active.push_back({d, ci});
        std::push_heap(active.begin(), active.end(), later);
      }
    }
  }
  if (found) ++counters.hits;
  return found;
}

namespace {

// Aabb::entry(BoxRay) on the lanes of a packet: the same operations in the
// same order per lane, so the same doubles (CGL-D170).
inline void packetEntries(const SplinePacket& p, const BoxRay& r, double d[4]) {
  if (!r.simple || !p.plain) {
    for (int lane = 0; lane < p.count; ++lane) {
      Aabb b;
      b.lo = {p.lo[0][lane], p.lo[1][lane], p.lo[2][lane]};
      b.hi = {p.hi[0][lane], p.hi[1][lane], p.hi[2][lane]};
      d[lane] = b.entry(r);
    }
    return;
  }
  // Four lanes at once (CGL-D172; GCC/Clang vector extensions: AVX2 or two
  // SSE2 halves on x86-64): x > t0 ? x : t0 is std::max(t0, x) and y < t1 ?
  // y : t1 is std::min(t1, y) for the NaN-free values here, lane by lane.
  V4 t0 = {0.0, 0.0, 0.0, 0.0}, t1 = {kInf, kInf, kInf, kInf};
  for (int a = 0; a < 3; ++a) {
    V4 nearPlane, farPlane;
    load4(nearPlane, r.neg[a] ? p.hi[a] : p.lo[a]);
    load4(farPlane, r.neg[a] ? p.lo[a] : p.hi[a]);
    const double o = r.ray.o[a], inv = r.inv[a];
    const V4 x = (nearPlane - o) * inv;
    const V4 y = (farPlane - o) * inv;
    t0 = x > t0 ? x : t0;
    t1 = y < t1 ? y : t1;
  }
  const V4 miss = {kInf, kInf, kInf, kInf};
  const V4 out = t0 <= t1 ? t0 : miss;
  std::memcpy(d, &out, sizeof out);
}

// A leaf the ray enters: its box entry, node index (the document's order)
// and leaf record.
struct Tried {
  double d;
  int node;
  int leaf;
};
thread_local std::vector<Tried> tTried;

struct StackEntry {
  double d;
  int ref;
};
// The tree's depth is at most 1 + log2 of the knots per side (< 32 for int
// counts); a packet adds at most 3 entries net per level: 128 is plenty.
constexpr int kStack = 128;
// Newton runs once ahead of the document's order, at the first leaf
// reached, for a bound (running ahead until a first hit cost
// as much as the boxes it spared on the shipped scenes).

// Pushes the lanes of packet `p` whose box the ray enters before tMax; with
// `Nearest`, the nearest on top (for the shadow query's early end).
template <bool Nearest>
inline void pushLanes(const SplinePacket& p, const BoxRay& boxRay, double tMax, double bound,
                      StackEntry* stack, int& top, SplineCounters& counters) {
  double d[4];
  packetEntries(p, boxRay, d);
  counters.boxes += static_cast<std::uint64_t>(p.count);
  if (!Nearest) {
    for (int lane = 0; lane < p.count; ++lane)
      if (d[lane] < tMax && !(d[lane] > bound)) stack[top++] = {d[lane], p.ref[lane]};
    return;
  }
  int order[4];
  int k = 0;
  for (int lane = 0; lane < p.count; ++lane)
    if (d[lane] < tMax && !(d[lane] > bound)) {
      int j = k++;
      for (; j > 0 && d[order[j - 1]] < d[lane]; --j) order[j] = order[j - 1];
      order[j] = lane;  // order: farthest first
    }
  for (int j = 0; j < k; ++j) stack[top++] = {d[order[j]], p.ref[order[j]]};
}

}  // namespace

bool intersectSpline(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                     SplineHit& hit, SplineCounters& counters, std::vector<NewtonStart>* record) {
  return intersectSpline(s, BoxRay(ray), tMin, tMax, hit, counters, record);
}

PRIME_SPLINE_CLONES bool intersectSplineBelowRoot(const SplineSurface& s, const BoxRay& boxRay,
                                                  double rootEntry, double tMin, double tMax,
                                                  SplineHit& hit, SplineCounters& counters,
                                                  std::vector<NewtonStart>* record) {
  const Ray& ray = boxRay.ray;
  std::vector<Tried>& tried = tTried;
  if (tried.size() < s.leafData.size()) tried.resize(s.leafData.size());
  // Each leaf is listed at most once: the sized scratch is enough.
  Tried* const list = tried.data();
  int listed = 0;
  RayPlanes planes;
  NewtonOptions options;
  options.tolerance = s.tolerance;
  // Depth first, nearest child first, listing the leaves the ray's box
  // entry puts before `bound`; Newton runs at the first leaf reached; if it
  // hits, bound = max(t_F, d_F) for that leaf F:
  // a leaf L with d_L > bound comes after F in the document's order (entry,
  // node index), where the nearest hit so far is at most t_F < d_L, so the
  // document's walk has stopped before L, and L need not be listed.
  double bound = tMax;
  // The one run ahead of the document's order: its leaf
  // and result, reused by the replay below.
  int aheadLeaf = -1;
  NewtonResult ahead;
  StackEntry stack[kStack];
  // The root, entered at rootEntry < tMax (the caller's test, CGL-D174).
  stack[0] = {rootEntry, s.packets[0].ref[0]};
  int top = 1;
  while (top > 0) {
    const StackEntry e = stack[--top];
    if (e.d > bound) continue;
    if (e.ref >= 0) {
      pushLanes<true>(s.packets[static_cast<std::size_t>(e.ref)], boxRay, tMax, bound, stack, top,
                      counters);
      continue;
    }
    const int leafIndex = ~e.ref;
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(leafIndex)];
    if (aheadLeaf < 0) {
      // The planes when a first leaf is reached (CGL-D173: most rays that
      // enter the root's box reach no leaf); every later run follows this one.
      planes = rayPlanes(ray);
      aheadLeaf = leafIndex;
      ahead = newtonImpl(s, planes, ray, leaf.u0, leaf.v0, leaf.start, options);
      if (ahead.hit && ahead.t > tMin && ahead.t < tMax) bound = std::max(ahead.t, e.d);
    }
    list[listed++] = {e.d, leaf.node, leafIndex};
  }
  if (listed == 0) return false;
  // The document's walk over the listed leaves: nearest entry first (ties
  // by node index, the heap's order), Newton at each (the run ahead
  // reused), stopping at the first leaf no nearer than the hit.
  // (entry, node index) is a strict order (node indices are unique), so
  // any sort gives the same list; a short list, the common case, by
  // insertion.
  const auto before = [](const Tried& a, const Tried& b) {
    return a.d < b.d || (a.d == b.d && a.node < b.node);
  };
  if (listed <= 16) {
    for (int i = 1; i < listed; ++i) {
      const Tried x = list[i];
      int j = i;
      for (; j > 0 && before(x, list[j - 1]); --j) list[j] = list[j - 1];
      list[j] = x;
    }
  } else {
    std::sort(list, list + listed, before);
  }
  double best = tMax;
  bool found = false;
  bool aheadUsed = false;
  for (int k = 0; k < listed; ++k) {
    const Tried& x = list[k];
    if (!(x.d < best)) break;
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(x.leaf)];
    NewtonResult r;
    if (x.leaf == aheadLeaf) {
      r = ahead;
      aheadUsed = true;
    } else {
      r = newtonImpl(s, planes, ray, leaf.u0, leaf.v0, leaf.start, options);
    }
    ++counters.newtonCalls;
    counters.iterations += static_cast<std::uint64_t>(r.iterations);
    if (record) record->push_back({leaf.u0, leaf.v0});
    if (r.hit && r.t > tMin && r.t < best) {
      best = r.t;
      found = true;
      hit = {r.t, r.u, r.v, leaf.u0, leaf.v0, r.iterations, r.qu, r.qv};
    }
  }
  if (aheadLeaf >= 0 && !aheadUsed) {
    // The run ahead at a leaf the document's walk does not reach.
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(aheadLeaf)];
    ++counters.newtonCalls;
    counters.iterations += static_cast<std::uint64_t>(ahead.iterations);
    if (record) record->push_back({leaf.u0, leaf.v0});
  }
  if (found) ++counters.hits;
  return found;
}

bool occludesSpline(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                    SplineCounters& counters) {
  return occludesSpline(s, BoxRay(ray), tMin, tMax, counters);
}

PRIME_SPLINE_CLONES bool occludesSplineBelowRoot(const SplineSurface& s, const BoxRay& boxRay,
                                                 double rootEntry, double tMin, double tMax,
                                                 SplineCounters& counters) {
  const Ray& ray = boxRay.ray;
  RayPlanes planes;
  bool havePlanes = false;  // CGL-D173: computed at the first leaf
  NewtonOptions options;
  options.tolerance = s.tolerance;
  StackEntry stack[kStack];
  stack[0] = {rootEntry, s.packets[0].ref[0]};
  int top = 1;
  while (top > 0) {
    const StackEntry e = stack[--top];
    if (e.ref >= 0) {
      pushLanes<true>(s.packets[static_cast<std::size_t>(e.ref)], boxRay, tMax, kInf, stack, top,
                      counters);
      continue;
    }
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(~e.ref)];
    if (!havePlanes) {
      planes = rayPlanes(ray);
      havePlanes = true;
    }
    ++counters.newtonCalls;
    const NewtonResult r = newtonImpl(s, planes, ray, leaf.u0, leaf.v0, leaf.start, options);
    counters.iterations += static_cast<std::uint64_t>(r.iterations);
    if (r.hit && r.t > tMin && r.t < tMax) {
      ++counters.hits;
      return true;
    }
  }
  return false;
}

bool intersectSplineReference(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                              SplineHit& hit) {
  const BoxRay boxRay(ray);
  const RayPlanes planes = rayPlanes(ray);
  NewtonOptions options;
  options.tolerance = s.tolerance;
  options.maxIterations = 40;
  const std::vector<int> ua = knotsInRange(s.m, s.divisions, {s.umin, s.umax});
  const std::vector<int> vb = knotsInRange(s.n, s.divisions, {s.vmin, s.vmax});
  double best = tMax;
  bool found = false;
  for (std::size_t jb = 0; jb + 1 < vb.size(); ++jb)
    for (std::size_t ia = 0; ia + 1 < ua.size(); ++ia) {
      const int a = ua[ia], b = vb[jb];
      // The surface over [w_a, w_{a+1}) x [t_b, t_{b+1}) lies in the convex
      // hull of W_{a-3..a, b-3..b} (section 6.1's convex hull property).
      Aabb box;
      for (int sj = b - 3; sj <= b; ++sj)
        for (int ri = a - 3; ri <= a; ++ri)
          box.add(s.w[static_cast<std::size_t>((ri + 4) + (sj + 4) * s.pu)]);
      const double pad = 4.0 * s.tolerance;
      box.lo = box.lo - Vec3{pad, pad, pad};
      box.hi = box.hi + Vec3{pad, pad, pad};
      if (!(box.entry(boxRay) < best)) continue;
      const double u0 = refinedKnot(a, s.m, s.divisions), u1 = refinedKnot(a + 1, s.m, s.divisions);
      const double v0 = refinedKnot(b, s.n, s.divisions), v1 = refinedKnot(b + 1, s.n, s.divisions);
      const double starts[5][2] = {
          {(u0 + u1) / 2, (v0 + v1) / 2}, {u0, v0}, {u1, v0}, {u0, v1}, {u1, v1}};
      for (const auto& st : starts) {
        const NewtonResult r = newton(s, planes, ray, st[0], st[1], options);
        if (r.hit && r.t > tMin && r.t < best) {
          best = r.t;
          found = true;
          hit = {r.t, r.u, r.v, st[0], st[1], r.iterations, r.qu, r.qv};
        }
      }
    }
  return found;
}

}  // namespace prime::cgl
