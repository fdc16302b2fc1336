// `prime cgl-splines`: the B-spline surfaces of a CGL scene measured as
// Sweeney 1985 measures them in Tables 3 and 6 (section 11.2), and the
// port's own checks of them (CGL-D170, CGL-D171). Each step prints its lines
// on standard output; src/cli/cgl/cmd_splines.cpp runs them in order.
#pragma once
#include <string>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "src/cgl/render.h"
#include "src/cgl/scene.h"

namespace prime::cgl {

class SplineStudy {
 public:
  // `settings` are the scene's; the study renders on one thread. The seconds
  // spent reading the file and building the scene, for the time shares.
  SplineStudy(const SceneFile& file, const Scene& scene, RenderSettings settings,
              double readSeconds, double buildSeconds);

  // The render (rays, seconds) and each surface's sizes and build times.
  void renderAndSurfaces();
  // The primary rays again, per surface: the intersection alone recording
  // Newton's starts, then Newton alone replayed from them (for the shares).
  void timeIntersections();
  // CGL-D170: the document's heap walk against the packet walk on the same
  // primary rays (CPU of this thread, interleaved, median of 5 runs each).
  void compareWalks() const;
  // Table 6's averages per ray, and the time shares of Table 3.
  void averagesAndShares() const;
  // Every `step`-th pixel's primary ray traced by the dense reference too.
  void holes(int step) const;
  // CGL-D171: every pixel's distance to the nearest spline hit, by the
  // reference and by the Newton path, as CSV (x,y,reference,path) at `path`.
  void distances(const std::string& path) const;

 private:
  const SceneFile& file_;
  const Scene& scene_;
  RenderSettings settings_;
  double readSeconds_, buildSeconds_;
  std::vector<Ray> primary_;  // the window's primary rays, top row first
  TraceStats stats_;
  double render_ = 0, refine_ = 0, tree_ = 0;
  double boxesAndNewton_ = 0, newtonOnly_ = 0;
};

}  // namespace prime::cgl
