// The options every CGL command shares: how the scene file is read, where
// its textures are found, and every program parameter of Appendix 1 section
// 5 as a flag that overrides the file (as Appendix 2's call statement does).
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "src/cgl/render.h"
#include "src/cgl/scene.h"
#include "src/cli/camera_flags.h"

namespace prime::cli::cgl {

struct CglOptions {
  std::string file;
  bool lenient = false;
  std::vector<std::string> textureDirs;
  std::string phosphors = "electrohome";
  int threads = 0;            // trace's shared --threads
  bool linearSearch = false;  // the document's object list for every ray (CGL-D43)
  std::string profile = "document";  // --profile: document, or modern splines (CGL-D180)
  // Overrides of the program parameters (unset: the file's, else the default).
  std::optional<int> yhigh, ylow, xleft, xright, depth, memory, aalevel;
  std::optional<double> brightness, aathreshold;
  std::vector<int> background;
  bool shadows = false, noShadows = false, quiet = false;
  // --eye --look-at --up --fov --size --camera: replace the display
  // parameters (and, with --size, the window; see readCgl).
  CameraFlags camera;
  std::optional<FreeCameraSettings> applied;  // the camera they made (readCgl)
};

// `withParameters`: also the program-parameter overrides (trace, probe, bench).
void addCglOptions(CLI::App* cmd, CglOptions& o, bool withParameters = true);

// Reads the scene file (strict, or lenient: then every repair is listed on
// stderr unless quiet) and applies the overrides. The camera flags make the
// display parameters of the free camera (src/geom/free_camera.h): eye, sight
// towards the look-at point, up, dist 1 and a square viewport whose --size
// H scanlines span --fov; --size W H also sets the window to the W x H
// pixels centred on the 512 x 512 screen (at most 512 x 512: the package's
// frame buffer, section 8.2). The scene's own camera, as the flags see it, is
// its eye, eye + sight, up, the field of view of the whole screen's height
// and 512 x 512 (CGL-D61). Throws io::InputError.
prime::cgl::SceneFile readCgl(CglOptions& o, bool quiet);

// Preprocess: the scene with its textures (the scene's directory, then
// --textures), under the chosen phosphors.
prime::cgl::Scene buildCgl(const CglOptions& o, const prime::cgl::SceneFile& file);

// The render settings: the (overridden) program parameters, phosphors, threads.
prime::cgl::RenderSettings renderSettings(const CglOptions& o, const prime::cgl::SceneFile& file);

}  // namespace prime::cli::cgl
