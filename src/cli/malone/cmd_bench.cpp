// prime bench SCENE.mal ...: Malone scenes in the shared bench table
// (src/cli/bench_table.h): reading, building (scene and BVH) and rendering
// separately, CPU and wall time, medians of repeated runs, rays and
// primitive tests per second, and the speed-up from one thread to more.
#include "src/bench/measure.h"
#include "src/cli/bench_table.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"

namespace prime::cli::malone {

namespace {

class MaloneBench : public BenchScene {
 public:
  MaloneBench(prime::malone::Scene scene, prime::malone::TraceSettings trace)
      : scene_(std::move(scene)), trace_(trace) {}
  int pixels() const override { return scene_.viewer.xRes * scene_.viewer.yRes; }
  BenchCounts render(int threads) override {
    prime::malone::RenderSettings settings;
    settings.trace = trace_;
    settings.threads = threads;
    // Each render builds its own BVH, as a `prime trace` does.
    const auto result = prime::malone::render(scene_, settings);
    BenchCounts c;
    c.rays = result.stats.rays();
    c.tests = result.stats.primitiveTests;
    c.extra = {{"hits", result.stats.hits}};  // tests: primitive tests
    return c;
  }

 private:
  prime::malone::Scene scene_;
  prime::malone::TraceSettings trace_;
};

}  // namespace

void addBenchOptions(CLI::App* cmd, Action& action) {
  auto linear = std::make_shared<bool>(false);
  cmd->add_flag("--linear-search", *linear, "Test every primitive for every ray, as the original");
  addBenchTable(cmd, action, "Malone", "Malone scene files", [linear](const std::string& path) {
    MaloneOptions o;
    o.file = path;
    o.trace.linearSearch = *linear;
    BenchLoad load;
    const double t0 = bench::wallSeconds();
    const auto file = prime::malone::readSceneFile(path);
    const double t1 = bench::wallSeconds();
    auto scene = prime::malone::buildScene(file, path);
    checkPictureMemory(scene, o);
    // "build" is the scene and the BVH.
    { const prime::malone::Tracer once(scene, o.trace); }
    const double t2 = bench::wallSeconds();
    load.readSeconds = t1 - t0;
    load.buildSeconds = t2 - t1;
    load.scene = std::make_unique<MaloneBench>(std::move(scene), o.trace);
    return load;
  });
}

}  // namespace prime::cli::malone
