// The one row scheduler of every system: rows handed out to a pool of
// threads, progress reported on the calling thread, an abort flag honoured
// between rows and, through checkAbort, between pixels (R9), and the first
// exception stopping everyone and rethrown.
// Each row is rendered by exactly one call and writes only its own pixels,
// so the picture is the same bytes for any thread count.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <thread>
#include <vector>

#include "src/render/rgb_image.h"

namespace prime {

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

// One pass of a walk's coarse-to-fine frame (src/render/progressive.h, T38)
// over the shared scheduler: for every block x block block of the width x
// height picture, sample(row, column, thread) gives the colour of its
// top-left pixel (unless an earlier pass sampled it: firstBlock is the
// frame's coarsest) and the block takes it. rowsDone(row0, rows) runs on
// the calling thread when picture rows row0 .. row0+rows-1 are final for this
// pass. Returns false when `abandon` stopped it. The last pass (block 1)
// samples each pixel once over the frame's passes.
bool progressivePass(int width, int height, int block, int firstBlock, int threads,
                     const std::atomic<bool>* abandon,
                     const std::function<void(int row0, int rows)>& rowsDone,
                     const std::function<Rgb(int row, int column, int thread)>& sample,
                     RgbImage& out);

}  // namespace prime
