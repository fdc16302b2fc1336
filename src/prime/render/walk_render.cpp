#include "src/prime/render/walk_render.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "src/render/render_rows.h"

namespace prime {

WalkRenderer::WalkRenderer(const Scene& scene, Profile profile, const TraceOptions& options,
                           const ThesisOptions& thesis) {
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
  // The pixels whose primary ray cannot meet an object get the background
  // without a ray, as in `prime trace` (deviation W6).
  const std::optional<PrimaryRayMask> mask = primaryMaskFor(tracer, PrimeCamera(settings));
  const bool masks = mask && mask->masks();
  const bool done = progressivePass(
      w, h, block, firstBlock, threads, abandon, rowsDone,
      [&](int row, int column, int thread) {
        TraceStats& local = perThread[static_cast<std::size_t>(thread)];
        if (masks && !mask->mayHit(row, column)) return maskedPrimaryRay(tracer.scene(), local);
        return tracer.castRay(camera.primaryRay(row, column), 0, local);
      },
      out, report);
  for (const TraceStats& s : perThread) stats += s;
  return done;
}

}  // namespace prime
