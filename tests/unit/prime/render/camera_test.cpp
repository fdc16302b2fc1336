// The listing's camera and window (RayTrace 7059-7140, Coords 3110-3216).
#include "src/prime/render/camera.h"

#include <gtest/gtest.h>

namespace prime {
namespace {

TEST(ListingCamera, DefaultsGive350By769RaysAndA349By768Header_K21_K22) {
  const ListingCamera c(CameraSettings{});
  // SetScrCoordsX(0.66) = (int)(0.66 * 1024) = (int)675.84 = 675; X(1.0) = 1024.
  EXPECT_EQ(c.screenX(0), 675);
  EXPECT_EQ(c.numPixAcross(), 1024 - 675);
  EXPECT_EQ(c.numPixDown(), 768);
  EXPECT_EQ(c.columns(), 350);
  EXPECT_EQ(c.rows(), 769);
  EXPECT_EQ(c.screenX(349), 1024);  // off-screen: putpixel clips, graph_scr keeps it
  EXPECT_EQ(c.screenY(768), 768);
}

TEST(ListingCamera, FirstAndLastRaysAimAtTheWindowCorners) {
  const ListingCamera c(CameraSettings{});
  // Top-left: window point (0,1000,0) - eye (500,500,-1500).
  const Ray tl = c.primaryRay(0, 0);
  EXPECT_EQ(tl.o, (Vec3{500, 500, -1500}));
  EXPECT_EQ(tl.d, (Vec3{-500, 500, 1500}));
  // Bottom-right after 349 and 768 additions of 1000/349 and -1000/768: the
  // sums are 1000 and -1000 to within rounding of the repeated additions.
  const Ray br = c.primaryRay(768, 349);
  EXPECT_NEAR(br.d[0], 500, 1e-9);
  EXPECT_NEAR(br.d[1], -500, 1e-9);
  EXPECT_EQ(br.d[2], 1500);
}

TEST(ListingCamera, StepsAreAccumulatedByRepeatedAdditionLikeCurAcross) {
  const ListingCamera c(CameraSettings{});
  double across = 0.0;
  for (int j = 0; j < 200; ++j) across += 1000.0 / 349.0;
  // curPt = startPt + curAcross + curDown, then MakeVector subtracts the eye.
  EXPECT_EQ(c.primaryRay(0, 200).d[0], (0.0 + across + -0.0) - 500.0);
  double down = 0.0;
  for (int i = 0; i < 500; ++i) down += -1000.0 / 768.0;
  EXPECT_EQ(c.primaryRay(500, 0).d[1], (1000.0 + 0.0 + down) - 500.0);
}

TEST(ListingCamera, BottomOfWindowIsImpliedByTheTopCorner_K23) {
  // wStepDown = -WL / numPixDown: with the top at y = 2000 the window runs
  // from 2000 down to 0, not to 1000 below the top.
  CameraSettings s;
  s.windowLeft = {0, 2000, 0};
  s.windowRight = {1000, 2000, 0};
  const ListingCamera c(s);
  EXPECT_NEAR(c.primaryRay(768, 0).d[1] + 500, 0.0, 1e-9);
}

TEST(ListingCamera, EmptyViewportIsRefused) {
  CameraSettings s;
  s.xMin = 0.5;
  s.xMax = 0.5;
  EXPECT_THROW(ListingCamera{s}, std::invalid_argument);
}

}  // namespace
}  // namespace prime

namespace prime {
namespace {

TEST(ListingCamera, SampleRayOffsetsByPixelSteps) {
  const ListingCamera c(CameraSettings{});
  const Ray centre = c.primaryRay(100, 50);
  EXPECT_EQ(c.sampleRay(100, 50, 0.0, 0.0).d, centre.d);  // exactly the listing's ray
  // Half a step across is 0.5 * 1000/349 in x; half a step down -0.5 * 1000/768 in y.
  const Ray corner = c.sampleRay(100, 50, 0.5, 0.5);
  EXPECT_NEAR(corner.d[0] - centre.d[0], 0.5 * 1000.0 / 349.0, 1e-12);
  EXPECT_NEAR(corner.d[1] - centre.d[1], -0.5 * 1000.0 / 768.0, 1e-12);
  EXPECT_EQ(corner.d[2], centre.d[2]);
}

}  // namespace
}  // namespace prime
