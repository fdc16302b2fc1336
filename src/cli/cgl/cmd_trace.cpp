// prime trace SCENE.cgl: the Waterloo CGL package's `trace` (Sweeney 1985,
// Appendix 2): the scene rendered at 512 x 512 as Render does it (one ray per
// pixel, or corner anti-aliasing), written as the package wrote it (RLE, or
// the raw frame) and as the port adds (PNG, PRIME's 8514/A view, a window
// that shows the scanlines as they finish, threads). Unless quiet, the
// parameters and the object list are reported first, as the program did.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "legacy_io/cgl/frame.h"
#include "legacy_io/common/output_file.h"
#include "palette/png_image.h"
#include "palette/window/live_rgb_frame.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"
#include "src/cli/cgl/picture.h"
#include "src/cli/live_render.h"
#include "src/cli/quantize_options.h"
#include "src/cli/view_8514.h"

namespace prime::cli::cgl {

namespace {

using prime::cgl::Frame;

// The program's report of its parameters (Appendix 1 section 5: `quiet`
// suppresses "the report of parameters, object list and memory allocation").
void printReport(const prime::cgl::SceneFile& file, const prime::cgl::Scene& scene) {
  const auto& p = file.program;
  std::printf("scene %s: %zu vertices, %zu surfaces, %zu lights, %zu scene nodes (root %d)\n",
              file.path.c_str(), file.vertices.size(), file.surfaces.size(), file.lights.size(),
              file.nodes.size(), file.numbers.root);
  std::printf(
      "parameters: window x %d..%d, y %d..%d; depth %d; shadows %s; background %d %d %d; "
      "aalevel %d%s",
      p.xleft, p.xright, p.ylow, p.yhigh, p.depth, p.shadows ? "on" : "off", p.background[0],
      p.background[1], p.background[2], p.aalevel, p.aalevel == 0 ? " (no anti-aliasing)" : "");
  if (p.aalevel != 0) std::printf(", aathreshold %.1f", p.aathreshold);
  std::printf("\n");
  std::printf("object list (%d primitives, %d super boxes; tested in this order):\n%s",
              scene.primitives, scene.boxes, prime::cgl::describeObjects(scene).c_str());
}

// Section 5.5's work, when the scene has fractals: surfaces tested, and the
// tree boxes and facets tested per such test.
std::string fractalSummary(const prime::cgl::TraceStats& s) {
  const auto n = s.tests[static_cast<std::size_t>(prime::cgl::ObjectKind::Fractal)];
  if (n == 0) return "";
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "; fractal tests %llu (%.1f boxes and %.2f facets per test, longest active "
                "list %llu)",
                static_cast<unsigned long long>(n), static_cast<double>(s.fractal.boxes) / n,
                static_cast<double>(s.fractal.facets) / n,
                static_cast<unsigned long long>(s.fractal.activeMax));
  return buf;
}

void printSummary(const prime::cgl::RenderResult& r, const std::string& what) {
  const auto& s = r.stats;
  std::printf("%s 512 x 512 pixels in %.2f s with %d thread(s)%s\n",
              r.run.aborted ? "ABORTED after" : "traced", r.run.seconds, r.run.threads,
              what.c_str());
  std::printf(
      "rays: %llu (primary %llu, shadow %llu, reflected %llu, refracted %llu), %.0f rays/s; "
      "tests: sphere %llu, cylinder %llu, polygon %llu, super box %llu; shade calls: Lambert "
      "%llu, Phong %llu, Cook-Torrance %llu%s\n",
      static_cast<unsigned long long>(s.rays.rays()),
      static_cast<unsigned long long>(s.rays.primaryRays),
      static_cast<unsigned long long>(s.rays.shadowRays),
      static_cast<unsigned long long>(s.rays.reflectedRays),
      static_cast<unsigned long long>(s.rays.transmittedRays),
      r.run.seconds > 0 ? static_cast<double>(s.rays.rays()) / r.run.seconds : 0.0,
      static_cast<unsigned long long>(s.tests[0]), static_cast<unsigned long long>(s.tests[1]),
      static_cast<unsigned long long>(s.tests[2]), static_cast<unsigned long long>(s.boxTests),
      static_cast<unsigned long long>(s.shadeCalls[0]),
      static_cast<unsigned long long>(s.shadeCalls[1]),
      static_cast<unsigned long long>(s.shadeCalls[2]), fractalSummary(s).c_str());
  if (s.spline.calls > 0)  // B-spline surfaces (section 6, Table 6)
    std::printf(
        "splines: %llu intersections, %llu boxes checked, %llu Newton calls, %.2f "
        "iterations per call, %llu hits\n",
        static_cast<unsigned long long>(s.spline.calls),
        static_cast<unsigned long long>(s.spline.boxes),
        static_cast<unsigned long long>(s.spline.newtonCalls),
        s.spline.newtonCalls
            ? static_cast<double>(s.spline.iterations) / static_cast<double>(s.spline.newtonCalls)
            : 0.0,
        static_cast<unsigned long long>(s.spline.hits));
}

}  // namespace

void addTraceCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      kTraceCommand,
      "Render a Waterloo CGL (1985) scene file: prime trace SCENE.cgl --png OUT.png");
  cmd->group("");  // reached through `prime trace FILE` (src/cli/main.cpp)
  auto o = std::make_shared<CglOptions>();
  auto rle = std::make_shared<std::string>();
  auto raw = std::make_shared<std::string>();
  auto png = std::make_shared<std::string>();
  auto png8514 = std::make_shared<std::string>();
  auto quant = std::make_shared<QuantizeOptions>();
  auto timings = std::make_shared<bool>(false);
  auto live = std::make_shared<LiveOptions>();
  addCglOptions(cmd, *o);
  cmd->add_option("--rle", *rle,
                  "Write the picture run-length encoded, as the package did (-Dencode); "
                  "Appendix 2's -o");
  cmd->add_option("--raw", *raw,
                  "Write the raw 512 x 512 x 32-bit frame (the build without encode)");
  cmd->add_option("--png", *png, "Write the picture as PNG (the same pixels as the RLE)");
  cmd->add_option("--png-8514", *png8514,
                  "Write the picture as PRIME's IBM 8514/A (1991) would have shown it: ColorNum's "
                  "fixed 256-colour palette");
  addQuantizeOptions(cmd, *quant, "the --png picture");
  cmd->add_flag("--no-window", live->noWindow, "Do not open a window (also without a DISPLAY)");
  cmd->add_option("--zoom", live->zoom, "Window zoom, 1..8")->check(CLI::Range(1, 8));
  addWindowFitOptions(cmd, live, true);
  cmd->add_flag("--no-wait", live->noWait, "Close the window when the render is done");
  cmd->add_flag("-q,--quiet", o->quiet,
                "The quiet parameter: no report, no progress and no summary (Appendix 2's -q)");
  cmd->add_flag("--timings", *timings,
                "Print the seconds spent reading, preprocessing and rendering")
      ->group("");  // for bench/cgl_pov_compare.sh
  cmd->callback([=, &action] {
    action = [=] {
      // Outputs whose directory is missing are found before the render, not after it.
      for (const std::string* out : {rle.get(), raw.get(), png.get(), png8514.get()})
        if (!out->empty()) io::checkOutputPath(*out);
      using Clock = std::chrono::steady_clock;
      const auto t0 = Clock::now();
      const prime::cgl::SceneFile file = readCgl(*o, o->quiet);
      const auto t1 = Clock::now();
      const prime::cgl::Scene scene = buildCgl(*o, file);
      // Again now that the inputs (scene, texture maps) are known: none may be an output.
      for (const std::string* out : {rle.get(), raw.get(), png.get(), png8514.get()})
        if (!out->empty()) io::checkOutputPath(*out);
      const auto t2 = Clock::now();
      const bool quiet = file.program.quiet;
      if (!quiet) {
        printReport(file, scene);
        if (file.program.given.output && rle->empty())
          std::printf(
              "the scene names the output file %s; the port writes only what the command line "
              "names: add --rle %s (CGL-D80)\n",
              file.program.output.c_str(), file.program.output.c_str());
        std::fflush(stdout);
      }
      display::LiveRgbFrame frame(Frame::kSize, Frame::kSize);
      LiveOptions options = *live;
      options.quiet = quiet;
      options.caption = o->file;
      options.commandName = "trace";
      LiveRender window(frame, options);

      const prime::cgl::RenderSettings settings = renderSettings(*o, file);
      // Made by the render (a default RenderResult would be one more 1 MiB frame).
      std::optional<prime::cgl::RenderResult> rendered;
      prime::cgl::RenderCallbacks cb;
      cb.abort = window.abortFlag();
      cb.progress = window.progress();
      std::vector<std::uint32_t> row(Frame::kSize);
      if (window.windowed())
        cb.rowDone = [&](int imageRow, std::span<const Rgb> colours) {
          for (int x = 0; x < Frame::kSize; ++x) {
            const Rgb& c = colours[static_cast<std::size_t>(x)];
            auto byte = [](double v) {
              return static_cast<std::uint32_t>(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5);
            };
            row[static_cast<std::size_t>(x)] = byte(c[0]) << 16 | byte(c[1]) << 8 | byte(c[2]);
          }
          frame.setRow(imageRow, row);
        };
      window.run([&] { rendered.emplace(prime::cgl::render(scene, settings, cb)); });
      const prime::cgl::RenderResult& result = *rendered;
      if (result.run.aborted) {
        window.closeWindow();
        std::cerr << "prime: trace aborted: no picture written\n";
        if (!quiet) printSummary(result, "");
        return 1;
      }
      std::string written;
      std::vector<std::string> files;
      auto wrote = [&](const std::string& path) {
        written += (written.empty() ? ": " : ", ") + path;
        files.push_back(path);
      };
      if (!rle->empty()) {
        prime::cgl::writeRleFile(*rle, result.frame);
        wrote(*rle);
      }
      if (!raw->empty()) {
        prime::cgl::writeRawFile(*raw, result.frame);
        wrote(*raw);
      }
      if (!png->empty()) {
        writePng(*png, quantizedImage(frameImage(result.frame), *quant));
        wrote(*png);
      }
      if (!png8514->empty()) {
        write8514Png(*png8514, prime::cgl::toRgbImage(result.frame));
        wrote(*png8514);
      }
      if (!quiet) {
        printSummary(result, written);
        // One "wrote PATH" line per file written, as every command (issue 16).
        for (const std::string& f : files) std::printf("wrote %s\n", f.c_str());
      }
      if (*timings)
        std::printf("timings: read %.3f s, preprocess %.3f s, render %.3f s\n",
                    std::chrono::duration<double>(t1 - t0).count(),
                    std::chrono::duration<double>(t2 - t1).count(), result.run.seconds);
      std::fflush(stdout);
      char status[64];
      std::snprintf(status, sizeof status, "done in %.2f s - Esc to close", result.run.seconds);
      window.waitForEsc(status);
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
