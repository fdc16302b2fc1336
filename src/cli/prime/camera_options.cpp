#include "src/cli/prime/camera_options.h"

#include <stdexcept>
#include <string>

#include "src/cli/camera_flags.h"

namespace prime::cli {

void addCameraOptions(CLI::App* cmd, CameraOptions& o) {
  addEyeFlag(cmd, o.flags, "Eye position x y z (listing: 500 500 -1500)");
  cmd->add_option("--window-left", o.windowLeft, "World window top-left corner (listing: 0 1000 0)")
      ->expected(3)
      ->allow_extra_args(false);
  cmd->add_option("--window-right", o.windowRight,
                  "World window top-right corner (listing: 1000 1000 0)")
      ->expected(3)
      ->allow_extra_args(false);
  cmd->add_option("--viewport", o.viewport,
                  "Screen viewport xMin yMin xMax yMax, normalised (listing: 0.66 0 1 1)")
      ->expected(4)
      ->allow_extra_args(false);
  cmd->add_option("--screen", o.screen, "Screen size in pixels W H (8514/A: 1024 768)")
      ->expected(2)
      ->allow_extra_args(false);
}

void addFreeCameraOptions(CLI::App* cmd, CameraOptions& o) {
  o.freeOptions = true;
  addCameraFlags(cmd, o.flags,
                 "the listing's camera; any of these makes a free camera at --eye looking at the "
                 "window's centre 500 500 0, up 0 1 0, the field of view that frames the window, "
                 "769 x 769 (walk: 512 x 512)",
                 false);
  auto* frame = cmd->add_flag("--frame-listing-window", o.frameListingWindow,
                              "Free camera that frames the listing's world window (0..1000 x "
                              "0..1000 at z = 0) from the eye, square pixels, at --size");
  frame->excludes("--look-at")->excludes("--fov")->excludes("--up")->excludes("--camera");
  for (const char* free :
       {"--look-at", "--up", "--fov", "--size", "--camera", "--frame-listing-window"})
    for (const char* listingOnly : {"--viewport", "--screen"})
      if (auto* other = cmd->get_option_no_throw(listingOnly))
        cmd->get_option(free)->excludes(other);
}

void applyCameraOptions(const CameraOptions& options, CameraSettings& c, int side) {
  const CameraFlags flags = withCameraFile(options.flags);
  const CameraOptions& o = options;
  if (flags.eye.size() == 3) c.eye = {flags.eye[0], flags.eye[1], flags.eye[2]};
  if (o.windowLeft.size() == 3) c.windowLeft = {o.windowLeft[0], o.windowLeft[1], o.windowLeft[2]};
  if (o.windowRight.size() == 3)
    c.windowRight = {o.windowRight[0], o.windowRight[1], o.windowRight[2]};
  if (o.viewport.size() == 4) {
    c.xMin = o.viewport[0];
    c.yMin = o.viewport[1];
    c.xMax = o.viewport[2];
    c.yMax = o.viewport[3];
  }
  if (o.screen.size() == 2) {
    c.screenWidth = o.screen[0];
    c.screenHeight = o.screen[1];
  }
  if (!flags.freeGiven() && !o.frameListingWindow) return;
  const int width = flags.size.size() == 2 ? flags.size[0] : side;
  const int height = flags.size.size() == 2 ? flags.size[1] : side;
  try {
    FreeCameraSettings f;
    const auto corners = listingWindowCorners(c);
    f.eye = c.eye;
    f.lookAt = flags.lookAt.empty() ? (corners[0] + corners[1] + corners[2] + corners[3]) * 0.25
                                    : Vec3{flags.lookAt[0], flags.lookAt[1], flags.lookAt[2]};
    if (!flags.up.empty()) f.up = {flags.up[0], flags.up[1], flags.up[2]};
    if (f.lookAt[0] == f.eye[0] && f.lookAt[1] == f.eye[1] && f.lookAt[2] == f.eye[2])
      throw std::invalid_argument(
          "the eye is the point it looks at, (" + numberText(f.eye[0]) + ", " +
          numberText(f.eye[1]) + ", " + numberText(f.eye[2]) + ")" +
          (flags.lookAt.empty() ? ", the listing window's centre (looked at without --look-at)"
                                : "") +
          ": give another --look-at or --eye");
    f.width = width;
    f.height = height;
    if (flags.fov > 0.0) {
      f.fovY = flags.fov;
    } else {
      try {
        f.fovY = fitFovY(f.eye, f.lookAt, f.up, width, height, corners);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(
            std::string(e.what()) +
            " (the listing's window cannot be framed from there: give --fov)");
      }
    }
    const FreeCamera check(f);  // refuses what cannot be a camera
    c.free = f;
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("free camera", e.what());
  }
}

}  // namespace prime::cli
