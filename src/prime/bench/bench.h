// `prime bench`: run time against error. For each scene, a reference picture
// (deep recursion, no cut-off, dense supersampling, unquantised colour) and a
// grid of cheaper settings, each timed (median of several runs, wall and CPU)
// and compared with the reference (metrics.h). Results go to a CSV, a
// Markdown table and a time-against-error plot with the Pareto front marked.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "src/bench/measure.h"
#include "src/prime/bench/metrics.h"
#include "src/prime/render/renderer.h"

namespace prime::bench {

struct BenchSetting {
  int maxDepth = 5;
  double minWeight = 0;
  Sampling sampling;
  int threads = 1;
  bool reference = false;
};

// "single", "grid2", "adaptive0.05".
std::string samplingName(const Sampling& s);
// "depth 5, min-weight 0, single, 1 thread" style label; "reference" for it.
std::string settingLabel(const BenchSetting& s);
// True for the listing's own settings: depth 5, no cut-off, one ray per pixel.
bool is1991Profile(const BenchSetting& s);

// The reference: MaxDepth 12, min-weight 0, 4 x 4 grid, `threads` threads.
BenchSetting referenceSetting(int threads);
// The grid of settings; `quick` is a handful for tests.
std::vector<BenchSetting> benchSettings(bool quick);
// The sampling study's reference (jittered 16 x 16, depth 5) and settings:
// grid n x n, jittered n x n (n = 1..6) and statistical supersampling
// (bounds 0.2 .. 0.01, at most 256 rays; 0.05 and 0.02 also with 16 first
// rays, T14), all depth 5, one thread.
BenchSetting samplingReference(int threads);
std::vector<BenchSetting> samplingSettings(bool quick);

// The camera: the listing's window on a reduced screen (full: 512 x 384, so
// 176 x 385 pixels; quick: 128 x 96, 45 x 97 pixels). The world window is
// the listing's, so the picture is the same, at a lower resolution.
CameraSettings benchCamera(bool quick);

// Every `root`/*/ that holds a Model.txt, sorted by name.
std::vector<std::filesystem::path> defaultScenes(const std::filesystem::path& root);
// Plate3 when the scene's Model.txt or README.md says "--palette plate3"
// (scenes/prime/plate3 does), else the listing's ColorNum.
ColorMapping sceneMapping(const std::filesystem::path& sceneDir);

// Copies `sceneDir` into `workDir`/<name>, models the copy (Model.c's
// builder, default options) and loads it. The original is not touched.
Scene modelSceneCopy(const std::filesystem::path& sceneDir, const std::filesystem::path& workDir);

struct BenchRow {
  std::string scene;
  BenchSetting setting;
  int runs = 0;
  int columns = 0, rows = 0;
  double wallMedian = 0, wallMin = 0, wallMax = 0;
  double cpuMedian = 0, cpuMin = 0, cpuMax = 0;
  TraceStats stats;  // of the first run (every run casts the same rays)
  ImageError error;
  bool pareto = false;
  // Rows with threads > 1: each run is paired with a run of the same
  // setting on one thread just before it; the median (and range) over the
  // pairs of wall(1 thread) / wall(this), robust to load that drifts.
  double pairedSpeedUp = 0, pairedSpeedUpMin = 0, pairedSpeedUpMax = 0;
  double pairedWallOne = 0;  // median wall time of the 1-thread partners
};

struct BenchOptions {
  int runs = 3;
  bool quick = false;
  bool onlyThreads = false;  // the reference and the multi-thread settings (with their pairs) only
  CameraSettings camera = benchCamera(false);
  int referenceThreads = 0;  // 0: all cores
  // The sampling study (thesis 2.6): the thesis profile with soft shadows
  // (lights of `lightRadius`), a jittered 16 x 16 reference at depth 5, and
  // regular n x n, jittered n x n and statistical supersampling against it
  // (samplingSettings) instead of benchSettings.
  bool samplingStudy = false;
  double lightRadius = 100.0;
  std::function<void(const std::string&)> log;  // progress lines
};

// Renders the reference and every setting of benchSettings(options.quick).
// The first row is the reference (zero error by construction).
std::vector<BenchRow> benchScene(const Scene& scene, ColorMapping mapping,
                                 const BenchOptions& options);

// The sampling study's summary: for every statistical row, the cheapest
// regular grid row of the same scene whose RMSE is no larger, and their rays.
std::string equalErrorMarkdown(const std::vector<BenchRow>& rows);

// Marks, per scene, the Pareto front of (CPU median, RMSE) over the
// single-thread rows other than the reference.
void markPareto(std::vector<BenchRow>& rows);

// The 1 -> 2 thread speed-up of each setting run both ways: wall median with
// 1 thread over wall median with 2.
struct SpeedUp {
  std::string scene;
  BenchSetting setting;         // with threads = 2
  double wall1 = 0, wall2 = 0;  // medians: the 1-thread partners, this row
  double cpu1 = 0, cpu2 = 0;    // medians of the 1-thread row (0 when not run) and this row
  double paired = 0, pairedMin = 0, pairedMax = 0;  // BenchRow::pairedSpeedUp*
  double ratio() const { return paired > 0 ? paired : wall1 / wall2; }
};
std::vector<SpeedUp> threadSpeedUps(const std::vector<BenchRow>& rows);

inline constexpr const char* kCsvHeader =
    "scene,setting,reference,max_depth,min_weight,sampling,threads,runs,columns,rows,"
    "wall_median_s,wall_min_s,wall_max_s,cpu_median_s,cpu_min_s,cpu_max_s,"
    "rays,primary_rays,reflected_rays,transmitted_rays,bound_tests,object_tests,primitive_tests,"
    "rmse,max_error,index_diff_share,pareto,paired_speedup";

void writeCsv(const std::filesystem::path& path, const std::vector<BenchRow>& rows);
// Markdown: the machine, the command, one table per scene, the speed-ups.
std::string markdownReport(const std::vector<BenchRow>& rows, const MachineFacts& before,
                           const MachineFacts& after, const std::string& command);
// CPU time (log) against RMSE (log): one colour per scene, dots for every
// single-thread setting, the Pareto front as a line through squares.
Image8 timeErrorPlot(const std::vector<BenchRow>& rows);

}  // namespace prime::bench
