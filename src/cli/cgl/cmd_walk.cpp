// prime walk SCENE.cgl: the Waterloo CGL package's part of the shared walk
// (src/cli/walk.h): the display parameters made a free camera (CGL-D61)
// that orbits the centre of the object nodes' boxes, each frame traced one
// ray per pixel through the pixel's corner (aalevel 0, Figure 41) in the
// W x H window in the middle of the 512 x 512 screen, by CGL's own tracer.
#include <cmath>
#include <string>
#include <vector>

#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"
#include "src/cli/cgl/probe_pixel.h"
#include "src/render/render_rows.h"

namespace prime::cli::cgl {

namespace {

using prime::cgl::Tracer;
using prime::cgl::TraceStats;

class CglWalkFrame : public WalkFrame {
 public:
  CglWalkFrame(const Tracer& tracer, std::string path) : tracer_(tracer), path_(std::move(path)) {}
  bool pass(const FreeCamera& camera, int block, int firstBlock, RgbImage& out, int threads,
            const std::atomic<bool>* abandon, const std::function<void(int, int)>& rowsDone,
            std::uint64_t& rays, ThreadReport* report) override {
    const prime::cgl::Camera cam =
        prime::cgl::cameraOf(prime::cgl::displayOf(camera.settings()), path_);
    // The window `--size W H` makes (src/cli/cgl/options.h): picture row r,
    // column c is the screen's scanline yhigh - r, pixel xleft + c.
    const int xleft = 256 - camera.columns() / 2;
    const int yhigh = 256 - camera.rows() / 2 + camera.rows() - 1;
    std::vector<TraceStats> perThread(
        static_cast<std::size_t>(threadCount(threads, (camera.rows() + block - 1) / block)));
    const bool done = progressivePass(
        camera.columns(), camera.rows(), block, firstBlock, threads, abandon, rowsDone,
        [&](int row, int column, int thread) {
          const prime::cgl::Rgb8 c = tracer_.screenPoint(
              cam, xleft + column, yhigh - row, perThread[static_cast<std::size_t>(thread)]);
          return Rgb{c.r / 255.0, c.g / 255.0, c.b / 255.0};
        },
        out, report);
    for (const TraceStats& s : perThread) rays += s.rays.rays();
    return done;
  }

 private:
  const Tracer& tracer_;
  std::string path_;
};

class CglWalkScene : public WalkScene {
 public:
  CglWalkScene(prime::cgl::Scene scene, const prime::cgl::RenderSettings& settings,
               std::string file, std::string profile)
      : profile_(std::move(profile)),
        scene_(std::move(scene)),
        tracer_(scene_, prime::cgl::traceSettings(settings)),
        settings_(settings),
        file_(std::move(file)) {}
  // The probe through the display parameters of the moment (CGL-D61): pixel
  // (x, y) of the W x H window is the screen point (xleft + x, yhigh - y).
  std::optional<ProbedPixel> probe(const WalkView& view, int x, int y) const override {
    const FreeCamera camera(view.view.camera());
    prime::cgl::Scene moved = scene_;
    moved.camera = prime::cgl::cameraOf(prime::cgl::displayOf(camera.settings()), scene_.path);
    const int xleft = 256 - camera.columns() / 2;
    const int yhigh = 256 - camera.rows() / 2 + camera.rows() - 1;
    return probePoint(moved, settings_, file_,
                      "pixel " + std::to_string(x) + " " + std::to_string(y) + " of the " +
                          std::to_string(camera.columns()) + " x " + std::to_string(camera.rows()) +
                          " window",
                      xleft + x, yhigh - y)
        .placedAt(-xleft, -(prime::cgl::Frame::kSize - 1 - yhigh));
  }
  // The one --profile chose (its scene is built for it: CGL-D180's cells or none).
  std::vector<std::string> profiles() const override { return {profile_}; }
  std::unique_ptr<WalkFrame> frame(const WalkView&) const override {
    return std::make_unique<CglWalkFrame>(tracer_, scene_.path);
  }
  // The frame buffer's bytes.
  void paint(const WalkView&, const RgbImage& image, int row,
             std::span<std::uint32_t> out) const override {
    auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(v * 255.0)); };
    for (int x = 0; x < image.width; ++x) {
      const Rgb& c = image.at(row, x);
      out[static_cast<std::size_t>(x)] = byte(c[0]) << 16 | byte(c[1]) << 8 | byte(c[2]);
    }
  }
  std::string cameraNote() const override {
    return "walk traces one ray per pixel: trace it with --aalevel 0 for this very frame";
  }

 private:
  std::string profile_;
  prime::cgl::Scene scene_;
  Tracer tracer_;  // over scene_: built once
  prime::cgl::RenderSettings settings_;
  std::string file_;
};

}  // namespace

WalkFactory addWalkOptions(CLI::App* cmd, const std::shared_ptr<WalkFlags>&) {
  auto o = std::make_shared<CglOptions>();
  addCglOptions(cmd, *o);
  return [o]() -> WalkJob {
    const prime::cgl::SceneFile file = readCgl(*o, o->quiet);
    prime::cgl::Scene scene = buildCgl(*o, file);
    const prime::cgl::RenderSettings settings = renderSettings(*o, file);
    Aabb box;
    for (const auto& obj : scene.objects) {
      if (obj.kind == prime::cgl::ObjectKind::Box || obj.box.empty()) continue;
      bool finite = true;
      for (int i = 0; i < 3; ++i)
        finite = finite && std::isfinite(obj.box.lo[i]) && std::isfinite(obj.box.hi[i]);
      if (finite) box.add(obj.box);
    }
    WalkJob job;
    job.name = o->file;
    // The camera the flags made (exactly, with its size), else the scene's own
    // over the whole screen.
    job.camera = o->applied ? *o->applied : prime::cgl::freeCamera(file.display);
    job.centre = box.empty() ? job.camera.lookAt : box.centre();
    job.scene = std::make_unique<CglWalkScene>(std::move(scene), settings, o->file, o->profile);
    return job;
  };
}

}  // namespace prime::cli::cgl
