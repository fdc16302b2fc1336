#include "src/cli/cgl/options.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "legacy_io/common/error.h"

namespace prime::cli::cgl {

void addCglOptions(CLI::App* cmd, CglOptions& o, bool withParameters) {
  cmd->add_option("SCENE", o.file, "CGL scene-description file (Appendix 1)")->required();
  cmd->add_flag("--lenient", o.lenient,
                "Also read the document's OCR-damaged examples, saying what was repaired");
  cmd->add_option("--textures", o.textureDirs,
                  "Directory to look in for texture files by their base name (after the scene's "
                  "own directory); may be repeated")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--phosphors", o.phosphors,
                  "XYZ to RGB: the Electrohome ECM 1301 monitor (default) or NTSC (the ntsc "
                  "compile option)")
      ->check(CLI::IsMember({"electrohome", "ntsc"}));
  cmd->add_flag("--linear-search", o.linearSearch,
                "Test the object list in order for every ray, as the package did (the same "
                "pixels, slower; operation counts as the document's program made them)");
  addCameraFlags(cmd, o.camera, "the scene's display parameters, section 6");
  if (!withParameters) return;
  cmd->add_option("--profile", o.profile,
                  "document: the package as the document describes it (default); modern: the "
                  "same, but spline surfaces by the modern intersector, tight knot-cell boxes "
                  "nearest first (docs/cgl/splines.md, CGL-D180)")
      ->check(CLI::IsMember({"document", "modern"}));

  const std::string g =
      "Program parameters (override the scene file; Appendix 2: -yh -yl -xl "
      "-xr -d -s -m -b -q -t -a)";
  cmd->add_option("--yhigh", o.yhigh, "Uppermost scanline rendered, 0..511 (511)")
      ->check(CLI::Range(0, 511))
      ->group(g);
  cmd->add_option("--ylow", o.ylow, "Lowest scanline rendered, 0..511 (0)")
      ->check(CLI::Range(0, 511))
      ->group(g);
  cmd->add_option("--xleft", o.xleft, "Leftmost pixel rendered, 0..511 (0)")
      ->check(CLI::Range(0, 511))
      ->group(g);
  cmd->add_option("--xright", o.xright, "Rightmost pixel rendered, 0..511 (511)")
      ->check(CLI::Range(0, 511))
      ->group(g);
  cmd->add_option("--max-depth", o.depth,
                  "Ray-tracing depth, 0..10 (0: primary rays only; Appendix 2's -d)")
      ->check(CLI::Range(0, 10))
      ->group(g);
  cmd->add_flag("--shadows", o.shadows, "Shadows on")->group(g);
  cmd->add_flag("--no-shadows", o.noShadows, "Shadows off, whatever the file says")->group(g);
  cmd->add_option("--memory", o.memory,
                  "Allocation block in Mbytes, 1..24: reported beside what the scene would "
                  "have needed, never a limit")
      ->check(CLI::Range(1, 24))
      ->group(g);
  cmd->add_option("--brightness", o.brightness,
                  "Brightness of the user Background procedure (-Dbackground), 0..1")
      ->check(CLI::Range(0.0, 1.0))
      ->group(g);
  cmd->add_option("--background", o.background, "Uniform background red green blue, 0..255")
      ->expected(3)
      ->check(CLI::Range(0, 255))
      ->group(g);
  cmd->add_option("--aathreshold", o.aathreshold,
                  "Anti-aliasing threshold: corners differing by more are subdivided (40.0)")
      ->check(CLI::Range(0.0, 765.0))
      ->group(g);
  cmd->add_option("--aalevel", o.aalevel,
                  "Anti-aliasing level: 0 none (one ray per pixel), 1 corners only, 2, 4, 8 "
                  "(one, two, three subdivisions; default 2)")
      ->check(CLI::IsMember({0, 1, 2, 4, 8}))
      ->group(g);
}

namespace {

// The window --size W H makes: the W x H pixels in the middle of the screen.
struct Window {
  int xleft, xright, ylow, yhigh;
};
Window centredWindow(int width, int height) {
  const int xleft = 256 - width / 2, ylow = 256 - height / 2;
  return {xleft, xleft + width - 1, ylow, ylow + height - 1};
}

// The scene's own camera as the flags see it: its display parameters, over
// its window when that is the centred one some --size makes (its field of
// view then spans the window's scanlines), else over the whole screen.
FreeCameraSettings ownCamera(const prime::cgl::SceneFile& file) {
  FreeCameraSettings c = prime::cgl::freeCamera(file.display);
  const auto& p = file.program;
  const int w = p.xright - p.xleft + 1, h = p.yhigh - p.ylow + 1;
  const Window centred = centredWindow(w, h);
  if (w >= 1 && h >= 1 && p.xleft == centred.xleft && p.ylow == centred.ylow) {
    c.width = w;
    c.height = h;
    c.fovY = 2.0 * std::atan(0.5 * file.display.viewportHeight * h / 512.0 / file.display.dist) *
             180.0 / std::numbers::pi;
  }
  return c;
}

FreeCameraSettings applyCamera(const CameraFlags& flags, prime::cgl::SceneFile& file) {
  const CameraFlags given = withCameraFile(flags);
  const FreeCameraSettings own = ownCamera(file);
  const FreeCameraSettings c = applyCameraFlags(given, own);
  if (c.width > 512 || c.height > 512)
    throw CLI::ValidationError("--size",
                               "the CGL package's screen is 512 x 512 (section 8.2); got " +
                                   std::to_string(c.width) + " x " + std::to_string(c.height));
  file.display = prime::cgl::displayOf(c);
  // The window follows the camera's size (the scene's own centred window
  // stays as it was); a window that is not centred stays unless --size.
  auto& p = file.program;
  // ownCamera took the window's size exactly when the window is centred.
  const bool ownCentred = own.width == p.xright - p.xleft + 1 && own.height == p.yhigh - p.ylow + 1;
  const Window w = centredWindow(c.width, c.height);
  if (!given.size.empty() || ownCentred) {
    p.xleft = w.xleft;
    p.xright = w.xright;
    p.ylow = w.ylow;
    p.yhigh = w.yhigh;
    p.given.xleft = p.given.xright = p.given.ylow = p.given.yhigh = true;
  }
  return c;
}

}  // namespace

prime::cgl::SceneFile readCgl(CglOptions& o, bool quiet) {
  prime::cgl::ReadOptions read;
  read.lenient = o.lenient;
  prime::cgl::SceneFile file = prime::cgl::readSceneFile(o.file, read);
  if (!quiet) {
    // In the order of the file, whatever order the reader found them in.
    std::vector<const prime::cgl::Repair*> repairs;
    for (const auto& r : file.repairs) repairs.push_back(&r);
    std::stable_sort(repairs.begin(), repairs.end(), [](const auto* a, const auto* b) {
      return a->where.line.value_or(0) < b->where.line.value_or(0);
    });
    for (const auto* r : repairs)
      std::cerr << "prime: " << io::describe(r->where) << ": repaired: " << r->what << "\n";
    for (const auto& w : file.warnings)
      std::cerr << "prime: " << io::describe(w.where) << ": warning: " << w.what << "\n";
  }
  auto& p = file.program;
  auto set = [](auto& field, bool& given, const auto& value) {
    if (value) {
      field = *value;
      given = true;
    }
  };
  set(p.yhigh, p.given.yhigh, o.yhigh);
  set(p.ylow, p.given.ylow, o.ylow);
  set(p.xleft, p.given.xleft, o.xleft);
  set(p.xright, p.given.xright, o.xright);
  set(p.depth, p.given.depth, o.depth);
  set(p.memory, p.given.memory, o.memory);
  set(p.aalevel, p.given.aalevel, o.aalevel);
  set(p.brightness, p.given.brightness, o.brightness);
  set(p.aathreshold, p.given.aathreshold, o.aathreshold);
  if (o.background.size() == 3) {
    p.background = {o.background[0], o.background[1], o.background[2]};
    p.given.background = true;
  }
  if (o.shadows) p.shadows = p.given.shadows = true;
  if (o.noShadows) {
    p.shadows = false;
    p.given.shadows = true;
  }
  if (o.quiet) p.quiet = p.given.quiet = true;
  if (o.camera.given()) o.applied = applyCamera(o.camera, file);
  return file;
}

prime::cgl::Phosphors phosphorsOf(const CglOptions& o) {
  return o.phosphors == "ntsc" ? prime::cgl::Phosphors::Ntsc : prime::cgl::Phosphors::Electrohome;
}

prime::cgl::Scene buildCgl(const CglOptions& o, const prime::cgl::SceneFile& file) {
  prime::cgl::BuildOptions build;
  build.textureDirs = o.textureDirs;
  build.phosphors = phosphorsOf(o);
  build.modernSplines = o.profile == "modern";
  return prime::cgl::buildScene(file, build);
}

prime::cgl::RenderSettings renderSettings(const CglOptions& o, const prime::cgl::SceneFile& file) {
  prime::cgl::RenderSettings settings;
  settings.program = file.program;
  settings.phosphors = phosphorsOf(o);
  settings.threads = o.threads;
  settings.linearSearch = o.linearSearch;
  return settings;
}

}  // namespace prime::cli::cgl
