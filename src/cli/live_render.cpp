#include "src/cli/live_render.h"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <sstream>
#include <thread>

namespace prime::cli {

namespace {

// Headless Ctrl-C / SIGTERM: set the render's abort flag (an atomic store is
// async-signal-safe). With a window, SDL turns both into a quit event instead.
std::atomic<bool>* gAbortOnSignal = nullptr;
volatile sig_atomic_t gSignal = 0;  // the signal that aborted, for the exit status
extern "C" void abortOnSignal(int sig) {
  gSignal = sig;
  if (gAbortOnSignal != nullptr) gAbortOnSignal->store(true);
}

class SignalsAbort {
 public:
  explicit SignalsAbort(std::atomic<bool>& flag) {
    gAbortOnSignal = &flag;
    struct sigaction sa {};
    sa.sa_handler = abortOnSignal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &oldInt_);
    sigaction(SIGTERM, &sa, &oldTerm_);
  }
  ~SignalsAbort() {
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
    gAbortOnSignal = nullptr;
  }
  SignalsAbort(const SignalsAbort&) = delete;
  SignalsAbort& operator=(const SignalsAbort&) = delete;

 private:
  struct sigaction oldInt_ {
  }, oldTerm_{};
};

}  // namespace

int interruptingSignal() {
  return gSignal;
}

LiveRender::LiveRender(display::LiveFrame& frame, LiveOptions options)
    : options_(std::move(options)), tty_(isatty(STDERR_FILENO) && !options_.quiet) {
  auto headless = display::headlessReason(options_.noWindow);
  if (!headless) {
    try {
      window_ = std::make_unique<display::ScreenWindow>(
          frame, display::WindowConfig{options_.caption, options_.zoom, "."});
    } catch (const std::exception& e) {
      headless = e.what();
      window_.reset();
    }
  }
  if (!window_ && !options_.quiet) std::cerr << "prime: running headless (" << *headless << ")\n";
  // InitGraph before the render: the window mapped and its first full
  // picture sent (up to 1 s), so that cost does not fall inside it.
  for (int i = 0; window_ && i < 100 && !window_->upToDate(); ++i) window_->poll(10);
  if (window_ && !options_.quiet)
    std::cerr << (std::ostringstream()
                  << "prime: drawing in window 0x" << std::hex << window_->nativeId()
                  << "; Esc aborts (keys: + - zoom, "
                  << (options_.keys.empty() ? "" : options_.keys + ", ") << "S screenshot)\n")
                     .str()
              << std::flush;
}

LiveRender::~LiveRender() = default;

std::function<void(int, int, std::uint64_t)> LiveRender::progress() {
  const auto start = std::chrono::steady_clock::now();
  return [this, start](int done, int rows, std::uint64_t rays) {
    rowsDone_ = done;
    rows_ = rows;
    if (!tty_) return;
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double left = done > 0 ? s * (rows - done) / done : 0.0;
    std::fprintf(stderr, "\rrows %d/%d  %.0f rays/s  %.0f s left   ", done, rows,
                 s > 0 ? rays / s : 0.0, left);
    std::fflush(stderr);
  };
}

void LiveRender::run(const std::function<void()>& render) {
  if (window_) {
    // The render on its own thread; this one keeps the window alive.
    std::exception_ptr error;
    std::atomic<bool> done{false};
    std::thread worker([&] {
      try {
        render();
      } catch (...) {
        error = std::current_exception();
      }
      done = true;
    });
    while (!done) {
      if (window_->poll(30)) abort_ = true;  // Esc, close, Ctrl-C: ExitOnEsc
      const int d = rowsDone_, n = rows_;
      window_->setStatus(abort_ ? "aborting"
                                : "rows " + std::to_string(d) + "/" + std::to_string(n) + " (" +
                                      std::to_string(n > 0 ? 100 * d / n : 0) + "%)");
    }
    worker.join();
    if (tty_) std::fprintf(stderr, "\n");
    if (error) std::rethrow_exception(error);
  } else {
    SignalsAbort signals(abort_);
    render();
    if (tty_) std::fprintf(stderr, "\n");
  }
}

void LiveRender::waitForEsc(const std::string& status) {
  // Esc (or close) pressed as the last rows finished: the user has had the
  // WaitForEsc already.
  if (!window_ || options_.noWait || abort_.load()) return;
  window_->setStatus(status);
  if (!options_.quiet)
    std::cerr << "prime: the window stays open until Esc or close (WaitForEsc); "
                 "--no-wait or --no-window to skip this\n";
  while (!window_->poll(100)) {
  }
}

}  // namespace prime::cli
