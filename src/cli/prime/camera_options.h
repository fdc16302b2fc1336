// The camera and window options of RayTrace.c (lines 7059-7140), each listing
// constant overridable, for every command that places a picture: trace,
// probe, export-pov, plate1.
#pragma once
#include <CLI/CLI.hpp>
#include <vector>

#include "src/prime/render/camera.h"

namespace prime::cli {

struct CameraOptions {
  std::vector<double> eye, windowLeft, windowRight, viewport;
  std::vector<int> screen;
};

// --eye, --window-left, --window-right, --viewport, --screen.
void addCameraOptions(CLI::App* cmd, CameraOptions& o);
// The options given override the listing's values in `c`.
void applyCameraOptions(const CameraOptions& o, CameraSettings& c);

}  // namespace prime::cli
