// A click on a pixel of a window, for every system: the pixel's ray tree
// drawn over the picture with a panel of the probe's text (src/cli/overlay.h),
// and the same text printed on stdout, as `prime probe` prints it. A right
// click (without a drag) takes the drawing away; so does anything that
// changes the picture (a new frame, another palette). `trace` (once the
// render is done), `walk` and `view --scene` windows have one.
#pragma once
#include <functional>
#include <optional>

#include "palette/window/screen_window.h"
#include "src/cli/overlay.h"

namespace prime::cli {

// The probe of the pixel at (column, row) of the window's frame, in the
// frame's coordinates; nullopt when no pixel of the picture is there (PRIME's
// 8514/A screen around the picture).
using PixelProbe = std::function<std::optional<ProbedPixel>(int column, int row)>;

class PixelInspector {
 public:
  PixelInspector(display::ScreenWindow& window, PixelProbe probe)
      : window_(window), probe_(std::move(probe)) {}
  // The window's event: true when it was a click this took (a left or right
  // button released where it was pressed, give or take 2 pixels, with no
  // drag between). Mouse motion and presses are never taken: a walk's drags
  // stay the walk's.
  bool handle(const display::module::Event& e);

 private:
  display::ScreenWindow& window_;
  PixelProbe probe_;
  int downX_ = 0, downY_ = 0, downButton_ = 0, moved_ = 0;
};

}  // namespace prime::cli
