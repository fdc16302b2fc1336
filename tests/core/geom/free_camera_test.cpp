// The free camera's rays, worked by hand (src/geom/free_camera.h): the image
// plane at distance 1, half height tan(fov / 2), pixels square, pixel centres
// at column + 0.5, row + 0.5.
#include "src/geom/free_camera.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace prime {
namespace {

void expectVec(const Vec3& got, const Vec3& want, double tol = 1e-12) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tol) << "component " << k;
}

double degreesBetween(const Vec3& a, const Vec3& b) {
  return std::acos(dot(a, b) / (length(a) * length(b))) * 180.0 / std::numbers::pi;
}

FreeCameraSettings axisCamera(double fov, int w, int h) {
  FreeCameraSettings s;  // eye at the origin, looking down +z, up +y
  s.fovY = fov;
  s.width = w;
  s.height = h;
  return s;
}

TEST(FreeCamera, TwoByTwoAtNinetyDegreesByHand) {
  // fov 90: half height tan(45) = 1, so the plane spans -1..1 both ways and
  // a pixel is 1 x 1. Pixel (0, 0)'s centre is (-0.5, 0.5, 1), (1, 1)'s (0.5, -0.5, 1).
  const FreeCamera c(axisCamera(90.0, 2, 2));
  expectVec(c.primaryRay(0, 0).d, {-0.5, 0.5, 1.0});
  expectVec(c.primaryRay(0, 1).d, {0.5, 0.5, 1.0});
  expectVec(c.primaryRay(1, 0).d, {-0.5, -0.5, 1.0});
  expectVec(c.primaryRay(1, 1).d, {0.5, -0.5, 1.0});
  expectVec(c.primaryRay(1, 1).o, {0.0, 0.0, 0.0});
  // The footprint's outer corners are the field of view's corners (x, y = +-1).
  expectVec(c.sampleRay(0, 0, -0.5, -0.5).d, {-1.0, 1.0, 1.0});
  expectVec(c.sampleRay(1, 1, 0.5, 0.5).d, {1.0, -1.0, 1.0});
}

TEST(FreeCamera, CentreRayRunsAlongTheLookAtDirection) {
  FreeCameraSettings s = axisCamera(30.0, 5, 3);
  s.eye = {500, 500, -1500};
  s.lookAt = {800, 100, 0};  // view direction (300, -400, 1500)
  const FreeCamera c(s);
  // 5 x 3: pixel (1, 2) is the centre pixel, and its centre the image's.
  const Vec3 d = c.primaryRay(1, 2).d;
  expectVec(normalized(d), normalized(Vec3{300, -400, 1500}));
  expectVec(c.primaryRay(1, 2).o, {500, 500, -1500});
}

TEST(FreeCamera, EdgeRaysMakeHalfTheVerticalFieldOfViewWithTheAxis) {
  const FreeCamera c(axisCamera(60.0, 8, 6));
  const Vec3 axis{0, 0, 1};
  // The top edge's middle (between columns 3 and 4, at the top of row 0):
  // 30 degrees up.
  const Vec3 top = c.sampleRay(0, 3, 0.5, -0.5).d;
  EXPECT_NEAR(degreesBetween(top, axis), 30.0, 1e-9);
  EXPECT_GT(top[1], 0.0);
  const Vec3 bottom = c.sampleRay(5, 4, -0.5, 0.5).d;
  EXPECT_NEAR(degreesBetween(bottom, axis), 30.0, 1e-9);
  EXPECT_LT(bottom[1], 0.0);
  // Horizontally the plane is 8/6 as wide: half width tan(30) * 4/3.
  const Vec3 left = c.sampleRay(2, 0, -0.5, 0.5).d;  // the left edge's middle
  EXPECT_NEAR(left[0] / left[2], -std::tan(std::numbers::pi / 6) * 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(left[1], 0.0, 1e-12);
}

TEST(FreeCamera, PixelsAreSquareWhateverTheAspect) {
  for (const auto& [w, h] : {std::array{4, 2}, std::array{350, 769}, std::array{1024, 768}}) {
    const FreeCamera c(axisCamera(45.0, w, h));
    EXPECT_NEAR(length(c.stepAcross()), length(c.stepDown()), 1e-15) << w << " x " << h;
    EXPECT_NEAR(dot(c.stepAcross(), c.stepDown()), 0.0, 1e-15);
    // Two steps across and two down subtend the same distance on the plane.
    const Vec3 a = c.primaryRay(0, 0).d, b = c.primaryRay(0, 1).d, d = c.primaryRay(1, 0).d;
    EXPECT_NEAR(length(b - a), length(d - a), 1e-15);
  }
  // 4 x 2 at 90 degrees: pixel 1 x 1, so the plane is 4 wide: x from -2 to 2.
  const FreeCamera wide(axisCamera(90.0, 4, 2));
  expectVec(wide.sampleRay(0, 0, -0.5, -0.5).d, {-2.0, 1.0, 1.0});
  expectVec(wide.sampleRay(1, 3, 0.5, 0.5).d, {2.0, -1.0, 1.0});
}

TEST(FreeCamera, UpVectorTurnsThePicture) {
  // Up +x while looking down +z: right = up x forward = (0, -1, 0) and the
  // true up is forward x right = (1, 0, 0), so row 0 lies towards +x and
  // column 0 towards +y: pixel (0, 0) of 2 x 2 at 90 degrees is
  // (0, 0, 1) - 0.5 * right + 0.5 * up = (0.5, 0.5, 1).
  FreeCameraSettings s = axisCamera(90.0, 2, 2);
  s.up = {1, 0, 0};
  const FreeCamera c(s);
  expectVec(c.right(), {0, -1, 0});
  expectVec(c.trueUp(), {1, 0, 0});
  expectVec(c.primaryRay(0, 0).d, {0.5, 0.5, 1.0});
  expectVec(c.primaryRay(1, 0).d, {-0.5, 0.5, 1.0});
  // An up vector not at right angles to the view is made so (only its
  // component across the view counts): up (0, 1, 1) acts as (0, 1, 0).
  s.up = {0, 1, 1};
  expectVec(FreeCamera(s).trueUp(), {0, 1, 0});
}

TEST(FreeCamera, RefusesWhatCannotBeACamera) {
  FreeCameraSettings s = axisCamera(60, 10, 10);
  s.lookAt = s.eye;
  EXPECT_THROW(FreeCamera{s}, std::invalid_argument);
  s = axisCamera(60, 10, 10);
  s.up = {0, 0, 5};  // along the view
  EXPECT_THROW(FreeCamera{s}, std::invalid_argument);
  s.up = {0, 0, 0};
  EXPECT_THROW(FreeCamera{s}, std::invalid_argument);
  EXPECT_THROW(FreeCamera{axisCamera(0.0, 10, 10)}, std::invalid_argument);
  EXPECT_THROW(FreeCamera{axisCamera(180.0, 10, 10)}, std::invalid_argument);
  EXPECT_THROW(FreeCamera{axisCamera(60.0, 0, 10)}, std::invalid_argument);
  EXPECT_THROW(FreeCamera{axisCamera(60.0, 10, 32768)}, std::invalid_argument);
}

TEST(FitFovY, SmallestFieldOfViewThatShowsEveryPoint) {
  const std::array<Vec3, 4> square{Vec3{-1, -1, 1}, Vec3{1, -1, 1}, Vec3{-1, 1, 1}, Vec3{1, 1, 1}};
  const Vec3 eye{0, 0, 0}, at{0, 0, 1}, up{0, 1, 0};
  // Square picture: half height 1 at distance 1, 90 degrees.
  EXPECT_NEAR(fitFovY(eye, at, up, 100, 100, square), 90.0, 1e-12);
  // Twice as wide: the height still decides.
  EXPECT_NEAR(fitFovY(eye, at, up, 200, 100, square), 90.0, 1e-12);
  // Twice as tall: the width decides, half height 2: 2 atan(2) = 126.87 degrees.
  EXPECT_NEAR(fitFovY(eye, at, up, 100, 200, square), 2.0 * std::atan(2.0) * 180 / std::numbers::pi,
              1e-12);
  const std::array<Vec3, 1> behind{Vec3{0, 0, -1}};
  EXPECT_THROW(fitFovY(eye, at, up, 10, 10, behind), std::invalid_argument);
}

}  // namespace
}  // namespace prime
