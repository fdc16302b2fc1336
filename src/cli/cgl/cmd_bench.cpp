// prime bench SCENE.cgl ...: Waterloo CGL scenes timed on the shared harness
// (src/bench/measure.h): reading the scene file, Preprocess (the object list
// and the texture maps) and rendering separately; CPU and wall time, medians
// of repeated renders per thread count; rays and intersection tests per
// second and the tests by kind of object node (sphere, cylinder, polygon,
// super box), the counts Table 5's costs multiply (Sweeney 1985, section 11).
#include <cstdio>
#include <fstream>
#include <iostream>

#include "legacy_io/common/output_file.h"
#include "src/bench/measure.h"
#include "src/cgl/render.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"

namespace prime::cli::cgl {

namespace {

struct Row {
  std::string scene;
  int pixels = 0;  // inside the window
  int aalevel = 0, depth = 0;
  double readMs = 0, buildMs = 0;
  std::vector<double> cpu, wall;  // per thread count: medians
  prime::cgl::TraceStats stats;   // of the last render (the same for every run)
};

std::uint64_t tests(const prime::cgl::TraceStats& s) {
  return s.tests[0] + s.tests[1] + s.tests[2] + s.boxTests +
         s.tests[static_cast<std::size_t>(prime::cgl::ObjectKind::Fractal)];
}

}  // namespace

void addBenchCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(kBenchCommand, "Time Waterloo CGL (1985) scenes");
  cmd->group("");  // reached through `prime bench FILE.cgl ...` (src/cli/main.cpp)
  auto files = std::make_shared<std::vector<std::string>>();
  auto runs = std::make_shared<int>(5);
  auto threads = std::make_shared<std::vector<int>>(std::vector<int>{1, 2});
  auto csv = std::make_shared<std::string>();
  auto base = std::make_shared<CglOptions>();
  cmd->add_option("SCENES", *files, "CGL scene-description files")->required();
  cmd->add_option("--runs", *runs, "Timed renders per scene and thread count (median)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--threads", *threads, "Thread counts to time (default 1,2)")
      ->delimiter(',')
      ->check(CLI::Range(1, 256));
  cmd->add_option("--aalevel", base->aalevel,
                  "Anti-aliasing level for every scene (default: each file's): 0 none, 1, 2, 4, 8")
      ->check(CLI::IsMember({0, 1, 2, 4, 8}));
  cmd->add_option("--depth", base->depth, "Ray-tracing depth for every scene (default: the file's)")
      ->check(CLI::Range(0, 10));
  cmd->add_flag("--lenient", base->lenient, "Also read the document's OCR-damaged examples");
  cmd->add_option("--textures", base->textureDirs,
                  "Directory to look in for texture files (after each scene's own directory)")
      ->check(CLI::ExistingDirectory);
  cmd->add_flag("--linear-search", base->linearSearch,
                "Test the object list in order for every ray, as the package did (CGL-D43)");
  cmd->add_option("--csv", *csv, "Also write the table as CSV");
  cmd->callback([=, &action] {
    action = [=] {
      const auto facts = bench::machineFacts();
      std::printf("# prime bench (Waterloo CGL): %s, %d cores, %s; load %s\n",
                  facts.cpuModel.c_str(), facts.nproc, facts.compiler.c_str(),
                  facts.loadAverage.c_str());
      std::vector<Row> rows;
      for (const auto& path : *files) {
        CglOptions o = *base;
        o.file = path;
        o.quiet = true;
        Row row;
        row.scene = path;
        const double t0 = bench::wallSeconds();
        const prime::cgl::SceneFile file = readCgl(o, true);
        const double t1 = bench::wallSeconds();
        const prime::cgl::Scene scene = buildCgl(o, file);
        const double t2 = bench::wallSeconds();
        row.readMs = 1e3 * (t1 - t0);
        row.buildMs = 1e3 * (t2 - t1);
        const auto& p = file.program;
        row.pixels = (p.xright - p.xleft + 1) * (p.yhigh - p.ylow + 1);
        row.aalevel = p.aalevel;
        row.depth = p.depth;
        for (int n : *threads) {
          std::vector<double> cpu, wall;
          for (int r = 0; r < *runs; ++r) {
            prime::cgl::RenderSettings settings = renderSettings(o, file);
            settings.threads = n;
            const double c0 = bench::processCpuSeconds(), w0 = bench::wallSeconds();
            const auto result = prime::cgl::render(scene, settings);
            cpu.push_back(bench::processCpuSeconds() - c0);
            wall.push_back(bench::wallSeconds() - w0);
            row.stats = result.stats;
          }
          row.cpu.push_back(bench::median(cpu));
          row.wall.push_back(bench::median(wall));
        }
        rows.push_back(row);
      }
      std::printf("%-34s %7s %2s %2s %7s %8s", "scene", "pixels", "aa", "d", "read ms", "build ms");
      for (int n : *threads) std::printf(" %6s%-2d %6s%-2d", "cpu s/", n, "wall/", n);
      std::printf(" %10s %10s %11s %9s %10s %10s %10s %10s", "rays", "rays/s", "tests", "tests/s",
                  "sphere", "cylinder", "polygon", "super box");
      if (threads->size() > 1) std::printf(" %8s", "speed-up");
      std::printf("\n");
      for (const Row& r : rows) {
        const auto& s = r.stats;
        const double c = r.cpu[0];
        std::printf("%-34s %7d %2d %2d %7.1f %8.1f", r.scene.c_str(), r.pixels, r.aalevel, r.depth,
                    r.readMs, r.buildMs);
        for (std::size_t k = 0; k < threads->size(); ++k)
          std::printf(" %8.4f %8.4f", r.cpu[k], r.wall[k]);
        std::printf(" %10llu %10.3g %11llu %9.3g %10llu %10llu %10llu %10llu",
                    static_cast<unsigned long long>(s.rays.rays()),
                    c > 0 ? static_cast<double>(s.rays.rays()) / c : 0.0,
                    static_cast<unsigned long long>(tests(s)),
                    c > 0 ? static_cast<double>(tests(s)) / c : 0.0,
                    static_cast<unsigned long long>(s.tests[0]),
                    static_cast<unsigned long long>(s.tests[1]),
                    static_cast<unsigned long long>(s.tests[2]),
                    static_cast<unsigned long long>(s.boxTests));
        if (threads->size() > 1) std::printf(" %7.2fx", r.wall[0] / r.wall.back());
        std::printf("\n");
      }
      std::printf(
          "(cpu and wall: seconds of the render alone, median of %d; rays/s and tests/s "
          "per CPU second with %d thread(s))\n",
          *runs, threads->front());
      if (!csv->empty()) {
        io::checkOutputPath(*csv);  // not an input of the run, its directory exists
        std::ofstream out(*csv);
        out << "scene,pixels,aalevel,depth,read_ms,build_ms";
        for (int n : *threads) out << ",cpu_s_" << n << ",wall_s_" << n;
        out << ",rays,primary,shadow,reflected,refracted,tests,sphere_tests,cylinder_tests,"
               "polygon_tests,box_tests,shade_lambert,shade_phong\n";
        for (const Row& r : rows) {
          const auto& s = r.stats;
          out << r.scene << "," << r.pixels << "," << r.aalevel << "," << r.depth << "," << r.readMs
              << "," << r.buildMs;
          for (std::size_t k = 0; k < threads->size(); ++k)
            out << "," << r.cpu[k] << "," << r.wall[k];
          out << "," << s.rays.rays() << "," << s.rays.primaryRays << "," << s.rays.shadowRays
              << "," << s.rays.reflectedRays << "," << s.rays.transmittedRays << "," << tests(s)
              << "," << s.tests[0] << "," << s.tests[1] << "," << s.tests[2] << "," << s.boxTests
              << "," << s.shadeCalls[0] << "," << s.shadeCalls[1] << "\n";
        }
        if (!out) throw std::runtime_error("cannot write " + *csv);
        std::fprintf(stderr, "prime: bench: wrote %s\n", csv->c_str());
      }
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
