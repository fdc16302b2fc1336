// prime walk SCENE.mal: Malone's part of the shared walk (src/cli/walk.h):
// the scene's viewer made a free camera (MAL-D7) that orbits the centre of
// the primitives' boxes, each frame traced one ray per pixel through the
// viewer of the moment by Malone's own tracer, shown as its PPM would be.
#include <string>
#include <vector>

#include "legacy_io/malone/ppm.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"
#include "src/cli/malone/probe_pixel.h"
#include "src/malone/primitives.h"
#include "src/render/render_rows.h"

namespace prime::cli::malone {

namespace {

using prime::malone::Tracer;
using prime::malone::TraceStats;

class MaloneWalkFrame : public WalkFrame {
 public:
  explicit MaloneWalkFrame(const Tracer& tracer) : tracer_(tracer) {}
  bool pass(const FreeCamera& camera, int block, int firstBlock, RgbImage& out, int threads,
            const std::atomic<bool>* abandon, const std::function<void(int, int)>& rowsDone,
            std::uint64_t& rays, ThreadReport* report) override {
    const prime::malone::ViewerRays primary(prime::malone::viewerOf(camera.settings()));
    std::vector<TraceStats> perThread(
        static_cast<std::size_t>(threadCount(threads, (camera.rows() + block - 1) / block)));
    const bool done = progressivePass(
        camera.columns(), camera.rows(), block, firstBlock, threads, abandon, rowsDone,
        [&](int row, int column, int thread) {
          return tracer_.pixel(primary(column, row), perThread[static_cast<std::size_t>(thread)]);
        },
        out, report);
    for (const TraceStats& s : perThread) rays += s.rays();
    return done;
  }

 private:
  const Tracer& tracer_;
};

class MaloneWalkScene : public WalkScene {
 public:
  MaloneWalkScene(prime::malone::Scene scene, prime::malone::TraceSettings settings,
                  std::string file)
      : scene_(std::move(scene)), tracer_(scene_, settings), file_(std::move(file)) {}
  // The probe through the viewer of the moment (MAL-D7), as `prime probe
  // --camera` gives it.
  std::optional<ProbedPixel> probe(const WalkView& view, int x, int y) const override {
    prime::malone::Scene moved = scene_;
    moved.viewer = prime::malone::viewerOf(view.view.camera());
    return probePixel(moved, tracer_.settings(), file_, x, y);
  }
  std::vector<std::string> profiles() const override { return {"document"}; }
  std::unique_ptr<WalkFrame> frame(const WalkView&) const override {
    return std::make_unique<MaloneWalkFrame>(tracer_);
  }
  // As the PPM's bytes (raster2ppm).
  void paint(const WalkView&, const RgbImage& image, int row,
             std::span<std::uint32_t> out) const override {
    for (int x = 0; x < image.width; ++x) {
      const Rgb& c = image.at(row, x);
      out[static_cast<std::size_t>(x)] =
          (static_cast<std::uint32_t>(prime::malone::toByte(c[0])) << 16) |
          (static_cast<std::uint32_t>(prime::malone::toByte(c[1])) << 8) |
          static_cast<std::uint32_t>(prime::malone::toByte(c[2]));
    }
  }

 private:
  prime::malone::Scene scene_;
  Tracer tracer_;  // over scene_: built once, lights and primitives fixed
  std::string file_;
};

}  // namespace

WalkFactory addWalkOptions(CLI::App* cmd, const std::shared_ptr<WalkFlags>&) {
  auto o = std::make_shared<MaloneOptions>();
  addMaloneOptions(cmd, *o);
  return [o]() -> WalkJob {
    prime::malone::Scene scene = loadMalone(*o);
    Aabb box;
    for (const auto& p : scene.primitives) {
      const Aabb b = prime::malone::bounds(scene, p);
      bool finite = !b.empty();
      for (int i = 0; i < 3 && finite; ++i)
        finite = std::isfinite(b.lo[i]) && std::isfinite(b.hi[i]);
      if (finite) box.add(b);
    }
    WalkJob job;
    job.name = o->file;
    job.camera = o->applied ? *o->applied : prime::malone::freeCamera(scene.viewer);
    job.centre = box.empty() ? job.camera.lookAt : box.centre();
    job.scene = std::make_unique<MaloneWalkScene>(std::move(scene), o->trace, o->file);
    return job;
  };
}

}  // namespace prime::cli::malone
