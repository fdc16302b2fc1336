#include "src/cli/live_render.h"

#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>

#include "src/cli/camera_flags.h"

namespace prime::cli {

namespace {

// Ctrl-C / SIGTERM: set the render's abort flag (an atomic store is
// async-signal-safe) and remember the signal for the exit status (130, 143).
// With a window too: installed after SDL's own handlers (SDL_Init, when the
// window opened), which would make them a quit event, an exit 1 like Esc.
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

void parsePace(const std::string& text, LiveOptions& o) {
  if (text == "1991") {
    o.pace1991 = true;
    return;
  }
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(v > 0.0) || !std::isfinite(v))
    throw CLI::ValidationError(
        "--pace", "expected rows a second (a number > 0) or 1991, found '" + text + "'");
  o.pace = v;
}

namespace {
// --fullscreen and --scale, and --pace when `pace` (G23, G24).
void addWindowFitOptions(CLI::App* cmd, const std::shared_ptr<LiveOptions>& o, bool pace) {
  cmd->add_flag("--fullscreen", o->fullscreen, "Show the picture fullscreen (key F11 toggles)");
  cmd->add_option_function<std::string>(
         "--scale",
         [o](const std::string& s) {
           o->scale = s == "aspect" ? display::ScaleMode::Aspect : display::ScaleMode::Integer;
         },
         "How a fullscreen or resized window scales the picture: integer (the largest whole "
         "factor, black borders; default) or aspect (fills one side, nearest neighbour)")
      ->check(CLI::IsMember({"integer", "aspect"}));
  if (pace)
    cmd->add_option_function<std::string>(
        "--pace", [o](const std::string& s) { parsePace(s, *o); },
        "Show the finished rows no faster than this many a second, or 1991 for an estimate of "
        "PRIME's 1991 speed (the render may finish first; the window catches up, Esc stops it)");
}
}  // namespace

void addLiveWindowOptions(CLI::App* cmd, const std::shared_ptr<LiveOptions>& o, bool pace,
                          bool wait) {
  cmd->add_flag("--no-window", o->noWindow,
                "Do not open a window (also the case when there is no DISPLAY)");
  cmd->add_option("--zoom", o->zoom,
                  "Window zoom, an integer 1..8, reduced to fit the display (keys + and - change "
                  "it)")
      ->check(CLI::Range(1, 8));
  addWindowFitOptions(cmd, o, pace);
  if (!wait) return;
  cmd->add_flag("--no-wait", o->noWait,
                "Close the window when the render is done instead of waiting for Esc");
}

std::string durationText(double s) {
  char buf[32];
  s = std::max(s, 0.0);
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s) / 60,
                  static_cast<int>(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%d h %02d min", static_cast<int>(s) / 3600,
                  static_cast<int>(s) / 60 % 60);
  return buf;
}

int interruptingSignal() {
  return gSignal;
}

LiveRender::LiveRender(display::LiveFrame& frame, LiveOptions options)
    : options_(std::move(options)), tty_(isatty(STDERR_FILENO) && !options_.quiet) {
  width_ = frame.width();
  auto headless = display::headlessReason(options_.noWindow);
  if (headless && options_.noWindow && !options_.headlessBecause.empty())
    headless = options_.headlessBecause;
  if (!headless) {
    try {
      window_ = std::make_unique<display::ScreenWindow>(
          frame, display::WindowConfig{options_.caption, options_.zoom, ".", options_.fullscreen,
                                       options_.scale, paced(), options_.screenshot});
    } catch (const std::exception& e) {
      headless = e.what();
      window_.reset();
    }
  }
  if (!window_ && !options_.quiet) std::cerr << "prime: running headless (" + *headless + ")\n";
  if (window_)
    window_->setInputHandler([this](const display::module::Event& e) {
      if (inspector_ && inspector_->handle(e)) return true;
      if (e.type == display::module::Event::Type::Key && paced() && paceClock_.onKey(e.key)) {
        if (!options_.quiet)
          std::cerr << (paceClock_.paused()
                            ? "\nprime: paused (Space resumes)\n"
                            : "\nprime: pace x" + numberText(paceClock_.speed()) + "\n");
        return true;
      }
      if (e.type != display::module::Event::Type::Key) return false;
      if (e.letter == 'r' && options_.recordKey) return options_.recordKey(), true;
      if (!options_.cameraKey || e.letter != 'c') return false;
      options_.cameraKey();
      return true;
    });
  // InitGraph before the render: the window mapped and its first full
  // picture sent (up to 1 s), so that cost does not fall inside it.
  for (int i = 0; window_ && i < 100 && !window_->upToDate(); ++i) window_->poll(10);
  if (window_ && !options_.quiet)
    std::cerr << (std::ostringstream()
                  << "prime: drawing in window 0x" << std::hex << window_->nativeId()
                  << "; Esc aborts (keys: + - zoom, "
                  << (options_.keys.empty() ? "" : options_.keys + ", ")
                  << (options_.cameraKey ? "C camera, " : "")
                  << (options_.recordKey ? "R recording, " : "") << "S screenshot"
                  << (paced() ? ", Space pause, [ ] slower / faster" : "")
                  << (options_.probe ? "; when done, click a pixel: its rays" : "") << ")\n")
                     .str()
              << std::flush;
}

LiveRender::~LiveRender() = default;

std::function<void(int, int, std::uint64_t)> LiveRender::progress() {
  const auto start = std::chrono::steady_clock::now();
  return [this, start](int done, int rows, std::uint64_t rays) {
    rowsDone_ = done;
    rows_ = rows;
    rays_ = rays;
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
    SignalsAbort signals(abort_);
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
    // --pace (G24): the finished rows reach the display no faster than the
    // pace; after the render the display catches up at it (Esc stops that).
    display::RowPacer pacer;
    // The pace's own clock (PaceClock: Space, ] and [).
    auto last = std::chrono::steady_clock::now();
    double clock = 0.0, lastLine = -1.0;
    int shown = 0;
    const auto pace = [&] {
      if (!paced()) return;
      const auto now = std::chrono::steady_clock::now();
      clock = paceClock_.advance(std::chrono::duration<double>(now - last).count());
      last = now;
      shown = pacer.advance(rowsDone_, clock, rowsPerSecond());
      window_->setRowLimit(options_.firstRow + shown);
    };
    while (!done || (paced() && !abort_ && shown < rowsDone_)) {
      pace();
      if (window_->poll(30)) abort_ = true;  // Esc, close, Ctrl-C: ExitOnEsc
      const int d = paced() ? shown : rowsDone_.load(), n = rows_;
      std::string status = "rows " + std::to_string(d) + "/" + std::to_string(n) + " (" +
                           std::to_string(n > 0 ? 100 * d / n : 0) + "%)";
      if (paced() && n > 0) {
        // The replay's time and what is left of it at this speed.
        const double total = n / std::max(rowsPerSecond(), 1e-9);
        status += ", " + std::string(options_.pace1991 ? "1991 time " : "") + durationText(clock) +
                  " of " + durationText(total) + ", " +
                  durationText((total - clock) / paceClock_.speed()) + " left" +
                  (paceClock_.speed() != 1.0 ? " at x" + numberText(paceClock_.speed()) : "") +
                  (paceClock_.paused() ? " (paused)" : "");
        if (tty_ && clock - lastLine >= 0.5 * paceClock_.speed()) {
          std::fprintf(stderr, "\r%s   ", status.c_str());
          lastLine = clock;
        }
      }
      window_->setStatus(abort_ ? "aborting" : status);
    }
    worker.join();
    if (paced()) window_->setRowLimit(INT_MAX);  // an abort shows what was drawn
    if (tty_) std::fprintf(stderr, "\n");
    if (paced() && !abort_ && !options_.quiet)
      // One write: std::cerr is unbuffered, and a reader of the pipe must
      // never see half of this line.
      std::cerr << "prime: the replay is done: " + std::to_string(rows_.load()) + " rows in " +
                       durationText(clock) + (options_.pace1991 ? " of 1991 time" : "") + "\n";
    if (error) std::rethrow_exception(error);
  } else {
    SignalsAbort signals(abort_);
    render();
    if (tty_) std::fprintf(stderr, "\n");
  }
}

bool LiveRender::paced() const {
  return options_.pace > 0.0 || options_.pace1991;
}

double LiveRender::rowsPerSecond() const {
  if (!options_.pace1991) return options_.pace;
  const int d = rowsDone_;
  // The era model's time of the rows finished (G24).
  if (options_.seconds1991)
    if (const double s = options_.seconds1991(); d > 0 && s > 0) return d / s;
  // The rays each row took so far (before the first row: one a pixel), at
  // the flat 1991 rate.
  const std::uint64_t rays = rays_;
  const double raysPerRow =
      d > 0 && rays > 0 ? static_cast<double>(rays) / d : static_cast<double>(std::max(width_, 1));
  return kRaysPerSecond1991 / raysPerRow;
}

void LiveRender::waitForEsc(const std::string& status) {
  // Esc (or close) pressed as the last rows finished: the user has had the
  // WaitForEsc already.
  if (!window_ || options_.noWait || abort_.load()) return;
  window_->setStatus(status);
  if (options_.probe) inspector_ = std::make_unique<PixelInspector>(*window_, options_.probe);
  if (!options_.quiet)
    std::cerr << std::string(
                     "prime: the window stays open until Esc or close (WaitForEsc); "
                     "--no-wait or --no-window to skip this") +
                     (options_.probe ? "; click a pixel to draw its rays (right click: away)"
                                     : "") +
                     "\n";
  while (!window_->poll(100)) {
  }
}

}  // namespace prime::cli
