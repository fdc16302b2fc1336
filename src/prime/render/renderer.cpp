#include "src/prime/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <optional>
#include <type_traits>
#include <vector>

#include "palette/prime/color_num.h"
#include "src/prime/render/primary_mask.h"
#include "src/prime/render/tracer_modern.h"
#include "src/render/picture_buffer.h"

namespace prime {

int paletteIndex(const Rgb& color, const RenderSettings& settings, TraceStats& stats) {
  ColorNumCounters counters;
  const int index = settings.mapping == ColorMapping::Plate3
                        ? colorNumPlate3(color, &counters)
                        : colorNum(color, settings.graphType, &counters);
  stats.nanColours += counters.nanColours;
  stats.indicesOutOfRange += counters.outOfRange;
  return index;
}

namespace {
// Every leaf primitive's box within its object's box, and (for the modern
// and thesis profiles) the points whose hull holds each primitive.
template <class Tracer>
std::optional<PrimaryRayMask> maskWithHulls(const Tracer& tracer, const PrimeCamera& camera) {
  const Scene& scene = tracer.scene();
  return PrimaryRayMask(camera, tracer.bvh().primitiveBoxesOfObjects(scene),
                        tracer.bvh().primitiveHullsOfObjects(scene));
}
}  // namespace

std::optional<PrimaryRayMask> primaryMaskFor(const Tracer1991& tracer, const PrimeCamera& camera) {
  if (!tracer.skipsUnneededWork()) return std::nullopt;
  return PrimaryRayMask(camera, tracer.primaryMaskBoxes());
}
std::optional<PrimaryRayMask> primaryMaskFor(const TracerModern& tracer,
                                             const PrimeCamera& camera) {
  return maskWithHulls(tracer, camera);
}
std::optional<PrimaryRayMask> primaryMaskFor(const TracerThesis& tracer,
                                             const PrimeCamera& camera) {
  return maskWithHulls(tracer, camera);
}

namespace {

// paletteIndex for a run of equal colours (the background, flat faces)
// computed once: the same bits give the same index and the same counts.
class PaletteIndexCache {
 public:
  explicit PaletteIndexCache(const RenderSettings& settings) : settings_(settings) {}
  int get(const Rgb& color, TraceStats& stats) {
    if (valid_ && std::memcmp(color.data(), last_.data(), sizeof last_) == 0) {
      stats.nanColours += delta_.nanColours;
      stats.indicesOutOfRange += delta_.indicesOutOfRange;
      return index_;
    }
    TraceStats fresh;
    index_ = paletteIndex(color, settings_, fresh);
    delta_ = fresh;
    stats.nanColours += fresh.nanColours;
    stats.indicesOutOfRange += fresh.indicesOutOfRange;
    last_ = color;
    valid_ = true;
    return index_;
  }
  // get(color, stats) called n >= 1 times: the same index, n times the counts.
  int getRepeated(const Rgb& color, std::uint64_t n, TraceStats& stats) {
    const int index = get(color, stats);
    stats.nanColours += (n - 1) * delta_.nanColours;
    stats.indicesOutOfRange += (n - 1) * delta_.indicesOutOfRange;
    return index;
  }

 private:
  const RenderSettings& settings_;
  bool valid_ = false;
  Rgb last_{};
  int index_ = 0;
  TraceStats delta_;
};

// A tracer for one pixel's primary rays; when the primary-ray mask says no
// ray of the pixel can meet an object box, each ray is what castRay returns
// for a ray that meets nothing (counted, background), without tracing it.
template <class Tracer>
struct PixelTracer {
  const Tracer& tracer;
  bool certainMiss;
  PixelKey key;  // the pixel's random numbers (the thesis profile's soft shadows)
  Rgb trace(const Ray& ray, int sample, TraceStats& stats) const {
    if constexpr (std::is_same_v<Tracer, TracerThesis>)
      return tracer.castRay(ray, 0, stats, SampleId{key, sample});
    else
      return tracer.castRay(ray, 0, stats);
  }
  Rgb castRay(const Ray& ray, int sample, TraceStats& stats) const {
    return certainMiss ? background(stats) : trace(ray, sample, stats);
  }
  // The listing's one ray per pixel; a masked pixel does not even need the ray.
  Rgb castPrimary(const PrimeCamera& camera, int i, int j, TraceStats& stats) const {
    return certainMiss ? background(stats) : trace(camera.primaryRay(i, j), 0, stats);
  }
  Rgb background(TraceStats& stats) const { return maskedPrimaryRay(tracer.scene(), stats); }
};

// One profile's render: each row's pixels through the sampler, traced by
// `tracer` (rays the mask rules out get the background untraced), then
// ColorNum'ed into the graph file.
template <class Tracer>
void renderWith(const Tracer& tracer, const PrimeCamera& camera,
                const std::optional<PrimaryRayMask>& mask, const RenderSettings& settings,
                const RenderCallbacks& callbacks, RenderResult& result) {
  const int rows = camera.rows(), columns = camera.columns();
  const int threads = threadCount(settings.threads, rows);
  struct alignas(kCacheLine) PerThread {  // a cache line of its own (kCacheLine)
    TraceStats stats;
    PaletteIndexCache indexOf;
    std::optional<SampleLattice> lattice;
    std::uint64_t samples = 0;
  };
  std::optional<MeanBound> bounds;  // statistical supersampling's stopping rule
  if (settings.sampling.mode == Sampling::Mode::Statistical) bounds.emplace(settings.sampling);
  std::vector<PerThread> perThread;
  perThread.reserve(threads);
  for (int t = 0; t < threads; ++t) {
    perThread.push_back({TraceStats{}, PaletteIndexCache(settings), std::nullopt, 0});
    if (settings.sampling.mode == Sampling::Mode::Adaptive)
      perThread.back().lattice.emplace(SampleLattice::levelsFor(settings.sampling));
  }

  // In Single mode a masked pixel is its one primary ray's background, so a
  // row's masked columns are filled run by run: what castPrimary and the
  // index cache give each of them, the same colour, index and counts.
  const bool fillMaskedRuns =
      settings.sampling.mode == Sampling::Mode::Single && mask && mask->masks();
  const auto& bg = tracer.scene().background;
  const Rgb background{bg[0], bg[1], bg[2]};
  auto fillBackground = [&](int i, int j0, int j1, PerThread& local) {
    if (j0 >= j1) return;
    checkAbort(callbacks.abort);  // R9
    const auto n = static_cast<std::uint64_t>(j1 - j0);
    local.stats.primaryRays += n;
    local.stats.maskedPrimaryRays += n;
    if (settings.keepColours)
      for (int j = j0; j < j1; ++j) result.rgb.at(i, j) = background;
    const auto index =
        static_cast<std::int16_t>(local.indexOf.getRepeated(background, n, local.stats));
    std::int16_t* row = &result.graph.pixels[static_cast<std::size_t>(i) * columns];
    std::fill(row + j0, row + j1, index);
  };

  auto renderRowWork = [&](int i, int thread) -> std::uint64_t {
    PerThread& local = perThread[thread];
    TraceStats& stats = local.stats;
    const std::uint64_t raysBefore = stats.rays();
    SampleLattice* lattice = local.lattice ? &*local.lattice : nullptr;
    if (fillMaskedRuns) {
      int j = 0;
      for (const PrimaryRayMask::Run& run : mask->runs(i)) {
        fillBackground(i, j, run.c0, local);
        // Single mode's samplePixel is castPrimary; called directly (one
        // pixel function shared with the loop below measured 2-4 % slower).
        for (j = run.c0; j <= run.c1; ++j) {
          checkAbort(callbacks.abort);  // R9
          const PixelKey key{settings.sampling.seed, static_cast<std::uint32_t>(i),
                             static_cast<std::uint32_t>(j)};
          const PixelTracer<Tracer> pixel{tracer, false, key};
          const Rgb color = pixel.castPrimary(camera, i, j, stats);
          if (settings.keepColours) result.rgb.at(i, j) = color;
          result.graph.pixels[static_cast<std::size_t>(i) * columns + j] =
              static_cast<std::int16_t>(local.indexOf.get(color, stats));
        }
      }
      fillBackground(i, j, columns, local);
      return stats.rays() - raysBefore;
    }
    for (int j = 0; j < columns; ++j) {
      checkAbort(callbacks.abort);  // R9
      const PixelKey key{settings.sampling.seed, static_cast<std::uint32_t>(i),
                         static_cast<std::uint32_t>(j)};
      const PixelTracer<Tracer> pixel{tracer, mask && !mask->mayHit(i, j), key};
      int taken = 0;
      const Rgb color = samplePixel(
          settings.sampling, lattice, key, bounds ? &*bounds : nullptr,
          [&] { return pixel.castPrimary(camera, i, j, stats); },
          [&](double fx, double fy, int k) {
            return pixel.castRay(camera.sampleRay(i, j, fx, fy), k, stats);
          },
          &taken);
      if (settings.sampling.mode != Sampling::Mode::Single)
        local.samples += static_cast<std::uint64_t>(taken);
      if (settings.keepColours) result.rgb.at(i, j) = color;
      // fwrite(&color, sizeof(int)): the raw 16-bit value (Q12).
      result.graph.pixels[static_cast<std::size_t>(i) * columns + j] =
          static_cast<std::int16_t>(local.indexOf.get(color, stats));
    }
    return stats.rays() - raysBefore;
  };

  // keepRowStats: each row's counts (the 1991 pace's cost of a row); a row
  // is one thread's, so each entry is written once.
  std::vector<TraceStats>* const rowStats = settings.rowStats;
  if (rowStats) rowStats->assign(static_cast<std::size_t>(rows), TraceStats{});
  auto renderRow = [&](int i, int thread) -> std::uint64_t {
    if (!rowStats) return renderRowWork(i, thread);
    const TraceStats before = perThread[thread].stats;
    const std::uint64_t rays = renderRowWork(i, thread);
    (*rowStats)[static_cast<std::size_t>(i)] = perThread[thread].stats - before;
    return rays;
  };

  RowCallbacks rowCallbacks;
  rowCallbacks.progress = callbacks.progress;
  rowCallbacks.abort = callbacks.abort;
  rowCallbacks.first = callbacks.firstRow;  // row i is the picture's row i from the top
  rowCallbacks.last = callbacks.lastRow;
  if (callbacks.rowDone)
    rowCallbacks.rowDone = [&](int i) {
      const auto* first = &result.graph.pixels[static_cast<std::size_t>(i) * columns];
      callbacks.rowDone(i, std::span<const std::int16_t>(first, static_cast<std::size_t>(columns)));
    };
  const RowsRun run = renderRows(rows, threads, renderRow, rowCallbacks);
  for (const PerThread& t : perThread) {
    result.stats += t.stats;
    result.samples += t.samples;
  }
  result.threads = run.threads;
  result.aborted = run.aborted;
  result.rowsDone = run.rowsDone;
  result.rows = run.rows;
}

}  // namespace

RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const RenderCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  const PrimeCamera camera(settings.camera);
  const int rows = camera.rows(), columns = camera.columns();

  RenderResult result;
  result.graph.graphType = static_cast<std::int16_t>(settings.graphType);
  result.graph.numPixAcross = static_cast<std::int16_t>(camera.numPixAcross());
  result.graph.numPixDown = static_cast<std::int16_t>(camera.numPixDown());
  result.graph.inclusive = true;
  result.graph.pixels.assign(static_cast<std::size_t>(rows) * columns, std::int16_t{0});
  if (settings.keepColours) result.rgb.assign(columns, rows);

  // Only the chosen profile's tracer is built. The 1991 profile tests boxes
  // only when it skips work (else it searches obj/List linearly, as the
  // listing did); the modern one always does.
  if (settings.profile == Profile::Thesis) {
    const TracerThesis tracer(scene, settings.trace, settings.thesis);
    renderWith(tracer, camera, primaryMaskFor(tracer, camera), settings, callbacks, result);
  } else if (settings.profile == Profile::Modern) {
    const TracerModern tracer(scene, settings.trace);
    renderWith(tracer, camera, primaryMaskFor(tracer, camera), settings, callbacks, result);
  } else {
    const Tracer1991 tracer(scene, settings.trace);
    renderWith(tracer, camera, primaryMaskFor(tracer, camera), settings, callbacks, result);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace prime
