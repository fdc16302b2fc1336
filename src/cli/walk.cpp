#include "src/cli/walk.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "palette/window/live_rgb_frame.h"
#include "palette/window/screen_window.h"
#include "src/bench/measure.h"
#include "src/cli/camera_path_file.h"
#include "src/cli/pixel_inspector.h"
#include "src/cli/system.h"
#include "src/render/progressive.h"
#include "src/render/walk_controller.h"

namespace prime::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// Each thread's share of the full-resolution passes, per frame.
void printThreadReport(const ThreadReport& report, int frames) {
  for (std::size_t k = 0; k < report.loads.size(); ++k) {
    const ThreadLoad& l = report.loads[k];
    std::string cpu =
        l.cpuFirst < 0 ? std::string("CPU not known") : "CPU " + std::to_string(l.cpuFirst);
    if (l.cpuLast >= 0 && l.cpuLast != l.cpuFirst) cpu += " .. " + std::to_string(l.cpuLast);
    if (l.migrated) cpu += ", moved between CPUs";
    std::printf("  thread %zu: %.1f rows, %.1f ms CPU per frame, %s\n", k,
                static_cast<double>(l.rows) / frames, 1000.0 * l.cpuSeconds / frames, cpu.c_str());
  }
}

int runBench(const WalkJob& job, const OrbitView& start, const WalkFlags& flags) {
  const WalkScene& scene = *job.scene;
  const FreeCamera first(start.camera());
  RgbImage image;
  image.assign(first.columns(), first.rows());
  std::vector<double> coarse, full, single, cpuFull, cpuSingle, singleOne, cpuSingleOne;
  WalkView state{start, scene.lights(), scene.firstProfile(), false};
  const std::unique_ptr<WalkFrame> renderer = scene.frame(state);
  std::uint64_t rays = 0;
  const int frames = flags.bench;
  // The speed-up from one thread to N: each frame's full-resolution pass
  // again on one thread (pinned like thread 0 when --pin).
  const int threads = threadCount(flags.threads, first.rows());
  ThreadReport report, reportOne;
  report.pin = reportOne.pin = flags.pin;
  for (int k = 0; k < frames; ++k) {
    state.view.orbit(360.0 / std::max(frames, 1) * 0.25, 0.0);  // a quarter turn over the run
    const FreeCamera camera(state.view.camera());
    const Clock::time_point t0 = Clock::now();
    const double c0 = bench::processCpuSeconds();
    for (const int block : kProgressiveBlocks) {
      renderer->pass(camera, block, kProgressiveBlocks[0], image, flags.threads, nullptr, {}, rays,
                     nullptr);
      if (block == kProgressiveBlocks[0]) coarse.push_back(msSince(t0));
    }
    full.push_back(msSince(t0));
    cpuFull.push_back(1000.0 * (bench::processCpuSeconds() - c0));
    const Clock::time_point t1 = Clock::now();
    const double c1 = bench::processCpuSeconds();
    renderer->pass(camera, 1, 1, image, flags.threads, nullptr, {}, rays, &report);
    single.push_back(msSince(t1));
    cpuSingle.push_back(1000.0 * (bench::processCpuSeconds() - c1));
    if (threads > 1) {
      const Clock::time_point t2 = Clock::now();
      const double c2 = bench::processCpuSeconds();
      renderer->pass(camera, 1, 1, image, 1, nullptr, {}, rays, &reportOne);
      singleOne.push_back(msSince(t2));
      cpuSingleOne.push_back(1000.0 * (bench::processCpuSeconds() - c2));
    }
  }
  const double f = bench::median(full), s = bench::median(single);
  std::printf("walk bench: %s, %d x %d, profile %s, %d frames, %d thread(s) asked (0: all)\n",
              job.name.c_str(), first.columns(), first.rows(),
              scene.profiles()[static_cast<std::size_t>(state.profile)].c_str(), frames,
              flags.threads);
  std::printf("first coarse pass (8 x 8 blocks): median %.1f ms\n", bench::median(coarse));
  std::printf("progressive frame (8, 4, 2, 1): median %.1f ms wall, %.1f ms CPU = %.2f fps\n", f,
              bench::median(cpuFull), f > 0 ? 1000.0 / f : 0.0);
  std::printf("full-resolution pass alone:     median %.1f ms wall, %.1f ms CPU = %.2f fps\n", s,
              bench::median(cpuSingle), s > 0 ? 1000.0 / s : 0.0);
  std::printf("threads of the full-resolution pass: %d%s\n", threads,
              flags.pin ? ", pinned" : " (not pinned: --pin pins them)");
  printThreadReport(report, frames);
  if (threads > 1) {
    const double one = bench::median(singleOne);
    std::printf(
        "the same pass on 1 thread:      median %.1f ms wall, %.1f ms CPU; speed-up 1 -> %d "
        "threads %.2f\n",
        one, bench::median(cpuSingleOne), threads, s > 0 ? one / s : 0.0);
    printThreadReport(reportOne, frames);
  }
  return 0;
}

// C: the camera as flags on stdout, appended to the camera file.
void saveCamera(const WalkJob& job, const WalkFlags& flags, const WalkController& ctl,
                const std::vector<Vec3>& startLights) {
  const WalkScene& scene = *job.scene;
  std::string comment = "prime walk " + job.name + ", profile " +
                        scene.profiles()[static_cast<std::size_t>(ctl.profile())];
  if (ctl.lights() != startLights) comment += " (lights moved: not part of the camera)";
  if (!scene.cameraNote().empty()) comment += " (" + scene.cameraNote() + ")";
  cameraKey(ctl.view().camera(), comment, flags.cameraFile, "");
}

// K: the camera as a key of the scene's camera path.
void addPathKey(const WalkJob& job, const WalkFlags& flags, const WalkController& ctl) {
  const std::string file = flags.pathFile.empty() ? defaultPathFile(job.name) : flags.pathFile;
  const WalkScene& scene = *job.scene;
  try {
    appendPathKey(file, ctl.view().camera(),
                  "prime walk " + job.name + ", profile " +
                      scene.profiles()[static_cast<std::size_t>(ctl.profile())]);
    std::fprintf(stderr,
                 "prime: key added to the camera path %s (prime trace %s --camera-path %s "
                 "--out frame%%04d... renders it)\n",
                 file.c_str(), job.name.c_str(), file.c_str());
  } catch (const std::exception& err) {
    std::fprintf(stderr, "prime: key not saved: %s\n", err.what());
  }
}

int runWindow(const WalkJob& job, const OrbitView& start, const WalkFlags& flags) {
  const WalkScene& scene = *job.scene;
  if (auto why = display::headlessReason(flags.live.noWindow))
    throw CLI::ValidationError("walk", "needs a window (" + *why + "); --bench N runs headless");
  const std::vector<std::string> profiles = scene.profiles();
  const std::vector<Vec3> startLights = scene.lights();
  WalkController ctl(start, startLights, static_cast<int>(profiles.size()));
  while (ctl.profile() != scene.firstProfile()) ctl.nextProfile();

  display::LiveRgbFrame frame(start.width, start.height);
  RgbImage image;
  image.assign(start.width, start.height);
  std::vector<std::uint32_t> row(static_cast<std::size_t>(start.width));
  std::atomic<int> passBlock{0};
  std::atomic<double> frameMs{0.0};
  std::atomic<int> framesDone{0};

  LatestJobRunner<WalkView> runner(
      [&](const WalkView& st, std::uint64_t, const std::atomic<bool>& abandon) {
        const Clock::time_point t0 = Clock::now();
        const std::unique_ptr<WalkFrame> renderer = scene.frame(st);
        const FreeCamera camera(st.view.camera());
        std::uint64_t rays = 0;
        for (const int block : kProgressiveBlocks) {
          const bool done = renderer->pass(
              camera, block, kProgressiveBlocks[0], image, flags.threads, &abandon,
              [&](int row0, int rows) {
                for (int y = row0; y < row0 + rows; ++y) {
                  scene.paint(st, image, y, row);
                  frame.setRow(y, row);
                }
              },
              rays, nullptr);
          if (!done) return;
          passBlock = block;
        }
        frameMs = msSince(t0);
        const int n = ++framesDone;
        if (flags.logFrames)
          std::fprintf(stderr, "prime: walk: frame %d done in %.1f ms (%s%s)\n", n, frameMs.load(),
                       profiles[static_cast<std::size_t>(st.profile)].c_str(),
                       st.paletteView ? ", 8514/A view" : "");
      });

  display::ScreenWindow window(
      frame, {job.name, flags.live.zoom, ".", flags.live.fullscreen, flags.live.scale, false,
              PngMeta{{{"Software", std::string("prime ") + PRIME_VERSION},
                       {"Scene", sceneNameOf(job.name)}},
                      1,
                      1}});
  std::fprintf(
      stderr,
      "prime: walk: window 0x%lx, %d x %d: arrows / left-drag orbit, shift+arrows / "
      "right-drag pan, I O wheel dolly, Home R reset,%s%s%s C camera, K key of the camera path, "
      "click a pixel: its rays; "
      "as in every "
      "window: S F12 screenshot, + - 1..8 zoom, F11 fullscreen, Esc quits\n",
      window.nativeId(), start.width, start.height, startLights.empty() ? "" : " L lights,",
      profiles.size() > 1 ? " P profile," : "", scene.paletteView() ? " V palette view," : "");
  auto stateOf = [&] {
    return WalkView{ctl.view(), ctl.lights(), ctl.profile(),
                    scene.paletteView() && ctl.paletteView()};
  };
  PixelInspector inspector(window, [&](int x, int y) -> std::optional<ProbedPixel> {
    if (x < 0 || y < 0 || x >= start.width || y >= start.height) return std::nullopt;
    return scene.probe(stateOf(), x, y);
  });
  window.setInputHandler([&](const display::module::Event& e) -> bool {
    using display::module::Event;
    using display::module::Key;
    if (inspector.handle(e)) return true;
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
    if (e.letter == 'v') return scene.paletteView() ? (ctl.togglePaletteView(), true) : false;
    if (e.letter == 'c') return saveCamera(job, flags, ctl, startLights), true;
    if (e.letter == 'k') return addPathKey(job, flags, ctl), true;
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
    const double fm = frameMs.load();
    std::string status = profiles[static_cast<std::size_t>(ctl.profile())];
    if (scene.paletteView() && ctl.paletteView()) status += " 8514/A";
    status += block == 0 ? " - rendering" : " - pass 1/" + std::to_string(block);
    if (fm > 0) {
      char rate[64];
      std::snprintf(rate, sizeof rate, " - %ld ms/frame (%.2f fps)", std::lround(fm), 1000.0 / fm);
      status += rate;
    }
    if (ctl.selectedLight() > 0) status += " - moving light " + std::to_string(ctl.selectedLight());
    if (status != lastStatus) {
      lastStatus = status;
      window.setStatus(status);
    }
  }
  return 0;
}

}  // namespace

int runWalk(const WalkJob& job, const WalkFlags& flags) {
  const Vec3 pivot =
      flags.pivot.size() == 3 ? Vec3{flags.pivot[0], flags.pivot[1], flags.pivot[2]} : job.centre;
  const OrbitView start = OrbitView::from(job.camera, pivot);
  if (flags.bench > 0) return runBench(job, start, flags);
  return runWindow(job, start, flags);
}

void addWalkVerb(CLI::App& app, Action& action, const System& system) {
  auto* cmd = app.add_subcommand(
      "walk",
      "Walk around a scene of any system in a window: orbit, pan, dolly, move lights, C saves "
      "the camera; progressive");
  auto flags = std::make_shared<WalkFlags>();
  addFormatOption(cmd, "scene");
  cmd->add_option("--threads", flags->threads, "Render threads (default: all cores)")
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--bench", flags->bench,
                  "Headless: render N frames along an orbit and print latency and frame rates")
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("--pin", flags->pin,
                "With --bench: pin render thread k to the k-th CPU the process may use, and say "
                "so");
  cmd->add_flag("--log-frames", flags->logFrames,
                "Say on stderr when each frame is complete (tests)");
  cmd->add_option("--pivot", flags->pivot,
                  "The point the camera turns about (default: the centre of the scene's objects)")
      ->expected(3)
      ->allow_extra_args(false);
  cmd->add_option("--camera-file", flags->cameraFile,
                  "Where the C key appends the camera (default: prime-cameras.txt here)");
  cmd->add_option("--path-file", flags->pathFile,
                  "The camera path the K key adds a key to (default: DIR/camera.path, or "
                  "beside a scene file its name with .path for its extension)");
  addLiveWindowOptions(cmd, std::shared_ptr<LiveOptions>(flags, &flags->live), false, false);
  if (system.walk == nullptr) {
    cmd->callback([&action, title = std::string(system.title)] {
      action = [title] {
        std::fprintf(stderr, "prime: walk: %s has no walk (prime walk --help)\n", title.c_str());
        return 2;
      };
    });
    return;
  }
  const WalkFactory make = system.walk(cmd, flags);
  cmd->footer(systemFooter(system, "walk"));
  cmd->callback(
      [flags, make, &action] { action = [flags, make] { return runWalk(make(), *flags); }; });
}

}  // namespace prime::cli
