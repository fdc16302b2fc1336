// prime trace SCENE.mal: Malone's ray_trace and raster2ppm (section 1.10.3):
// the scene rendered one ray per pixel, written as a binary PPM, with what
// the port adds: a window that shows the rows as they finish, PNG, threads.
// `prime trace` sends a scene file here when it reads as Malone's numbers
// (or with --format malone).
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "legacy_io/common/output_file.h"
#include "legacy_io/malone/ppm.h"
#include "palette/png_image.h"
#include "palette/window/live_rgb_frame.h"
#include "src/cli/live_render.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"
#include "src/cli/quantize_options.h"
#include "src/cli/view_8514.h"

namespace prime::cli::malone {

namespace {

Image8 toImage8(const RgbImage& raster) {
  Image8 img;
  img.width = raster.width;
  img.height = raster.height;
  img.rgb.reserve(raster.pixels.size() * 3);
  for (const Rgb& c : raster.pixels)
    for (int k = 0; k < 3; ++k) img.rgb.push_back(prime::malone::toByte(c[k]));
  return img;
}

void printSummary(const prime::malone::RenderResult& r, const std::string& what) {
  const auto& s = r.stats;
  std::printf("%s %d x %d pixels in %.2f s with %d thread(s)%s\n",
              r.run.aborted ? "ABORTED after" : "traced", r.raster.width, r.raster.height,
              r.run.seconds, r.run.threads, what.c_str());
  std::printf(
      "rays: %llu (primary %llu, shadow %llu, reflected %llu, transmitted %llu), %.0f rays/s; "
      "primitive tests %llu, hits %llu, total internal reflections %llu; rays cut by depth %llu, "
      "by weight %llu\n",
      static_cast<unsigned long long>(s.rays()), static_cast<unsigned long long>(s.primaryRays),
      static_cast<unsigned long long>(s.shadowRays),
      static_cast<unsigned long long>(s.reflectedRays),
      static_cast<unsigned long long>(s.transmittedRays),
      r.run.seconds > 0 ? s.rays() / r.run.seconds : 0.0,
      static_cast<unsigned long long>(s.primitiveTests), static_cast<unsigned long long>(s.hits),
      static_cast<unsigned long long>(s.totalInternalReflections),
      static_cast<unsigned long long>(s.cutByDepth),
      static_cast<unsigned long long>(s.cutByWeight));
}

}  // namespace

void addTraceCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      kTraceCommand, "Render a Malone (1995) scene file: prime trace SCENE.mal --ppm OUT.ppm");
  cmd->group("");  // reached through `prime trace FILE` (src/cli/main.cpp)
  auto o = std::make_shared<MaloneOptions>();
  auto ppm = std::make_shared<std::string>();
  auto png = std::make_shared<std::string>();
  auto png8514 = std::make_shared<std::string>();
  auto quant = std::make_shared<QuantizeOptions>();
  auto quiet = std::make_shared<bool>(false);
  auto timings = std::make_shared<bool>(false);
  auto live = std::make_shared<LiveOptions>();
  addMaloneOptions(cmd, *o);
  cmd->add_option("--ppm", *ppm, "Write the picture as a binary PPM (P6), as the original did");
  cmd->add_option("--png", *png, "Write the picture as PNG (the same bytes as the PPM)");
  cmd->add_option("--png-8514", *png8514,
                  "Write the picture as PRIME's IBM 8514/A (1991) would have shown it: ColorNum's "
                  "fixed 256-colour palette");
  addQuantizeOptions(cmd, *quant, "the --png picture");
  cmd->add_flag("--no-window", live->noWindow, "Do not open a window (also without a DISPLAY)");
  cmd->add_option("--zoom", live->zoom, "Window zoom, 1..8")->check(CLI::Range(1, 8));
  addWindowFitOptions(cmd, live, true);
  cmd->add_flag("--no-wait", live->noWait, "Close the window when the render is done");
  cmd->add_flag("-q,--quiet", *quiet, "No progress and no summary");
  cmd->add_flag("--timings", *timings,
                "Print the seconds spent reading, building (scene and BVH) and rendering")
      ->group("");  // for bench/malone_pov_compare.sh
  cmd->callback([=, &action] {
    action = [=] {
      // Outputs whose directory is missing are found before the render, not after it.
      for (const std::string* out : {ppm.get(), png.get(), png8514.get()}) {
        if (out->empty()) continue;
        const std::filesystem::path dir = std::filesystem::path(*out).parent_path();
        if (!dir.empty() && !std::filesystem::is_directory(dir)) {
          std::cerr << "prime: trace: cannot write " << *out << ": the directory " << dir.string()
                    << " does not exist\n";
          return 1;
        }
        if (std::filesystem::is_directory(*out)) {
          std::cerr << "prime: trace: cannot write " << *out << ": it is a directory\n";
          return 1;
        }
      }
      LoadTimings load;
      const prime::malone::Scene scene = loadMalone(*o, &load);
      // Found before the render: a missing directory, a directory, an input.
      for (const std::string* out : {ppm.get(), png.get(), png8514.get()})
        if (!out->empty()) io::checkOutputPath(*out);
      const int width = scene.viewer.xRes, height = scene.viewer.yRes;
      display::LiveRgbFrame frame(width, height);
      LiveOptions options = *live;
      options.quiet = *quiet;
      options.caption = o->file;
      options.commandName = "trace";
      LiveRender window(frame, options);

      prime::malone::RenderSettings settings;
      settings.trace = o->trace;
      settings.threads = o->threads;
      prime::malone::RenderResult result;
      prime::malone::RenderCallbacks cb;
      cb.abort = window.abortFlag();
      cb.progress = window.progress();
      std::vector<std::uint32_t> row(static_cast<std::size_t>(width));
      if (window.windowed())
        cb.rowDone = [&](int y, std::span<const Rgb> colours) {
          for (int x = 0; x < width; ++x) {
            const Rgb& c = colours[static_cast<std::size_t>(x)];
            row[static_cast<std::size_t>(x)] =
                static_cast<std::uint32_t>(prime::malone::toByte(c[0])) << 16 |
                static_cast<std::uint32_t>(prime::malone::toByte(c[1])) << 8 |
                prime::malone::toByte(c[2]);
          }
          frame.setRow(y, row);
        };
      window.run([&] { result = prime::malone::render(scene, settings, cb); });
      if (result.run.aborted) {
        window.closeWindow();
        std::cerr << "prime: trace aborted: no picture written\n";
        if (!*quiet) printSummary(result, "");
        return 1;
      }
      std::string written;
      if (!ppm->empty()) {
        prime::malone::writePpm(*ppm, result.raster);
        written += ": " + *ppm;
      }
      if (!png->empty()) {
        writePng(*png, quantizedImage(toImage8(result.raster), *quant));
        written += (written.empty() ? ": " : ", ") + *png;
      }
      if (!png8514->empty()) {
        write8514Png(*png8514, result.raster);
        written += (written.empty() ? ": " : ", ") + *png8514;
      }
      if (!*quiet) {
        printSummary(result, written);
        // One "wrote PATH" line per file written, as every command (issue 16).
        for (const std::string& f : {*ppm, *png, *png8514})
          if (!f.empty()) std::printf("wrote %s\n", f.c_str());
      }
      if (*timings)
        std::printf(
            "timings: read %.3f s, build %.3f s (scene %.3f s, BVH %.3f s), render %.3f s\n",
            load.read, load.build + result.setupSeconds, load.build, result.setupSeconds,
            result.run.seconds);
      std::fflush(stdout);
      char status[64];
      std::snprintf(status, sizeof status, "done in %.2f s - Esc to close", result.run.seconds);
      window.waitForEsc(status);
      return 0;
    };
  });
}

}  // namespace prime::cli::malone
