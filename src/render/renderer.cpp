#include "src/render/renderer.h"

#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

#include "palette/color_num.h"

namespace prime {

int paletteIndex(const Rgb& color, const RenderSettings& settings, TraceStats& stats) {
  ColorNumCounters counters;
  const int index = settings.mapping == ColorMapping::Plate3 ? colorNumPlate3(color, &counters)
                                                             : colorNum(color, settings.graphType, &counters);
  stats.nanColours += counters.nanColours;
  stats.indicesOutOfRange += counters.outOfRange;
  return index;
}

RenderResult render(const Scene& scene, const RenderSettings& settings, const RenderCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  const ListingCamera camera(settings.camera);
  const Tracer1991 tracer(scene, settings.trace);
  const int rows = camera.rows(), columns = camera.columns();

  RenderResult result;
  result.graph.graphType = static_cast<std::int16_t>(settings.graphType);
  result.graph.numPixAcross = static_cast<std::int16_t>(camera.numPixAcross());
  result.graph.numPixDown = static_cast<std::int16_t>(camera.numPixDown());
  result.graph.inclusive = true;
  result.graph.pixels.assign(static_cast<std::size_t>(rows) * columns, 0);
  result.rgb.assign(result.graph.pixels.size(), Rgb{});

  int threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min(threads, rows));
  result.threads = threads;

  std::atomic<int> nextRow{0}, rowsDone{0};
  std::atomic<std::uint64_t> raysSoFar{0};
  std::mutex mutex;  // guards the shared counters, the finished-row queue and the first error
  TraceStats total;
  std::vector<int> finished;
  std::exception_ptr error;

  auto worker = [&] {
    TraceStats local;
    std::uint64_t raysReported = 0;
    for (;;) {
      if (callbacks.abort && callbacks.abort->load()) break;
      const int i = nextRow.fetch_add(1);
      if (i >= rows) break;
      try {
        for (int j = 0; j < columns; ++j) {
          const std::size_t at = static_cast<std::size_t>(i) * columns + j;
          const Rgb color = tracer.castRay(camera.primaryRay(i, j), 0, local);
          result.rgb[at] = color;
          // fwrite(&color, sizeof(int)): the raw 16-bit value (Q12).
          result.graph.pixels[at] = static_cast<std::int16_t>(paletteIndex(color, settings, local));
        }
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        nextRow = rows;  // stop everyone
        break;
      }
      raysSoFar += local.rays() - raysReported;
      raysReported = local.rays();
      std::lock_guard lock(mutex);
      finished.push_back(i);
      ++rowsDone;
    }
    std::lock_guard lock(mutex);
    total += local;
  };

  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);

  auto report = [&] {
    std::vector<int> rowsNow;
    {
      std::lock_guard lock(mutex);
      rowsNow.swap(finished);
    }
    if (callbacks.rowDone)
      for (int i : rowsNow) {
        const auto* first = &result.graph.pixels[static_cast<std::size_t>(i) * columns];
        callbacks.rowDone(i, std::vector<std::int16_t>(first, first + columns));
      }
    if (callbacks.progress) callbacks.progress(rowsDone.load(), rows, raysSoFar.load());
  };
  while (rowsDone.load() < rows && !error && !(callbacks.abort && callbacks.abort->load())) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    report();
  }
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  report();

  result.stats = total;
  result.aborted = rowsDone.load() < rows;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace prime
