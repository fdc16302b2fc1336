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
#include <vector>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/csg_program_1991.h"
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
    double t = 0;
    int obj = -1, prim = -1, surfType = 0;
    Vec3 norm{};
  };
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
