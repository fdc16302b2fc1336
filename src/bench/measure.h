// Timing and memory measurement for the benchmarks: process CPU time, medians,
// the machine's facts, and peak memory of work run in a child process.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace prime::bench {

// CPU time of the whole process (all threads), clock_gettime(CLOCK_PROCESS_CPUTIME_ID).
double processCpuSeconds();
// Monotonic wall-clock seconds.
double wallSeconds();

// Median (mean of the middle two for an even count); NaN for none.
double median(std::vector<double> values);

struct MachineFacts {
  int nproc = 0;
  std::string cpuModel;     // /proc/cpuinfo "model name"
  std::string kernel;       // uname -sr
  std::string loadAverage;  // /proc/loadavg, first three fields
  std::string compiler;     // __VERSION__
  std::string date;         // UTC, ISO 8601
};
MachineFacts machineFacts();

struct ChildRun {
  std::vector<double> values;  // what `work` returned
  long maxRssKb = 0;           // getrusage ru_maxrss of the child
};

// Forks; the child runs `work` and sends its values back through a pipe; the
// parent waits (wait4) and returns them with the child's peak resident set
// size. The child starts with the parent's resident pages, so callers
// subtract the peak of an empty `work` (a baseline). Throws
// std::runtime_error when the child fails (its message is passed back).
// Call only while the process has a single thread.
ChildRun runInChild(const std::function<std::vector<double>()>& work);

}  // namespace prime::bench
