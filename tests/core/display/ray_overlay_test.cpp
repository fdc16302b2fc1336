// The ray overlay (palette/ray_overlay.h): world points to picture points by
// hand, clipping at the eye, and what is drawn where.
#include "palette/ray_overlay.h"

#include <gtest/gtest.h>

namespace prime {
namespace {

// A pinhole at the origin looking down +z, 100 x 100 pixels of 0.01 at
// distance 1, pixel (0, 0)'s centre up and to the left: the free camera's map.
PictureProjection pinhole() {
  return {{0, 0, 0}, {-0.495, 0.495, 1.0}, {0.01, 0, 0}, {0, -0.01, 0}, 0.5, 0.5};
}

TEST(RayOverlay, ProjectsWorldPointsWhereWorkedOutByHand) {
  // (0.2, 0.1, 2): at distance 2 the direction is (0.1, 0.05, 1); across:
  // (0.1 + 0.495) / 0.01 = 59.5 steps from pixel 0's centre, so x = 60;
  // down: (0.495 - 0.05) / 0.01 = 44.5, so y = 45.
  const auto p = pinhole().project({0.2, 0.1, 2.0});
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x, 60.0, 1e-9);
  EXPECT_NEAR(p->y, 45.0, 1e-9);
  EXPECT_NEAR(p->s, 2.0, 1e-12);
  // The centre of the view is the picture's centre (50, 50); behind the eye s < 0.
  const auto c = pinhole().project({0, 0, 7});
  EXPECT_NEAR(c->x, 50.0, 1e-9);
  EXPECT_NEAR(c->y, 50.0, 1e-9);
  EXPECT_LT(pinhole().project({0, 0, -1})->s, 0.0);
  // A corner camera (offset 0): Malone's ray of pixel (X, Y) through its corner.
  PictureProjection corner = pinhole();
  corner.offsetX = corner.offsetY = 0.0;
  EXPECT_NEAR(corner.project({0.2, 0.1, 2.0})->x, 59.5, 1e-9);
}

TEST(RayOverlay, ClipsSegmentsAtTheEye) {
  const PictureProjection cam = pinhole();
  // From behind the eye to a point in view: the far end is where it was,
  // the near end moved in front of the eye.
  const auto ends = projectSegment(cam, {{0.0, 0.0, -1.0}, {0.2, 0.1, 2.0}, OverlayKind::Primary});
  ASSERT_TRUE(ends.has_value());
  EXPECT_GT((*ends)[0].s, 0.0);
  EXPECT_NEAR((*ends)[1].x, 60.0, 1e-9);
  EXPECT_NEAR((*ends)[1].y, 45.0, 1e-9);
  // Wholly behind: nothing to draw.
  EXPECT_FALSE(projectSegment(cam, {{0, 0, -1}, {1, 1, -2}, OverlayKind::Reflected}).has_value());
}

TEST(RayOverlay, DrawsTheSegmentsOverTheDimmedPictureAndOutlinesThePixel) {
  Image8 picture;
  picture.width = picture.height = 100;
  picture.rgb.assign(100 * 100 * 3, 200);
  // A reflected ray from the picture point (20, 50) to (80, 50), both at
  // distance 1 (x = -0.295 and 0.305 on the image plane), ending on a hit.
  const OverlaySegment seg{{-0.295, 0.0, 1.0}, {0.305, 0.0, 1.0}, OverlayKind::Reflected, true};
  const Image8 img = drawRayOverlay(picture, std::span(&seg, 1), pinhole(), 10, 10);
  auto at = [&](int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * 100 + x) * 3;
    return std::array<std::uint8_t, 3>{img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]};
  };
  const auto cyan = overlayColour(OverlayKind::Reflected);
  for (int x = 21; x < 78; ++x) EXPECT_EQ(at(x, 50), cyan) << x;        // along the ray
  EXPECT_EQ(at(80 + 2, 50), cyan);                                      // the hit's square
  EXPECT_EQ(at(50, 20), (std::array<std::uint8_t, 3>{100, 100, 100}));  // dimmed to half
  EXPECT_EQ(at(13, 10), (std::array<std::uint8_t, 3>{255, 0, 255}));    // the probed pixel
}

}  // namespace
}  // namespace prime
