#include "src/cli/prime/camera_options.h"

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
}

}  // namespace prime::cli
