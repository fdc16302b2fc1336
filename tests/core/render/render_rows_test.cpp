// The shared row scheduler: every row rendered once, the same picture for
// any thread count, the first error rethrown, abort honoured.
#include "src/render/render_rows.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace prime {
namespace {

std::vector<std::uint64_t> renderPicture(int rows, int threads, std::vector<int>* calls = nullptr) {
  std::vector<std::uint64_t> picture(static_cast<std::size_t>(rows) * 7, 0);
  std::vector<std::atomic<int>> counts(static_cast<std::size_t>(rows));
  const RowsRun run = renderRows(rows, threads, [&](int row, int thread) -> std::uint64_t {
    EXPECT_GE(thread, 0);
    EXPECT_LT(thread, threadCount(threads, rows));
    for (int x = 0; x < 7; ++x)
      picture[static_cast<std::size_t>(row) * 7 + x] = static_cast<std::uint64_t>(row) * 1000 + x;
    ++counts[static_cast<std::size_t>(row)];
    return 7;
  });
  EXPECT_FALSE(run.aborted);
  EXPECT_EQ(run.threads, threadCount(threads, rows));
  if (calls)
    for (auto& c : counts) calls->push_back(c.load());
  return picture;
}

TEST(RenderRows, EveryRowOnceAndTheSamePictureForAnyThreadCount) {
  std::vector<int> calls;
  const auto one = renderPicture(97, 1, &calls);
  for (int c : calls) EXPECT_EQ(c, 1);
  for (int threads : {2, 3, 8, 200}) EXPECT_EQ(renderPicture(97, threads), one) << threads;
  EXPECT_EQ(one[96 * 7 + 6], 96006u);
}

// The benchmark's thread report: each thread's rows add up to the picture's,
// each thread counts CPU time of its own, and the sums grow run by run.
TEST(RenderRows, ThreadReportCountsEachThreadsRowsAndCpu) {
  for (const bool pin : {false, true}) {
    ThreadReport report;
    report.pin = pin;
    RowCallbacks cb;
    cb.threads = &report;
    std::atomic<int> work{0};
    const RowsRun run = renderRows(
        40, 3,
        [&](int, int) -> std::uint64_t {
          const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(2);
          while (std::chrono::steady_clock::now() < until) ++work;  // CPU, not sleep
          return 1;
        },
        cb);
    ASSERT_EQ(report.loads.size(), static_cast<std::size_t>(run.threads)) << pin;
    int rows = 0;
    double cpu = 0;
    for (const ThreadLoad& l : report.loads) {
      rows += l.rows;
      cpu += l.cpuSeconds;
      EXPECT_GE(l.cpuSeconds, 0.0);
#ifdef __linux__
      EXPECT_GE(l.cpuFirst, 0) << "sched_getcpu names the CPU on Linux";
#endif
    }
    EXPECT_EQ(rows, 40) << pin;
    EXPECT_GT(cpu, 0.040) << "40 rows of 2 ms of CPU each";
    // A second run adds to the same report.
    renderRows(
        10, 3, [](int, int) -> std::uint64_t { return 1; }, cb);
    rows = 0;
    for (const ThreadLoad& l : report.loads) rows += l.rows;
    EXPECT_EQ(rows, 50) << pin;
  }
}

TEST(RenderRows, ThreadCountNeverExceedsTheRows) {
  EXPECT_EQ(threadCount(8, 3), 3);
  EXPECT_EQ(threadCount(2, 100), 2);
  EXPECT_GE(threadCount(0, 100), 1);
  EXPECT_EQ(threadCount(4, 0), 1);
}

TEST(RenderRows, ProgressAndRowDoneOnTheCallingThreadWithAllRaysCounted) {
  RowCallbacks cb;
  std::set<int> done;
  std::uint64_t lastRays = 0;
  int lastDone = 0;
  cb.rowDone = [&](int row) { EXPECT_TRUE(done.insert(row).second) << "row " << row << " twice"; };
  cb.progress = [&](int rowsDone, int rows, std::uint64_t rays) {
    EXPECT_EQ(rows, 50);
    lastDone = rowsDone;
    lastRays = rays;
  };
  renderRows(
      50, 4, [](int row, int) -> std::uint64_t { return static_cast<std::uint64_t>(row); }, cb);
  EXPECT_EQ(done.size(), 50u);
  EXPECT_EQ(lastDone, 50);
  EXPECT_EQ(lastRays, 49u * 50u / 2u);
}

TEST(RenderRows, TheFirstErrorStopsTheRenderAndIsRethrown) {
  std::atomic<int> started{0};
  EXPECT_THROW(renderRows(1000, 2,
                          [&](int row, int) -> std::uint64_t {
                            ++started;
                            if (row == 3) throw std::runtime_error("row 3 failed");
                            // Rows take a while, so the other thread cannot finish
                            // all 1000 before the error reaches it (under a
                            // sanitizer, empty rows sometimes did: a flaky test).
                            std::this_thread::sleep_for(std::chrono::microseconds(200));
                            return 0;
                          }),
               std::runtime_error);
  EXPECT_LT(started.load(), 1000);
}

TEST(RenderRows, AbortStopsBeforeTheLastRow) {
  std::atomic<bool> abort{false};
  RowCallbacks cb;
  cb.abort = &abort;
  std::atomic<int> rendered{0};
  const RowsRun run = renderRows(
      10000, 2,
      [&](int, int) -> std::uint64_t {
        if (++rendered == 10) abort = true;
        return 0;
      },
      cb);
  EXPECT_TRUE(run.aborted);
  EXPECT_LT(rendered.load(), 10000);
}

// R9: an abort inside a row stops it within a pixel. One row of "pixels"
// that would take 1000 s (a million pixels of 1 ms); the flag is set from
// another thread after 50 ms. The run ends as aborted, the row is not
// reported done, and it took nowhere near the row's time.
TEST(RenderRows, AbortInsideARowStopsWithinAPixel) {
  std::atomic<bool> abort{false};
  RowCallbacks cb;
  cb.abort = &abort;
  std::atomic<int> done{0}, pixels{0};
  cb.rowDone = [&](int) { ++done; };
  std::thread setter([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    abort = true;
  });
  const auto start = std::chrono::steady_clock::now();
  const RowsRun run = renderRows(
      1, 1,
      [&](int, int) -> std::uint64_t {
        for (int x = 0; x < 1000000; ++x) {
          checkAbort(cb.abort);
          ++pixels;
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        return 0;
      },
      cb);
  setter.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(run.aborted);
  EXPECT_EQ(done.load(), 0);
  EXPECT_GT(pixels.load(), 0);
  EXPECT_LT(seconds, 10.0);  // (a loaded machine: 0.05 s expected)
}

TEST(RenderRows, CheckAbortThrowsOnlyWhenSet) {
  EXPECT_NO_THROW(checkAbort(nullptr));
  std::atomic<bool> flag{false};
  EXPECT_NO_THROW(checkAbort(&flag));
  flag = true;
  EXPECT_THROW(checkAbort(&flag), RowAborted);
}

// A band (prime trace --rows): exactly its rows, each once, on any number of
// threads; progress counts the band's rows; a band outside the picture is empty.
TEST(RenderRows, BandRendersOnlyItsRows) {
  for (const int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> calls(40);
    RowCallbacks cb;
    cb.first = 7;
    cb.last = 19;
    int lastDone = -1, lastTotal = -1;
    cb.progress = [&](int done, int total, std::uint64_t) {
      lastDone = done;
      lastTotal = total;
    };
    const RowsRun run = renderRows(
        40, threads,
        [&](int row, int) -> std::uint64_t {
          ++calls[static_cast<std::size_t>(row)];
          return 1;
        },
        cb);
    EXPECT_FALSE(run.aborted);
    for (int row = 0; row < 40; ++row)
      EXPECT_EQ(calls[static_cast<std::size_t>(row)].load(), row >= 7 && row <= 19 ? 1 : 0)
          << "row " << row << ", threads " << threads;
    EXPECT_EQ(lastDone, 13);
    EXPECT_EQ(lastTotal, 13);
  }
  RowCallbacks outside;
  outside.first = 50;
  int rendered = 0;
  const RowsRun run = renderRows(
      40, 2, [&](int, int) -> std::uint64_t { return ++rendered, 0; }, outside);
  EXPECT_EQ(rendered, 0);
  EXPECT_FALSE(run.aborted);
}

}  // namespace
}  // namespace prime
