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
#include "src/cli/cgl/probe_pixel.h"
#include "src/cli/live_render.h"
#include "src/cli/option_values.h"
#include "src/cli/quantize_options.h"
#include "src/cli/system.h"
#include "src/cli/view_8514.h"
#include "src/render/rgb_image.h"

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
  // An abort: the rows rendered, of how many.
  const std::string rows = rowsRenderedText(r.run.aborted, r.run.rowsDone, r.run.rows, r.run.rows);
  std::printf("%s %s512 x 512 pixels in %.2f s with %d thread(s)%s\n",
              r.run.aborted ? "ABORTED after" : "traced", rows.c_str(), r.run.seconds,
              r.run.threads, what.c_str());
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

class CglTrace : public TraceJob {
 public:
  CglTrace(std::shared_ptr<CglOptions> o, std::shared_ptr<TraceFlags> flags,
           std::shared_ptr<std::string> rle, std::shared_ptr<std::string> raw)
      : o_(std::move(o)), flags_(std::move(flags)), rle_(std::move(rle)), raw_(std::move(raw)) {}

  std::vector<Output> outputs() const override {
    return {{"--rle", *rle_},
            {"--raw", *raw_},
            {"--png", flags_->png},
            {"--true-color-png", flags_->trueColourPng},
            {"--png-8514", flags_->png8514}};
  }
  std::string outputHint() const override { return "--png OUT.png or --rle OUT.rle"; }
  std::string scene() const override { return o_->file; }
  void load() override {
    o_->threads = flags_->threads;
    o_->quiet = flags_->quiet;
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    file_.emplace(readCgl(*o_, o_->quiet));
    const auto t1 = Clock::now();
    scene_.emplace(buildCgl(*o_, *file_));
    const auto t2 = Clock::now();
    readSeconds_ = std::chrono::duration<double>(t1 - t0).count();
    buildSeconds_ = std::chrono::duration<double>(t2 - t1).count();
    if (!quiet()) {
      printReport(*file_, *scene_);
      if (file_->program.given.output && rle_->empty())
        std::printf(
            "the scene names the output file %s; the port writes only what the command line "
            "names: add --rle %s (CGL-D80)\n",
            file_->program.output.c_str(), file_->program.output.c_str());
      std::fflush(stdout);
    }
  }
  // The quiet parameter: the command line's -q, or the scene file's own.
  bool quiet() const override { return file_->program.quiet; }
  display::LiveFrame& frame() override { return frame_; }
  void configure(LiveOptions& options) const override {
    options.caption = o_->file;
    options.cameraKey = [camera = o_->applied, file = o_->file] {
      cameraKey(camera, "prime trace " + file, kDefaultCameraFile,
                "the scene's own display parameters: prime trace " + file +
                    " renders this frame with no camera flag");
    };
    // A click: the probe of the pixel's corner (Figure 41), row r being
    // scanline 511 - r, as `prime probe --pixel` takes it.
    options.probe = [this](int x, int y) -> std::optional<ProbedPixel> {
      const int n = prime::cgl::Frame::kSize;
      if (x < 0 || y < 0 || x >= n || y >= n) return std::nullopt;
      return probePoint(*scene_, renderSettings(*o_, *file_), o_->file,
                        "pixel " + std::to_string(x) + " " + std::to_string(y), x, n - 1 - y);
    };
  }
  void render(LiveRender& live) override {
    const prime::cgl::RenderSettings settings = renderSettings(*o_, *file_);
    prime::cgl::RenderCallbacks cb;
    cb.abort = live.abortFlag();
    cb.progress = live.progress();
    cb.firstRow = firstRow_;
    cb.lastRow = lastRow_;
    std::vector<std::uint32_t> row(Frame::kSize);
    if (live.windowed())
      cb.rowDone = [&](int imageRow, std::span<const Rgb> colours) {
        for (int x = 0; x < Frame::kSize; ++x)
          row[static_cast<std::size_t>(x)] = xrgbOf(colours[static_cast<std::size_t>(x)]);
        frame_.setRow(imageRow, row);
      };
    // Made by the render (a default RenderResult would be one more 1 MiB frame).
    live.run([&] { result_.emplace(prime::cgl::render(*scene_, settings, cb)); });
  }
  bool aborted() const override { return result_->run.aborted; }
  void abort() override {
    std::cerr << "prime: trace aborted: no picture written\n";
    if (!quiet()) printSummary(*result_, "");
  }
  std::vector<std::string> write() override {
    std::vector<std::string> written;
    if (!rle_->empty()) {
      prime::cgl::writeRleFile(*rle_, result_->frame);
      written.push_back(*rle_);
    }
    if (!raw_->empty()) {
      prime::cgl::writeRawFile(*raw_, result_->frame);
      written.push_back(*raw_);
    }
    if (!flags_->png.empty()) {
      writePng(flags_->png, quantizedImage(frameImage(result_->frame), flags_->quantize),
               provenance_);
      written.push_back(flags_->png);
    }
    if (!flags_->trueColourPng.empty()) {
      writePng(flags_->trueColourPng, frameImage(result_->frame), provenance_);
      written.push_back(flags_->trueColourPng);
    }
    if (!flags_->png8514.empty()) {
      write8514Png(flags_->png8514, prime::cgl::toRgbImage(result_->frame), provenance_);
      written.push_back(flags_->png8514);
    }
    return written;
  }
  void summary(const std::vector<std::string>& written) const override {
    std::string list;
    for (const std::string& f : written) list += (list.empty() ? ": " : ", ") + f;
    printSummary(*result_, list);
  }
  void timings() const override {
    std::printf("timings: read %.3f s, preprocess %.3f s, render %.3f s\n", readSeconds_,
                buildSeconds_, result_->run.seconds);
  }
  double seconds() const override { return result_->run.seconds; }
  int pictureRows() const override { return Frame::kSize; }  // the whole frame (CGL-Q25)

 private:
  std::shared_ptr<CglOptions> o_;
  std::shared_ptr<TraceFlags> flags_;
  std::shared_ptr<std::string> rle_, raw_;
  std::optional<prime::cgl::SceneFile> file_;
  std::optional<prime::cgl::Scene> scene_;
  display::LiveRgbFrame frame_{Frame::kSize, Frame::kSize};
  std::optional<prime::cgl::RenderResult> result_;
  double readSeconds_ = 0, buildSeconds_ = 0;
};

}  // namespace

TraceFactory addTraceOptions(CLI::App* cmd, const std::shared_ptr<TraceFlags>& flags) {
  auto o = std::make_shared<CglOptions>();
  auto rle = std::make_shared<std::string>();
  auto raw = std::make_shared<std::string>();
  addCglOptions(cmd, *o);
  cmd->add_option("--rle,--out", *rle,
                  "Write the picture run-length encoded, as the package did (-Dencode); "
                  "Appendix 2's -o (--out: the same, the system's own picture as every system "
                  "names it)")
      ->check(outputName());
  cmd->add_option("--raw", *raw,
                  "Write the raw 512 x 512 x 32-bit frame (the build without encode)")
      ->check(outputName());
  flags->camera = &o->camera;
  flags->ownOutputs = {rle.get(), raw.get()};
  return [o, flags, rle, raw] { return std::make_unique<CglTrace>(o, flags, rle, raw); };
}

}  // namespace prime::cli::cgl
