// prime trace DIR: render a scene as RayTrace.c did, to DIR/graph_scr, while
// the emulated 8514/A screen shows each row where PutPixel put it.
//
// With a display, a window shows the whole screen as the render proceeds; Esc
// (or closing it, or Ctrl-C) aborts like ExitOnEsc; when the render is done
// the window stays until Esc or close, like WaitForEsc. Without one (no
// DISPLAY, or --no-window) it runs headless, says so, and Ctrl-C aborts.
//
// An aborted render never writes its target: a previous complete graph file
// there is kept as it was, and TARGET.partial holds the header and the rows
// finished from the top, as the listing's exit(1) would have left them.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "legacy_io/prime/graph_file.h"
#include "palette/prime/export.h"
#include "palette/prime/live_screen.h"
#include "src/cli/commands.h"
#include "src/cli/live_render.h"
#include "src/cli/prime/display_options.h"
#include "src/cli/prime/render_options.h"

namespace prime::cli {

namespace {

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
  if (s.shadowRays > 0 || r.samples > 0)  // the thesis profile's shadow rays; pixel samples
    std::printf("shadow rays: %llu; pixel samples: %llu (%.2f a pixel)\n",
                static_cast<unsigned long long>(s.shadowRays),
                static_cast<unsigned long long>(r.samples),
                r.graph.pixels.empty()
                    ? 0.0
                    : static_cast<double>(r.samples) / static_cast<double>(r.graph.pixels.size()));
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

// An aborted render never writes its target: a previous good render there is
// kept (an interrupted re-render must not cost the last finished picture),
// and `partial` gets the header and the rows finished from the top, as the
// listing's exit(1) would have left them.
void writeAborted(const RenderResult& result, const std::vector<char>& finished,
                  const std::string& target, const std::string& partial) {
  std::size_t prefix = 0;
  while (prefix < finished.size() && finished[prefix]) ++prefix;
  std::error_code ec;
  const bool kept = std::filesystem::exists(target, ec);
  io::GraphFile head = result.graph;
  head.pixels.resize(prefix * static_cast<std::size_t>(head.width()));
  io::writeGraphFile(partial, head);
  const auto rowsFinished = std::count(finished.begin(), finished.end(), 1);
  std::cerr << "prime: trace aborted after " << rowsFinished << " of " << finished.size()
            << " rows: " << target << " not written" << (kept ? " (the previous one is kept)" : "")
            << "; the " << prefix << " rows finished from the top are in " << partial
            << " (prime view shows it); no PNG written\n";
}

// The PNGs of a finished render: the emulated screen's area through the
// display palette, and the unquantised colours of the same area.
void writePngs(const RenderResult& result, const RenderSettings& settings, Placement at,
               const Palette& palette, const DisplayOptions& display, const std::string& png,
               const std::string& trueColourPng) {
  const int screenW = settings.camera.screenWidth, screenH = settings.camera.screenHeight;
  const ImageArea area = areaOf(display);
  if (!png.empty()) {
    Screen screen(screenW, screenH);
    drawGraph(screen, result.graph, at);
    writePng(png, exportImage(screen, result.graph, result.graph.pixels.size(), at,
                              present(palette.dac, dacOf(display)), area));
  }
  if (!trueColourPng.empty())
    writePng(trueColourPng,
             exportTrueColour(screenW, screenH, result.graph, result.rgb.pixels, at, area));
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
  auto format = std::make_shared<std::string>("prime");
  cmd->add_option("--format", *format,
                  "Scene format (detected: a directory is PRIME's, a file of numbers "
                  "Malone's, which takes its own options: prime trace FILE --help)")
      ->check(CLI::IsMember({"prime"}));
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

      // The emulated screen, in a window if there can be one.
      display::LiveScreen screen(screenW, screenH, windowPalettes(palette), dacOf(*display));
      LiveRender live(screen, {display->noWindow, *quiet, *noWait, display->zoom, *dir, "trace",
                               "P palette, D DAC"});

      // Which rows are done (rowDone runs on one thread, the render's caller).
      std::vector<char> finished(static_cast<std::size_t>(camera.rows()), 0);
      RenderCallbacks cb;
      cb.abort = live.abortFlag();
      cb.progress = live.progress();
      cb.rowDone = [&](int row, const std::vector<std::int16_t>& indices) {
        finished[static_cast<std::size_t>(row)] = 1;
        if (live.windowed()) screen.drawRow(at, row, indices);  // PutPixel(j, i, color)
      };
      RenderResult result;
      live.run([&] { result = render(scene, settings, cb); });

      if (result.aborted) {
        live.closeWindow();  // ExitOnEsc: the screen goes at once
        writeAborted(result, finished, target, partial);
        if (!*quiet) printSummary(result, partial);
        return 1;  // as ExitOnEsc's exit(1)
      }

      io::writeGraphFile(target, result.graph);
      std::error_code ec;
      std::filesystem::remove(partial, ec);  // an older aborted run's
      writePngs(result, settings, at, palette, *display, *png, *trueColourPng);
      if (!*quiet) printSummary(result, target);
      std::fflush(stdout);
      char status[64];
      std::snprintf(status, sizeof status, "done in %.2f s - Esc to close", result.seconds);
      live.waitForEsc(status);
      return 0;
    };
  });
}

}  // namespace prime::cli
