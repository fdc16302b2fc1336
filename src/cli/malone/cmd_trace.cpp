// prime trace SCENE.mal: Malone's ray_trace and raster2ppm (section 1.10.3):
// the scene rendered one ray per pixel, written as a binary PPM, with what
// the port adds: a window that shows the rows as they finish, PNG, threads.
// The shared verb (src/cli/verbs.cpp) runs it when the scene reads as
// Malone's numbers (or with --format malone).
#include <cstdio>
#include <iostream>
#include <optional>

#include "legacy_io/common/output_file.h"
#include "legacy_io/malone/ppm.h"
#include "palette/png_image.h"
#include "palette/window/live_rgb_frame.h"
#include "src/cli/live_render.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"
#include "src/cli/malone/probe_pixel.h"
#include "src/cli/option_values.h"
#include "src/cli/quantize_options.h"
#include "src/cli/system.h"
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
  // An abort or a band (--rows): the rows rendered, of how many.
  const std::string rows =
      rowsRenderedText(r.run.aborted, r.run.rowsDone, r.run.rows, r.raster.height);
  std::printf("%s %s%d x %d pixels in %.2f s with %d thread(s)%s\n",
              r.run.aborted ? "ABORTED after" : "traced", rows.c_str(), r.raster.width,
              r.raster.height, r.run.seconds, r.run.threads, what.c_str());
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

class MaloneTrace : public TraceJob {
 public:
  MaloneTrace(std::shared_ptr<MaloneOptions> o, std::shared_ptr<TraceFlags> flags,
              std::shared_ptr<std::string> ppm)
      : o_(std::move(o)), flags_(std::move(flags)), ppm_(std::move(ppm)) {}

  std::vector<Output> outputs() const override {
    return {{"--ppm", *ppm_},
            {"--png", flags_->png},
            {"--true-color-png", flags_->trueColourPng},
            {"--png-8514", flags_->png8514}};
  }
  std::string outputHint() const override { return "--png OUT.png or --ppm OUT.ppm"; }
  std::string scene() const override { return o_->file; }
  void load() override {
    o_->threads = flags_->threads;
    scene_.emplace(loadMalone(*o_, &load_));
    checkPictureMemory(*scene_, *o_);
    frame_.emplace(scene_->viewer.xRes, scene_->viewer.yRes);
  }
  bool quiet() const override { return flags_->quiet; }
  display::LiveFrame& frame() override { return *frame_; }
  void configure(LiveOptions& options) const override {
    options.caption = o_->file;
    options.cameraKey = [camera = o_->applied, file = o_->file] {
      cameraKey(camera, "prime trace " + file, kDefaultCameraFile,
                "the scene's own viewer: prime trace " + file +
                    " renders this frame with no camera flag");
    };
    options.probe = [this](int x, int y) -> std::optional<ProbedPixel> {
      if (x < 0 || y < 0 || x >= scene_->viewer.xRes || y >= scene_->viewer.yRes)
        return std::nullopt;
      return probePixel(*scene_, o_->trace, o_->file, x, y);
    };
  }
  void render(LiveRender& live) override {
    prime::malone::RenderSettings settings;
    settings.trace = o_->trace;
    settings.threads = o_->threads;
    prime::malone::RenderCallbacks cb;
    cb.abort = live.abortFlag();
    cb.progress = live.progress();
    cb.firstRow = firstRow_;
    cb.lastRow = lastRow_;
    const int width = scene_->viewer.xRes;
    std::vector<std::uint32_t> row(static_cast<std::size_t>(width));
    if (live.windowed())
      cb.rowDone = [&](int y, std::span<const Rgb> colours) {
        for (int x = 0; x < width; ++x) {
          const Rgb& c = colours[static_cast<std::size_t>(x)];
          row[static_cast<std::size_t>(x)] =
              static_cast<std::uint32_t>(prime::malone::toByte(c[0])) << 16 |
              static_cast<std::uint32_t>(prime::malone::toByte(c[1])) << 8 |
              prime::malone::toByte(c[2]);
        }
        frame_->setRow(y, row);
      };
    live.run([&] { result_ = prime::malone::render(*scene_, settings, cb); });
  }
  bool aborted() const override { return result_.run.aborted; }
  void abort() override {
    std::cerr << "prime: trace aborted: no picture written\n";
    if (!flags_->quiet) printSummary(result_, "");
  }
  std::vector<std::string> write() override {
    std::vector<std::string> written;
    if (!ppm_->empty()) {
      prime::malone::writePpm(*ppm_, result_.raster);
      written.push_back(*ppm_);
    }
    if (!flags_->png.empty()) {
      writePng(flags_->png, quantizedImage(toImage8(result_.raster), flags_->quantize),
               provenance_);
      written.push_back(flags_->png);
    }
    if (!flags_->trueColourPng.empty()) {
      writePng(flags_->trueColourPng, toImage8(result_.raster), provenance_);
      written.push_back(flags_->trueColourPng);
    }
    if (!flags_->png8514.empty()) {
      write8514Png(flags_->png8514, result_.raster, provenance_);
      written.push_back(flags_->png8514);
    }
    return written;
  }
  void summary(const std::vector<std::string>& written) const override {
    std::string list;
    for (const std::string& f : written) list += (list.empty() ? ": " : ", ") + f;
    printSummary(result_, list);
  }
  void timings() const override {
    std::printf("timings: read %.3f s, build %.3f s (scene %.3f s, BVH %.3f s), render %.3f s\n",
                load_.read, load_.build + result_.setupSeconds, load_.build, result_.setupSeconds,
                result_.run.seconds);
  }
  double seconds() const override { return result_.run.seconds; }
  int pictureRows() const override { return scene_->viewer.yRes; }

 private:
  std::shared_ptr<MaloneOptions> o_;
  std::shared_ptr<TraceFlags> flags_;
  std::shared_ptr<std::string> ppm_;
  LoadTimings load_;
  std::optional<prime::malone::Scene> scene_;
  std::optional<display::LiveRgbFrame> frame_;
  prime::malone::RenderResult result_;
};

}  // namespace

TraceFactory addTraceOptions(CLI::App* cmd, const std::shared_ptr<TraceFlags>& flags) {
  auto o = std::make_shared<MaloneOptions>();
  auto ppm = std::make_shared<std::string>();
  addMaloneOptions(cmd, *o);
  cmd->add_option("--ppm,--out", *ppm,
                  "Write the picture as a binary PPM (P6), as the original did (--out: the same, "
                  "the system's own picture as every system names it)")
      ->check(outputName());
  flags->camera = &o->camera;
  flags->ownOutputs = {ppm.get()};
  return [o, flags, ppm] { return std::make_unique<MaloneTrace>(o, flags, ppm); };
}

}  // namespace prime::cli::malone
