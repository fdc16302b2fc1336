#include "src/prime/render/walk_render.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "src/prime/render/primary_mask.h"
#include "src/render/render_rows.h"

namespace prime {

namespace {
// The pixels whose primary ray can meet an object, as `prime trace` finds
// them for the same tracer (renderer.cpp): the others are the background
// without a ray, the colour the tracer would return.
std::optional<PrimaryRayMask> maskFor(const Tracer1991& tracer, const PrimeCamera& camera,
                                      const TraceOptions& options) {
  if (!options.skipUnneededWork) return std::nullopt;
  return PrimaryRayMask(camera, tracer.primaryMaskBoxes());
}
template <class Tracer>
std::optional<PrimaryRayMask> maskFor(const Tracer& tracer, const PrimeCamera& camera,
                                      const TraceOptions&) {
  const Scene& scene = tracer.scene();
  return PrimaryRayMask(camera, tracer.bvh().primitiveBoxesOfObjects(scene),
                        tracer.bvh().primitiveHullsOfObjects(scene));
}
}  // namespace

WalkRenderer::WalkRenderer(const Scene& scene, Profile profile, const TraceOptions& options,
                           const ThesisOptions& thesis)
    : options_(options) {
  if (profile == Profile::Thesis)
    thesis_.emplace(scene, options, thesis);
  else if (profile == Profile::Modern)
    modern_.emplace(scene, options);
  else if (profile == Profile::Listing1991)
    t1991_.emplace(scene, options);
  else
    throw std::invalid_argument("prime walk does not know this profile");
}

bool WalkRenderer::pass(const FreeCamera& camera, int block, int firstBlock, RgbImage& out,
                        int threads, const std::atomic<bool>* abandon,
                        const std::function<void(int, int)>& rowsDone, TraceStats& stats,
                        ThreadReport* report) const {
  if (thesis_)
    return passWith(*thesis_, camera, block, firstBlock, out, threads, abandon, rowsDone, stats,
                    report);
  if (modern_)
    return passWith(*modern_, camera, block, firstBlock, out, threads, abandon, rowsDone, stats,
                    report);
  return passWith(*t1991_, camera, block, firstBlock, out, threads, abandon, rowsDone, stats,
                  report);
}

template <class Tracer>
bool WalkRenderer::passWith(const Tracer& tracer, const FreeCamera& camera, int block,
                            int firstBlock, RgbImage& out, int threads,
                            const std::atomic<bool>* abandon,
                            const std::function<void(int, int)>& rowsDone, TraceStats& stats,
                            ThreadReport* report) const {
  const int w = camera.columns(), h = camera.rows();
  std::vector<TraceStats> perThread(
      static_cast<std::size_t>(threadCount(threads, (h + block - 1) / block)));
  CameraSettings settings;
  settings.free = camera.settings();
  const std::optional<PrimaryRayMask> mask = maskFor(tracer, PrimeCamera(settings), options_);
  const Vec3& bg = tracer.scene().background;
  const Rgb background{bg[0], bg[1], bg[2]};
  const bool masks = mask && mask->masks();
  const bool done = progressivePass(
      w, h, block, firstBlock, threads, abandon, rowsDone,
      [&](int row, int column, int thread) {
        TraceStats& local = perThread[static_cast<std::size_t>(thread)];
        if (masks && !mask->mayHit(row, column)) {
          ++local.primaryRays;
          ++local.maskedPrimaryRays;
          return background;
        }
        return tracer.castRay(camera.primaryRay(row, column), 0, local);
      },
      out, report);
  for (const TraceStats& s : perThread) stats += s;
  return done;
}

}  // namespace prime
