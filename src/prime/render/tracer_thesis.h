// The thesis profile's ray tree (`--profile thesis`, docs/prime/thesis-profile.md):
// the modern profile's geometry and arithmetic (TracerModern: nearest hit,
// object intervals, secondary-ray origins, refraction; every N row of
// docs/prime/deviations.md), plus what the thesis describes and the listing
// never built:
//   - shadow rays (thesis 2.3.2) from every shaded point to every light:
//     an opaque object between them blocks the light, a transparent one
//     passes kST * tT^d of it, d the length of the shadow ray inside (T2,
//     T3); an any-hit walk of the BVH that stops at the first opaque blocker;
//   - Hall's model as the thesis writes it (hall_thesis.h);
//   - lights with a radius (the thesis' "distributed" light sources, 4.6.6):
//     a disc facing the shaded point, sample k of a pixel going to the k-th
//     point of a stratified sequence over the disc (T10, T11).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "src/prime/render/hall_thesis.h"
#include "src/prime/render/pixel_sampling.h"
#include "src/prime/render/tracer_modern.h"

namespace prime {

struct ThesisOptions {
  bool shadows = true;       // false: every light reaches every point (as the listing)
  double lightRadius = 0.0;  // every light's radius, world units (0: point lights)
  // Per-light radii (index = the light's position in the light file);
  // where given (>= 0) they replace lightRadius.
  std::vector<double> lightRadii;
  bool texelInDiffuse = true;  // T8: the texel also colours F_dr and F_dt (K11 corrected)
};

// Which sample of which pixel a ray belongs to: the key of its soft-shadow
// points (the same numbers whatever thread traces it).
struct SampleId {
  PixelKey pixel;
  int sample = 0;
};

class TracerThesis {
 public:
  TracerThesis(const Scene& scene, RayTreeOptions options = {}, ThesisOptions thesis = {});

  // `leaves`: as TracerModern::castRay's.
  Rgb castRay(Ray ray, int depth, TraceStats& stats, const SampleId& sample, Probe* probe = nullptr,
              RayKind kind = RayKind::Primary, double weight = 1.0, int leaves = -1) const;
  // Without a sample id: sample 0 of pixel (0, 0), seed 1.
  Rgb castRay(const Ray& ray, int depth, TraceStats& stats) const {
    return castRay(ray, depth, stats, SampleId{});
  }

  // The fraction of light that travels from `origin` to `target` per channel:
  // 1 with nothing between, 0 behind an opaque object, kST * tT^d through a
  // transparent one (T3). Counts one shadow ray; stops at the first opaque
  // blocker. `leaves`: an object the segment is known to run outside of
  // (TracerModern::leavingSolid, N18), not tested; -1 for none.
  Rgb transmittance(const Vec3& origin, const Vec3& target, TraceStats& stats,
                    Probe* probe = nullptr, int depth = 0, int leaves = -1) const;
  // The point of light `j` that sample `sample` at `depth` of the pixel
  // aims its shadow ray at, seen from `from`: the centre for a point light,
  // else a stratified point of the disc of the light's radius facing `from`.
  Vec3 lightPoint(int j, const Vec3& from, const SampleId& sample, int depth) const;
  double lightRadius(int j) const { return radius_[static_cast<std::size_t>(j)]; }

  const Scene& scene() const { return modern_.scene(); }
  const ObjectBvh& bvh() const { return modern_.bvh(); }
  const TracerModern& geometry() const { return modern_; }

 private:
  TracerModern modern_;
  RayTreeOptions options_;
  ThesisOptions thesis_;
  std::vector<double> radius_;
  std::vector<double> opacity_;  // per object: kST (0 = opaque)
};

}  // namespace prime
