#include "src/bench/measure.h"

#include <sys/resource.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace prime::bench {

double processCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

MachineFacts machineFacts() {
  MachineFacts m;
  m.nproc = static_cast<int>(std::thread::hardware_concurrency());
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);)
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      m.cpuModel = colon == std::string::npos ? line : line.substr(colon + 2);
      break;
    }
  utsname u{};
  if (uname(&u) == 0) m.kernel = std::string(u.sysname) + " " + u.release + " " + u.machine;
  std::ifstream load("/proc/loadavg");
  std::string a, b, c;
  if (load >> a >> b >> c) m.loadAverage = a + " " + b + " " + c;
#ifdef __VERSION__
  m.compiler = __VERSION__;
#endif
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  m.date = buf;
  return m;
}

#ifdef __EMSCRIPTEN__
// The web build has no processes to fork (docs/web.md): the work runs here,
// and the peak memory is the WebAssembly memory's size.
ChildRun runInChild(const std::function<std::vector<double>()>& work) {
  ChildRun run;
  run.values = work();
  run.maxRssKb = static_cast<long>(__builtin_wasm_memory_size(0) * 64);
  return run;
}
#else
namespace {
bool writeAll(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}
}  // namespace

ChildRun runInChild(const std::function<std::vector<double>()>& work) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    close(fds[0]);
    int status = 0;
    try {
      const std::vector<double> v = work();
      const char ok = 'V';
      const std::uint64_t n = v.size();
      writeAll(fds[1], &ok, 1);
      writeAll(fds[1], &n, sizeof n);
      writeAll(fds[1], v.data(), v.size() * sizeof(double));
    } catch (const std::exception& e) {
      const char bad = 'E';
      writeAll(fds[1], &bad, 1);
      writeAll(fds[1], e.what(), std::strlen(e.what()));
      status = 1;
    }
    close(fds[1]);
    _exit(status);
  }
  close(fds[1]);
  std::string bytes;
  char buf[4096];
  for (;;) {
    const ssize_t r = ::read(fds[0], buf, sizeof buf);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    bytes.append(buf, static_cast<std::size_t>(r));
  }
  close(fds[0]);
  int status = 0;
  rusage ru{};
  while (wait4(pid, &status, 0, &ru) < 0 && errno == EINTR) {
  }
  if (bytes.empty() || bytes[0] != 'V') {
    const std::string why = bytes.size() > 1
                                ? bytes.substr(1)
                                : "the child process died (status " + std::to_string(status) + ")";
    throw std::runtime_error("benchmark child: " + why);
  }
  ChildRun run;
  std::uint64_t n = 0;
  if (bytes.size() < 1 + sizeof n) throw std::runtime_error("benchmark child: short reply");
  std::memcpy(&n, bytes.data() + 1, sizeof n);
  if (bytes.size() != 1 + sizeof n + n * sizeof(double))
    throw std::runtime_error("benchmark child: short reply");
  run.values.resize(n);
  if (n > 0) std::memcpy(run.values.data(), bytes.data() + 1 + sizeof n, n * sizeof(double));
  run.maxRssKb = ru.ru_maxrss;
  return run;
}
#endif

}  // namespace prime::bench
