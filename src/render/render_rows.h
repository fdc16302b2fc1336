// The one row scheduler of every system: rows handed out to a pool of
// threads, progress reported on the calling thread, an abort flag honoured
// between rows and, through checkAbort, between pixels (R9), and the first
// exception stopping everyone and rethrown.
// Each row is rendered by exactly one call and writes only its own pixels,
// so the picture is the same bytes for any thread count.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <thread>
#include <vector>

#include "src/render/progressive.h"
#include "src/render/rgb_image.h"

namespace prime {

// What one thread of a run did: for the benchmark's thread report (`prime
// walk --bench`), so that a slow thread, a thread that had no core of its
// own or one the system moved between CPUs shows.
struct ThreadLoad {
  int rows = 0;           // rows (or rows of blocks) it rendered
  double cpuSeconds = 0;  // its own CPU time (CLOCK_THREAD_CPUTIME_ID)
  int cpuFirst = -1;      // the CPU it started on (-1: the system does not say)
  int cpuLast = -1;       // the CPU it ended on
  bool migrated = false;  // seen on another CPU between rows
  ThreadLoad& operator+=(const ThreadLoad& o);
};

// Per-thread figures of one or more runs, and whether the threads are
// pinned: thread k to the k-th CPU this process may use (modulo their count).
struct ThreadReport {
  bool pin = false;
  std::vector<ThreadLoad> loads;  // index: the thread; summed over runs
};

struct RowCallbacks {
  // Called on the calling thread about five times a second and once at the end.
  std::function<void(int rowsDone, int rows, std::uint64_t raysSoFar)> progress;
  // Called on the calling thread for every finished row, in no fixed order,
  // within about 25 ms of its finishing.
  std::function<void(int row)> rowDone;
  // Set by anyone (Esc, Ctrl-C): no new row is started.
  const std::atomic<bool>* abort = nullptr;
  // Only rows first .. last (last < 0: to the end) are rendered: a band of a
  // picture rendered in pieces (`prime trace --rows`). The others are not
  // touched; progress counts the band's rows.
  int first = 0, last = -1;
  // When set: each thread's rows, CPU time and CPUs are added to it (and
  // the threads pinned when it says so).
  ThreadReport* threads = nullptr;
};

// Thrown by checkAbort inside a row: renderRows abandons the row (it is not
// finished: no rowDone, not counted) and ends the run as aborted.
struct RowAborted {};

// For a row's pixel loop (R9): one relaxed load per call, so Ctrl-C or Esc
// stops a render within one pixel instead of one row (a row of a heavy
// scene can take minutes). Throws RowAborted when `abort` is set.
inline void checkAbort(const std::atomic<bool>* abort) {
  if (abort && abort->load(std::memory_order_relaxed)) throw RowAborted{};
}

// The width of a cache line: each thread's own state (its statistics, its
// caches) starts on a line of its own, so that two threads writing their
// own counters never write the same line (false sharing cost up to 15 % of
// a two-thread render, depending on where the heap put the states).
inline constexpr std::size_t kCacheLine = 64;

// A per-thread slot for renderRow's `thread` index: std::vector<ThreadSlot<T>>.
template <class T>
struct alignas(kCacheLine) ThreadSlot {
  T value{};
};

// What a system's render() reports while it runs, for every system: progress,
// each finished row's pixels (PRIME's palette indices, Malone's and CGL's
// colours), and the abort flag it honours between rows.
template <class Pixel>
struct PictureCallbacks {
  // Called on the calling thread about five times a second and once at the end.
  std::function<void(int rowsDone, int rows, std::uint64_t raysSoFar)> progress;
  // Called on the calling thread for every finished row of the picture (from
  // its top), in no fixed order; the pixels stay where they are, unchanged,
  // until render() returns.
  std::function<void(int row, std::span<const Pixel> pixels)> rowDone;
  const std::atomic<bool>* abort = nullptr;
  // Only the picture's rows firstRow .. lastRow (from its top; lastRow < 0:
  // to the bottom) are rendered, each exactly as in the whole picture; the
  // others keep their initial value (`prime trace --rows`).
  int firstRow = 0, lastRow = -1;
};

struct RowsRun {
  double seconds = 0;
  int threads = 1;
  bool aborted = false;  // stopped by `abort` before the last row
  int rowsDone = 0;      // rows finished: all of the band's unless aborted
  int rows = 0;          // rows in the band
};

// Starts up to `count` threads running fn(0), fn(1), ... into `pool` and
// returns how many started: a system that refuses a thread (too many asked
// for) stops the starting, never the program. The caller joins them.
int startThreads(std::vector<std::thread>& pool, int count, const std::function<void(int)>& fn);

// Threads for `rows` rows: `requested`, or all cores for 0; never more than
// the rows, at least one.
int threadCount(int requested, int rows);

// Calls renderRow(row, thread) once for every row 0..rows-1 (or of the band
// callbacks.first .. last) on threadCount(threads, rows in the band) threads; `thread`
// (0..threads-1) indexes the caller's per-thread state (statistics, caches). renderRow returns the
// rays it cast, for progress. The first exception stops all threads and is rethrown here;
// RowAborted (checkAbort) only abandons its row.
RowsRun renderRows(int rows, int threads,
                   const std::function<std::uint64_t(int row, int thread)>& renderRow,
                   const RowCallbacks& callbacks = {});

// The rows of blocks of one progressive pass (progressivePass below) on the
// shared scheduler: renderRow(blockRow, thread) for each, rowsDone with the
// picture rows a finished block row covers. False when `abandon` stopped it.
bool runBlockRows(int height, int block, int threads, const std::atomic<bool>* abandon,
                  const std::function<void(int row0, int rows)>& rowsDone,
                  const std::function<std::uint64_t(int blockRow, int thread)>& renderRow,
                  ThreadReport* report);

// One pass of a walk's coarse-to-fine frame (src/render/progressive.h, T38)
// over the shared scheduler: for every block x block block of the width x
// height picture, sample(row, column, thread) gives the colour of its
// top-left pixel (unless an earlier pass sampled it: firstBlock is the
// frame's coarsest) and the block takes it. rowsDone(row0, rows) runs on
// the calling thread when picture rows row0 .. row0+rows-1 are final for this
// pass. Returns false when `abandon` stopped it. The last pass (block 1)
// samples each pixel once over the frame's passes. A template, so that a
// system's sample is called directly, not through a function object per
// pixel.
template <class Sample>
bool progressivePass(int width, int height, int block, int firstBlock, int threads,
                     const std::atomic<bool>* abandon,
                     const std::function<void(int row0, int rows)>& rowsDone, Sample&& sample,
                     RgbImage& out, ThreadReport* report = nullptr) {
  auto renderRow = [&](int br, int thread) -> std::uint64_t {
    std::uint64_t sampled = 0;
    const int y0 = br * block, y1 = std::min(height, y0 + block);
    for (int x0 = 0; x0 < width; x0 += block) {
      if (!sampledInEarlierPass(y0, x0, block, firstBlock)) {
        out.at(y0, x0) = sample(y0, x0, thread);
        ++sampled;
      }
      if (block == 1) continue;
      const Rgb c = out.at(y0, x0);
      const int x1 = std::min(width, x0 + block);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) out.at(y, x) = c;
    }
    return sampled;
  };
  return runBlockRows(height, block, threads, abandon, rowsDone, renderRow, report);
}

}  // namespace prime
