// prime bench SCENE.mal ...: Malone scenes timed on the shared harness
// (src/bench/measure.h): reading, building (scene and BVH) and rendering
// separately, CPU and wall time, medians of repeated runs, rays and
// primitive tests per second, and the speed-up from one thread to more.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "legacy_io/common/output_file.h"
#include "src/bench/measure.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"

namespace prime::cli::malone {

namespace {

struct Row {
  std::string scene;
  int width = 0, height = 0;
  double readMs = 0, buildMs = 0;
  std::vector<double> cpu, wall;  // per thread count: medians
  std::uint64_t rays = 0, tests = 0;
};

}  // namespace

void addBenchCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(kBenchCommand, "Time Malone (1995) scenes");
  cmd->group("");  // reached through `prime bench FILE.mal ...` (src/cli/main.cpp)
  auto files = std::make_shared<std::vector<std::string>>();
  auto runs = std::make_shared<int>(5);
  auto threads = std::make_shared<std::vector<int>>(std::vector<int>{1, 2});
  auto csv = std::make_shared<std::string>();
  auto linear = std::make_shared<bool>(false);
  cmd->add_option("SCENES", *files, "Malone scene files")->required();
  cmd->add_option("--runs", *runs, "Timed renders per scene and thread count (median)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--threads", *threads, "Thread counts to time (default 1 2)")
      ->delimiter(',')
      ->check(CLI::Range(1, 256));
  cmd->add_option("--csv", *csv, "Also write the table as CSV");
  cmd->add_flag("--linear-search", *linear, "Test every primitive for every ray, as the original");
  cmd->callback([=, &action] {
    action = [=] {
      const auto facts = bench::machineFacts();
      std::printf("# prime bench (Malone): %s, %d cores, %s; load %s\n", facts.cpuModel.c_str(),
                  facts.nproc, facts.compiler.c_str(), facts.loadAverage.c_str());
      std::vector<Row> rows;
      for (const auto& file : *files) {
        Row row;
        row.scene = file;
        MaloneOptions o;
        o.file = file;
        o.trace.linearSearch = *linear;
        const double t0 = bench::wallSeconds();
        const auto sceneFile = prime::malone::readSceneFile(file);
        const double t1 = bench::wallSeconds();
        const auto scene = prime::malone::buildScene(sceneFile, file);
        // "build" is the scene and the BVH; each timed render builds its own
        // BVH again, as a `prime trace` does, so render times include it.
        { const prime::malone::Tracer once(scene, o.trace); }
        const double t2 = bench::wallSeconds();
        row.readMs = 1e3 * (t1 - t0);
        row.buildMs = 1e3 * (t2 - t1);
        row.width = scene.viewer.xRes;
        row.height = scene.viewer.yRes;
        for (int n : *threads) {
          std::vector<double> cpu, wall;
          for (int r = 0; r < *runs; ++r) {
            prime::malone::RenderSettings settings;
            settings.trace = o.trace;
            settings.threads = n;
            const double c0 = bench::processCpuSeconds(), w0 = bench::wallSeconds();
            const auto result = prime::malone::render(scene, settings);
            cpu.push_back(bench::processCpuSeconds() - c0);
            wall.push_back(bench::wallSeconds() - w0);
            row.rays = result.stats.rays();
            row.tests = result.stats.primitiveTests;
          }
          row.cpu.push_back(bench::median(cpu));
          row.wall.push_back(bench::median(wall));
        }
        rows.push_back(row);
      }
      std::printf("%-36s %9s %8s %8s", "scene", "pixels", "read ms", "build ms");
      for (int n : *threads) std::printf(" %6s%-2d %6s%-2d", "cpu s/", n, "wall/", n);
      std::printf(" %10s %12s %9s", "rays", "prim tests", "ns/test");
      if (threads->size() > 1) std::printf(" %8s", "speed-up");
      std::printf("\n");
      for (const Row& r : rows) {
        std::printf("%-36s %9d %8.1f %8.1f", r.scene.c_str(), r.width * r.height, r.readMs,
                    r.buildMs);
        for (std::size_t k = 0; k < threads->size(); ++k)
          std::printf(" %8.3f %8.3f", r.cpu[k], r.wall[k]);
        std::printf(" %10llu %12llu %9.1f", static_cast<unsigned long long>(r.rays),
                    static_cast<unsigned long long>(r.tests),
                    r.tests > 0 ? 1e9 * r.cpu[0] / static_cast<double>(r.tests) : 0.0);
        if (threads->size() > 1) std::printf(" %7.2fx", r.wall[0] / r.wall.back());
        std::printf("\n");
      }
      if (!csv->empty()) {
        io::checkOutputPath(*csv);  // not an input of the run, its directory exists
        std::ofstream out(*csv);
        out << "scene,pixels,read_ms,build_ms";
        for (int n : *threads) out << ",cpu_s_" << n << ",wall_s_" << n;
        out << ",rays,primitive_tests\n";
        for (const Row& r : rows) {
          out << r.scene << "," << r.width * r.height << "," << r.readMs << "," << r.buildMs;
          for (std::size_t k = 0; k < threads->size(); ++k)
            out << "," << r.cpu[k] << "," << r.wall[k];
          out << "," << r.rays << "," << r.tests << "\n";
        }
        if (!out) throw std::runtime_error("cannot write " + *csv);
        std::fprintf(stderr, "prime: bench: wrote %s\n", csv->c_str());
      }
      return 0;
    };
  });
}

}  // namespace prime::cli::malone
