// prime trace DIR: render a scene as RayTrace.c did, to DIR/graph_scr.
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "legacy_io/graph_file.h"
#include "palette/dac.h"
#include "src/cli/commands.h"
#include "src/cli/render_options.h"

namespace prime::cli {

namespace {

Image8 graphToImage(const io::GraphFile& g, const PaletteTable& table) {
  Image8 img;
  img.width = g.width();
  img.height = g.height();
  img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  for (std::size_t i = 0; i < g.pixels.size(); ++i) indexToRgb8(table, g.pixels[i], &img.rgb[i * 3]);
  return img;
}

void printSummary(const RenderResult& r, const std::string& out) {
  const auto& s = r.stats;
  std::printf("%s %d x %d pixels (graph file header %d x %d) in %.2f s with %d thread(s): %s\n",
              r.aborted ? "ABORTED after" : "traced", r.graph.width(), r.graph.height(), r.graph.numPixAcross,
              r.graph.numPixDown, r.seconds, r.threads, out.c_str());
  std::printf("rays: %llu (primary %llu, reflected %llu, transmitted %llu), %.0f rays/s\n",
              static_cast<unsigned long long>(s.rays()), static_cast<unsigned long long>(s.primaryRays),
              static_cast<unsigned long long>(s.reflectedRays), static_cast<unsigned long long>(s.transmittedRays),
              r.seconds > 0 ? s.rays() / r.seconds : 0.0);
  std::printf("tests: %llu bound, %llu object, %llu primitive; hits %llu; TIR %llu\n",
              static_cast<unsigned long long>(s.boundTests), static_cast<unsigned long long>(s.objectTests),
              static_cast<unsigned long long>(s.primitiveTests), static_cast<unsigned long long>(s.hits),
              static_cast<unsigned long long>(s.totalInternalReflections));
  std::printf("1991 diagnostics (X3): E46 empty transmit lists %llu, E59 capped TIR loops %llu, E51 failed "
              "texel reads %llu, E44 no face %llu, NaN colours %llu, indices outside 0..255 %llu\n",
              static_cast<unsigned long long>(s.emptyTransmitLists), static_cast<unsigned long long>(s.cappedTirLoops),
              static_cast<unsigned long long>(s.failedTexelReads), static_cast<unsigned long long>(s.noFaceMatched),
              static_cast<unsigned long long>(s.nanColours), static_cast<unsigned long long>(s.indicesOutOfRange));
}

}  // namespace

void addTraceCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("trace", "Render a modelled scene as RayTrace.c did (1991 profile)");
  auto dir = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto png = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto options = std::make_shared<RenderOptions>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--out", *out, "Graph file to write (default: DIR/graph_scr)");
  cmd->add_option("--png", *png, "Also write the screen image as PNG (8514/A palette)");
  cmd->add_option("--threads", options->settings.threads, "Render threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("-q,--quiet", *quiet, "No progress and no summary");
  addRenderOptions(cmd, *options);
  cmd->callback([=, &action] {
    action = [=] {
      finishRenderOptions(*options);
      const Scene scene = prepareScene(*dir, *options);
      const std::string target = out->empty() ? *dir + "/graph_scr" : *out;
      const bool tty = isatty(STDERR_FILENO) && !*quiet;
      RenderCallbacks cb;
      const auto start = std::chrono::steady_clock::now();
      if (tty)
        cb.progress = [start](int done, int rows, std::uint64_t rays) {
          const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const double left = done > 0 ? s * (rows - done) / done : 0.0;
          std::fprintf(stderr, "\rrows %d/%d  %.0f rays/s  %.0f s left   ", done, rows, s > 0 ? rays / s : 0.0, left);
          std::fflush(stderr);
        };
      const RenderResult result = render(scene, options->settings, cb);
      if (tty) std::fprintf(stderr, "\n");
      io::writeGraphFile(target, result.graph);
      if (!png->empty())
        writePng(*png, graphToImage(result.graph, options->settings.mapping == ColorMapping::Plate3
                                                      ? plate3Palette()
                                                      : initPalette()));
      if (!*quiet) printSummary(result, target);
      return 0;
    };
  });
}

}  // namespace prime::cli
