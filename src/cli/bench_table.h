// `prime bench SCENE...` for the systems whose bench is a table of scenes
// (Malone's and CGL's): the same columns, CSV and machine line for each,
// timed on the shared harness (src/bench/measure.h). A system gives a loader:
// how to read and build one scene, and what one render of it counts.
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "src/cli/commands.h"

namespace prime::cli {

// One of a system's own counters: in the CSV always, in the printed table
// when `shown`.
struct BenchColumn {
  std::string name;
  std::uint64_t value = 0;
  bool shown = true;
};
// What one render of a scene counted: rays, intersection tests, and the
// system's own columns, the same names for every scene.
struct BenchCounts {
  std::uint64_t rays = 0, tests = 0;
  std::vector<BenchColumn> extra;
};

class BenchScene {
 public:
  virtual ~BenchScene() = default;
  virtual int pixels() const = 0;
  // The system's settings columns (name, value): CGL's anti-aliasing and depth.
  virtual std::vector<std::pair<std::string, int>> settings() const { return {}; }
  virtual BenchCounts render(int threads) = 0;
};

struct BenchLoad {
  std::unique_ptr<BenchScene> scene;
  double readSeconds = 0, buildSeconds = 0;  // reading the file; building the scene
};
using BenchLoader = std::function<BenchLoad(const std::string& path)>;

// Adds SCENES, --runs, --threads and --csv to `cmd` (the system adds its own
// flags) and sets the action: each scene loaded by `loader`, rendered --runs
// times per thread count, the medians in one table.
void addBenchTable(CLI::App* cmd, Action& action, const std::string& title,
                   const std::string& scenesHelp, const BenchLoader& loader);

}  // namespace prime::cli
