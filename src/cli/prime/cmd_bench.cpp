// prime bench [SCENE_DIR...]: run time against error for every scene (and,
// with --scale, the generated-scene scale study). The work is in src/bench.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/prime/bench/bench.h"
#include "src/prime/bench/scale.h"

namespace prime::cli {

namespace {

struct BenchCliOptions {
  std::vector<std::string> scenes;
  std::string out = "out/bench";
  int runs = 0;  // 0: 3, or 1 with --quick
  bool quick = false;
  bool onlyThreads = false;
  bool sampling = false;
  double lightRadius = 100.0;
  bool scale = false, onlyScale = false;
  std::vector<int> scaleSizes;
  int scaleOffMax = -1;
  int scaleRuns = 3;
  std::vector<int> screen;
  bool quiet = false;
};

std::string commandLine(const BenchCliOptions& o) {
  std::ostringstream c;
  c << "prime bench";
  for (const auto& s : o.scenes) c << " " << s;
  c << " --out " << o.out;
  if (o.runs > 0) c << " --runs " << o.runs;
  if (o.quick) c << " --quick";
  if (o.onlyThreads) c << " --only-threads";
  if (o.sampling) c << " --sampling --light-radius " << o.lightRadius;
  if (o.scale) c << " --scale";
  if (o.onlyScale) c << " --only-scale";
  if (!o.scaleSizes.empty()) {
    c << " --scale-sizes";
    for (int n : o.scaleSizes) c << " " << n;
  }
  if (o.scaleOffMax >= 0) c << " --scale-off-max " << o.scaleOffMax;
  if (o.scaleRuns != 3) c << " --scale-runs " << o.scaleRuns;
  if (o.screen.size() == 2) c << " --screen " << o.screen[0] << " " << o.screen[1];
  return c.str();
}

int runBench(const BenchCliOptions& o) {
  namespace fs = std::filesystem;
  using namespace prime::bench;
  const fs::path out = o.out;
  fs::create_directories(out);
  auto log = [&](const std::string& m) {
    if (!o.quiet) std::cerr << "prime bench: " << m << "\n";
  };
  const int runs = o.runs > 0 ? o.runs : (o.quick ? 1 : 3);
  const std::string command = commandLine(o);

  if (!o.onlyScale) {
    std::vector<fs::path> scenes;
    for (const auto& s : o.scenes) scenes.emplace_back(s);
    if (scenes.empty()) scenes = defaultScenes("scenes/prime");
    if (scenes.empty())
      throw std::runtime_error(
          "no scenes: give SCENE_DIR arguments, or run where scenes/prime/*/Model.txt exist");
    const fs::path work = fs::temp_directory_path() / ("prime-bench-" + std::to_string(::getpid()));
    struct Cleanup {
      fs::path p;
      ~Cleanup() {
        std::error_code ec;
        fs::remove_all(p, ec);
      }
    } cleanup{work};
    BenchOptions options;
    options.runs = runs;
    options.quick = o.quick;
    options.onlyThreads = o.onlyThreads;
    options.samplingStudy = o.sampling;
    options.lightRadius = o.lightRadius;
    options.camera = benchCamera(o.quick);
    if (o.screen.size() == 2) {
      options.camera.screenWidth = o.screen[0];
      options.camera.screenHeight = o.screen[1];
    }
    options.log = log;
    const MachineFacts before = machineFacts();
    std::vector<BenchRow> rows;
    for (const auto& dir : scenes) {
      const Scene scene = modelSceneCopy(dir, work);
      const auto sceneRows = benchScene(scene, sceneMapping(dir), options);
      rows.insert(rows.end(), sceneRows.begin(), sceneRows.end());
    }
    markPareto(rows);
    const MachineFacts after = machineFacts();
    writeCsv(out / "bench.csv", rows);
    std::ofstream(out / "bench.md") << markdownReport(rows, before, after, command);
    writePng((out / "time_error.png").string(), timeErrorPlot(rows));
    log("wrote " + (out / "bench.csv").string() + ", bench.md, time_error.png");
  }

  if (o.scale || o.onlyScale) {
    ScaleOptions s;
    s.runs = o.quick ? 1 : o.scaleRuns;
    s.camera =
        benchCamera(true);  // 45 x 97 pixels: the object count, not the pixels, is what varies
    s.camera.screenWidth = 256;
    s.camera.screenHeight = 192;  // 89 x 193 pixels
    if (o.quick) s.sizes = {1, 10, 100};
    if (!o.scaleSizes.empty()) s.sizes = o.scaleSizes;
    if (o.scaleOffMax >= 0) s.offMaxObjects = o.scaleOffMax;
    s.log = log;
    const MachineFacts facts = machineFacts();
    const auto rows = runScale(s);
    writeScaleCsv((out / "scale.csv").string(), rows);
    std::ofstream(out / "scale.md")
        << "Run " << facts.date << " on " << facts.nproc << " x " << facts.cpuModel
        << "; load average " << facts.loadAverage << " before.\n\n```sh\n"
        << command << "\n```\n\n"
        << scaleMarkdown(rows, s.camera);
    writePng((out / "scale_time.png").string(), scaleTimePlot(rows));
    writePng((out / "scale_memory.png").string(), scaleMemoryPlot(rows));
    log("wrote " + (out / "scale.csv").string() + ", scale.md, scale_time.png, scale_memory.png");
  }
  return 0;
}

}  // namespace

void addBenchOptions(CLI::App* cmd, Action& action) {
  auto o = std::make_shared<BenchCliOptions>();
  cmd->add_option("SCENE_DIR", o->scenes,
                  "Scene directories (default: every scenes/prime/*/ with a Model.txt)")
      ->check(sceneDirectory());
  cmd->add_option("--out", o->out,
                  "Directory for bench.csv, bench.md, time_error.png (default: out/bench)");
  cmd->add_option("--runs", o->runs,
                  "Runs per setting; the median is reported (default 3; 1 with --quick)")
      ->check(CLI::Range(1, 100));
  cmd->add_flag("--sampling", o->sampling,
                "The sampling study instead: the thesis profile with soft shadows; regular, "
                "jittered and statistical supersampling against a jittered 16 x 16 reference");
  cmd->add_option("--light-radius", o->lightRadius,
                  "The sampling study's light radius (100; 0: point lights, hard shadows)")
      ->check(atLeast(0));
  cmd->add_flag("--quick", o->quick, "A few settings, one run, a 45 x 97 picture: for tests");
  cmd->add_option(
         "--screen", o->screen,
         "Screen size W H for the scenes (default 512 x 384: 176 x 385 pixels; 1024 768 is the "
         "listing's 350 x 769)")
      ->expected(2)
      ->allow_extra_args(false)
      ->check(CLI::Range(8, 4096));
  cmd->add_flag(
      "--only-threads", o->onlyThreads,
      "Only the reference and the 2-thread settings, each run paired with a 1-thread run: "
      "the thread speed-up alone, for a quiet moment");
  cmd->add_flag("--scale", o->scale,
                "Also run the scale study (generated scenes of 1 .. 10,000 objects)");
  cmd->add_flag("--only-scale", o->onlyScale, "Run only the scale study");
  cmd->add_option("--scale-sizes", o->scaleSizes,
                  "Object counts of the scale study (default 1 10 100 1000 10000)")
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--scale-off-max", o->scaleOffMax,
                  "Largest scene rendered with the skips and the BVH off (default: all)")
      ->check(atLeast(0));
  cmd->add_option("--scale-runs", o->scaleRuns,
                  "Renders per scale case; the median is reported (default 3)")
      ->check(CLI::Range(1, 100));
  cmd->add_flag("-q,--quiet", o->quiet, "No progress lines");
  cmd->callback([o, &action] { action = [o] { return runBench(*o); }; });
}

}  // namespace prime::cli
