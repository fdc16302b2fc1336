#include "src/prime/render/walk_render.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "src/render/progressive.h"

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
  const int blockRows = (h + block - 1) / block;
  const int n = threadCount(threads, blockRows);
  std::vector<TraceStats> perThread(static_cast<std::size_t>(n));
  auto renderRow = [&](int br, int thread) -> std::uint64_t {
    TraceStats& s = perThread[static_cast<std::size_t>(thread)];
    const std::uint64_t before = s.rays();
    const int y0 = br * block, y1 = std::min(h, y0 + block);
    for (int x0 = 0; x0 < w; x0 += block) {
      if (!sampledInEarlierPass(y0, x0, block, firstBlock)) {
        out.at(y0, x0) = tracer.castRay(camera.primaryRay(y0, x0), 0, s);
      }
      const Rgb c = out.at(y0, x0);
      const int x1 = std::min(w, x0 + block);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) out.at(y, x) = c;
    }
    return s.rays() - before;
  };
  RowCallbacks cb;
  cb.abort = abandon;
  if (rowsDone)
    cb.rowDone = [&](int br) {
      const int y0 = br * block;
      rowsDone(y0, std::min(h, y0 + block) - y0);
    };
  const RowsRun run = renderRows(blockRows, n, renderRow, cb);
  for (const TraceStats& s : perThread) stats += s;
  return !run.aborted;
}

}  // namespace prime
