#include "src/prime/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "palette/prime/color_num.h"
#include "src/prime/render/primary_mask.h"
#include "src/prime/render/tracer_modern.h"

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

 private:
  const RenderSettings& settings_;
  bool valid_ = false;
  Rgb last_{};
  int index_ = 0;
  TraceStats delta_;
};

Rgb average(const Rgb* c, int n) {
  Rgb sum{};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) sum[k] += c[i][k];
  for (auto& v : sum) v /= n;
  return sum;
}

double spread(const Rgb* c, int n) {
  double d = 0.0;
  for (int k = 0; k < 3; ++k) {
    double lo = c[0][k], hi = c[0][k];
    for (int i = 1; i < n; ++i) {
      lo = std::min(lo, c[i][k]);
      hi = std::max(hi, c[i][k]);
    }
    d = std::max(d, hi - lo);
  }
  return d;
}

// The colours of one pixel's adaptive samples, by lattice point. The
// squares of Whitted's subdivision share points: a child's corners are its
// parent's corners, centre and edge midpoints. Every offset is a multiple of
// 2^-(maxLevel+1) pixel, exact in binary, so the same point always gives the
// same ray and the same colour: each is traced once per pixel.
class SampleLattice {
 public:
  explicit SampleLattice(int maxLevel)
      : scale_(static_cast<double>(1 << (maxLevel + 1))),
        side_((1 << (maxLevel + 1)) + 1),
        stamp_(static_cast<std::size_t>(side_) * side_, 0),
        colour_(stamp_.size()) {}
  void nextPixel() { ++generation_; }
  // The colour at offset (fx, fy), traced by `trace` the first time.
  template <class Trace>
  Rgb at(double fx, double fy, Trace&& trace) {
    const double u = (fx + 0.5) * scale_, v = (fy + 0.5) * scale_;
    if (!(u >= 0.0 && v >= 0.0 && u < side_ && v < side_) || u != std::floor(u) ||
        v != std::floor(v))
      return trace();  // not a lattice point (cannot happen for the subdivision)
    const std::size_t k =
        static_cast<std::size_t>(v) * static_cast<std::size_t>(side_) + static_cast<std::size_t>(u);
    if (stamp_[k] != generation_) {
      colour_[k] = trace();
      stamp_[k] = generation_;
    }
    return colour_[k];
  }

 private:
  double scale_;
  int side_;
  std::uint32_t generation_ = 1;
  std::vector<std::uint32_t> stamp_;
  std::vector<Rgb> colour_;
};

// Whitted's adaptive supersampling over the square centred at (fx, fy) with
// half-width h, in pixel steps.
template <class Tracer>
Rgb adaptive(const Tracer& tracer, const ListingCamera& camera, int i, int j, double fx, double fy,
             double h, int level, const Sampling& s, TraceStats& stats, SampleLattice& lattice) {
  Rgb c[5];
  const double off[5][2] = {{0, 0}, {-h, -h}, {h, -h}, {-h, h}, {h, h}};
  for (int k = 0; k < 5; ++k) {
    const double x = fx + off[k][0], y = fy + off[k][1];
    c[k] = lattice.at(x, y, [&] { return tracer.castRay(camera.sampleRay(i, j, x, y), 0, stats); });
  }
  if (level >= s.maxLevel || !(spread(c, 5) > s.tolerance)) return average(c, 5);
  Rgb q[4];
  for (int k = 0; k < 4; ++k)
    q[k] = adaptive(tracer, camera, i, j, fx + off[k + 1][0] / 2, fy + off[k + 1][1] / 2, h / 2,
                    level + 1, s, stats, lattice);
  return average(q, 4);
}

// A tracer for one pixel's primary rays; when the primary-ray mask says no
// ray of the pixel can meet an object box, each ray is what castRay returns
// for a ray that meets nothing (counted, background), without tracing it.
template <class Tracer>
struct PixelTracer {
  const Tracer& tracer;
  bool certainMiss;
  Rgb castRay(const Ray& ray, int depth, TraceStats& stats) const {
    return certainMiss ? background(stats) : tracer.castRay(ray, depth, stats);
  }
  // The listing's one ray per pixel; a masked pixel does not even need the ray.
  Rgb castPrimary(const ListingCamera& camera, int i, int j, TraceStats& stats) const {
    return certainMiss ? background(stats) : tracer.castRay(camera.primaryRay(i, j), 0, stats);
  }
  Rgb background(TraceStats& stats) const {
    ++stats.primaryRays;
    ++stats.maskedPrimaryRays;
    const auto& b = tracer.scene().background;
    return {b[0], b[1], b[2]};
  }
};

template <class Tracer>
Rgb pixelColour(const Tracer& tracer, const ListingCamera& camera, int i, int j, const Sampling& s,
                TraceStats& stats, SampleLattice* lattice) {
  switch (s.mode) {
    case Sampling::Mode::Single:
      return tracer.castPrimary(camera, i, j, stats);
    case Sampling::Mode::Grid: {
      Rgb sum{};
      const int n = std::max(1, s.gridN);
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const Rgb c = tracer.castRay(
              camera.sampleRay(i, j, (b + 0.5) / n - 0.5, (a + 0.5) / n - 0.5), 0, stats);
          for (int k = 0; k < 3; ++k) sum[k] += c[k];
        }
      for (auto& v : sum) v /= n * n;
      return sum;
    }
    case Sampling::Mode::Adaptive:
      lattice->nextPixel();
      return adaptive(tracer, camera, i, j, 0.0, 0.0, 0.5, 0, s, stats, *lattice);
  }
  return {};
}

}  // namespace

RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const RenderCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  const ListingCamera camera(settings.camera);
  const bool modern = settings.profile == Profile::Modern;
  std::optional<Tracer1991> tracer1991;
  std::optional<TracerModern> tracerModern;
  if (modern)
    tracerModern.emplace(scene, settings.trace);
  else
    tracer1991.emplace(scene, settings.trace);
  // The 1991 profile tests boxes only when it skips work (else it searches
  // obj/List linearly, as the listing did); the modern one always does.
  std::optional<PrimaryRayMask> mask;
  if (modern)
    mask.emplace(camera, tracerModern->bvh().objectBoxes());
  else if (settings.trace.skipUnneededWork)
    mask.emplace(camera, tracer1991->primaryMaskBoxes());
  const int rows = camera.rows(), columns = camera.columns();

  RenderResult result;
  result.graph.graphType = static_cast<std::int16_t>(settings.graphType);
  result.graph.numPixAcross = static_cast<std::int16_t>(camera.numPixAcross());
  result.graph.numPixDown = static_cast<std::int16_t>(camera.numPixDown());
  result.graph.inclusive = true;
  result.graph.pixels.assign(static_cast<std::size_t>(rows) * columns, 0);
  if (settings.keepColours) result.rgb.assign(result.graph.pixels.size(), Rgb{});

  int threads = settings.threads > 0 ? settings.threads
                                     : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min(threads, rows));
  result.threads = threads;

  std::atomic<int> nextRow{0}, rowsDone{0};
  std::atomic<std::uint64_t> raysSoFar{0};
  std::mutex mutex;  // guards the shared counters, the finished-row queue and the first error
  std::condition_variable
      wake;  // the last row is done, or an error: no need to sleep out the 200 ms
  TraceStats total;
  std::vector<int> finished;
  std::exception_ptr error;

  auto worker = [&] {
    TraceStats local;
    PaletteIndexCache indexOf(settings);
    std::optional<SampleLattice> lattice;
    if (settings.sampling.mode == Sampling::Mode::Adaptive)
      lattice.emplace(std::clamp(settings.sampling.maxLevel, 0, 6));  // deeper: traced uncached
    SampleLattice* samples = lattice ? &*lattice : nullptr;
    std::uint64_t raysReported = 0;
    for (;;) {
      if (callbacks.abort && callbacks.abort->load()) break;
      const int i = nextRow.fetch_add(1);
      if (i >= rows) break;
      try {
        for (int j = 0; j < columns; ++j) {
          const std::size_t at = static_cast<std::size_t>(i) * columns + j;
          const bool miss = mask && !mask->mayHit(i, j);
          const Rgb color = modern ? pixelColour(PixelTracer<TracerModern>{*tracerModern, miss},
                                                 camera, i, j, settings.sampling, local, samples)
                                   : pixelColour(PixelTracer<Tracer1991>{*tracer1991, miss}, camera,
                                                 i, j, settings.sampling, local, samples);
          if (settings.keepColours) result.rgb[at] = color;
          // fwrite(&color, sizeof(int)): the raw 16-bit value (Q12).
          result.graph.pixels[at] = static_cast<std::int16_t>(indexOf.get(color, local));
        }
      } catch (...) {
        {
          std::lock_guard lock(mutex);
          if (!error) error = std::current_exception();
          nextRow = rows;  // stop everyone
        }
        wake.notify_all();
        break;
      }
      raysSoFar += local.rays() - raysReported;
      raysReported = local.rays();
      bool last = false;
      {
        std::lock_guard lock(mutex);
        finished.push_back(i);
        last = ++rowsDone == rows;
      }
      if (last) wake.notify_all();
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
  auto stop = [&] {
    return rowsDone.load() >= rows || error || (callbacks.abort && callbacks.abort->load());
  };
  for (;;) {
    {
      std::unique_lock lock(mutex);
      if (stop()) break;
      wake.wait_for(lock, std::chrono::milliseconds(200), stop);
      if (stop()) break;
    }
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
