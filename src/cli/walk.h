// `prime walk SCENE` for every system, written once: a window showing the
// scene through a free camera (src/geom/free_camera.h) that orbits, pans and
// dollies with the keys and the mouse, each frame rendered coarse to fine
// (blocks of 8, 4, 2, 1 pixels, src/render/progressive.h) and abandoned as
// soon as the view changes; `--bench N` renders N frames headless. A system
// plugs in with a WalkScene: its renderer for one frame, the way its colours
// are shown, and what P, L and V mean for it (its profiles, its movable
// lights, a palette view).
//
// The first frame is the scene's own camera, or the one the camera flags
// give (src/cli/camera_flags.h); the camera turns about the centre of the
// scene's objects (--pivot), which so stays on its pixel of the picture.
//
// Keys: arrows / left-drag orbit, shift+arrows / right-drag pan, I O and the
// wheel dolly, Home or R resets, L cycles camera / light 1 / light 2 ... (a
// selected light moves with the same keys and drags instead of the camera),
// P switches the profile, V the palette view, C prints the camera as flags
// and appends it to the camera file, K adds it as a key to the scene's camera
// path (src/cli/camera_path_file.h), a click on a pixel draws its rays
// (src/cli/pixel_inspector.h; right click: away); as in every window: S F12 screenshot,
// + - 1..8 zoom, F11 fullscreen, Esc quits.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "src/cli/camera_flags.h"
#include "src/cli/live_render.h"
#include "src/cli/overlay.h"
#include "src/geom/orbit_view.h"
#include "src/render/render_rows.h"
#include "src/render/rgb_image.h"

namespace prime::cli {

// What one frame shows: the camera, the lights where the user put them, the
// profile (an index into WalkScene::profiles) and the view mode.
struct WalkView {
  OrbitView view;
  std::vector<Vec3> lights;
  int profile = 0;
  bool paletteView = false;
};

// One frame's renderer (made once per frame: the lights or the profile may
// have changed).
class WalkFrame {
 public:
  virtual ~WalkFrame() = default;
  // Pass `block` of the frame (firstBlock: the coarsest) into `out` (the
  // camera's size; it keeps the earlier passes' colours). rowsDone(row0,
  // rows) on the calling thread; false when `abandon` stopped it. The last
  // pass gives the pixels `prime trace` gives with the same camera and one
  // ray per pixel. Adds the rays cast to `rays`, and each thread's rows and
  // CPU time to `report` when it is given (`--bench`).
  virtual bool pass(const FreeCamera& camera, int block, int firstBlock, RgbImage& out, int threads,
                    const std::atomic<bool>* abandon, const std::function<void(int, int)>& rowsDone,
                    std::uint64_t& rays, ThreadReport* report) = 0;
};

// What a system gives `prime walk`.
class WalkScene {
 public:
  virtual ~WalkScene() = default;
  // What P cycles through, in order (one: P does nothing); the first shown.
  virtual std::vector<std::string> profiles() const = 0;
  virtual int firstProfile() const { return 0; }
  // The lights L selects and the keys move (empty: L does nothing).
  virtual std::vector<Vec3> lights() const { return {}; }
  // Whether V has a palette view to switch to.
  virtual bool paletteView() const { return false; }
  virtual std::unique_ptr<WalkFrame> frame(const WalkView& view) const = 0;
  // A row of the picture as the window shows it (0x00RRGGBB).
  virtual void paint(const WalkView& view, const RgbImage& image, int row,
                     std::span<std::uint32_t> out) const = 0;
  // A click on pixel (x, y) of the frame `view` shows: the system's probe of
  // it with that camera, profile and lights (src/cli/overlay.h); nullopt when
  // the system has none.
  virtual std::optional<ProbedPixel> probe(const WalkView& view, int x, int y) const = 0;
  // What the camera file's comment adds after the scene and the profile
  // (CGL: the anti-aliasing a trace of the camera should turn off).
  virtual std::string cameraNote() const { return ""; }
};

// The flags `prime walk` has for every system.
struct WalkFlags {
  int threads = 0;                              // --threads
  int bench = 0;                                // --bench N: N frames headless
  bool pin = false;                             // --pin: the bench's threads pinned to CPUs
  bool logFrames = false;                       // --log-frames
  std::vector<double> pivot;                    // --pivot X Y Z
  std::string cameraFile = kDefaultCameraFile;  // --camera-file
  std::string pathFile;                         // --path-file (default: beside the scene)
  // --no-window (walk then says it needs one), --zoom, --fullscreen, --scale
  LiveOptions live;
};

// What a system's walk part returns once the command line is parsed.
struct WalkJob {
  std::unique_ptr<WalkScene> scene;
  std::string name;           // the scene as named on the command line
  FreeCameraSettings camera;  // the first frame's
  Vec3 centre{};              // the centre of the scene's objects (the default pivot)
};
using WalkFactory = std::function<WalkJob()>;

// Runs the walk: the window, or --bench.
int runWalk(const WalkJob& job, const WalkFlags& flags);

}  // namespace prime::cli
