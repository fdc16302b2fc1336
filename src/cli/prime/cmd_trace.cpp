// prime trace DIR: render a scene as RayTrace.c did, to DIR/graph_scr, while
// the emulated 8514/A screen shows each row where PutPixel put it.
//
// With a display, a window shows the whole screen as the render proceeds; Esc
// (or closing it, or Ctrl-C) aborts like ExitOnEsc; when the render is done
// the window stays until Esc or close, like WaitForEsc. Without one (no
// DISPLAY, or --no-window) it runs headless, says so, and Ctrl-C aborts.
//
// An aborted render never leaves a graph file that looks complete: the target
// is removed (an older one too), and TARGET.partial holds the header and the
// rows finished from the top, as the listing's exit(1) would have left it.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

#include "legacy_io/prime/graph_file.h"
#include "palette/prime/export.h"
#include "palette/prime/live_screen.h"
#include "palette/window/screen_window.h"
#include "src/cli/commands.h"
#include "src/cli/prime/display_options.h"
#include "src/cli/prime/render_options.h"

namespace prime::cli {

namespace {

// Headless Ctrl-C / SIGTERM: set the render's abort flag (an atomic store is
// async-signal-safe). With a window, SDL turns both into a quit event instead.
std::atomic<bool>* gAbortOnSignal = nullptr;
extern "C" void abortOnSignal(int) {
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

void printSummary(const RenderResult& r, const std::string& out) {
  const auto& s = r.stats;
  std::printf("%s %d x %d pixels (graph file header %d x %d) in %.2f s with %d thread(s): %s\n",
              r.aborted ? "ABORTED after" : "traced", r.graph.width(), r.graph.height(),
              r.graph.numPixAcross, r.graph.numPixDown, r.seconds, r.threads, out.c_str());
  std::printf("rays: %llu (primary %llu, reflected %llu, transmitted %llu), %.0f rays/s\n",
              static_cast<unsigned long long>(s.rays()),
              static_cast<unsigned long long>(s.primaryRays),
              static_cast<unsigned long long>(s.reflectedRays),
              static_cast<unsigned long long>(s.transmittedRays),
              r.seconds > 0 ? s.rays() / r.seconds : 0.0);
  std::printf(
      "tests: %llu bound, %llu object, %llu primitive; hits %llu; TIR %llu; primary rays that "
      "could meet no object box (background, not traced) %llu\n",
      static_cast<unsigned long long>(s.boundTests), static_cast<unsigned long long>(s.objectTests),
      static_cast<unsigned long long>(s.primitiveTests), static_cast<unsigned long long>(s.hits),
      static_cast<unsigned long long>(s.totalInternalReflections),
      static_cast<unsigned long long>(s.maskedPrimaryRays));
  std::printf(
      "1991 diagnostics (X3): E46 empty transmit lists %llu, E59 capped TIR loops %llu, E51 failed "
      "texel reads %llu, E44 no face %llu, NaN colours %llu, indices outside 0..255 %llu\n",
      static_cast<unsigned long long>(s.emptyTransmitLists),
      static_cast<unsigned long long>(s.cappedTirLoops),
      static_cast<unsigned long long>(s.failedTexelReads),
      static_cast<unsigned long long>(s.noFaceMatched),
      static_cast<unsigned long long>(s.nanColours),
      static_cast<unsigned long long>(s.indicesOutOfRange));
}

}  // namespace

void addTraceCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand("trace", "Render a modelled scene as RayTrace.c did (1991 profile)");
  auto dir = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto png = std::make_shared<std::string>();
  auto trueColourPng = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto noWait = std::make_shared<bool>(false);
  auto options = std::make_shared<RenderOptions>();
  auto display = std::make_shared<DisplayOptions>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--out", *out, "Graph file to write (default: DIR/graph_scr)");
  cmd->add_option("--png", *png,
                  "Also write the picture as PNG, through the display palette (see --png-area)");
  cmd->add_option(
      "--true-color-png", *trueColourPng,
      "Also write the unquantised colours as PNG (same area as --png): what the 256 colours cost");
  addAreaOption(cmd, *display, "--png-area");
  cmd->add_option(
      "--display-palette", display->palette,
      "Palette for the window and PNG: listing, plate3, vga or a palette file (default: the one "
      "--palette implies)");
  addDacOption(cmd, *display);
  addWindowOptions(cmd, *display);
  cmd->add_flag("--no-wait", *noWait,
                "Close the window when the render is done instead of waiting for Esc");
  cmd->add_option("--threads", options->settings.threads, "Render threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("-q,--quiet", *quiet, "No progress and no summary");
  addRenderOptions(cmd, *options);
  cmd->callback([=, &action] {
    action = [=] {
      finishRenderOptions(*options);
      const Scene scene = prepareScene(*dir, options->model);
      const std::string target = out->empty() ? *dir + "/graph_scr" : *out;
      const std::string partial = target + ".partial";
      options->settings.keepColours =
          !trueColourPng->empty();  // only the true-colour PNG reads them
      const RenderSettings& settings = options->settings;
      const ListingCamera camera(settings.camera);
      const Placement at{camera.screenX(0), camera.screenY(0)};
      const int screenW = settings.camera.screenWidth, screenH = settings.camera.screenHeight;
      const Palette palette =
          paletteOf(*display, settings.mapping == ColorMapping::Plate3
                                  ? "plate3"
                                  : paletteNameForGraphType(settings.graphType));

      // The window, if there can be one.
      auto headless = display::headlessReason(display->noWindow);
      std::unique_ptr<display::LiveScreen> live;
      std::unique_ptr<display::ScreenWindow> window;
      if (!headless) {
        try {
          live = std::make_unique<display::LiveScreen>(screenW, screenH, windowPalettes(palette),
                                                       dacOf(*display));
          window = std::make_unique<display::ScreenWindow>(
              *live, display::WindowConfig{*dir, display->zoom, "."});
        } catch (const std::exception& e) {
          headless = e.what();
          window.reset();
          live.reset();
        }
      }
      if (!window && !*quiet) std::cerr << "prime: running headless (" << *headless << ")\n";
      // InitGraph before the render: the window mapped and its first full
      // picture sent (up to 1 s), so that cost does not fall inside it.
      for (int i = 0; window && i < 100 && !window->upToDate(); ++i) window->poll(10);
      if (window && !*quiet)
        std::cerr << (std::ostringstream()
                      << "prime: drawing in window 0x" << std::hex << window->nativeId()
                      << "; Esc aborts (keys: + - zoom, P palette, D DAC, S screenshot)\n")
                         .str()
                  << std::flush;

      std::atomic<bool> abort{false};
      std::atomic<int> rowsDone{0}, rowsTotal{camera.rows()};
      // Which rows are done (rowDone runs on one thread, the render's caller).
      std::vector<char> finished(static_cast<std::size_t>(camera.rows()), 0);
      RenderCallbacks cb;
      cb.abort = &abort;
      const bool tty = isatty(STDERR_FILENO) && !*quiet;
      const auto start = std::chrono::steady_clock::now();
      cb.progress = [&, start](int done, int rows, std::uint64_t rays) {
        rowsDone = done;
        rowsTotal = rows;
        if (!tty) return;
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double left = done > 0 ? s * (rows - done) / done : 0.0;
        std::fprintf(stderr, "\rrows %d/%d  %.0f rays/s  %.0f s left   ", done, rows,
                     s > 0 ? rays / s : 0.0, left);
        std::fflush(stderr);
      };
      cb.rowDone = [&](int row, const std::vector<std::int16_t>& indices) {
        finished[static_cast<std::size_t>(row)] = 1;
        if (live) live->drawRow(at, row, indices);  // PutPixel(j, i, color)
      };

      RenderResult result;
      if (window) {
        // The render on its own thread; this one keeps the window alive.
        std::exception_ptr error;
        std::atomic<bool> done{false};
        std::thread worker([&] {
          try {
            result = render(scene, settings, cb);
          } catch (...) {
            error = std::current_exception();
          }
          done = true;
        });
        while (!done) {
          if (window->poll(30)) abort = true;  // Esc, close, Ctrl-C: ExitOnEsc
          const int d = rowsDone, n = rowsTotal;
          window->setStatus(abort ? "aborting"
                                  : "rows " + std::to_string(d) + "/" + std::to_string(n) + " (" +
                                        std::to_string(n > 0 ? 100 * d / n : 0) + "%)");
        }
        worker.join();
        if (error) std::rethrow_exception(error);
      } else {
        SignalsAbort signals(abort);
        result = render(scene, settings, cb);
      }
      if (tty) std::fprintf(stderr, "\n");

      if (result.aborted) {
        window.reset();  // ExitOnEsc: the screen goes at once
        std::size_t prefix = 0;
        while (prefix < finished.size() && finished[prefix]) ++prefix;
        std::error_code ec;
        const bool removed = std::filesystem::remove(target, ec);
        io::GraphFile head = result.graph;
        head.pixels.resize(prefix * static_cast<std::size_t>(head.width()));
        io::writeGraphFile(partial, head);
        const auto rowsFinished = std::count(finished.begin(), finished.end(), 1);
        std::cerr << "prime: trace aborted after " << rowsFinished << " of " << finished.size()
                  << " rows: " << target << " not written"
                  << (removed ? " (the old one was removed)" : "") << "; the " << prefix
                  << " rows finished from the top are in " << partial
                  << " (prime view shows it); no PNG written\n";
        if (!*quiet) printSummary(result, partial);
        return 1;  // as ExitOnEsc's exit(1)
      }

      io::writeGraphFile(target, result.graph);
      std::error_code ec;
      std::filesystem::remove(partial, ec);  // an older aborted run's
      if (!png->empty() || !trueColourPng->empty()) {
        const ImageArea area = areaOf(*display);
        if (!png->empty()) {
          Screen screen(screenW, screenH);
          drawGraph(screen, result.graph, at);
          writePng(*png, exportImage(screen, result.graph, result.graph.pixels.size(), at,
                                     present(palette.dac, dacOf(*display)), area));
        }
        if (!trueColourPng->empty())
          writePng(*trueColourPng,
                   exportTrueColour(screenW, screenH, result.graph, result.rgb, at, area));
      }
      if (!*quiet) printSummary(result, target);
      std::fflush(stdout);
      // Esc (or close) pressed as the last rows finished: the user has had
      // the WaitForEsc already.
      if (window && !*noWait && !abort.load()) {
        char status[64];
        std::snprintf(status, sizeof status, "done in %.2f s - Esc to close", result.seconds);
        window->setStatus(status);
        if (!*quiet)
          std::cerr << "prime: the window stays open until Esc or close (WaitForEsc); "
                       "--no-wait or --no-window to skip this\n";
        while (!window->poll(100)) {
        }
      }
      return 0;
    };
  });
}

}  // namespace prime::cli
