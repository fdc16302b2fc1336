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
                        const std::function<void(int, int)>& rowsDone, TraceStats& stats) const {
  if (thesis_)
    return passWith(*thesis_, camera, block, firstBlock, out, threads, abandon, rowsDone, stats);
  return modern_
             ? passWith(*modern_, camera, block, firstBlock, out, threads, abandon, rowsDone, stats)
             : passWith(*t1991_, camera, block, firstBlock, out, threads, abandon, rowsDone, stats);
}

template <class Tracer>
bool WalkRenderer::passWith(const Tracer& tracer, const FreeCamera& camera, int block,
                            int firstBlock, RgbImage& out, int threads,
                            const std::atomic<bool>* abandon,
                            const std::function<void(int, int)>& rowsDone,
                            TraceStats& stats) const {
  const int w = camera.columns(), h = camera.rows();
  std::vector<TraceStats> perThread(
      static_cast<std::size_t>(threadCount(threads, (h + block - 1) / block)));
  const bool done = progressivePass(
      w, h, block, firstBlock, threads, abandon, rowsDone,
      [&](int row, int column, int thread) {
        return tracer.castRay(camera.primaryRay(row, column), 0,
                              perThread[static_cast<std::size_t>(thread)]);
      },
      out);
  for (const TraceStats& s : perThread) stats += s;
  return done;
}

}  // namespace prime
