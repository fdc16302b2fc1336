// The modern profile's object queries along a ray (TracerModern, the CSG
// half): an object's Roth list by its compiled program, the list ahead of a
// point with marker normals, and the pointwise answers (a lone pair, a leaf's
// span, what blocks a shadow ray, how far a ray stays inside, where it leaves,
// the first node ahead) that spare the full list where one answer will do.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "src/prime/geom/csg_modern.h"
#include "src/prime/geom/primitives_modern.h"
#include "src/prime/render/tracer_modern.h"

namespace prime {

TList TracerModern::objectIntervals(const SceneObject& obj, const Ray& ray, TraceStats& stats,
                                    Probe* probe, int depth) const {
  ++stats.objectTests;
  auto leaf = [&](int primNum) -> std::optional<PrimHit> {
    ++stats.primitiveTests;
    const ScenePrim& p = scene_.prims[primNum];
    PrimHit in;
    const bool ok = intersectModern(p.type, transformRay(ray, inverse_[primNum]), in);
    if (probe)
      probe->primitive(depth, obj.number, primNum, p.type,
                       ok ? std::optional<PrimHit>(in) : std::nullopt);
    if (!ok) return std::nullopt;
    return in;
  };
  TList list = programs_[static_cast<std::size_t>(&obj - scene_.objects.data())].runModern(leaf);
  if (probe) probe->csgList(depth, obj.number, list);
  return list;
}

namespace {
// Normals::kMarkers: a leaf's entry and exit normals stand for "this
// primitive's entry (exit) normal"; a difference negates its right operand's
// nodes as it would negate their normals, so the sign comes along.
constexpr Vec3 kEntryMarker{1, 0, 0}, kExitMarker{1, 1, 0};
}  // namespace

TList TracerModern::objectIntervalsAhead(const SceneObject& obj, const BoxRay& boxRay, double tMax,
                                         TraceStats& stats, Normals normals) const {
  ++stats.objectTests;
  const Ray& ray = boxRay.ray;
  auto leaf = [&](int primNum) -> std::optional<PrimHit> {
    // N18: a primitive whose box the ray does not enter in [0, tMax] has no
    // surface there; outside that range the list is not used.
    // (entry() is +inf for a box the ray misses.)
    const double entry = bvh_.primBox(primNum).entry(boxRay);
    if (entry == std::numeric_limits<double>::infinity() || !(entry <= tMax)) return std::nullopt;
    ++stats.primitiveTests;
    PrimHit in;
    const Ray local = transformRay(ray, inverse_[primNum]);
    if (normals == Normals::kFull) {
      if (!intersectModern(scene_.prims[primNum].type, local, in)) return std::nullopt;
    } else {
      if (!intersectModernT(scene_.prims[primNum].type, local, in)) return std::nullopt;
      in.nIn = kEntryMarker;
      in.nOut = kExitMarker;
    }
    return in;
  };
  const std::size_t k = static_cast<std::size_t>(&obj - scene_.objects.data());
  const CsgProgram1991& program = programs_[k];
  if (program.isSingleLeaf()) {  // a lone primitive: runModern's answer without the walk
    TList list;
    const int prim = obj.entries[0].l;
    if (const std::optional<PrimHit> hit = leaf(prim))
      list.addPair(hit->tIn, hit->tOut, hit->nIn, hit->nOut, prim);
    return list;
  }
  return program.runModern(leaf);
}

bool TracerModern::lonePair(std::size_t object, const BoxRay& boxRay, double tMax, bool normals,
                            TraceStats& stats, int& prim, PrimHit& in) const {
  ++stats.objectTests;
  prim = scene_.objects[object].entries[0].l;
  const double entry = bvh_.primBox(prim).entry(boxRay);
  if (entry == std::numeric_limits<double>::infinity() || !(entry <= tMax)) return false;
  ++stats.primitiveTests;
  const Ray local = transformRay(boxRay.ray, inverse_[prim]);
  return normals ? intersectModern(scene_.prims[prim].type, local, in)
                 : intersectModernT(scene_.prims[prim].type, local, in);
}

bool TracerModern::leafSpan(int prim, const Ray& ray, TraceStats& stats,
                            CsgPointwise::Span& span) const {
  ++stats.primitiveTests;
  PrimHit in;
  if (!intersectModernT(scene_.prims[prim].type, transformRay(ray, inverse_[prim]), in))
    return false;
  span.tIn = in.tIn;
  span.tOut = in.tOut;
  return true;
}

bool TracerModern::pointwiseSpans(
    std::size_t object, const BoxRay& boxRay, double tMax, TraceStats& stats,
    std::array<CsgPointwise::Span, CsgPointwise::kMaxLeaves>& spans) const {
  return pointwise_[object]->gather(
      [&](int prim, CsgPointwise::Span& span) {
        const double entry = bvh_.primBox(prim).entry(boxRay);
        if (entry == std::numeric_limits<double>::infinity() || !(entry <= tMax)) return false;
        return leafSpan(prim, boxRay.ray, stats, span);
      },
      spans);
}

CsgPointwise::Answer TracerModern::pointwiseFirstAhead(std::size_t object, const BoxRay& boxRay,
                                                       double tMax, TraceStats& stats,
                                                       TNode& node) const {
  return pointwise_[object]->firstAheadLazy(
      [&](int prim) { return bvh_.primBox(prim).entry(boxRay); },
      [&](int prim, CsgPointwise::Span& span) { return leafSpan(prim, boxRay.ray, stats, span); },
      tMax, kEntryMarker, kExitMarker, node);
}

bool TracerModern::blocks(std::size_t object, const BoxRay& boxRay, double tMax,
                          TraceStats& stats) const {
  if (pointwise_[object]) {
    ++stats.objectTests;
    TNode node;
    switch (pointwiseFirstAhead(object, boxRay, tMax, stats, node)) {
      case CsgPointwise::Answer::kNone:
        return false;
      case CsgPointwise::Answer::kFound:
        // An exit first: the solid holds the start; an entry: before tMax?
        return node.surfType == kSurfIn || node.t < tMax;
      case CsgPointwise::Answer::kGeneral:
        break;
    }
    --stats.objectTests;  // counted again below
  }
  return insideLength(object, boxRay, tMax, stats) > 0.0;
}

double TracerModern::insideLength(std::size_t object, const BoxRay& boxRay, double tMax,
                                  TraceStats& stats) const {
  double inside = 0.0;
  auto add = [&](double in, double out) {
    const double lo = std::max(0.0, in), hi = std::min(tMax, out);
    if (hi > lo) inside += hi - lo;
  };
  if (programs_[object].isSingleLeaf()) {  // objectIntervalsAhead's one pair, if any
    int prim = 0;
    PrimHit in;
    if (lonePair(object, boxRay, tMax, false, stats, prim, in)) add(in.tIn, in.tOut);
    return inside;
  }
  if (pointwise_[object]) {  // the list's pairs without the list (N18)
    ++stats.objectTests;
    std::array<CsgPointwise::Span, CsgPointwise::kMaxLeaves> spans;
    if (pointwiseSpans(object, boxRay, tMax, stats, spans)) {
      pointwise_[object]->insideLength(spans, tMax, inside);
      return inside;
    }
    --stats.objectTests;  // counted again below
  }
  const TList list =
      objectIntervalsAhead(scene_.objects[object], boxRay, tMax, stats, Normals::kNone);
  for (std::size_t i = 0; i + 1 < list.size(); i += 2) add(list[i].t, list[i + 1].t);
  return inside;
}

bool TracerModern::exitAhead(std::size_t object, const Ray& ray, TraceStats& stats,
                             TNode& exit) const {
  const BoxRay boxRay(ray);
  if (programs_[object].isSingleLeaf()) {  // its pair's exit, the one node that leaves
    int prim = 0;
    PrimHit in;
    if (!lonePair(object, boxRay, std::numeric_limits<double>::infinity(), true, stats, prim, in) ||
        !(in.tOut > 0.0))
      return false;
    exit = TNode{in.tOut, prim, kSurfIn, in.nOut};
    return true;
  }
  if (pointwise_[object]) {  // the list's first exit ahead without the list (N18)
    ++stats.objectTests;
    std::array<CsgPointwise::Span, CsgPointwise::kMaxLeaves> spans;
    TNode node;
    if (pointwiseSpans(object, boxRay, std::numeric_limits<double>::infinity(), stats, spans)) {
      switch (pointwise_[object]->firstExit(spans, kEntryMarker, kExitMarker, node)) {
        case CsgPointwise::Answer::kNone:
          return false;
        case CsgPointwise::Answer::kFound: {
          // The primitive's own normal at that end, as the list carries it.
          PrimHit in;
          if (!intersectModern(scene_.prims[node.prim].type, transformRay(ray, inverse_[node.prim]),
                               in))
            break;  // (not reached: the same test found the end)
          const Vec3& n = node.norm[1] != 0.0 ? in.nOut : in.nIn;
          exit = TNode{node.t, node.prim, kSurfIn, node.norm[0] < 0.0 ? -n : n};
          return true;
        }
        case CsgPointwise::Answer::kGeneral:
          break;
      }
    }
    --stats.objectTests;  // counted again below
  }
  const TList list = objectIntervalsAhead(scene_.objects[object], boxRay,
                                          std::numeric_limits<double>::infinity(), stats);
  for (const TNode& node : list)
    if (node.t > 0.0 && node.surfType == kSurfIn) {
      exit = node;
      return true;
    }
  return false;
}

bool TracerModern::firstNodeAhead(std::size_t object, const BoxRay& boxRay, double tMax,
                                  TraceStats& stats, TNode& node) const {
  if (programs_[object].isSingleLeaf()) {
    // A lone primitive: objectIntervalsAhead's two nodes (entry, exit) and
    // the first of them ahead, without building the list (N18).
    int prim = 0;
    PrimHit in;
    if (!lonePair(object, boxRay, tMax, false, stats, prim, in)) return false;
    if (in.tIn > 0.0) {
      node = TNode{in.tIn, prim, kSurfOut, kEntryMarker};
      return true;
    }
    if (in.tOut > 0.0) {
      node = TNode{in.tOut, prim, kSurfIn, kExitMarker};
      return true;
    }
    return false;
  }
  const std::vector<int>& leaves = unionLeaves_[object];
  if (!leaves.empty()) {
    // A union of primitives seen from outside all of them: its first node
    // ahead is the nearest entry, the leftmost leaf's on a tie, as the
    // sweep of setUnion keeps its left operand's node (N18). Pairs that
    // normalisation drops (t_in >= t_out) take no part; a ray that starts
    // inside one (t_in <= 0 < t_out) or a NaN goes the general way.
    ++stats.objectTests;
    const Ray& ray = boxRay.ray;
    bool found = false, general = false;
    for (const int prim : leaves) {
      const double entry = bvh_.primBox(prim).entry(boxRay);
      if (entry == std::numeric_limits<double>::infinity() || !(entry <= tMax)) continue;
      ++stats.primitiveTests;
      PrimHit in;
      if (!intersectModernT(scene_.prims[prim].type, transformRay(ray, inverse_[prim]), in))
        continue;
      if (std::isnan(in.tIn) || std::isnan(in.tOut) || (in.tIn <= 0.0 && in.tOut > 0.0)) {
        general = true;
        break;
      }
      if (!(in.tIn < in.tOut) || !(in.tIn > 0.0)) continue;
      if (!found || in.tIn < node.t) {
        node = TNode{in.tIn, prim, kSurfOut, kEntryMarker};
        found = true;
      }
    }
    if (!general) return found;
    --stats.objectTests;  // counted again below
  }
  if (pointwise_[object]) {  // the list's first node ahead without the list (N18)
    ++stats.objectTests;
    const CsgPointwise::Answer a = pointwiseFirstAhead(object, boxRay, tMax, stats, node);
    if (a != CsgPointwise::Answer::kGeneral) return a == CsgPointwise::Answer::kFound;
    --stats.objectTests;  // counted again below
  }
  const TList list =
      objectIntervalsAhead(scene_.objects[object], boxRay, tMax, stats, Normals::kMarkers);
  for (const TNode& n : list)
    if (n.t > 0.0) {
      node = n;
      return true;
    }
  return false;
}
}  // namespace prime
