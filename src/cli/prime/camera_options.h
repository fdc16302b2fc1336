// The camera and window options of RayTrace.c (lines 7059-7140), each listing
// constant overridable, for every command that places a picture: trace,
// probe, export-pov, plate1; and the free camera's (T30-T34): --look-at,
// --up, --fov, --size, --frame-listing-window (trace, probe, walk, compare).
#pragma once
#include <CLI/CLI.hpp>
#include <vector>

#include "src/prime/render/camera.h"

namespace prime::cli {

struct CameraOptions {
  std::vector<double> eye, windowLeft, windowRight, viewport;
  std::vector<int> screen;
  std::vector<double> lookAt, up;
  double fov = 0.0;  // 0: not given
  std::vector<int> size;
  bool frameListingWindow = false;
  bool freeOptions = false;  // whether the command offers the free camera's options
  bool anyFree() const {
    return !lookAt.empty() || !up.empty() || fov > 0.0 || !size.empty() || frameListingWindow;
  }
};

// --eye, --window-left, --window-right, --viewport, --screen.
void addCameraOptions(CLI::App* cmd, CameraOptions& o);
// --look-at, --up, --fov, --size, --frame-listing-window (after addCameraOptions).
void addFreeCameraOptions(CLI::App* cmd, CameraOptions& o);
// The options given override the listing's values in `c`; any free-camera
// option sets c.free (T31): eye --eye (listing: 500 500 -1500), look-at the
// listing window's centre, up +y, size 769 x 769 (T34), and the field of view
// that frames the listing's window (T33) unless --fov. Throws
// CLI::ValidationError for a camera that cannot be (look-at at the eye, ...).
void applyCameraOptions(const CameraOptions& o, CameraSettings& c);

}  // namespace prime::cli
