#include "src/geom/free_camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace prime {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

struct Basis {
  Vec3 forward, right, up;
};

Basis basisOf(const Vec3& eye, const Vec3& lookAt, const Vec3& up) {
  const Vec3 view = lookAt - eye;
  if (!(length(view) > 0.0) || !std::isfinite(length(view)))
    throw std::invalid_argument("look-at: the look-at point must differ from the eye");
  const Vec3 forward = normalized(view);
  const Vec3 side = cross(up, forward);
  if (!(length(side) > 1e-9 * std::max(length(up), 1e-300)) || !std::isfinite(length(side)))
    throw std::invalid_argument("up: the up vector must not be zero or parallel to the view");
  const Vec3 right = normalized(side);
  return {forward, right, cross(forward, right)};
}

}  // namespace

FreeCamera::FreeCamera(const FreeCameraSettings& s) : s_(s) {
  if (s.width < 1 || s.height < 1 || s.width > 32767 || s.height > 32767)
    throw std::invalid_argument("size: " + std::to_string(s.width) + " x " +
                                std::to_string(s.height) + " pixels; need 1 .. 32767 each");
  if (!(s.fovY > 0.0 && s.fovY < 180.0))
    throw std::invalid_argument("fov: " + std::to_string(s.fovY) +
                                " degrees; need more than 0 and less than 180");
  const Basis b = basisOf(s.eye, s.lookAt, s.up);
  forward_ = b.forward;
  right_ = b.right;
  trueUp_ = b.up;
  const double halfH = std::tan(0.5 * s.fovY * kDegree);
  const double pixel = 2.0 * halfH / static_cast<double>(s.height);  // square pixels
  const double halfW = 0.5 * pixel * static_cast<double>(s.width);
  stepAcross_ = right_ * pixel;
  stepDown_ = trueUp_ * -pixel;
  // Pixel (0, 0)'s centre: the top-left corner plus half a pixel each way.
  toFirst_ = forward_ - right_ * halfW + trueUp_ * halfH + stepAcross_ * 0.5 + stepDown_ * 0.5;
}

double fitFovY(const Vec3& eye, const Vec3& lookAt, const Vec3& up, int width, int height,
               std::span<const Vec3> points) {
  if (width < 1 || height < 1) throw std::invalid_argument("size: need at least 1 x 1 pixels");
  const Basis b = basisOf(eye, lookAt, up);
  const double aspect = static_cast<double>(width) / static_cast<double>(height);
  double halfH = 0.0;
  for (const Vec3& p : points) {
    const Vec3 r = p - eye;
    const double z = dot(r, b.forward);
    if (!(z > 0.0))
      throw std::invalid_argument("a point to be framed is level with or behind the eye");
    halfH = std::max({halfH, std::abs(dot(r, b.up)) / z, std::abs(dot(r, b.right)) / z / aspect});
  }
  if (!(halfH > 0.0)) throw std::invalid_argument("nothing to frame");
  return 2.0 * std::atan(halfH) / kDegree;
}

}  // namespace prime
