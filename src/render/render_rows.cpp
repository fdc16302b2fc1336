#include "src/render/render_rows.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "src/render/progressive.h"

namespace prime {

int startThreads(std::vector<std::thread>& pool, int count, const std::function<void(int)>& fn) {
  pool.reserve(pool.size() + static_cast<std::size_t>(std::max(0, count)));
  int started = 0;
  for (; started < count; ++started) {
    try {
      pool.emplace_back(fn, started);
    } catch (const std::system_error&) {
      break;  // the system has no more threads for us: go on with those running
    }
  }
  return started;
}

int threadCount(int requested, int rows) {
  int threads = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
  return std::max(1, std::min(threads, rows));
}

RowsRun renderRows(int rows, int threads,
                   const std::function<std::uint64_t(int row, int thread)>& renderRow,
                   const RowCallbacks& callbacks) {
  const auto start = std::chrono::steady_clock::now();
  // A band (the rows first .. last of a picture rendered in pieces): only
  // those rows, each by the same call as in the whole picture.
  const int first = std::clamp(callbacks.first, 0, rows);
  const int end = callbacks.last < 0 ? rows : std::clamp(callbacks.last + 1, first, rows);
  const int bandRows = end - first;
  RowsRun run;
  run.threads = threadCount(threads, bandRows);

  std::atomic<int> nextRow{first}, rowsDone{0};
  std::atomic<std::uint64_t> raysSoFar{0};
  std::mutex mutex;  // guards the finished-row queue and the first error
  std::condition_variable
      wake;  // the last row is done, or an error: no need to sleep out the 200 ms
  std::vector<int> finished;
  std::exception_ptr error;

  auto worker = [&](int thread) {
    for (;;) {
      if (callbacks.abort && callbacks.abort->load()) break;
      const int row = nextRow.fetch_add(1);
      if (row >= end) break;
      try {
        raysSoFar += renderRow(row, thread);
      } catch (const RowAborted&) {
        break;  // the abort flag is set: the row is left unfinished
      } catch (...) {
        {
          std::lock_guard lock(mutex);
          if (!error) error = std::current_exception();
          nextRow = end;  // stop everyone
        }
        wake.notify_all();
        break;
      }
      bool last = false;
      {
        std::lock_guard lock(mutex);
        finished.push_back(row);
        last = ++rowsDone == bandRows;
      }
      if (last) wake.notify_all();
    }
  };

  std::vector<std::thread> pool;
  const int started = startThreads(pool, run.threads, worker);
  if (started == 0) worker(0);  // not even one thread: the rows on this one
  run.threads = std::max(1, started);

  // Finished rows go to rowDone every 25 ms (a window shows them, trace
  // writes them to its file while the render goes on); progress about five
  // times a second, and once at the end.
  auto lastProgress = std::chrono::steady_clock::now();
  auto report = [&](bool final) {
    std::vector<int> rowsNow;
    {
      std::lock_guard lock(mutex);
      rowsNow.swap(finished);
    }
    if (callbacks.rowDone)
      for (int row : rowsNow) callbacks.rowDone(row);
    const auto now = std::chrono::steady_clock::now();
    if (callbacks.progress && (final || now - lastProgress >= std::chrono::milliseconds(200))) {
      lastProgress = now;
      callbacks.progress(rowsDone.load(), bandRows, raysSoFar.load());
    }
  };
  auto stop = [&] {
    return rowsDone.load() >= bandRows || error || (callbacks.abort && callbacks.abort->load());
  };
  for (;;) {
    {
      std::unique_lock lock(mutex);
      if (stop()) break;
      wake.wait_for(lock, std::chrono::milliseconds(25), stop);
      if (stop()) break;
    }
    report(false);
  }
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  report(true);

  run.aborted = rowsDone.load() < bandRows;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

bool progressivePass(int width, int height, int block, int firstBlock, int threads,
                     const std::atomic<bool>* abandon,
                     const std::function<void(int row0, int rows)>& rowsDone,
                     const std::function<Rgb(int row, int column, int thread)>& sample,
                     RgbImage& out) {
  const int blockRows = (height + block - 1) / block;
  auto renderRow = [&](int br, int thread) -> std::uint64_t {
    std::uint64_t sampled = 0;
    const int y0 = br * block, y1 = std::min(height, y0 + block);
    for (int x0 = 0; x0 < width; x0 += block) {
      if (!sampledInEarlierPass(y0, x0, block, firstBlock)) {
        out.at(y0, x0) = sample(y0, x0, thread);
        ++sampled;
      }
      const Rgb c = out.at(y0, x0);
      const int x1 = std::min(width, x0 + block);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) out.at(y, x) = c;
    }
    return sampled;
  };
  RowCallbacks cb;
  cb.abort = abandon;
  if (rowsDone)
    cb.rowDone = [&](int br) {
      const int y0 = br * block;
      rowsDone(y0, std::min(height, y0 + block) - y0);
    };
  return !renderRows(blockRows, threads, renderRow, cb).aborted;
}

}  // namespace prime
