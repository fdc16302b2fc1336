#include "src/render/render_rows.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <pthread.h>
#include <sched.h>
#define PRIME_THREAD_CPUS 1
#endif
#include <ctime>

namespace prime {

ThreadLoad& ThreadLoad::operator+=(const ThreadLoad& o) {
  rows += o.rows;
  cpuSeconds += o.cpuSeconds;
  if (cpuFirst < 0) cpuFirst = o.cpuFirst;
  migrated = migrated || o.migrated || (cpuLast >= 0 && o.cpuFirst >= 0 && o.cpuFirst != cpuLast);
  if (o.cpuLast >= 0) cpuLast = o.cpuLast;
  return *this;
}

namespace {

double threadCpuSeconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) return 0.0;
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

int currentCpu() {
#ifdef PRIME_THREAD_CPUS
  return sched_getcpu();
#else
  return -1;
#endif
}

// The CPUs this process may run on, in order (empty: the system does not say).
std::vector<int> allowedCpus() {
  std::vector<int> cpus;
#ifdef PRIME_THREAD_CPUS
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0)
    for (int c = 0; c < CPU_SETSIZE; ++c)
      if (CPU_ISSET(c, &set)) cpus.push_back(c);
#endif
  return cpus;
}

// Pins the calling thread to `cpu`; false when the system refuses.
bool pinTo(int cpu) {
#ifdef PRIME_THREAD_CPUS
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
#else
  (void)cpu;
  return false;
#endif
}

}  // namespace

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

  std::vector<ThreadLoad> loads(static_cast<std::size_t>(run.threads));
  const std::vector<int> cpus =
      callbacks.threads && callbacks.threads->pin ? allowedCpus() : std::vector<int>{};
  const std::thread::id caller = std::this_thread::get_id();
  auto worker = [&](int thread) {
    ThreadLoad* const load = callbacks.threads ? &loads[static_cast<std::size_t>(thread)] : nullptr;
    if (!cpus.empty() && std::this_thread::get_id() != caller)  // never the caller's own thread
      pinTo(cpus[static_cast<std::size_t>(thread) % cpus.size()]);
    const double cpu0 = load ? threadCpuSeconds() : 0.0;
    if (load) load->cpuFirst = load->cpuLast = currentCpu();
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
      if (load) {
        ++load->rows;
        const int cpu = currentCpu();
        load->migrated = load->migrated || cpu != load->cpuLast;
        load->cpuLast = cpu;
      }
      bool last = false;
      {
        std::lock_guard lock(mutex);
        finished.push_back(row);
        last = ++rowsDone == bandRows;
      }
      if (last) wake.notify_all();
    }
    if (load) load->cpuSeconds = threadCpuSeconds() - cpu0;
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
  if (callbacks.threads) {
    std::vector<ThreadLoad>& sum = callbacks.threads->loads;
    if (sum.size() < loads.size()) sum.resize(loads.size());
    for (std::size_t k = 0; k < loads.size(); ++k) sum[k] += loads[k];
  }

  run.rowsDone = rowsDone.load();
  run.rows = bandRows;
  run.aborted = run.rowsDone < bandRows;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

bool runBlockRows(int height, int block, int threads, const std::atomic<bool>* abandon,
                  const std::function<void(int row0, int rows)>& rowsDone,
                  const std::function<std::uint64_t(int blockRow, int thread)>& renderRow,
                  ThreadReport* report) {
  const int blockRows = (height + block - 1) / block;
  RowCallbacks cb;
  cb.abort = abandon;
  cb.threads = report;
  if (rowsDone)
    cb.rowDone = [&](int br) {
      const int y0 = br * block;
      rowsDone(y0, std::min(height, y0 + block) - y0);
    };
  return !renderRows(blockRows, threads, renderRow, cb).aborted;
}

}  // namespace prime
