// prime bench SCENE.cgl ...: Waterloo CGL scenes in the shared bench table
// (src/cli/bench_table.h): reading the scene file, Preprocess (the object
// list and the texture maps) and rendering separately; CPU and wall time,
// medians of repeated renders per thread count; rays and intersection tests
// per second and the tests by kind of object node (sphere, cylinder,
// polygon, super box), the counts Table 5's costs multiply (Sweeney 1985,
// section 11).
#include "src/bench/measure.h"
#include "src/cgl/render.h"
#include "src/cli/bench_table.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"

namespace prime::cli::cgl {

namespace {

std::uint64_t tests(const prime::cgl::TraceStats& s) {
  return s.tests[0] + s.tests[1] + s.tests[2] + s.boxTests +
         s.tests[static_cast<std::size_t>(prime::cgl::ObjectKind::Fractal)];
}

class CglBench : public BenchScene {
 public:
  CglBench(CglOptions o, prime::cgl::SceneFile file, prime::cgl::Scene scene)
      : o_(std::move(o)), file_(std::move(file)), scene_(std::move(scene)) {}
  int pixels() const override {
    const auto& p = file_.program;
    return (p.xright - p.xleft + 1) * (p.yhigh - p.ylow + 1);  // inside the window
  }
  std::vector<std::pair<std::string, int>> settings() const override {
    return {{"aalevel", file_.program.aalevel}, {"depth", file_.program.depth}};
  }
  BenchCounts render(int threads) override {
    prime::cgl::RenderSettings settings = renderSettings(o_, file_);
    settings.threads = threads;
    const auto s = prime::cgl::render(scene_, settings).stats;
    BenchCounts c;
    c.rays = s.rays.rays();
    c.tests = tests(s);
    c.extra = {{"primary", s.rays.primaryRays, false},
               {"shadow", s.rays.shadowRays, false},
               {"reflected", s.rays.reflectedRays, false},
               {"refracted", s.rays.transmittedRays, false},
               {"sphere_tests", s.tests[0]},
               {"cylinder_tests", s.tests[1]},
               {"polygon_tests", s.tests[2]},
               {"box_tests", s.boxTests},
               {"shade_lambert", s.shadeCalls[0], false},
               {"shade_phong", s.shadeCalls[1], false}};
    return c;
  }

 private:
  CglOptions o_;
  prime::cgl::SceneFile file_;
  prime::cgl::Scene scene_;
};

}  // namespace

void addBenchOptions(CLI::App* cmd, Action& action) {
  auto base = std::make_shared<CglOptions>();
  cmd->add_option("--aalevel", base->aalevel,
                  "Anti-aliasing level for every scene (default: each file's): 0 none, 1, 2, 4, 8")
      ->check(CLI::IsMember({0, 1, 2, 4, 8}));
  cmd->add_option("--max-depth", base->depth,
                  "Ray-tracing depth for every scene (default: the file's)")
      ->check(CLI::Range(0, 10));
  cmd->add_flag("--lenient", base->lenient, "Also read the document's OCR-damaged examples");
  cmd->add_option("--textures", base->textureDirs,
                  "Directory to look in for texture files (after each scene's own directory)")
      ->check(CLI::ExistingDirectory);
  cmd->add_flag("--linear-search", base->linearSearch,
                "Test the object list in order for every ray, as the package did (CGL-D43)");
  cmd->add_option("--profile", base->profile,
                  "document (default) or modern: spline surfaces by the modern intersector "
                  "(CGL-D180)")
      ->check(CLI::IsMember({"document", "modern"}));
  addBenchTable(cmd, action, "Waterloo CGL", "CGL scene-description files",
                [base](const std::string& path) {
                  CglOptions o = *base;
                  o.file = path;
                  o.quiet = true;
                  BenchLoad load;
                  const double t0 = bench::wallSeconds();
                  prime::cgl::SceneFile file = readCgl(o, true);
                  const double t1 = bench::wallSeconds();
                  prime::cgl::Scene scene = buildCgl(o, file);
                  const double t2 = bench::wallSeconds();
                  load.readSeconds = t1 - t0;
                  load.buildSeconds = t2 - t1;
                  load.scene = std::make_unique<CglBench>(o, std::move(file), std::move(scene));
                  return load;
                });
}

}  // namespace prime::cli::cgl
