// Interactive rendering for any system (`prime walk`): the picture is
// rendered in passes from coarse to fine (blocks of 8, 4, 2, then 1 pixel,
// each block filled with the colour of the ray through its top-left pixel, so
// every pass is a whole picture at once), and a newer request abandons the
// frame in flight (LatestJobRunner). Nothing here knows a system.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

namespace prime {

// The passes' block sizes, coarse to fine: 8, 4, 2, 1 (T38).
inline constexpr int kProgressiveBlocks[] = {8, 4, 2, 1};

// Whether pass `block` can reuse (row, column)'s colour from the pass before:
// its top-left pixel was sampled there when it lies on that pass's grid
// (every 2 * block pixels); the first pass (firstBlock) samples everything.
inline bool sampledInEarlierPass(int row, int column, int block, int firstBlock) {
  return block < firstBlock && row % (2 * block) == 0 && column % (2 * block) == 0;
}

// One worker thread that runs `job` for the latest request only. A request
// made while a job runs sets that job's `abandon` flag (the job should
// return soon: renderRows stops between rows) and the worker then starts the
// newest request; requests made meanwhile are skipped, never queued.
template <class Request>
class LatestJobRunner {
 public:
  using Job = std::function<void(const Request&, std::uint64_t generation,
                                 const std::atomic<bool>& abandon)>;

  explicit LatestJobRunner(Job job) : job_(std::move(job)), worker_([this] { loop(); }) {}
  ~LatestJobRunner() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
      abandon_ = true;
    }
    wake_.notify_all();
    worker_.join();
  }
  LatestJobRunner(const LatestJobRunner&) = delete;
  LatestJobRunner& operator=(const LatestJobRunner&) = delete;

  // Any thread: render `r` next, abandoning what runs now. Returns its generation (1, 2, ...).
  std::uint64_t request(Request r) {
    std::uint64_t g;
    {
      std::lock_guard lock(mutex_);
      pending_ = std::move(r);
      g = ++requested_;
      abandon_ = true;
    }
    wake_.notify_all();
    return g;
  }
  // Waits until the latest request's job has returned (or thrown: rethrown here).
  void waitIdle() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [&] { return finished_ == requested_ || error_; });
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }
  // The generation of the last job that ran to its end without being abandoned.
  std::uint64_t completed() const {
    std::lock_guard lock(mutex_);
    return completed_;
  }

 private:
  void loop() {
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || started_ != requested_; });
      if (stop_) return;
      const Request r = pending_;
      const std::uint64_t g = started_ = requested_;
      abandon_ = false;
      lock.unlock();
      std::exception_ptr error;
      try {
        job_(r, g, abandon_);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      if (error) error_ = error;
      if (!abandon_ && !error) completed_ = g;
      finished_ = g;
      idle_.notify_all();
    }
  }

  Job job_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, idle_;
  Request pending_{};
  std::uint64_t requested_ = 0, started_ = 0, finished_ = 0, completed_ = 0;
  std::atomic<bool> abandon_{false};
  bool stop_ = false;
  std::exception_ptr error_;
  std::thread worker_;  // last: starts once everything above exists
};

}  // namespace prime
