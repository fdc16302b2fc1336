// Malone's ray_trace (section 1.10.3): one ray per pixel, rows from the top,
// over the shared row scheduler, into a raster of doubles (an RgbImage);
// raster2ppm is legacy_io/malone/ppm.h.
#pragma once
#include <atomic>
#include <functional>
#include <span>

#include "src/malone/tracer.h"
#include "src/render/render_rows.h"
#include "src/render/rgb_image.h"

namespace prime::malone {

struct RenderSettings {
  TraceSettings trace;
  int threads = 0;  // 0: all cores
};

struct RenderResult {
  RgbImage raster;  // X_RES x Y_RES, row 0 at the top
  TraceStats stats;
  RowsRun run;
  double setupSeconds = 0;  // the tracer's set-up before the first ray: the BVH
};

// The shared scheduler's callbacks, with each finished row's colours (what
// a live window shows).
using RenderCallbacks = PictureCallbacks<Rgb>;  // rows of colours, from the top

RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const RenderCallbacks& callbacks = {});

}  // namespace prime::malone
