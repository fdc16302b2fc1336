// The intersection and normal functions of Malone's primitives (section 2),
// one pair per object type as the original's object table held them. A ray
// has a unit direction and a length (DBL_MAX when infinite); intersect
// returns the nearest t with eps < t < length (the trapped-ray rule of
// section 1.10.1, applied in the primitive's own space), normal the outward
// unit normal at a point on the surface.
#pragma once
#include <limits>

#include "src/geom/aabb.h"
#include "src/malone/scene.h"

namespace prime::malone {

inline constexpr double kInfinite = std::numeric_limits<double>::max();  // DBL_MAX

struct MRay {
  Vec3 o{}, d{};  // d of unit length
  double length = kInfinite;
};

bool intersect(const Scene& scene, const Primitive& p, const MRay& ray, double eps, double& t);
Vec3 normal(const Scene& scene, const Primitive& p, const Vec3& x);

// A box around the primitive, padded; empty for an unbounded one (a plane),
// which the tracer tests on every ray as the original tested everything.
Aabb bounds(const Scene& scene, const Primitive& p);

}  // namespace prime::malone
