#include "src/malone/render.h"

#include <chrono>
#include <vector>

namespace prime::malone {

RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const RenderCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  const Tracer tracer(scene, settings.trace, callbacks.abort);
  const double setupSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int width = scene.viewer.xRes, height = scene.viewer.yRes;
  RenderResult result;
  result.setupSeconds = setupSeconds;
  result.raster.assign(width, height);
  RowCallbacks rowCallbacks;
  rowCallbacks.progress = callbacks.progress;
  rowCallbacks.abort = callbacks.abort;
  rowCallbacks.first = callbacks.firstRow;  // the raster's rows, from the top
  rowCallbacks.last = callbacks.lastRow;
  if (callbacks.rowDone)
    rowCallbacks.rowDone = [&](int row) {
      callbacks.rowDone(
          row, std::span<const Rgb>(&result.raster.at(row, 0), static_cast<std::size_t>(width)));
    };
  std::vector<ThreadSlot<TraceStats>> perThread(
      static_cast<std::size_t>(threadCount(settings.threads, height)));
  result.run = renderRows(
      height, settings.threads,
      [&](int row, int thread) -> std::uint64_t {
        TraceStats& stats = perThread[static_cast<std::size_t>(thread)].value;
        const std::uint64_t before = stats.rays();
        for (int x = 0; x < width; ++x) {
          checkAbort(callbacks.abort);  // R9
          result.raster.at(row, x) = tracer.pixel(x, row, stats);
        }
        return stats.rays() - before;
      },
      rowCallbacks);
  for (const auto& s : perThread) result.stats += s.value;
  return result;
}

}  // namespace prime::malone
