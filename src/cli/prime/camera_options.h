// The camera and window options of RayTrace.c (lines 7059-7140), each listing
// constant overridable, for every command that places a picture: trace,
// probe, export-pov, plate1; and the free camera's (T30-T34), the flags every
// system shares (src/cli/camera_flags.h): --look-at, --up, --fov, --size,
// --camera, and PRIME's --frame-listing-window (trace, probe, walk, compare).
#pragma once
#include <CLI/CLI.hpp>
#include <vector>

#include "src/cli/camera_flags.h"
#include "src/prime/render/camera.h"

namespace prime::cli {

struct CameraOptions {
  CameraFlags flags;  // --eye (the listing's or the free camera's), and the free camera's
  std::vector<double> windowLeft, windowRight, viewport;
  std::vector<int> screen;
  bool frameListingWindow = false;
  bool freeOptions = false;  // whether the command offers the free camera's options
};

// --eye, --window-left, --window-right, --viewport, --screen.
void addCameraOptions(CLI::App* cmd, CameraOptions& o);
// --look-at, --up, --fov, --size, --frame-listing-window (after addCameraOptions).
void addFreeCameraOptions(CLI::App* cmd, CameraOptions& o);
// The options given override the listing's values in `c`; any free-camera
// option (or a camera file) sets c.free (T31): eye --eye (listing: 500 500
// -1500), look-at the listing window's centre, up +y, size `side` x `side`
// (trace: 769, T34; walk: 512), and the field of view that frames the
// listing's window (T33) unless --fov. Throws CLI::ValidationError for a
// camera that cannot be (look-at at the eye, ...), io::InputError for a bad
// camera file.
void applyCameraOptions(const CameraOptions& o, CameraSettings& c, int side = 769);

}  // namespace prime::cli
