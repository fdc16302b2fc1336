// CastRay, ReflectedRay and TransmittedRay of the Rays module (lines
// 6681-7019) over an in-memory scene: the 1991 profile's ray tree.
//   - objects in obj/List order, each tested against its bound first
//     (IntersectObjBound, with E42's reading), then through its CSG tree;
//   - the nearest object wins on a strict `t < nearest` (ties keep the first);
//   - the hit normal is the local normal times the FORWARD matrix (K4);
//   - reflected and transmitted rays are cast at every hit up to MaxDepth
//     (K20), with no shadow rays (K9);
//   - TransmittedRay walks through the whole object (K19), with TIR and the
//     raw local exit normal (K5); E46 and E59 guard the cases that crashed or
//     hung the original.
// The tracer holds no mutable state: one instance serves all threads.
#pragma once
#include <array>
#include <vector>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/csg_program_1991.h"
#include "src/prime/geom/primitives_1991_packet.h"
#include "src/prime/render/hall_1991.h"
#include "src/prime/render/probe.h"
#include "src/prime/render/trace_options.h"
#include "src/prime/render/trace_stats.h"
#include "src/prime/scene/object_bvh.h"
#include "src/prime/scene/scene.h"

namespace prime {

class Tracer1991 {
 public:
  Tracer1991(const Scene& scene, TraceOptions options = {});

  // CastRay(ray, depth, color). `ray.d` need not be unit (CastRay normalises it).
  Rgb castRay(Ray ray, int depth, TraceStats& stats, Probe* probe = nullptr,
              RayKind kind = RayKind::Primary, double weight = 1.0) const;
  // castRay(rays[l], 0, stats) for up to kPacketLanes primary rays at once,
  // into out[0 .. count-1]: the nearest-hit search runs as one packet (one
  // walk of the object BVH, the bounds and the leaves tested four lanes at a
  // time, src/prime/geom/primitives_1991_packet.h), then each lane's hit is
  // shaded as castRay shades it. Each colour is castRay's, bit for bit; the
  // counts can differ a little (a lane may test an object its own nearest-
  // first walk would have pruned). Without skipsUnneededWork (the listing's
  // linear search of obj/List) it is castRay ray by ray.
  void castPrimaries(const Ray* rays, int count, TraceStats& stats, Rgb* out) const;

  const Scene& scene() const { return scene_; }
  // TraceOptions::skipUnneededWork: the boxes, the mask and the skips are used.
  bool skipsUnneededWork() const { return options_.skipUnneededWork; }
  // The object boxes every ray is tested against first (the BVH's).
  const ObjectBvh& bvh() const { return bvh_; }
  // Boxes a ray must meet to hit anything: the box of every primitive that
  // is a leaf of an object's tree. (An object is only hit through a leaf's
  // interval, and objectList skips a leaf whose box the ray misses.) Tighter
  // than the object boxes for CSG objects; for PrimaryRayMask.
  std::vector<Aabb> primaryMaskBoxes() const;

  // ReflectedRay(ray, t, n): the reflected ray leaving the hit point ray.o + t*ray.d.
  Ray reflectedRay(const Ray& ray, double t, const Vec3& n) const;
  // TransmittedRay(ray, obj, t, n, indx, &distance): the ray after passing
  // through `obj`; `distance` receives sT, the path length inside.
  Ray transmittedRay(const Ray& ray, const SceneObject& obj, double t, const Vec3& n, double indx,
                     double& distance, TraceStats& stats, Probe* probe = nullptr,
                     int depth = 0) const;

 private:
  struct Nearest {
    double t = 1E100;  // the Rays module's Infinity: nothing hit yet
    int obj = -1, prim = -1, surfType = 0;
    Vec3 norm{};
  };
  static void keepNearer(int k, const TList& list, Nearest& best);
  // The colour for the hit `best` (or the background) of `ray` (unit).
  Rgb shade(const Ray& ray, const Nearest& best, int depth, TraceStats& stats, Probe* probe,
            double weight) const;
  // castPrimaries' consider: object k for the packet's lanes in `mask`.
  void considerPacket(int k, unsigned mask, const std::array<Ray, kPacketLanes>& rays,
                      const std::array<BoxRay, kPacketLanes>& boxRays, const RayPacket& packet,
                      std::array<Nearest, kPacketLanes>& best, TraceStats& stats) const;
  // The object's list from a leaf function: its program, or csg1991's walk.
  TList runObject(const SceneObject& obj, const Ray& ray, LeafFn leaf, TraceStats& stats) const;
  bool hitsBound(const SceneObject& obj, const Ray& ray, TraceStats& stats, Probe* probe,
                 int depth) const;
  void childWeights(const SceneObject& obj, const Vec3& n, const Vec3& reflectedDir,
                    const Rgb& surfColor, double sT, double& wR, double& wT) const;
  // The ray comes prepared for the primitives' box tests.
  TList objectList(const SceneObject& obj, const BoxRay& ray, TraceStats& stats, Probe* probe,
                   int depth) const;

  const Scene& scene_;
  Vec3 exitNormal(const TNode& exit) const;  // K5, --fix K5
  TraceOptions options_;
  ObjectBvh bvh_;                                        // used when options_.skipUnneededWork
  std::vector<std::optional<CsgProgram1991>> programs_;  // per object; none: csg1991 walks the tree
  std::vector<HallLight> lights_;
  HallSkipping hallSkipping_;  // on with skipUnneededWork and bounded lights (per scene)
};

}  // namespace prime
