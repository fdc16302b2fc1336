// What `prime probe` records while one pixel's ray tree is traced: every ray,
// every bound, object and primitive test, the chosen hit, the texture and the
// shading, as typed events that each keep a human-readable line and the same
// as a JSON object. The tracers call them only when a probe is attached, so a
// normal render pays one pointer test per event site.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "legacy_io/prime/records.h"
#include "src/geom/ray.h"
#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/interval_list.h"
#include "src/prime/render/hall_1991.h"
#include "src/prime/render/trace_stats.h"
#include "src/render/probe_log.h"

namespace prime {

const char* rayKindName(RayKind k);

class Probe : public ProbeLog {
 public:
  // CastRay: a ray of the tree (its direction unit).
  void ray(int depth, RayKind kind, const Ray& ray);
  // IntersectObjBound: the object's bounding primitive met or missed (then
  // the object is skipped).
  void boundTest(int depth, int object, io::PrimType boundType, int boundPrim, bool hit);
  // One leaf of an object's CSG tree: the primitive's interval, or a miss.
  void primitive(int depth, int object, int prim, io::PrimType type,
                 const std::optional<PrimHit>& in);
  // The object's combined list along the ray.
  void csgList(int depth, int object, const TList& list);
  // The nearest surface: world point, primitive-space point, unit world
  // normal, and whether the ray meets the surface from inside (kSurfIn).
  void hit(int depth, int object, int prim, io::PrimType type, double t, const Vec3& point,
           const Vec3& local, const Vec3& normal, bool inside);
  // The texture lookup at the hit: u, v, the surface and its map, the colour.
  void texture(int depth, double u, double v, int surface, bool noFaceMatched, int map, int uScale,
               int vScale, const Rgb& colour);
  // TransmittedRay: the walk through the object and the ray that leaves it;
  // when it does not leave, why not.
  void transmit(int depth, int object, int steps, double distance, bool exited, const Ray& leaving,
                std::string_view whyNoExit);
  // A shadow ray's verdict (thesis profile): light `light` aimed at `target`
  // (its centre or a point of its disc) passes `visibility` per channel
  // (1 lit, 0 in shadow, between: through transparent blockers).
  void shadow(int depth, int light, const Vec3& target, const Rgb& visibility);
  // No object hit: the background colour.
  void miss(int depth, const Vec3& background);
  // Hall's six terms of the hit's colour, per channel.
  void hallTerms(int depth, const std::array<HallTerms, 3>& terms);
  // The hit's colour from the returned reflected and transmitted colours.
  void shade(int depth, const Rgb& reflected, const Rgb& transmitted, double sT, const Rgb& colour);
};

// Formatting helpers for the probe's lines (an Rgb is a Vec3; fmt and json
// are the shared ones of src/render/probe_log.h).
std::string describe(const TList& list);
std::string jsonList(const TList& list);

}  // namespace prime
