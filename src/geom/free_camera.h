// A free pinhole camera for any system: eye, look-at point, up vector,
// VERTICAL field of view (the full angle, in degrees) and width x height
// pixels, square. No listing's quirk lives here.
//
// Axes: `right` = unit(up x forward), `trueUp` = forward x right, so with
// forward +z and up +y, right is +x: the image's columns run along +x and its
// rows down -y, as PRIME's listing window does (x right, y up, z away from
// the eye).
//
// Pixel (row, column) is sampled at its centre: the ray's direction is
//   toFirst + (column + fx) * stepAcross + (row + fy) * stepDown
// with (fx, fy) = (0, 0) the centre and |fx|, |fy| <= 0.5 the pixel's
// footprint (the sampler's offsets, as ListingCamera::sampleRay takes them).
// The image plane lies at distance 1 from the eye; directions are not
// normalised (a tracer that needs a unit direction normalises it).
#pragma once
#include <span>

#include "src/geom/ray.h"

namespace prime {

struct FreeCameraSettings {
  Vec3 eye{0.0, 0.0, 0.0};
  Vec3 lookAt{0.0, 0.0, 1.0};
  Vec3 up{0.0, 1.0, 0.0};
  double fovY = 40.0;  // vertical, full angle, degrees, in (0, 180)
  int width = 640, height = 480;
};

class FreeCamera {
 public:
  // Throws std::invalid_argument naming the field: eye == look-at, up
  // parallel to the view direction, fov outside (0, 180), a size < 1 or
  // > 32767 (a graph file's 16-bit header).
  explicit FreeCamera(const FreeCameraSettings& s);

  int columns() const { return s_.width; }
  int rows() const { return s_.height; }
  Ray primaryRay(int row, int column) const { return sampleRay(row, column, 0.0, 0.0); }
  Ray sampleRay(int row, int column, double fx, double fy) const {
    const double a = static_cast<double>(column) + fx, b = static_cast<double>(row) + fy;
    Ray r;
    r.o = s_.eye;
    for (int k = 0; k < 3; ++k) r.d[k] = toFirst_[k] + a * stepAcross_[k] + b * stepDown_[k];
    return r;
  }

  const FreeCameraSettings& settings() const { return s_; }
  const Vec3& forward() const { return forward_; }
  const Vec3& right() const { return right_; }
  const Vec3& trueUp() const { return trueUp_; }
  // The linear map from pixel coordinates to directions (above).
  const Vec3& toFirst() const { return toFirst_; }
  const Vec3& stepAcross() const { return stepAcross_; }
  const Vec3& stepDown() const { return stepDown_; }

 private:
  FreeCameraSettings s_;
  Vec3 forward_{}, right_{}, trueUp_{}, toFirst_{}, stepAcross_{}, stepDown_{};
};

// The smallest vertical field of view (degrees) with which a camera at
// `eye` looking at `lookAt` (up `up`) at width x height shows every one of
// `points` (all must lie in front of the eye; throws std::invalid_argument
// otherwise), centred on the look-at direction.
double fitFovY(const Vec3& eye, const Vec3& lookAt, const Vec3& up, int width, int height,
               std::span<const Vec3> points);

}  // namespace prime
