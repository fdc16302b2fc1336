// prime walk DIR: PRIME's part of the shared walk (src/cli/walk.h, T38-T42).
// The picture is the free camera's (src/geom/free_camera.h; the listing's
// camera is replaced by it in every profile, T31), traced by the chosen
// profile's tracer one ray per pixel (src/prime/render/walk_render.h); P
// cycles the 1991, modern and thesis profiles (T41), L selects a light to
// move, V switches between true colour and the 8514/A palette (G22). The
// first frame is the listing's window framed at 512 x 512 (T34), or the
// camera the flags give, at 512 x 512 unless --size says otherwise.
#include <algorithm>
#include <string>
#include <vector>

#include "palette/prime/color_num.h"
#include "palette/prime/export.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/commands.h"
#include "src/cli/prime/probe_pixel.h"
#include "src/cli/prime/render_options.h"
#include "src/prime/render/walk_render.h"
#include "src/prime/scene/object_bvh.h"

namespace prime::cli {

namespace {

// The profiles walk can trace, in P's order (T41).
const std::vector<Profile>& walkProfiles() {
  static const std::vector<Profile> all{Profile::Listing1991, Profile::Modern, Profile::Thesis};
  return all;
}

std::uint32_t xrgb(Rgb8 c) {
  return (static_cast<std::uint32_t>(c.r) << 16) | (static_cast<std::uint32_t>(c.g) << 8) | c.b;
}

class PrimeWalkFrame : public WalkFrame {
 public:
  PrimeWalkFrame(Scene scene, Profile profile, const RenderSettings& settings)
      : scene_(std::move(scene)), renderer_(scene_, profile, settings.trace, settings.thesis) {}
  bool pass(const FreeCamera& camera, int block, int firstBlock, RgbImage& out, int threads,
            const std::atomic<bool>* abandon, const std::function<void(int, int)>& rowsDone,
            std::uint64_t& rays, ThreadReport* report) override {
    TraceStats stats;
    const bool done =
        renderer_.pass(camera, block, firstBlock, out, threads, abandon, rowsDone, stats, report);
    rays += stats.rays();
    return done;
  }

 private:
  Scene scene_;  // with the lights where the user put them
  WalkRenderer renderer_;
};

class PrimeWalkScene : public WalkScene {
 public:
  PrimeWalkScene(Scene scene, RenderSettings settings)
      : scene_(std::move(scene)),
        settings_(std::move(settings)),
        table_(settings_.mapping == ColorMapping::Plate3 ? plate3Palette() : initPalette()) {}

  std::vector<std::string> profiles() const override {
    const std::string fixes = fixIds(settings_.trace.fixes);
    return {fixes.empty() ? "1991" : "1991 --fix " + fixes, "modern", "thesis"};
  }
  int firstProfile() const override {
    const auto& all = walkProfiles();
    return static_cast<int>(std::find(all.begin(), all.end(), settings_.profile) - all.begin());
  }
  std::vector<Vec3> lights() const override {
    std::vector<Vec3> out;
    for (const auto& l : scene_.lights) out.push_back(l.pt);
    return out;
  }
  bool paletteView() const override { return true; }
  std::unique_ptr<WalkFrame> frame(const WalkView& view) const override {
    Scene lit = scene_;
    for (std::size_t i = 0; i < view.lights.size() && i < lit.lights.size(); ++i)
      lit.lights[i].pt = view.lights[i];
    return std::make_unique<PrimeWalkFrame>(
        std::move(lit), walkProfiles()[static_cast<std::size_t>(view.profile)], settings_);
  }
  std::optional<ProbedPixel> probe(const WalkView& view, int x, int y) const override {
    Scene lit = scene_;
    for (std::size_t i = 0; i < view.lights.size() && i < lit.lights.size(); ++i)
      lit.lights[i].pt = view.lights[i];
    RenderSettings settings = settings_;
    settings.profile = walkProfiles()[static_cast<std::size_t>(view.profile)];
    settings.camera.free = view.view.camera();
    const PrimeCamera camera(settings.camera);
    return probePixel(lit, settings, camera.primaryRay(y, x), pixelWhere(camera, x, y), x, y);
  }
  // True colour, or each colour's palette index (ColorNum / X1 as the
  // settings map it) through the palette's 8-bit table (the 8514/A view
  // without its DAC rounding: G22).
  void paint(const WalkView& view, const RgbImage& image, int row,
             std::span<std::uint32_t> out) const override {
    TraceStats ignored;
    for (int x = 0; x < image.width; ++x) {
      const Rgb& c = image.at(row, x);
      if (view.paletteView) {
        const PaletteRgb p =
            table_[static_cast<std::size_t>(paletteIndex(c, settings_, ignored) & 0xFF)];
        out[static_cast<std::size_t>(x)] =
            xrgb({static_cast<std::uint8_t>(p.r), static_cast<std::uint8_t>(p.g),
                  static_cast<std::uint8_t>(p.b)});
      } else {
        out[static_cast<std::size_t>(x)] = xrgb(trueColour(c));
      }
    }
  }

 private:
  Scene scene_;
  RenderSettings settings_;
  PaletteTable table_;
};

}  // namespace

WalkFactory addWalkOptions(CLI::App* cmd, const std::shared_ptr<WalkFlags>& flags) {
  auto dir = std::make_shared<std::string>();
  auto options = std::make_shared<RenderOptions>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(sceneDirectory());
  addRenderOptions(cmd, *options, false);  // one ray per pixel: no sampling options
  return [dir, options, flags]() -> WalkJob {
    // A free camera is 512 x 512 unless --size says otherwise (T34).
    finishRenderOptions(*options, 512);
    RenderSettings settings = options->settings;
    settings.threads = flags->threads;
    if (std::find(walkProfiles().begin(), walkProfiles().end(), settings.profile) ==
        walkProfiles().end())
      throw CLI::ValidationError("--profile",
                                 "prime walk traces the 1991, modern and thesis profiles only");
    // Without free-camera options: the listing's window framed at 512 x 512.
    if (!settings.camera.free)
      settings.camera.free = framedListingWindow(settings.camera, 512, 512);
    Scene scene = prepareScene(*dir, options->model);
    // The centre of the box round the scene's objects (as the set operations
    // make them); the look-at point when no object is bounded (T42).
    const Aabb box = ObjectBvh(scene, ObjectBvh::ObjectBoxes::kSolid).objectsBox();
    WalkJob job;
    job.name = *dir;
    job.camera = *settings.camera.free;
    job.centre = box.empty() ? job.camera.lookAt : box.centre();
    job.scene = std::make_unique<PrimeWalkScene>(std::move(scene), std::move(settings));
    return job;
  };
}

}  // namespace prime::cli
