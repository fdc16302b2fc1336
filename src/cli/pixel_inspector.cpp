#include "src/cli/pixel_inspector.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace prime::cli {

bool PixelInspector::handle(const display::module::Event& e) {
  using display::module::Event;
  if (e.type == Event::Type::MouseMotion && downButton_ != 0) {
    moved_ += std::abs(e.dx) + std::abs(e.dy);  // a drag (a walk's orbit) is no click
    return false;
  }
  if (e.type != Event::Type::MouseButton) return false;
  if (e.down) {
    downX_ = e.x;
    downY_ = e.y;
    downButton_ = e.button;
    moved_ = 0;
    return false;
  }
  const bool click = e.button == downButton_ && moved_ <= 2 && std::abs(e.x - downX_) <= 2 &&
                     std::abs(e.y - downY_) <= 2;
  downButton_ = 0;
  if (!click) return false;
  if (e.button == 3) {
    window_.clearOverlay();
    return true;
  }
  if (e.button != 1) return false;
  const auto at = window_.pictureAt(e.x, e.y);
  if (!at) return true;
  try {
    const std::optional<ProbedPixel> probed = probe_((*at)[0], (*at)[1]);
    if (!probed) {
      window_.clearOverlay();
      return true;
    }
    std::fputs(probed->text.c_str(), stdout);
    std::fflush(stdout);
    window_.showOverlay(drawProbedPixel(window_.picture(), *probed));
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "prime: cannot draw pixel %d %d: %s\n", (*at)[0], (*at)[1], ex.what());
  }
  return true;
}

}  // namespace prime::cli
