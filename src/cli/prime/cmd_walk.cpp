// prime walk DIR: walk around a PRIME scene in a window (T38-T41). The
// picture is the free camera's (src/geom/free_camera.h; the listing's camera
// is replaced by it in every profile, T31), rendered coarse to fine (blocks of
// 8, 4, 2, 1 pixels) on the shared row scheduler; any key or mouse move
// abandons the frame in flight and starts again from the coarse pass.
//
// The first frame is the scene's own camera (the listing's eye looking at
// its window's centre, the window framed at 512 x 512) or the camera the
// flags give (src/cli/camera_flags.h); the camera turns about the centre of
// the scene's objects (--pivot), which so stays on its pixel of the picture.
//
// Keys: arrows / left-drag orbit, shift+arrows / right-drag pan, I O and the
// wheel dolly, Home or R resets, L cycles camera / light 1 / light 2 ... (a
// selected light moves with the same keys and drags instead of the camera),
// P switches the profile, V switches between true colour and the 8514/A
// palette, C prints the camera as flags and appends it to the camera file;
// as in every window: S F12 screenshot, + - 1..8 zoom, F11, Esc quits.
//
// --bench N renders N frames headless along an orbit and prints the first
// coarse pass's latency and the frame rates (docs/prime/interactive.md).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <string>
#include <vector>

#include "palette/prime/color_num.h"
#include "palette/prime/export.h"
#include "palette/window/live_rgb_frame.h"
#include "palette/window/screen_window.h"
#include "src/cli/camera_flags.h"
#include "src/cli/commands.h"
#include "src/cli/prime/display_options.h"
#include "src/cli/prime/render_options.h"
#include "src/prime/render/walk_render.h"
#include "src/prime/scene/object_bvh.h"
#include "src/render/progressive.h"
#include "src/render/walk_controller.h"

namespace prime::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct WalkState {
  OrbitView view;
  std::vector<Vec3> lights;
  Profile profile = Profile::Listing1991;
  bool paletteView = false;
};

const char* profileName(Profile p) {
  return p == Profile::Modern ? "modern" : p == Profile::Thesis ? "thesis" : "1991";
}

// The profiles walk can trace, in P's order (T41).
const std::vector<Profile>& walkProfiles() {
  static const std::vector<Profile> all{Profile::Listing1991, Profile::Modern, Profile::Thesis};
  return all;
}

// A scene with the lights where the user put them.
Scene withLights(const Scene& base, const std::vector<Vec3>& lights) {
  Scene s = base;
  for (std::size_t i = 0; i < lights.size() && i < s.lights.size(); ++i) s.lights[i].pt = lights[i];
  return s;
}

std::uint32_t xrgb(Rgb8 c) {
  return (static_cast<std::uint32_t>(c.r) << 16) | (static_cast<std::uint32_t>(c.g) << 8) | c.b;
}

// Rows of the picture as the window shows them: true colour, or each
// colour's palette index (ColorNum / X1 as the settings map it) through the
// palette's 8-bit table (the 8514/A view without its DAC rounding: G22).
class RowPainter {
 public:
  RowPainter(const RenderSettings& settings, int width)
      : settings_(settings),
        table_(settings.mapping == ColorMapping::Plate3 ? plate3Palette() : initPalette()),
        row_(static_cast<std::size_t>(width)) {}
  void paint(display::LiveRgbFrame& frame, const RgbImage& image, int row, bool palette) {
    TraceStats ignored;
    for (int x = 0; x < image.width; ++x) {
      const Rgb& c = image.at(row, x);
      if (palette) {
        const PaletteRgb p =
            table_[static_cast<std::size_t>(paletteIndex(c, settings_, ignored) & 0xFF)];
        row_[static_cast<std::size_t>(x)] =
            xrgb({static_cast<std::uint8_t>(p.r), static_cast<std::uint8_t>(p.g),
                  static_cast<std::uint8_t>(p.b)});
      } else {
        row_[static_cast<std::size_t>(x)] = xrgb(trueColour(c));
      }
    }
    frame.setRow(row, row_);
  }

 private:
  const RenderSettings& settings_;
  PaletteTable table_;
  std::vector<std::uint32_t> row_;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int runBench(const Scene& scene, const RenderSettings& settings, const OrbitView& start,
             int frames) {
  const FreeCamera first(start.camera());
  RgbImage image;
  image.assign(first.columns(), first.rows());
  std::vector<double> coarse, full, single, cpuFull, cpuSingle;
  OrbitView view = start;
  const WalkRenderer renderer(scene, settings.profile, settings.trace, settings.thesis);
  TraceStats stats;
  for (int k = 0; k < frames; ++k) {
    view.orbit(360.0 / std::max(frames, 1) * 0.25, 0.0);  // a quarter turn over the run
    const FreeCamera camera(view.camera());
    const Clock::time_point t0 = Clock::now();
    const double c0 = cpuSeconds();
    for (const int block : kProgressiveBlocks) {
      renderer.pass(camera, block, kProgressiveBlocks[0], image, settings.threads, nullptr, {},
                    stats);
      if (block == kProgressiveBlocks[0]) coarse.push_back(msSince(t0));
    }
    full.push_back(msSince(t0));
    cpuFull.push_back(1000.0 * (cpuSeconds() - c0));
    const Clock::time_point t1 = Clock::now();
    const double c1 = cpuSeconds();
    renderer.pass(camera, 1, 1, image, settings.threads, nullptr, {}, stats);
    single.push_back(msSince(t1));
    cpuSingle.push_back(1000.0 * (cpuSeconds() - c1));
  }
  const double f = median(full), s = median(single);
  std::printf("walk bench: %s, %d x %d, profile %s, %d frames, %d thread(s) asked (0: all)\n",
              scene.name.c_str(), first.columns(), first.rows(), profileName(settings.profile),
              frames, settings.threads);
  std::printf("first coarse pass (8 x 8 blocks): median %.1f ms\n", median(coarse));
  std::printf("progressive frame (8, 4, 2, 1): median %.1f ms wall, %.1f ms CPU = %.2f fps\n", f,
              median(cpuFull), f > 0 ? 1000.0 / f : 0.0);
  std::printf("full-resolution pass alone:     median %.1f ms wall, %.1f ms CPU = %.2f fps\n", s,
              median(cpuSingle), s > 0 ? 1000.0 / s : 0.0);
  return 0;
}

// The centre of the box round the scene's objects (as the set operations
// make them): what the walk turns about. The window's centre when the scene
// has no bounded object.
Vec3 sceneCentre(const Scene& scene, const Vec3& otherwise) {
  const Aabb all = ObjectBvh(scene, ObjectBvh::ObjectBoxes::kSolid).objectsBox();
  if (all.empty()) return otherwise;
  return all.centre();
}

struct WalkWindowOptions {
  DisplayOptions display;
  std::string caption, sceneDir, cameraFile = kDefaultCameraFile;
  bool logFrames = false;
};

int runWindow(const Scene& scene, const RenderSettings& settings, const OrbitView& start,
              const WalkWindowOptions& options) {
  const DisplayOptions& display = options.display;
  const std::string& caption = options.caption;
  const bool logFrames = options.logFrames;
  if (auto why = display::headlessReason(display.noWindow))
    throw CLI::ValidationError("walk", "needs a window (" + *why + "); --bench N runs headless");
  std::vector<Vec3> lights;
  for (const auto& l : scene.lights) lights.push_back(l.pt);
  const auto& profiles = walkProfiles();
  WalkController ctl(start, lights, static_cast<int>(profiles.size()));
  if (std::find(profiles.begin(), profiles.end(), settings.profile) == profiles.end())
    throw CLI::ValidationError("--profile",
                               "prime walk traces the 1991, modern and thesis profiles only");
  while (profiles[static_cast<std::size_t>(ctl.profile())] != settings.profile) ctl.nextProfile();

  display::LiveRgbFrame frame(start.width, start.height);
  RgbImage image;
  image.assign(start.width, start.height);
  RowPainter painter(settings, start.width);
  std::atomic<int> passBlock{0};
  std::atomic<double> passMs{0.0}, frameMs{0.0};
  std::atomic<int> framesDone{0};

  LatestJobRunner<WalkState> runner(
      [&](const WalkState& st, std::uint64_t, const std::atomic<bool>& abandon) {
        const Clock::time_point t0 = Clock::now();
        const Scene lit = withLights(scene, st.lights);
        const WalkRenderer renderer(lit, st.profile, settings.trace, settings.thesis);
        const FreeCamera camera(st.view.camera());
        TraceStats stats;
        for (const int block : kProgressiveBlocks) {
          const bool done = renderer.pass(
              camera, block, kProgressiveBlocks[0], image, settings.threads, &abandon,
              [&](int row0, int rows) {
                for (int y = row0; y < row0 + rows; ++y)
                  painter.paint(frame, image, y, st.paletteView);
              },
              stats);
          if (!done) return;
          passBlock = block;
          passMs = msSince(t0);
        }
        frameMs = msSince(t0);
        const int n = ++framesDone;
        if (logFrames)
          std::fprintf(stderr, "prime: walk: frame %d done in %.1f ms (%s%s)\n", n, frameMs.load(),
                       profileName(st.profile), st.paletteView ? ", 8514/A view" : "");
      });

  display::ScreenWindow window(frame, {caption, display.zoom, "."});
  std::fprintf(
      stderr,
      "prime: walk: window 0x%lx, %d x %d: arrows / left-drag orbit, shift+arrows / "
      "right-drag pan, I O wheel dolly, Home R reset, L lights, P profile, V palette "
      "view, C camera; as in every window: S F12 screenshot, + - 1..8 zoom, F11 fullscreen, Esc "
      "quits\n",
      window.nativeId(), start.width, start.height);
  auto stateOf = [&] {
    return WalkState{ctl.view(), ctl.lights(), profiles[static_cast<std::size_t>(ctl.profile())],
                     ctl.paletteView()};
  };
  window.setInputHandler([&](const display::module::Event& e) -> bool {
    using display::module::Event;
    using display::module::Key;
    switch (e.type) {
      case Event::Type::MouseMotion:
        if (e.buttons & 1u)
          ctl.drag(true, e.dx, e.dy);
        else if (e.buttons & 4u)
          ctl.drag(false, e.dx, e.dy);
        return true;
      case Event::Type::Wheel:
        ctl.dolly(e.wheel);
        return true;
      case Event::Type::MouseButton:
        return true;
      case Event::Type::Key:
        break;
      default:
        return false;
    }
    const int sx = e.key == Key::Left ? -1 : e.key == Key::Right ? 1 : 0;
    const int sy = e.key == Key::Down ? -1 : e.key == Key::Up ? 1 : 0;
    if (sx != 0 || sy != 0) {
      if (e.shift)
        ctl.panArrows(sx, sy);
      else
        ctl.arrows(sx, sy);
      return true;
    }
    if (e.key == Key::Home || e.letter == 'r') return ctl.reset(), true;
    // The window's own keys mean what they mean in trace and view: S and F12
    // screenshot, + - and 1..8 zoom, F11 fullscreen, Esc quit.
    if (e.letter == 'i') return ctl.dolly(1), true;
    if (e.letter == 'o') return ctl.dolly(-1), true;
    if (e.letter == 'l') return ctl.cycleSelection(), true;
    if (e.letter == 'p') return ctl.nextProfile(), true;
    if (e.letter == 'v') return ctl.togglePaletteView(), true;
    if (e.letter == 'c') {
      // The camera as flags that render this very frame with trace, probe,
      // compare or walk, on stdout; and appended to the camera file.
      const FreeCameraSettings camera = ctl.view().camera();
      std::printf("%s\n", cameraFlagsText(camera).c_str());
      std::fflush(stdout);
      try {
        appendCamera(options.cameraFile, camera,
                     "prime walk " + options.sceneDir + ", profile " +
                         profileName(profiles[static_cast<std::size_t>(ctl.profile())]) +
                         (ctl.selectedLight() > 0 || ctl.lights() != lights
                              ? " (lights moved: not part of the camera)"
                              : ""));
        std::fprintf(stderr, "prime: walk: camera appended to %s (prime trace %s --camera %s)\n",
                     options.cameraFile.c_str(), options.sceneDir.c_str(),
                     options.cameraFile.c_str());
      } catch (const std::exception& err) {
        std::fprintf(stderr, "prime: walk: camera not saved: %s\n", err.what());
      }
      return true;
    }
    return false;  // the window's
  });

  std::uint64_t shown = ctl.generation();
  runner.request(stateOf());
  std::string lastStatus;
  while (!window.poll(15)) {
    if (ctl.generation() != shown) {
      shown = ctl.generation();
      passBlock = 0;
      runner.request(stateOf());
    }
    const int block = passBlock.load();
    char status[160];
    const double fm = frameMs.load();
    std::snprintf(status, sizeof status, "%s%s - %s - %s%s",
                  profileName(profiles[static_cast<std::size_t>(ctl.profile())]),
                  ctl.paletteView() ? " 8514/A" : "",
                  block == 0 ? "rendering" : ("pass 1/" + std::to_string(block)).c_str(),
                  fm > 0 ? (std::to_string(static_cast<int>(std::lround(fm))) + " ms/frame (" +
                            std::to_string(1000.0 / fm).substr(0, 4) + " fps)")
                               .c_str()
                         : "",
                  ctl.selectedLight() > 0
                      ? (" - moving light " + std::to_string(ctl.selectedLight())).c_str()
                      : "");
    if (status != lastStatus) {
      lastStatus = status;
      window.setStatus(status);
    }
  }
  return 0;
}

}  // namespace

void addWalkCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "walk", "Walk around a scene in a window: orbit, pan, dolly, move lights; progressive");
  auto dir = std::make_shared<std::string>();
  auto options = std::make_shared<RenderOptions>();
  auto bench = std::make_shared<int>(0);
  auto window = std::make_shared<WalkWindowOptions>();
  auto pivot = std::make_shared<std::vector<double>>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--threads", options->settings.threads, "Render threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--bench", *bench,
                  "Headless: render N frames along an orbit and print latency and frame rates")
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("--log-frames", window->logFrames,
                "Say on stderr when each frame is complete (tests)");
  cmd->add_option("--pivot", *pivot,
                  "The point the camera turns about (default: the centre of the scene's objects)")
      ->expected(3)
      ->allow_extra_args(false);
  cmd->add_option("--camera-file", window->cameraFile,
                  "Where the C key appends the camera (default: prime-cameras.txt here)");
  addWindowOptions(cmd, window->display);
  addRenderOptions(cmd, *options, false);  // one ray per pixel: no sampling options
  cmd->callback([=, &action] {
    action = [=] {
      // A free camera is 512 x 512 unless --size says otherwise (T41).
      finishRenderOptions(*options, 512);
      RenderSettings settings = options->settings;
      // Without free-camera options: the listing's window framed at 512 x 512.
      if (!settings.camera.free)
        settings.camera.free = framedListingWindow(settings.camera, 512, 512);
      const Scene scene = prepareScene(*dir, options->model);
      const Vec3 centre = pivot->size() == 3 ? Vec3{(*pivot)[0], (*pivot)[1], (*pivot)[2]}
                                             : sceneCentre(scene, settings.camera.free->lookAt);
      const OrbitView start = OrbitView::from(*settings.camera.free, centre);
      if (*bench > 0) return runBench(scene, settings, start, *bench);
      WalkWindowOptions w = *window;
      w.caption = w.sceneDir = *dir;
      return runWindow(scene, settings, start, w);
    };
  });
}

}  // namespace prime::cli
