// Running any system's render live: in a window when there can be one (else
// headless, saying why once), the render on a worker thread while this one
// keeps the window alive, Esc / close / Ctrl-C aborting it (headless:
// SIGINT and SIGTERM), progress on a terminal, and afterwards a window that
// stays until Esc (the 1991 program's WaitForEsc) unless asked not to.
// What the window shows is the system's LiveFrame; what the render writes is
// the command's business.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "palette/window/live_frame.h"
#include "palette/window/screen_window.h"
#include "palette/window/window_fit.h"
#include "src/cli/pixel_inspector.h"

namespace CLI {
class App;
}

namespace prime::cli {

struct LiveOptions {
  bool noWindow = false;  // --no-window
  // Why noWindow is set when the user did not say --no-window ("--rows: a
  // band renders headless"): the headless line says that, not the flag.
  std::string headlessBecause;
  bool quiet = false;   // no progress, no messages
  bool noWait = false;  // close the window when the render is done
  int zoom = 1;
  std::string caption;      // the window title's first part: scene or file
  std::string commandName;  // for messages: "trace"
  std::string keys;         // the frame's own keys, for the first message ("P palette, D DAC")
  bool fullscreen = false;  // --fullscreen
  display::ScaleMode scale = display::ScaleMode::Integer;  // --scale
  // --pace: rows a second shown at most (0: as fast as they come); `pace1991`
  // estimates it from the rays each row took (G24).
  double pace = 0.0;
  bool pace1991 = false;
  // With --pace 1991: the 1991 seconds of the rows finished so far, by the
  // system's era model (PRIME: src/prime/render/era_cost.h); unset: the
  // flat 300 rays a second.
  std::function<double()> seconds1991;
  int firstRow = 0;  // the frame row of the render's row 0 (PRIME: the placement)
  // The R key: keep the drawing as prime-recording-N.gif (PRIME: --record's
  // film of the render shown); unset: R does nothing.
  std::function<void()> recordKey;
  // What the S key's screenshots say made them (runTrace: the render's
  // provenance).
  PngMeta screenshot;
  // The C key: print and save the render's camera (src/cli/camera_flags.h,
  // cameraKey); unset: C does nothing.
  std::function<void()> cameraKey;
  // A click on a pixel once the render is done: its ray tree and the probe's
  // text (src/cli/pixel_inspector.h); unset: clicks do nothing.
  PixelProbe probe;
};

// The window flags of a command that renders live, for every system:
// --no-window, --zoom, --fullscreen, --scale, --no-wait (unless `wait` is
// false: a window that is the command, as walk's), and --pace when `pace` (a
// render to watch).
void addLiveWindowOptions(CLI::App* cmd, const std::shared_ptr<LiveOptions>& o, bool pace,
                          bool wait = true);

// The value of --pace: a number of rows a second (> 0), or "1991" (G24).
// Sets o.pace or o.pace1991; a CLI::ValidationError for anything else.
void parsePace(const std::string& text, LiveOptions& o);
// A duration for people: "4.2 s", "12 min 03 s", "1 h 30 min".
std::string durationText(double seconds);

// The 1991 estimate of rays a second (G24).
inline constexpr double kRaysPerSecond1991 = 300.0;

// The signal (SIGINT, SIGTERM) that aborted a headless render, or 0: main()
// exits with 128 + it, as a shell reports a process the signal ended.
int interruptingSignal();

class LiveRender {
 public:
  // Opens a window on `frame` unless there can be none (no DISPLAY,
  // --no-window, no window module): then headless, and says why unless quiet.
  LiveRender(display::LiveFrame& frame, LiveOptions options);
  ~LiveRender();
  LiveRender(const LiveRender&) = delete;
  LiveRender& operator=(const LiveRender&) = delete;

  bool windowed() const { return window_ != nullptr; }
  // The flag the render must honour (between rows).
  const std::atomic<bool>* abortFlag() const { return &abort_; }
  bool aborted() const { return abort_.load(); }

  // A progress callback that prints rows, rays per second and the time left
  // on a terminal (nothing otherwise), and feeds the window's title.
  std::function<void(int rowsDone, int rows, std::uint64_t raysSoFar)> progress();

  // Runs `render` to its end: with a window, on a worker thread while this
  // thread polls the window; headless, here, with SIGINT/SIGTERM setting
  // the abort flag. An exception from `render` is rethrown here.
  void run(const std::function<void()>& render);

  // The window goes at once (an aborted render: the 1991 ExitOnEsc).
  void closeWindow() {
    inspector_.reset();
    window_.reset();
  }
  // After a finished render: the window shows `status` and stays until Esc
  // or close, unless --no-wait, no window, or Esc was already pressed.
  void waitForEsc(const std::string& status);

 private:
  bool paced() const;
  double rowsPerSecond() const;

  LiveOptions options_;
  std::unique_ptr<display::ScreenWindow> window_;
  std::unique_ptr<PixelInspector> inspector_;  // from waitForEsc on
  std::atomic<bool> abort_{false};
  std::atomic<int> rowsDone_{0}, rows_{0};
  std::atomic<std::uint64_t> rays_{0};
  display::PaceClock paceClock_;  // the window's thread only: Space, ] and [
  int width_ = 0;                 // the frame's
  bool tty_ = false;
};

}  // namespace prime::cli
