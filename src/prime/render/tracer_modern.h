// The modern profile's ray tree: the same scenes and databases as the 1991
// profile, with the arithmetic and the geometry done right (see the "Modern
// profile" section of docs/prime/deviations.md for every difference):
//   - whole-line primitive intervals with cancellation-free quadratics and
//     correct set operations (a ray that starts inside a solid sees its exit);
//   - the nearest hit is the smallest t ahead, not the list's first node;
//   - normals transformed by the inverse transpose, faced towards the ray;
//   - secondary rays start from the hit point pushed off the surface by a
//     bound on its floating-point error (pbrt-v4 style), not a 1-unit step;
//   - Hall's terms with the light vector pointing at the light, clamped
//     dot products and inverse trigonometry, world-frame refraction;
//   - no NaN or Inf ever reaches a pixel.
#pragma once
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "src/prime/geom/csg_pointwise.h"
#include "src/prime/geom/csg_program_1991.h"
#include "src/prime/math/robust.h"
#include "src/prime/render/hall_1991.h"
#include "src/prime/render/probe.h"
#include "src/prime/render/trace_options.h"
#include "src/prime/render/trace_stats.h"
#include "src/prime/scene/object_bvh.h"
#include "src/prime/scene/scene.h"

namespace prime {

struct SurfaceHit {
  double t = 0;
  int obj = -1, prim = -1;
  bool fromInsidePrim = false;  // the ray meets the primitive's surface from inside (inside map)
  bool exitsObject = false;     // the ray starts inside the object's solid and leaves it here
  Vec3 point{}, local{},
      normal{};       // world point, primitive-space point, unit normal facing the ray
  Vec3 pointError{};  // bound on the point's distance from the exact surface, per axis
  // Every surface of the object's primitives that passes within the error
  // bound of `point` (the hit surface, and the other faces at an edge or a
  // corner): world unit normals and how far to step off each. Only the
  // first nearCount entries are ever written or read: left uninitialised,
  // since every ray cast makes a SurfaceHit and most never hit.
  std::array<Vec3, 12> near;
  std::array<double, 12> nearStep;
  int nearCount = 0;
  bool nearOwn = false;  // a surface of the hit's own primitive is among them
};

// Whether w leaves through every surface near the hit (hit.near, outward
// normals): w points out of each, so a ray from spawnOrigin(hit, w) starts
// outside all of them and, when they bound a convex solid, runs outside it.
// "Out" by more than 1e-9 (w and the normals are unit vectors): a ray within
// rounding of parallel to a surface, whose side the primitive's own test in
// its local frame might see otherwise, is not counted as leaving. False
// when no surface was found near the point.
inline bool leavesThrough(const SurfaceHit& hit, const Vec3& w) {
  constexpr double kClearlyOut = 1e-9;
  if (hit.nearCount == 0) return false;
  for (int k = 0; k < hit.nearCount; ++k)
    if (!(dot(w, hit.near[static_cast<std::size_t>(k)]) > kClearlyOut)) return false;
  return true;
}

class TracerModern {
 public:
  TracerModern(const Scene& scene, RayTreeOptions options = {});

  // With a probe, every ray, the tests of the objects the BVH visits (as a
  // render visits them), the hit, texture, transmission and Hall's terms are
  // recorded, as Tracer1991::castRay records the 1991 profile's.
  // `leaves`: an object the ray starts on and provably never meets again
  // (leavingSolid), not tested; -1 for none.
  Rgb castRay(Ray ray, int depth, TraceStats& stats, Probe* probe = nullptr,
              RayKind kind = RayKind::Primary, double weight = 1.0, int leaves = -1) const;
  // The nearest surface along the ray with t > 0, if any; object `leaves`
  // (as castRay's) is not tested.
  bool nearestHit(const Ray& ray, SurfaceHit& hit, TraceStats& stats, Probe* probe = nullptr,
                  int depth = 0, int leaves = -1) const;
  // The object's solid along the whole line of `ray` (sorted intervals).
  TList objectIntervals(const SceneObject& obj, const Ray& ray, TraceStats& stats,
                        Probe* probe = nullptr, int depth = 0) const;
  // The object's solid along `ray`, exact for 0 <= t <= tMax (N18): a
  // primitive whose padded world box the ray does not enter in [0, tMax]
  // counts as missed without being tested. Set operations are pointwise in
  // t, so every node of the list in that range -- its t, surface type,
  // primitive and normal -- is objectIntervals' node; outside it the list may
  // differ. What the render uses (the first node ahead, the solid's length
  // up to a light) lies in the range. No probe: a probe sees every test.
  // `normals` says what the nodes' normals hold: the primitives' (kFull);
  // nothing to be read (kNone: for the length inside a solid); or, for
  // nearestHit, a marker of the primitive's end and sign that
  // recoverNormal turns into kFull's normal once a node is chosen
  // (kMarkers: the candidates' normals are never computed).
  enum class Normals { kFull, kNone, kMarkers };
  TList objectIntervalsAhead(const SceneObject& obj, const BoxRay& ray, double tMax,
                             TraceStats& stats, Normals normals = Normals::kFull) const;
  // The length of object `object`'s solid along `ray` between 0 and tMax
  // (a shadow ray's path inside it): the sum over objectIntervalsAhead's
  // pairs of min(tMax, exit) - max(0, entry) where positive, in list order;
  // a lone primitive's without building the list (N18).
  double insideLength(std::size_t object, const BoxRay& ray, double tMax, TraceStats& stats) const;
  // Whether insideLength(object, ray, tMax) > 0, the solid met between 0
  // and tMax, asking only the leaves it depends on (N18).
  bool blocks(std::size_t object, const BoxRay& ray, double tMax, TraceStats& stats) const;
  // Object `object` when a ray leaving `at` (a point of its surface, as
  // surfaceAt gives it) in direction w provably never meets it again, else
  // -1 (castRay's `leaves`): the point is on a primitive that holds the
  // whole solid (containingPrimitives: a lone primitive, the left operand
  // of a difference, either operand of an intersection), that primitive is
  // convex (every PRIME primitive is), and w leaves through every surface
  // near the point, the primitive's among them (leavesThrough; not when
  // at.near is full, since a near surface may have been left out).
  int leavingSolid(std::size_t object, const SurfaceHit& at, const Vec3& w) const {
    const std::vector<int>& holders = containers_[object];
    return at.nearOwn && at.nearCount < static_cast<int>(at.near.size()) &&
                   std::find(holders.begin(), holders.end(), at.prim) != holders.end() &&
                   leavesThrough(at, w)
               ? static_cast<int>(object)
               : -1;
  }
  int leavingSolid(const SurfaceHit& hit, const Vec3& w) const {
    return leavingSolid(static_cast<std::size_t>(hit.obj), hit, w);
  }

  // The texel at the hit (inverse mapping, N11, N12, N17), probed.
  Rgb surfaceColour(const SurfaceHit& hit, int depth, Probe* probe) const;
  // Refract into the hit's object, walk to where the ray leaves it and
  // refract out (N9): the leaving ray, the distance inside, and whether it
  // got through (false: total internal reflection or trapped).
  // `leaves` (if given): the object the leaving ray provably never meets
  // again (castRay's `leaves`), or -1.
  Ray transmit(const Ray& ray, const SurfaceHit& hit, double indx, double& distance, bool& through,
               TraceStats& stats, Probe* probe, int depth, int* leaves = nullptr) const;

  const Scene& scene() const { return scene_; }
  // The object boxes every ray is tested against first (the BVH's).
  const ObjectBvh& bvh() const { return bvh_; }
  // accurateInverse of primitive `prim`'s transform (N15).
  const Matrix4& primInverse(int prim) const { return inverse_[static_cast<std::size_t>(prim)]; }

 private:
  // `local`: the ray in the node's primitive's frame, when the caller has it.
  void surfaceAt(const SceneObject& obj, const Ray& ray, const TNode& node, SurfaceHit& hit,
                 const Ray* local = nullptr) const;
  // The object's first surface at 0 < t <= tMax: objectIntervalsAhead's
  // first node with t > 0, if any.
  bool firstNodeAhead(std::size_t object, const BoxRay& ray, double tMax, TraceStats& stats,
                      TNode& node) const;
  // A lone primitive's pair along the ray, counted and culled as
  // objectIntervalsAhead's leaf (N18): false when its padded box is not
  // entered in [0, tMax] or the line misses it; with `normals`,
  // intersectModern's normals, else none (intersectModernT).
  bool lonePair(std::size_t object, const BoxRay& ray, double tMax, bool normals, TraceStats& stats,
                int& prim, PrimHit& in) const;
  // Primitive `prim`'s interval along the ray (intersectModernT), counted.
  bool leafSpan(int prim, const Ray& ray, TraceStats& stats, CsgPointwise::Span& span) const;
  // The spans of object `object`'s leaves along the ray, culled and counted
  // as objectIntervalsAhead's leaves (CsgPointwise::gather); false when the
  // list must be built (an empty or NaN interval).
  bool pointwiseSpans(std::size_t object, const BoxRay& ray, double tMax, TraceStats& stats,
                      std::array<CsgPointwise::Span, CsgPointwise::kMaxLeaves>& spans) const;
  // firstNodeAhead for a tree with a pointwise form: firstAheadLazy with
  // the leaves culled by their padded boxes and counted.
  CsgPointwise::Answer pointwiseFirstAhead(std::size_t object, const BoxRay& ray, double tMax,
                                           TraceStats& stats, TNode& node) const;
  // Where a ray inside the object leaves it: objectIntervalsAhead's (kFull)
  // first node ahead that leaves the solid, if any.
  bool exitAhead(std::size_t object, const Ray& ray, TraceStats& stats, TNode& exit) const;
  const Scene& scene_;
  RayTreeOptions options_;
  ObjectBvh bvh_;
  std::vector<HallLight> lights_;
  std::vector<Matrix4> inverse_;  // accurateInverse of every primitive's transform
  // Per primitive: the colour every point of it shows when each map its
  // surfaces use (outside and inside) is one colour, the same for all; the
  // texel then does not depend on (u, v), and surfaceColour skips the
  // inverse mapping (probes still make it).
  std::vector<std::optional<Rgb>> plainColour_;
  std::vector<CsgProgram1991> programs_;       // per object: its tree compiled (compileModern)
  std::vector<std::vector<int>> unionLeaves_;  // per object: CsgProgram1991::unionLeaves
  std::vector<std::vector<int>> containers_;   // per object: containingPrimitives
  // Per object: its tree read point by point (N18), for trees of up to
  // CsgPointwise::kMaxLeaves leaves and no shared subtree.
  std::vector<std::optional<CsgPointwise>> pointwise_;
};

// The origin of a secondary ray leaving `hit` in direction w: the hit point
// stepped, for every surface near it (hit.near), to the side w travels into,
// by that surface's step, so that the new ray sees none of them at t ~ 0
// (an edge or corner needs steps along two or three normals; one along the
// hit normal alone leaves the point on the other face).
Vec3 spawnOrigin(const SurfaceHit& hit, const Vec3& w);

}  // namespace prime
