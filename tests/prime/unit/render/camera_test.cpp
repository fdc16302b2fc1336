// The listing's camera and window (RayTrace 7059-7140, Coords 3110-3216).
#include "src/prime/render/camera.h"

#include <gtest/gtest.h>

#include <cmath>

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

// The free camera in PRIME (T30-T34).
namespace prime {
namespace {

TEST(ListingWindow, CornersAreTheOnesTheListingsRaysReach_K23) {
  const auto c = listingWindowCorners(CameraSettings{});
  EXPECT_EQ(c[0], (Vec3{0, 1000, 0}));
  EXPECT_EQ(c[1], (Vec3{1000, 1000, 0}));
  EXPECT_EQ(c[2], (Vec3{0, 0, 0}));
  EXPECT_EQ(c[3], (Vec3{1000, 0, 0}));
  // The listing's last row really ends there: row 768's window points are
  // WL + j * stepAcross + 768 * stepDown = (x, 0, 0).
  const ListingCamera l(CameraSettings{});
  const Ray r = l.primaryRay(768, 349);  // d = point - eye
  EXPECT_NEAR(r.d[0] + 500.0, 1000.0, 1e-9);
  EXPECT_NEAR(r.d[1] + 500.0, 0.0, 1e-9);
}

TEST(FramedListingWindow, SquarePictureShowsExactlyTheWindow_T33) {
  // From (500, 500, -1500) the window's half side 500 lies at distance 1500:
  // half height 1/3, fov = 2 atan(1/3) = 36.87 degrees. The outer corner of
  // pixel (0, 0) then looks at (0, 1000, 0): direction (-500, 500, 1500) / 1500.
  const FreeCameraSettings f = framedListingWindow(CameraSettings{}, 769, 769);
  EXPECT_EQ(f.lookAt, (Vec3{500, 500, 0}));
  EXPECT_NEAR(f.fovY, 2.0 * std::atan(1.0 / 3.0) * 180.0 / 3.14159265358979323846, 1e-9);
  const FreeCamera c(f);
  const auto expectDir = [](const Vec3& d, const Vec3& want) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(d[k] / d[2], want[k] / want[2], 1e-12) << k;
  };
  expectDir(c.sampleRay(0, 0, -0.5, -0.5).d, {-500, 500, 1500});
  expectDir(c.sampleRay(768, 768, 0.5, 0.5).d, {500, -500, 1500});
  // The centre pixel looks at the window's centre.
  expectDir(c.primaryRay(384, 384).d, {0, 0, 1500});
}

TEST(FramedListingWindow, WidePictureFitsTheHeightAndCentresTheWindow_T33) {
  // 1024 x 768: the height decides (half height 1/3 against half width
  // 1/3 / (4/3) = 1/4); the 1000-unit window is 768 pixels wide, from
  // column 512 - 384 = 128 to 896: pixel 128's left edge looks at x = 0.
  const FreeCamera c(framedListingWindow(CameraSettings{}, 1024, 768));
  const Vec3 d = c.sampleRay(0, 128, -0.5, -0.5).d;
  EXPECT_NEAR(500.0 + 1500.0 * d[0] / d[2], 0.0, 1e-9);
  EXPECT_NEAR(500.0 + 1500.0 * d[1] / d[2], 1000.0, 1e-9);
  const Vec3 e = c.sampleRay(767, 895, 0.5, 0.5).d;
  EXPECT_NEAR(500.0 + 1500.0 * e[0] / e[2], 1000.0, 1e-9);
  EXPECT_NEAR(500.0 + 1500.0 * e[1] / e[2], 0.0, 1e-9);
}

TEST(PrimeCamera, ListingByDefaultAndBitIdenticalToIt) {
  const PrimeCamera p(CameraSettings{});
  const ListingCamera l(CameraSettings{});
  EXPECT_FALSE(p.isFree());
  EXPECT_EQ(p.columns(), 350);
  EXPECT_EQ(p.rows(), 769);
  EXPECT_EQ(p.numPixAcross(), 349);
  EXPECT_EQ(p.numPixDown(), 768);
  EXPECT_EQ(p.screenX(0), 675);
  EXPECT_EQ(p.screenWidth(), 1024);
  for (int i : {0, 100, 768})
    for (int j : {0, 17, 349}) {
      EXPECT_EQ(p.primaryRay(i, j).d, l.primaryRay(i, j).d);
      EXPECT_EQ(p.sampleRay(i, j, 0.25, -0.25).d, l.sampleRay(i, j, 0.25, -0.25).d);
    }
}

TEST(PrimeCamera, FreeCameraIsItsOwnScreenWithAnInclusiveHeader_T32) {
  CameraSettings s;
  s.free = framedListingWindow(s, 7, 5);
  const PrimeCamera p(s);
  EXPECT_TRUE(p.isFree());
  EXPECT_EQ(p.columns(), 7);
  EXPECT_EQ(p.rows(), 5);
  EXPECT_EQ(p.numPixAcross(), 6);  // as the listing's header: columns - 1
  EXPECT_EQ(p.numPixDown(), 4);
  EXPECT_EQ(p.screenWidth(), 7);
  EXPECT_EQ(p.screenHeight(), 5);
  EXPECT_EQ(p.screenX(3), 3);
  EXPECT_EQ(p.primaryRay(2, 3).d, FreeCamera(*s.free).primaryRay(2, 3).d);
}

}  // namespace
}  // namespace prime
