// The scale study: generated scenes of 1 .. 10,000 objects, built in memory
// (no PrimFile, so the 1991 limit of 113 primitives, E40/K37, does not apply),
// rendered at a fixed reduced size with the skips and the object BVH on and
// off (TraceOptions::skipUnneededWork), timing and peak memory measured in a
// child process per case.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "src/bench/measure.h"
#include "src/prime/render/renderer.h"

namespace prime::bench {

// `objects` one-primitive objects (sphere, cube, cylinder, cone, pyramid in
// turn) on a k x k grid (k = ceil(sqrt(objects))) filling the listing's
// world window, at depths z = 300 .. 500; shiny (kSR = 0.3), opaque
// (kST = 0), four constant-colour maps, two lights. No bounding volumes.
Scene makeScaleScene(int objects);

struct ScaleOptions {
  std::vector<int> sizes{1, 10, 100, 1000, 10000};
  int runs = 3;
  int offMaxObjects = 10000;  // render with the skips off only up to this size
  CameraSettings camera;      // set by the caller
  int threads = 1;
  std::function<void(const std::string&)> log;
};

struct ScaleRow {
  int objects = 0;
  bool skips = true;
  int runs = 0;
  double wallMedian = 0, cpuMedian = 0, wallMin = 0, wallMax = 0;
  double rays = 0, objectTests = 0, primitiveTests = 0;
  long peakRssKb = 0;      // of the child that built and rendered the scene
  long baselineRssKb = 0;  // of a child that did nothing
};

std::vector<ScaleRow> runScale(const ScaleOptions& options);

inline constexpr const char* kScaleCsvHeader =
    "objects,skips,runs,wall_median_s,wall_min_s,wall_max_s,cpu_median_s,rays,object_tests,"
    "primitive_tests,"
    "peak_rss_kb,baseline_rss_kb";
void writeScaleCsv(const std::string& path, const std::vector<ScaleRow>& rows);
std::string scaleMarkdown(const std::vector<ScaleRow>& rows, const CameraSettings& camera);
Image8 scaleTimePlot(const std::vector<ScaleRow>& rows);
Image8 scaleMemoryPlot(const std::vector<ScaleRow>& rows);

}  // namespace prime::bench
