#include "src/geom/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace prime {
namespace {

CameraKey key(double x, double y, double z, std::optional<double> frame = std::nullopt) {
  CameraKey k;
  k.eye = {x, y, z};
  k.lookAt = {0, 0, 0};
  k.fovY = 40;
  k.frame = frame;
  return k;
}

double dist(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

TEST(CameraPath, EndsAreTheEndKeys) {
  CameraPathSpec spec;
  spec.keys = {key(0, 0, -10), key(5, 0, -10), key(20, 3, -10)};
  spec.frames = 50;
  const CameraPath path(spec);
  EXPECT_EQ(path.frames(), 50);
  EXPECT_EQ(path.camera(0, 64, 48).eye, (Vec3{0, 0, -10}));
  EXPECT_EQ(path.camera(49, 64, 48).eye, (Vec3{20, 3, -10}));
  EXPECT_EQ(path.camera(49, 64, 48).width, 64);
  EXPECT_EQ(path.camera(49, 64, 48).height, 48);
}

TEST(CameraPath, ConstantSpeedAcrossUnevenKeys) {
  // Keys 5 and 15 apart: a path by key index would move three times as fast
  // in the second segment; by length every frame moves the same distance.
  CameraPathSpec spec;
  spec.keys = {key(0, 0, -10), key(5, 0, -10), key(20, 0, -10)};
  spec.frames = 41;
  const CameraPath path(spec);
  double lo = 1e9, hi = 0;
  for (int k = 1; k < path.frames(); ++k) {
    const double d = dist(path.camera(k, 8, 8).eye, path.camera(k - 1, 8, 8).eye);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  EXPECT_GT(lo, 0.0);
  EXPECT_LT(hi / lo, 1.02) << "steps from " << lo << " to " << hi;
  // The middle key lands a quarter of the way along: at frame 10.
  EXPECT_NEAR(path.keyFrames()[1], 10.0, 1e-9);
}

TEST(CameraPath, KeyWithAFrameIsMetAtThatFrame) {
  CameraPathSpec spec;
  spec.keys = {key(0, 0, -10), key(5, 1, -10, 30.0), key(20, 0, -10)};
  spec.frames = 40;
  const CameraPath path(spec);
  const Vec3 at30 = path.camera(30, 8, 8).eye;
  EXPECT_NEAR(at30[0], 5, 1e-9);
  EXPECT_NEAR(at30[1], 1, 1e-9);
}

TEST(CameraPath, SameFrameSameCameraBitForBit) {
  CameraPathSpec spec;
  spec.keys = {key(0, 0, -10), key(3, 4, -9), key(-2, 7, -3), key(1, 1, 1)};
  spec.frames = 97;
  const CameraPath a(spec), b(spec);
  for (int k : {0, 1, 17, 48, 96}) {
    const FreeCameraSettings x = a.camera(k, 10, 10), y = b.camera(k, 10, 10);
    // Twice, and in another order: no state carried between frames.
    const FreeCameraSettings z = a.camera(k, 10, 10);
    EXPECT_EQ(x.eye, y.eye);
    EXPECT_EQ(x.lookAt, y.lookAt);
    EXPECT_EQ(x.up, y.up);
    EXPECT_EQ(x.fovY, y.fovY);
    EXPECT_EQ(x.eye, z.eye);
  }
}

TEST(CameraPath, LoopOfTwentyFourKeysStaysOnItsCircle) {
  CameraPathSpec spec;
  const double r = 100;
  for (int j = 0; j < 24; ++j) {
    const double a = 2 * std::numbers::pi * j / 24;
    spec.keys.push_back(key(r * std::sin(a), 5, r * std::cos(a)));
  }
  spec.loop = true;
  spec.frames = 240;
  const CameraPath path(spec);
  double worst = 0;
  for (int k = 0; k < path.frames(); ++k) {
    const Vec3 e = path.camera(k, 8, 8).eye;
    worst = std::max(worst, std::abs(std::hypot(e[0], e[2]) - r));
  }
  EXPECT_LT(worst, 1e-3 * r);  // uniform Catmull-Rom through 24 points of a circle
  // The last frame is one step before the first again, as far as the others.
  const double step = dist(path.camera(1, 8, 8).eye, path.camera(0, 8, 8).eye);
  const double wrap = dist(path.camera(239, 8, 8).eye, path.camera(0, 8, 8).eye);
  EXPECT_NEAR(wrap, step, 1e-3 * step);
}

TEST(CameraPath, DefaultLengthSixtyFramesASegment) {
  CameraPathSpec spec;
  spec.keys = {key(0, 0, -10), key(5, 0, -10), key(9, 0, -10)};
  EXPECT_EQ(CameraPath(spec).frames(), 121);
  spec.loop = true;
  EXPECT_EQ(CameraPath(spec).frames(), 180);
  spec.keys.resize(1);
  EXPECT_EQ(CameraPath(spec).frames(), 1);
}

TEST(CameraPath, RefusesWhatCannotBe) {
  CameraPathSpec none;
  EXPECT_THROW(CameraPath{none}, std::invalid_argument);
  CameraPathSpec backwards;
  backwards.keys = {key(0, 0, -10, 20.0), key(5, 0, -10, 10.0), key(9, 0, -10)};
  backwards.frames = 30;
  EXPECT_THROW(CameraPath{backwards}, std::invalid_argument);
  CameraPathSpec past;
  past.keys = {key(0, 0, -10), key(5, 0, -10, 40.0)};
  past.frames = 30;
  EXPECT_THROW(CameraPath{past}, std::invalid_argument);
}

}  // namespace
}  // namespace prime
