// What `prime probe` records of one pixel of a Malone scene: the tracer
// reports each step of the ray tree as typed values, and this recorder writes
// them once as a text line and a JSON object (src/render/probe_log.h). The
// tracer calls it only when a probe is attached.
#pragma once
#include <string>

#include "legacy_io/common/error.h"
#include "src/malone/primitives.h"
#include "src/render/probe_log.h"

namespace prime::malone {

class Probe : public ProbeLog {
 public:
  // The primary ray of pixel (X, Y).
  void pixel(int X, int Y, const MRay& ray);
  // A ray of depth `depth` (the primary ray 1) that hits nothing: black.
  void miss(int depth);
  // Its nearest hit: object `object` (input order), a primitive `kind` read
  // at `where` in the scene file, at t, the point and the normal.
  void hit(int depth, int object, const std::string& kind, const io::InputLocation& where, double t,
           const Vec3& point, const Vec3& normal);
  // Light sample `light` (0-based) at `position`: shadowed, or its terms
  // d.s, r.s, the distance l and the colour it adds.
  void shadowed(int depth, int light, const Vec3& position);
  void light(int depth, int light, const Vec3& position, double ds, double rs, double l,
             const Rgb& adds);
  // Total internal reflection: k_s' becomes ks.
  void tir(int depth, double ks);
  // The transmitted and reflected rays spawned.
  void transmitted(int depth, bool leaving, double eta, const Vec3& direction);
  void reflected(int depth, double ks, const Vec3& direction);
  // The colour the ray returns.
  void returns(int depth, const Rgb& colour);
};

}  // namespace prime::malone
