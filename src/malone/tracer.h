// Malone's trace (section 1.6-1.10): one function that "takes a ray and then
// calculates the light shining back from that ray", called for each primary
// ray and again for reflected and transmitted rays. In the document's order:
// the nearest hit; transmission first (so that total internal reflection
// can add k_t to k_s); Phong with the r^-2 law and shadow rays to every
// light sample; the reflected ray; the cut-offs by depth and weight.
#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "src/geom/bvh.h"
#include "src/malone/primitives.h"
#include "src/malone/probe.h"
#include "src/malone/scene.h"
#include "src/render/ray_counts.h"

namespace prime::malone {

struct TraceSettings {
  int maxDepth = 7;                 // section 1.10.2: "currently defaults to 7"
  double minWeight = 0.01 / 256.0;  // MIN_WEIGHT (MAL-Q3)
  double eps = 1e-6;                // the trapped-ray threshold (MAL-Q4)
  // "The ability to turn off parts of the illumination model for testing."
  bool ambient = true, diffuse = true, specular = true, shadows = true, reflection = true,
       refraction = true;
  // The debug renders of section 3.3.1: depth (grey = 1/r), colour (K_d of
  // the first hit), normal (|n.i|).
  enum class Debug { None, Depth, Colour, Normal } debug = Debug::None;
  // Test every primitive for every ray, as the original did (same pixels,
  // slower): for checking the BVH.
  bool linearSearch = false;
};

// The shared ray counts (src/render/ray_counts.h) and Malone's own.
struct TraceStats : RayCounts {
  std::uint64_t primitiveTests = 0, totalInternalReflections = 0;
  std::uint64_t cutByDepth = 0, cutByWeight = 0;
  TraceStats& operator+=(const TraceStats& o);
};

// The primary rays of a viewer (section 1.6): through v((2X - X_RES)/X_RES,
// -(2Y - Y_RES)/Y_RES), no half-pixel offset (MAL-Q23); (l - e)/|l - e| once.
class ViewerRays {
 public:
  explicit ViewerRays(const Viewer& viewer);
  MRay operator()(int X, int Y) const;

 private:
  Viewer v_;
  Vec3 forward_{};
};

class Tracer {
 public:
  // `abort`: the render's Ctrl-C / Esc flag, also checked every 4096 shadow
  // rays within a pixel (a pixel of many sampled lights takes seconds), by
  // checkAbort (src/render/render_rows.h). Null: never aborted.
  Tracer(const Scene& scene, TraceSettings settings, const std::atomic<bool>* abort = nullptr);

  // The primary ray of pixel (X, Y), exactly as printed (section 1.6):
  // through v((2X - X_RES)/X_RES, -(2Y - Y_RES)/Y_RES), no half-pixel offset.
  MRay primaryRay(int X, int Y) const;
  // The colour of pixel (X, Y) (or its debug value).
  // With `probe`, every ray, hit, light and returned colour is recorded
  // (src/cli/malone/cmd_probe.cpp prints them).
  Rgb pixel(int X, int Y, TraceStats& stats, Probe* probe = nullptr) const;
  // The colour of a primary ray made elsewhere (`prime walk`'s camera of the
  // moment, ViewerRays): what pixel(X, Y) gives for the same ray.
  Rgb pixel(const MRay& primary, TraceStats& stats) const;
  // trace(ray, depth, weight, index): the primary ray has depth 1, weight 1
  // and index 1.
  Rgb trace(const MRay& ray, int depth, double weight, double index, TraceStats& stats,
            Probe* probe = nullptr) const;

  const Scene& scene() const { return scene_; }
  const TraceSettings& settings() const { return settings_; }

 private:
  struct Hit {
    double t = 0;
    int primitive = -1;
  };
  Hit nearest(const MRay& ray, TraceStats& stats) const;
  bool blocked(const MRay& ray, TraceStats& stats) const;
  Rgb debugValue(const MRay& ray, TraceStats& stats) const;
  Rgb illumination(const Surface& s, const Vec3& x, const Vec3& df, const Vec3& r, double ks,
                   TraceStats& stats, Probe* probe, int depth) const;

  const Scene& scene_;
  TraceSettings settings_;
  const std::atomic<bool>* abort_ = nullptr;
  ViewerRays rays_;  // the scene's viewer's
  Bvh bvh_;
  std::vector<int> unbounded_;  // planes: tested on every ray
};

}  // namespace prime::malone
