// The one row scheduler of every system: rows handed out to a pool of
// threads, progress reported on the calling thread, an abort flag honoured
// between rows, and the first exception stopping everyone and rethrown.
// Each row is rendered by exactly one call and writes only its own pixels,
// so the picture is the same bytes for any thread count.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace prime {

struct RowCallbacks {
  // Called on the calling thread about five times a second and once at the end.
  std::function<void(int rowsDone, int rows, std::uint64_t raysSoFar)> progress;
  // Called on the calling thread for every finished row, in no fixed order.
  std::function<void(int row)> rowDone;
  // Set by anyone (Esc, Ctrl-C): no new row is started.
  const std::atomic<bool>* abort = nullptr;
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

// Calls renderRow(row, thread) once for every row 0..rows-1 on
// threadCount(threads, rows) threads; `thread` (0..threads-1) indexes the
// caller's per-thread state (statistics, caches). renderRow returns the rays
// it cast, for progress. The first exception stops all threads and is
// rethrown here.
RowsRun renderRows(int rows, int threads,
                   const std::function<std::uint64_t(int row, int thread)>& renderRow,
                   const RowCallbacks& callbacks = {});

}  // namespace prime
