#include "src/cli/prime/camera_options.h"

#include <stdexcept>

namespace prime::cli {

void addCameraOptions(CLI::App* cmd, CameraOptions& o) {
  cmd->add_option("--eye", o.eye, "Eye position x y z (listing: 500 500 -1500)")
      ->expected(3)
      ->allow_extra_args(false);
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
  auto* lookAt = cmd->add_option("--look-at", o.lookAt,
                                 "Free camera: the point looked at x y z (default: the listing "
                                 "window's centre 500 500 0)")
                     ->expected(3)
                     ->allow_extra_args(false);
  auto* up = cmd->add_option("--up", o.up, "Free camera: the up vector x y z (default 0 1 0)")
                 ->expected(3)
                 ->allow_extra_args(false);
  auto* fov = cmd->add_option("--fov", o.fov,
                              "Free camera: vertical field of view in degrees (default: what "
                              "frames the listing's window)")
                  ->check(CLI::Range(0.001, 179.0));
  auto* size =
      cmd->add_option("--size", o.size, "Free camera: picture size W H, square pixels (769 769)")
          ->expected(2)
          ->allow_extra_args(false)
          ->check(CLI::Range(1, 32767));
  auto* frame = cmd->add_flag("--frame-listing-window", o.frameListingWindow,
                              "Free camera that frames the listing's world window (0..1000 x "
                              "0..1000 at z = 0) from the eye, square pixels, at --size");
  frame->excludes(lookAt)->excludes(fov)->excludes(up);
  for (auto* free : {lookAt, up, fov, size, frame})
    for (const char* listingOnly : {"--viewport", "--screen"})
      if (auto* other = cmd->get_option_no_throw(listingOnly)) free->excludes(other);
}

void applyCameraOptions(const CameraOptions& o, CameraSettings& c) {
  if (o.eye.size() == 3) c.eye = {o.eye[0], o.eye[1], o.eye[2]};
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
  if (!o.anyFree()) return;
  const int width = o.size.size() == 2 ? o.size[0] : 769;
  const int height = o.size.size() == 2 ? o.size[1] : 769;
  try {
    FreeCameraSettings f;
    const auto corners = listingWindowCorners(c);
    f.eye = c.eye;
    f.lookAt = o.lookAt.empty() ? (corners[0] + corners[1] + corners[2] + corners[3]) * 0.25
                                : Vec3{o.lookAt[0], o.lookAt[1], o.lookAt[2]};
    if (!o.up.empty()) f.up = {o.up[0], o.up[1], o.up[2]};
    f.width = width;
    f.height = height;
    if (o.fov > 0.0) {
      f.fovY = o.fov;
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
