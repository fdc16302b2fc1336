#include "src/prime/bench/bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "legacy_io/common/input_file.h"
#include "legacy_io/prime/model_builder.h"
#include "legacy_io/prime/scene_dir.h"
#include "src/prime/bench/pareto.h"
#include "src/prime/bench/plot.h"
#include "src/prime/scene/scene_loader.h"

namespace prime::bench {

namespace fs = std::filesystem;

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

Sampling single() {
  return {};
}
Sampling grid(int n) {
  Sampling s;
  s.mode = Sampling::Mode::Grid;
  s.gridN = n;
  return s;
}
Sampling jittered(int n) {
  Sampling s;
  s.mode = Sampling::Mode::Jittered;
  s.gridN = n;
  return s;
}
Sampling statistical(double bound, int minSamples = 4) {
  Sampling s;
  s.mode = Sampling::Mode::Statistical;
  s.bound = bound;
  s.minSamples = minSamples;
  s.maxSamples = 256;
  return s;
}
Sampling adaptive(double tolerance) {
  Sampling s;
  s.mode = Sampling::Mode::Adaptive;
  s.tolerance = tolerance;
  s.maxLevel = 2;
  return s;
}

bool sameSetting(const BenchSetting& a, const BenchSetting& b) {
  return a.maxDepth == b.maxDepth && a.minWeight == b.minWeight &&
         samplingName(a.sampling) == samplingName(b.sampling) && a.reference == b.reference;
}

std::string readText(const fs::path& p) {
  return io::readInputText(p.string());
}

}  // namespace

std::string samplingName(const Sampling& s) {
  switch (s.mode) {
    case Sampling::Mode::Single:
      return "single";
    case Sampling::Mode::Grid:
      return "grid" + std::to_string(s.gridN);
    case Sampling::Mode::Adaptive:
      return "adaptive" + fmt("%g", s.tolerance);
    case Sampling::Mode::Jittered:
      return "jitter" + std::to_string(s.gridN);
    case Sampling::Mode::Statistical:
      return "statistical" + fmt("%g", s.bound) +
             (s.minSamples != 4 ? "min" + std::to_string(s.minSamples) : std::string());
  }
  return "?";
}

std::string settingLabel(const BenchSetting& s) {
  std::string l = s.reference ? "reference: " : "";
  l += "depth " + std::to_string(s.maxDepth) + ", min-weight " + fmt("%g", s.minWeight) + ", " +
       samplingName(s.sampling) + ", " + std::to_string(s.threads) +
       (s.threads == 1 ? " thread" : " threads");
  return l;
}

bool is1991Profile(const BenchSetting& s) {
  return !s.reference && s.maxDepth == 5 && s.minWeight == 0 &&
         s.sampling.mode == Sampling::Mode::Single;
}

BenchSetting referenceSetting(int threads) {
  BenchSetting r;
  r.maxDepth = 12;
  r.minWeight = 0;
  r.sampling = grid(4);
  r.threads = threads;
  r.reference = true;
  return r;
}

std::vector<BenchSetting> benchSettings(bool quick) {
  std::vector<BenchSetting> out;
  auto add = [&](int depth, double w, Sampling s, int threads) {
    out.push_back({depth, w, s, threads, false});
  };
  if (quick) {
    add(1, 0, single(), 1);
    add(5, 0, single(), 1);
    add(5, 0.05, single(), 1);
    add(5, 0, grid(2), 1);
    add(5, 0, adaptive(0.05), 1);
    add(5, 0, single(), 2);
    return out;
  }
  // Depth against the tree cut-off, one ray per pixel.
  for (int depth = 1; depth <= 5; ++depth)
    for (double w : {0.0, 0.01, 0.05, 0.2}) add(depth, w, single(), 1);
  // Sampling density.
  for (const Sampling& s : {grid(2), grid(3), adaptive(0.05), adaptive(0.02)}) {
    add(3, 0, s, 1);
    add(5, 0, s, 1);
    add(5, 0.05, s, 1);
  }
  // Threads: the listing's settings and a supersampled one, on two threads.
  add(5, 0, single(), 2);
  add(5, 0, grid(3), 2);
  return out;
}

BenchSetting samplingReference(int threads) {
  BenchSetting r;
  r.maxDepth = 5;
  r.sampling = jittered(16);
  r.sampling.seed = 999;  // numbers of their own, not the settings' (seed 1)
  r.threads = threads;
  r.reference = true;
  return r;
}

std::vector<BenchSetting> samplingSettings(bool quick) {
  std::vector<BenchSetting> out;
  auto add = [&](Sampling s) { out.push_back({5, 0, s, 1, false}); };
  const int maxN = quick ? 2 : 6;
  for (int n = 1; n <= maxN; ++n) add(n == 1 ? single() : grid(n));
  for (int n = 1; n <= maxN; ++n) add(jittered(n));
  for (double b :
       quick ? std::vector<double>{0.1} : std::vector<double>{0.2, 0.1, 0.05, 0.03, 0.02, 0.01})
    add(statistical(b));
  if (!quick)  // T14: sixteen first rays, for what four identical ones hide
    for (double b : {0.05, 0.02}) add(statistical(b, 16));
  return out;
}

std::string equalErrorMarkdown(const std::vector<BenchRow>& rows) {
  std::ostringstream md;
  md << "| scene | statistical | rays | RMSE | cheapest regular grid as good | its rays | its RMSE "
        "| rays saved |\n|---|---|---|---|---|---|---|---|\n";
  bool any = false;
  for (const auto& st : rows) {
    if (st.setting.reference || st.setting.sampling.mode != Sampling::Mode::Statistical) continue;
    const BenchRow* best = nullptr;
    for (const auto& g : rows) {
      const auto m = g.setting.sampling.mode;
      if (g.scene != st.scene || g.setting.reference ||
          (m != Sampling::Mode::Grid && m != Sampling::Mode::Single) ||
          g.error.rmse > st.error.rmse)
        continue;
      if (!best || g.stats.rays() < best->stats.rays()) best = &g;
    }
    any = true;
    md << "| " << st.scene << " | " << samplingName(st.setting.sampling) << " | " << st.stats.rays()
       << " | " << fmt("%.5f", st.error.rmse) << " | ";
    if (best)
      md << samplingName(best->setting.sampling) << " | " << best->stats.rays() << " | "
         << fmt("%.5f", best->error.rmse) << " | "
         << fmt("%.2f", static_cast<double>(best->stats.rays()) /
                            static_cast<double>(std::max<std::uint64_t>(1, st.stats.rays())))
         << "x |\n";
    else {
      // No grid is as good: the best one, for scale.
      const BenchRow* top = nullptr;
      for (const auto& g : rows)
        if (g.scene == st.scene && !g.setting.reference &&
            g.setting.sampling.mode == Sampling::Mode::Grid &&
            (!top || g.error.rmse < top->error.rmse))
          top = &g;
      if (top)
        md << "none; the best, " << samplingName(top->setting.sampling) << " | "
           << top->stats.rays() << " | " << fmt("%.5f", top->error.rmse) << " | "
           << fmt("%.2f", static_cast<double>(top->stats.rays()) /
                              static_cast<double>(std::max<std::uint64_t>(1, st.stats.rays())))
           << "x, and more error |\n";
      else
        md << "none | - | - | - |\n";
    }
  }
  return any ? md.str() : std::string();
}

CameraSettings benchCamera(bool quick) {
  CameraSettings c;
  c.screenWidth = quick ? 128 : 512;
  c.screenHeight = quick ? 96 : 384;
  return c;
}

std::vector<fs::path> defaultScenes(const fs::path& root) {
  std::vector<fs::path> out;
  if (!fs::is_directory(root)) return out;
  for (const auto& e : fs::directory_iterator(root))
    if (e.is_directory() && fs::is_regular_file(e.path() / "Model.txt")) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

ColorMapping sceneMapping(const fs::path& sceneDir) {
  for (const char* f : {"Model.txt", "README.md"}) {
    const fs::path p = sceneDir / f;
    if (fs::is_regular_file(p) && readText(p).find("--palette plate3") != std::string::npos)
      return ColorMapping::Plate3;
  }
  return ColorMapping::Listing;
}

Scene modelSceneCopy(const fs::path& sceneDir, const fs::path& workDir) {
  fs::path name = sceneDir.filename();
  if (name.empty()) name = sceneDir.parent_path().filename();  // "scenes/prime/default/"
  const fs::path copy = workDir / name;
  fs::remove_all(copy);
  fs::create_directories(copy);
  fs::copy(sceneDir, copy, fs::copy_options::recursive | fs::copy_options::skip_symlinks);
  fs::remove(copy / "graph_scr");
  const io::SceneDir dir(copy);
  io::writeModel(dir, io::buildModel(dir));
  Scene scene = loadScene(dir);
  scene.name = name.string();
  return scene;
}

std::vector<BenchRow> benchScene(const Scene& scene, ColorMapping mapping,
                                 const BenchOptions& options) {
  auto settingsOf = [&](const BenchSetting& b) {
    RenderSettings s;
    if (options.samplingStudy) {
      s.profile = Profile::Thesis;
      s.thesis.lightRadius = options.lightRadius;
    }
    s.camera = options.camera;
    s.mapping = mapping;
    s.sampling = b.sampling;
    s.trace.maxDepth = b.maxDepth;
    s.trace.minWeight = b.minWeight;
    s.threads = b.threads;
    return s;
  };
  auto log = [&](const std::string& m) {
    if (options.log) options.log(m);
  };

  std::vector<BenchRow> rows;
  const BenchSetting refSetting = options.samplingStudy
                                      ? samplingReference(options.referenceThreads)
                                      : referenceSetting(options.referenceThreads);
  RenderResult reference;
  {
    const double w0 = wallSeconds(), c0 = processCpuSeconds();
    reference = render(scene, settingsOf(refSetting));
    const double wall = wallSeconds() - w0, cpu = processCpuSeconds() - c0;
    BenchRow r;
    r.scene = scene.name;
    r.setting = refSetting;
    r.setting.threads = reference.threads;
    r.runs = 1;
    r.columns = reference.graph.width();
    r.rows = reference.graph.height();
    r.wallMedian = r.wallMin = r.wallMax = wall;
    r.cpuMedian = r.cpuMin = r.cpuMax = cpu;
    r.stats = reference.stats;
    r.error = compareImages(reference.rgb.pixels, reference.graph.pixels, reference.rgb.pixels,
                            reference.graph.pixels);
    rows.push_back(r);
    log(scene.name + ": " + settingLabel(r.setting) + ": " + fmt("%.3f s", wall));
  }

  for (const BenchSetting& b :
       options.samplingStudy ? samplingSettings(options.quick) : benchSettings(options.quick)) {
    if (options.onlyThreads && b.threads == 1) continue;
    BenchRow r;
    r.scene = scene.name;
    r.setting = b;
    r.runs = std::max(1, options.runs);
    std::vector<double> walls, cpus, pairs, wallOnes;
    BenchSetting one = b;
    one.threads = 1;
    for (int run = 0; run < r.runs; ++run) {
      double wallOne = 0;
      if (b.threads > 1) {
        const double t0 = wallSeconds();
        render(scene, settingsOf(one));
        wallOne = wallSeconds() - t0;
      }
      const double w0 = wallSeconds(), c0 = processCpuSeconds();
      RenderResult res = render(scene, settingsOf(b));
      walls.push_back(wallSeconds() - w0);
      cpus.push_back(processCpuSeconds() - c0);
      if (b.threads > 1) {
        pairs.push_back(wallOne / walls.back());
        wallOnes.push_back(wallOne);
      }
      if (run == 0) {
        r.columns = res.graph.width();
        r.rows = res.graph.height();
        r.stats = res.stats;
        r.error = compareImages(reference.rgb.pixels, reference.graph.pixels, res.rgb.pixels,
                                res.graph.pixels);
      }
    }
    r.wallMedian = median(walls);
    r.cpuMedian = median(cpus);
    r.wallMin = *std::min_element(walls.begin(), walls.end());
    r.wallMax = *std::max_element(walls.begin(), walls.end());
    r.cpuMin = *std::min_element(cpus.begin(), cpus.end());
    r.cpuMax = *std::max_element(cpus.begin(), cpus.end());
    if (!pairs.empty()) {
      r.pairedSpeedUp = median(pairs);
      r.pairedWallOne = median(wallOnes);
      r.pairedSpeedUpMin = *std::min_element(pairs.begin(), pairs.end());
      r.pairedSpeedUpMax = *std::max_element(pairs.begin(), pairs.end());
    }
    rows.push_back(r);
    log(scene.name + ": " + settingLabel(b) + ": " + fmt("%.4f s", r.wallMedian) + " wall, RMSE " +
        fmt("%.5f", r.error.rmse));
  }
  return rows;
}

void markPareto(std::vector<BenchRow>& rows) {
  std::map<std::string, std::vector<int>> byScene;
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    rows[i].pareto = false;
    if (!rows[i].setting.reference && rows[i].setting.threads == 1)
      byScene[rows[i].scene].push_back(i);
  }
  for (const auto& [scene, idx] : byScene) {
    std::vector<CostError> pts;
    for (int i : idx) pts.push_back({rows[i].cpuMedian, rows[i].error.rmse});
    for (int k : paretoFront(pts)) rows[idx[k]].pareto = true;
  }
}

std::vector<SpeedUp> threadSpeedUps(const std::vector<BenchRow>& rows) {
  std::vector<SpeedUp> out;
  for (const auto& two : rows) {
    if (two.setting.threads < 2 || two.setting.reference || two.pairedSpeedUp <= 0) continue;
    SpeedUp u{two.scene,     two.setting,       two.pairedWallOne,    two.wallMedian,      0.0,
              two.cpuMedian, two.pairedSpeedUp, two.pairedSpeedUpMin, two.pairedSpeedUpMax};
    for (const auto& one : rows)
      if (one.scene == two.scene && one.setting.threads == 1 &&
          sameSetting(one.setting, two.setting))
        u.cpu1 = one.cpuMedian;
    out.push_back(u);
  }
  return out;
}

void writeCsv(const fs::path& path, const std::vector<BenchRow>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
  out << kCsvHeader << "\n";
  for (const auto& r : rows) {
    const auto& s = r.setting;
    const auto& t = r.stats;
    out << r.scene << ",\"" << settingLabel(s) << "\"," << (s.reference ? 1 : 0) << ","
        << s.maxDepth << "," << fmt("%g", s.minWeight) << "," << samplingName(s.sampling) << ","
        << s.threads << "," << r.runs << "," << r.columns << "," << r.rows << ","
        << fmt("%.6f", r.wallMedian) << "," << fmt("%.6f", r.wallMin) << ","
        << fmt("%.6f", r.wallMax) << "," << fmt("%.6f", r.cpuMedian) << "," << fmt("%.6f", r.cpuMin)
        << "," << fmt("%.6f", r.cpuMax) << "," << t.rays() << "," << t.primaryRays << ","
        << t.reflectedRays << "," << t.transmittedRays << "," << t.boundTests << ","
        << t.objectTests << "," << t.primitiveTests << "," << fmt("%.8g", r.error.rmse) << ","
        << fmt("%.8g", r.error.maxError) << "," << fmt("%.8g", r.error.indexShare) << ","
        << (r.pareto ? 1 : 0) << ","
        << (r.pairedSpeedUp > 0 ? fmt("%.4f", r.pairedSpeedUp) : std::string()) << "\n";
  }
  if (!out) throw std::runtime_error(path.string() + ": write failed");
}

namespace {

const BenchRow* findRow(const std::vector<BenchRow>& rows, const std::string& scene, int depth,
                        double w, const std::string& sampling, int threads) {
  for (const auto& r : rows)
    if (r.scene == scene && !r.setting.reference && r.setting.maxDepth == depth &&
        r.setting.minWeight == w && samplingName(r.setting.sampling) == sampling &&
        r.setting.threads == threads)
      return &r;
  return nullptr;
}

// "4.1x / 0.38" : CPU time relative to the 1991 row, RMSE.
std::string versus(const BenchRow* r, const BenchRow& base) {
  if (!r) return "-";
  return fmt("%.1fx", r->cpuMedian / base.cpuMedian) + " / " + fmt("%.4f", r->error.rmse);
}

std::string summaryTable(const std::vector<BenchRow>& rows) {
  std::ostringstream md;
  md << "| scene | pixels | reference CPU ms | 1991 profile: CPU ms, RMSE, max, index diff | depth "
        "1 | "
        "min-weight 0.2 | grid2 | grid3 | adaptive 0.05 |\n"
        "|---|---:|---:|---|---|---|---|---|---|\n";
  for (const auto& ref : rows) {
    if (!ref.setting.reference) continue;
    const BenchRow* base = findRow(rows, ref.scene, 5, 0, "single", 1);
    if (!base) continue;
    md << "| " << ref.scene << " | " << ref.columns << " x " << ref.rows << " | "
       << fmt("%.0f", ref.cpuMedian * 1e3) << " | " << fmt("%.1f", base->cpuMedian * 1e3) << ", "
       << fmt("%.4f", base->error.rmse) << ", " << fmt("%.3f", base->error.maxError) << ", "
       << fmt("%.1f%%", base->error.indexShare * 100) << " | "
       << versus(findRow(rows, ref.scene, 1, 0, "single", 1), *base) << " | "
       << versus(findRow(rows, ref.scene, 5, 0.2, "single", 1), *base) << " | "
       << versus(findRow(rows, ref.scene, 5, 0, "grid2", 1), *base) << " | "
       << versus(findRow(rows, ref.scene, 5, 0, "grid3", 1), *base) << " | "
       << versus(findRow(rows, ref.scene, 5, 0, "adaptive0.05", 1), *base) << " |\n";
  }
  return md.str();
}

}  // namespace

std::string markdownReport(const std::vector<BenchRow>& rows, const MachineFacts& before,
                           const MachineFacts& after, const std::string& command) {
  std::ostringstream md;
  md << "Run " << before.date << " on " << before.nproc << " x " << before.cpuModel << " ("
     << before.kernel << "; " << before.compiler << "); load average " << before.loadAverage
     << " before, " << after.loadAverage << " after.\n\n";
  md << "```sh\n" << command << "\n```\n\n";
  md << "Times are medians over the runs; `spread` is (max - min) / median of the wall times. "
        "Errors are against the scene's reference (depth 12, no cut-off, 4 x 4 rays per pixel), in "
        "linear RGB with every channel clamped to [0, 1] (the 1991 colours can leave that range, "
        "K15) and NaN counted as 0; `index diff` is the share of pixels whose palette index "
        "differs from the reference's. `P` marks the Pareto front of CPU time against RMSE "
        "(single-thread rows); `1991` the listing's own settings (depth 5, no cut-off, one ray per "
        "pixel).\n\n";
  if (findRow(rows, rows.empty() ? "" : rows.front().scene, 5, 0, "single", 1))
    md << "### Summary\n\nOther settings (depth 5, one thread unless named) as CPU time relative "
          "to the 1991 profile / RMSE.\n\n"
       << summaryTable(rows);
  std::string scene;
  for (const auto& r : rows) {
    if (r.scene != scene) {
      scene = r.scene;
      md << "\n### " << scene << " (" << r.columns << " x " << r.rows << " pixels)\n\n";
      md << "| setting | wall ms | spread | CPU ms | rays (primary / reflected / transmitted) | "
            "RMSE | max error | index diff | |\n";
      md << "|---|---:|---:|---:|---|---:|---:|---:|---|\n";
    }
    const auto& t = r.stats;
    const double spread = r.wallMedian > 0 ? (r.wallMax - r.wallMin) / r.wallMedian : 0.0;
    md << "| " << settingLabel(r.setting) << " | " << fmt("%.1f", r.wallMedian * 1e3) << " | "
       << fmt("%.0f%%", spread * 100) << " | " << fmt("%.1f", r.cpuMedian * 1e3) << " | "
       << t.rays() << " (" << t.primaryRays << " / " << t.reflectedRays << " / "
       << t.transmittedRays << ") | " << fmt("%.5f", r.error.rmse) << " | "
       << fmt("%.4f", r.error.maxError) << " | " << fmt("%.2f%%", r.error.indexShare * 100) << " | "
       << (r.pareto ? "P " : "")
       << (is1991Profile(r.setting) && r.setting.threads == 1 ? "1991" : "") << " |\n";
  }
  const auto ups = threadSpeedUps(rows);
  if (!ups.empty()) {
    md << "\n### 1 -> 2 threads\n\nEach 2-thread run is paired with a 1-thread run of the "
          "same setting just before it; `speed-up` is the median over the pairs of wall(1 "
          "thread) / wall(2 threads), with its range.\n\n| scene | setting | wall 1 thread ms | "
          "wall 2 threads ms | speed-up (min-max) | CPU 2 threads / CPU 1 thread "
          "|\n|---|---|---:|---:|---:|---:|\n";
    std::vector<double> ratios;
    for (const auto& u : ups) {
      md << "| " << u.scene << " | " << samplingName(u.setting.sampling) << ", depth "
         << u.setting.maxDepth << " | " << fmt("%.1f", u.wall1 * 1e3) << " | "
         << fmt("%.1f", u.wall2 * 1e3) << " | **" << fmt("%.2f", u.ratio()) << "**"
         << (u.paired > 0 ? " (" + fmt("%.2f", u.pairedMin) + "-" + fmt("%.2f", u.pairedMax) + ")"
                          : std::string())
         << " | " << (u.cpu1 > 0 ? fmt("%.2f", u.cpu2 / u.cpu1) : std::string("-")) << " |\n";
      ratios.push_back(u.ratio());
    }
    md << "\nMedian speed-up over these rows: " << fmt("%.2f", median(ratios)) << "x.\n";
  }
  if (const std::string eq = equalErrorMarkdown(rows); !eq.empty())
    md << "\n## Statistical against regular supersampling at equal error\n\n"
       << "Rays include the shadow rays. `rays saved`: the grid's rays over the statistical "
          "row's.\n\n"
       << eq;
  return md.str();
}

Image8 timeErrorPlot(const std::vector<BenchRow>& rows) {
  std::vector<Series> series;
  std::map<std::string, int> index;
  for (const auto& r : rows) {
    if (r.setting.reference || r.setting.threads != 1) continue;
    if (!index.count(r.scene)) {
      index[r.scene] = static_cast<int>(series.size());
      Series s;
      s.name = r.scene;
      s.colour = seriesColour(static_cast<int>(series.size()));
      series.push_back(s);
    }
    Series& s = series[index[r.scene]];
    s.dots.push_back({r.cpuMedian, r.error.rmse});
    if (r.pareto) s.marked.push_back({r.cpuMedian, r.error.rmse});
  }
  for (auto& s : series) {
    s.line = s.marked;
    std::sort(s.line.begin(), s.line.end(),
              [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
  }
  PlotSpec spec;
  spec.title = "PRIME BENCH: CPU TIME AGAINST ERROR";
  spec.xLabel = "CPU SECONDS PER PICTURE (MEDIAN, 1 THREAD)";
  spec.yLabel = "RMSE VS REFERENCE";
  spec.yFloor = 1e-4;
  spec.notes = {"DOTS: EVERY SETTING", "SQUARES + LINE:", "  PARETO FRONT",
                "RMSE < 1E-4 DRAWN AT 1E-4"};
  return drawPlot(spec, series);
}

}  // namespace prime::bench
