#include "src/geom/orbit_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace prime {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kMaxPitch = 89.0;
}  // namespace

OrbitView OrbitView::from(const FreeCameraSettings& c) {
  OrbitView v;
  v.target = c.lookAt;
  const Vec3 off = c.eye - c.lookAt;
  v.distance = length(off);
  v.pitch = std::clamp(std::asin(std::clamp(off[1] / v.distance, -1.0, 1.0)) / kDegree, -kMaxPitch,
                       kMaxPitch);
  v.yaw = std::atan2(off[0], -off[2]) / kDegree;
  v.fovY = c.fovY;
  v.width = c.width;
  v.height = c.height;
  return v;
}

Vec3 OrbitView::eye() const {
  const double y = yaw * kDegree, p = pitch * kDegree;
  // Exact for yaw = pitch = 0: sin(0) = 0 and cos(0) = 1.
  const Vec3 off{std::cos(p) * std::sin(y), std::sin(p), -std::cos(p) * std::cos(y)};
  return target + off * distance;
}

FreeCameraSettings OrbitView::camera() const {
  FreeCameraSettings c;
  c.eye = eye();
  c.lookAt = target;
  c.up = {0.0, 1.0, 0.0};
  c.fovY = fovY;
  c.width = width;
  c.height = height;
  return c;
}

void OrbitView::orbit(double dYaw, double dPitch) {
  yaw = std::remainder(yaw + dYaw, 360.0);
  pitch = std::clamp(pitch + dPitch, -kMaxPitch, kMaxPitch);
}

double OrbitView::pixelAtTarget() const {
  return 2.0 * distance * std::tan(0.5 * fovY * kDegree) / static_cast<double>(height);
}

void OrbitView::pan(double dxPixels, double dyPixels) {
  const FreeCamera c(camera());
  const double s = pixelAtTarget();
  target = target + c.right() * (dxPixels * s) + c.trueUp() * (dyPixels * s);
}

void OrbitView::dolly(double factor) {
  if (factor > 0.0 && std::isfinite(factor)) distance = std::max(distance * factor, 1e-6);
}

}  // namespace prime
