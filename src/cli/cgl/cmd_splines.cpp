// prime cgl-splines SCENE.cgl (the study itself: src/cgl/spline_study.h): the B-spline surfaces of
// a CGL scene measured as Sweeney 1985 measures them in Tables 3 and 6 (section 11.2): per surface
// the original (extended) and refined vertices, tree nodes and bytes, then for the picture
// (rendered on one thread) boxes checked and Newton calls per ray, iterations per call, and the
// share of time in refinement, tree building, box tests, Newton and shading with the rest. Box and
// Newton times come from a second pass over the primary rays: the intersection alone, then Newton
// alone replayed from the same starts. With --holes N, every N-th pixel's primary ray is also
// traced by the dense reference (src/cgl/spline.h): the rays it hits and the Newton path misses.
// With --distances FILE, every pixel's primary ray is traced by both and the distances to the
// nearest spline hit are written as CSV (the holes against POV-Ray: bench/cgl/spline_holes.sh,
// CGL-D171).
#include <chrono>

#include "legacy_io/common/output_file.h"
#include "src/cgl/spline_study.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"
#include "src/cli/option_values.h"

namespace prime::cli::cgl {

void addSplinesCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand("cgl-splines", "Tables 3 and 6 for the B-spline surfaces of a CGL scene");
  auto o = std::make_shared<CglOptions>();
  auto holes = std::make_shared<int>(0);
  addCglOptions(cmd, *o);
  cmd->add_option("--holes", *holes,
                  "Count holes on every N-th pixel's primary ray (0: do not; slow)")
      ->check(CLI::Range(0, 512));
  auto distances = std::make_shared<std::string>();
  cmd->add_option("--distances", *distances,
                  "Write every pixel's distance to the nearest spline hit, by the dense "
                  "reference and by the Newton path, as CSV (x,y,reference,path; empty: none)")
      ->check(outputName());
  cmd->callback([o, holes, distances, &action] {
    action = [o, holes, distances] {
      // Refused before the study, not after its minutes of rendering.
      if (!distances->empty()) io::checkOutputPath(*distances);
      using Clock = std::chrono::steady_clock;
      const auto t0 = Clock::now();
      const prime::cgl::SceneFile file = readCgl(*o, true);
      const auto t1 = Clock::now();
      const prime::cgl::Scene scene = buildCgl(*o, file);
      const auto t2 = Clock::now();
      prime::cgl::SplineStudy study(file, scene, renderSettings(*o, file),
                                    std::chrono::duration<double>(t1 - t0).count(),
                                    std::chrono::duration<double>(t2 - t1).count());
      study.renderAndSurfaces();
      study.timeIntersections();
      study.compareWalks();
      study.averagesAndShares();
      if (*holes > 0) study.holes(*holes);
      if (!distances->empty()) study.distances(*distances);
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
