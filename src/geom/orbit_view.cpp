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
  v.pivot = c.lookAt;
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

OrbitView OrbitView::from(const FreeCameraSettings& c, const Vec3& pivot) {
  OrbitView v = from(c);
  v.pivot = pivot;
  return v;
}

namespace {
// The camera's frame for (yaw, pitch): forward, right = up x forward, and
// the true up, as FreeCamera makes them for up +y.
struct Frame {
  Vec3 forward, right, up;
};
Frame frameOf(double yaw, double pitch) {
  const double y = yaw * kDegree, p = pitch * kDegree;
  Frame f;
  f.forward = {-std::cos(p) * std::sin(y), -std::sin(p), std::cos(p) * std::cos(y)};
  f.right = normalized(cross(Vec3{0.0, 1.0, 0.0}, f.forward));
  f.up = cross(f.forward, f.right);
  return f;
}
}  // namespace

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
  const double oldYaw = yaw, oldPitch = pitch;
  yaw = std::remainder(yaw + dYaw, 360.0);
  pitch = std::clamp(pitch + dPitch, -kMaxPitch, kMaxPitch);
  const Vec3 arm = target - pivot;
  if (arm[0] == 0.0 && arm[1] == 0.0 && arm[2] == 0.0) return;  // turning about the target
  // The rigid turn that takes the old frame to the new one, applied to the
  // target about the pivot (the eye follows: it is the target's offset in
  // the camera's frame).
  const Frame a = frameOf(oldYaw, oldPitch), b = frameOf(yaw, pitch);
  target =
      pivot + b.right * dot(arm, a.right) + b.up * dot(arm, a.up) + b.forward * dot(arm, a.forward);
}

double OrbitView::pixelAtTarget() const {
  return 2.0 * distance * std::tan(0.5 * fovY * kDegree) / static_cast<double>(height);
}

void OrbitView::pan(double dxPixels, double dyPixels) {
  const FreeCamera c(camera());
  const double s = pixelAtTarget();
  const Vec3 move = c.right() * (dxPixels * s) + c.trueUp() * (dyPixels * s);
  target = target + move;
  pivot = pivot + move;
}

void OrbitView::dolly(double factor) {
  if (factor > 0.0 && std::isfinite(factor)) distance = std::max(distance * factor, 1e-6);
}

}  // namespace prime
