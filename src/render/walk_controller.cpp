#include "src/render/walk_controller.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace prime {

WalkController::WalkController(const OrbitView& start, std::vector<Vec3> lights, int profiles)
    : start_(start),
      view_(start),
      startLights_(lights),
      lights_(std::move(lights)),
      profiles_(std::max(profiles, 1)) {}

void WalkController::moveLight(double dxPixels, double dyPixels, double forward) {
  Vec3& l = lights_[static_cast<std::size_t>(selected_ - 1)];
  const FreeCamera c(view_.camera());
  const double s = view_.pixelAtTarget();
  l = l + c.right() * (dxPixels * s) + c.trueUp() * (dyPixels * s) +
      c.forward() * (forward * view_.distance);
  changed();
}

void WalkController::arrows(int dx, int dy) {
  if (dx == 0 && dy == 0) return;
  if (selected_ > 0) return moveLight(dx * kPanStep, dy * kPanStep, 0.0);
  view_.orbit(dx * kOrbitStep, dy * kOrbitStep);
  changed();
}

void WalkController::panArrows(int dx, int dy) {
  if (dx == 0 && dy == 0) return;
  if (selected_ > 0) return moveLight(dx * kPanStep, dy * kPanStep, 0.0);
  view_.pan(dx * kPanStep, dy * kPanStep);
  changed();
}

void WalkController::dolly(int steps) {
  if (steps == 0) return;
  if (selected_ > 0) return moveLight(0.0, 0.0, 0.1 * steps);
  view_.dolly(std::pow(kDollyStep, steps));
  changed();
}

void WalkController::drag(bool leftButton, int dx, int dy) {
  if (dx == 0 && dy == 0) return;
  // The mouse's y grows downwards; the picture's up is the other way.
  if (selected_ > 0) return moveLight(dx, -dy, 0.0);
  if (leftButton)
    view_.orbit(-dx * kDragDegrees, dy * kDragDegrees);  // the scene turns with the mouse
  else
    view_.pan(-dx, dy);  // the scene follows the mouse
  changed();
}

void WalkController::reset() {
  view_ = start_;
  lights_ = startLights_;
  selected_ = 0;
  changed();
}

void WalkController::selectLight(int n) {
  if (n < 0 || n > static_cast<int>(lights_.size())) return;
  selected_ = n;  // what is rendered stays the same
}

void WalkController::cycleSelection() {
  selected_ = (selected_ + 1) % (static_cast<int>(lights_.size()) + 1);
}

void WalkController::nextProfile() {
  profile_ = (profile_ + 1) % profiles_;
  changed();
}

void WalkController::togglePaletteView() {
  paletteView_ = !paletteView_;
  changed();
}

}  // namespace prime
