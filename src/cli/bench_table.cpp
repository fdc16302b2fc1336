#include "src/cli/bench_table.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "legacy_io/common/output_file.h"
#include "src/bench/measure.h"
#include "src/cli/option_values.h"

namespace prime::cli {

namespace {

struct Row {
  std::string scene;
  int pixels = 0;
  std::vector<std::pair<std::string, int>> settings;
  double readMs = 0, buildMs = 0;
  std::vector<double> cpu, wall;  // per thread count: medians
  BenchCounts counts;             // of the last render (the same for every run)
};

struct Options {
  std::vector<std::string> scenes;
  int runs = 5;
  std::vector<int> threads{1, 2};
  std::string csv;
};

Row measure(const std::string& path, const BenchLoader& loader, const Options& o) {
  Row row;
  row.scene = path;
  BenchLoad load = loader(path);
  row.readMs = 1e3 * load.readSeconds;
  row.buildMs = 1e3 * load.buildSeconds;
  row.pixels = load.scene->pixels();
  row.settings = load.scene->settings();
  for (int n : o.threads) {
    std::vector<double> cpu, wall;
    for (int r = 0; r < o.runs; ++r) {
      const double c0 = bench::processCpuSeconds(), w0 = bench::wallSeconds();
      row.counts = load.scene->render(n);
      cpu.push_back(bench::processCpuSeconds() - c0);
      wall.push_back(bench::wallSeconds() - w0);
    }
    row.cpu.push_back(bench::median(cpu));
    row.wall.push_back(bench::median(wall));
  }
  return row;
}

void printTable(const std::vector<Row>& rows, const Options& o) {
  const Row& first = rows.front();
  std::printf("%-34s %9s", "scene", "pixels");
  for (const auto& [name, v] : first.settings) std::printf(" %7s", name.c_str());
  std::printf(" %8s %8s", "read ms", "build ms");
  for (int n : o.threads) std::printf(" %6s%-2d %6s%-2d", "cpu s/", n, "wall/", n);
  std::printf(" %10s %10s %11s %9s", "rays", "rays/s", "tests", "tests/s");
  for (const BenchColumn& c : first.counts.extra)
    if (c.shown) std::printf(" %10s", c.name.c_str());
  if (o.threads.size() > 1) std::printf(" %8s", "speed-up");
  std::printf("\n");
  for (const Row& r : rows) {
    const double c = r.cpu[0];
    std::printf("%-34s %9d", r.scene.c_str(), r.pixels);
    for (const auto& [name, v] : r.settings) std::printf(" %7d", v);
    std::printf(" %8.1f %8.1f", r.readMs, r.buildMs);
    for (std::size_t k = 0; k < o.threads.size(); ++k)
      std::printf(" %8.4f %8.4f", r.cpu[k], r.wall[k]);
    std::printf(" %10llu %10.3g %11llu %9.3g", static_cast<unsigned long long>(r.counts.rays),
                c > 0 ? static_cast<double>(r.counts.rays) / c : 0.0,
                static_cast<unsigned long long>(r.counts.tests),
                c > 0 ? static_cast<double>(r.counts.tests) / c : 0.0);
    for (const BenchColumn& col : r.counts.extra)
      if (col.shown) std::printf(" %10llu", static_cast<unsigned long long>(col.value));
    if (o.threads.size() > 1) std::printf(" %7.2fx", r.wall[0] / r.wall.back());
    std::printf("\n");
  }
  std::printf(
      "(cpu and wall: seconds of the render alone, median of %d; rays/s and tests/s per CPU "
      "second with %d thread(s))\n",
      o.runs, o.threads.front());
}

void writeCsv(const std::vector<Row>& rows, const Options& o) {
  io::checkOutputPath(o.csv);  // not an input of the run, its directory exists
  io::OutputFile file(o.csv);
  std::string text = "scene,pixels";
  const Row& first = rows.front();
  for (const auto& [name, v] : first.settings) text += "," + name;
  text += ",read_ms,build_ms";
  for (int n : o.threads) text += ",cpu_s_" + std::to_string(n) + ",wall_s_" + std::to_string(n);
  text += ",rays,tests";
  for (const BenchColumn& c : first.counts.extra) text += "," + c.name;
  text += "\n";
  char buf[64];
  auto number = [&buf](double v) {
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return std::string(buf);
  };
  for (const Row& r : rows) {
    text += r.scene + "," + std::to_string(r.pixels);
    for (const auto& [name, v] : r.settings) text += "," + std::to_string(v);
    text += "," + number(r.readMs) + "," + number(r.buildMs);
    for (std::size_t k = 0; k < o.threads.size(); ++k)
      text += "," + number(r.cpu[k]) + "," + number(r.wall[k]);
    text += "," + std::to_string(r.counts.rays) + "," + std::to_string(r.counts.tests);
    for (const BenchColumn& c : r.counts.extra) text += "," + std::to_string(c.value);
    text += "\n";
  }
  file.write(std::string_view(text));
  file.commit();
  std::fprintf(stderr, "prime: bench: wrote %s\n", o.csv.c_str());
}

}  // namespace

void addBenchTable(CLI::App* cmd, Action& action, const std::string& title,
                   const std::string& scenesHelp, const BenchLoader& loader) {
  auto o = std::make_shared<Options>();
  cmd->add_option("SCENES", o->scenes, scenesHelp)->required();
  cmd->add_option("--runs", o->runs, "Timed renders per scene and thread count (median)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--threads", o->threads, "Thread counts to time (default 1,2)")
      ->delimiter(',')
      ->check(CLI::Range(1, 256));
  cmd->add_option("--csv", o->csv, "Also write the table as CSV")->check(outputName());
  cmd->callback([o, loader, title, &action] {
    action = [o, loader, title] {
      const auto facts = bench::machineFacts();
      std::printf("# prime bench (%s): %s, %d cores, %s; load %s\n", title.c_str(),
                  facts.cpuModel.c_str(), facts.nproc, facts.compiler.c_str(),
                  facts.loadAverage.c_str());
      std::vector<Row> rows;
      for (const std::string& path : o->scenes) rows.push_back(measure(path, loader, *o));
      printTable(rows, *o);
      if (!o->csv.empty()) writeCsv(rows, *o);
      return 0;
    };
  });
}

}  // namespace prime::cli
