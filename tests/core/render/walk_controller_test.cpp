// prime walk's input logic without a window (src/render/walk_controller.h,
// src/render/progressive.h): synthetic keys and drags change the view and
// bump the generation; a newer request abandons the frame in flight.
#include "src/render/walk_controller.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "src/render/progressive.h"

namespace prime {
namespace {

OrbitView listingView() {
  FreeCameraSettings c;
  c.eye = {500, 500, -1500};
  c.lookAt = {500, 500, 0};
  c.fovY = 36.0;
  c.width = c.height = 100;
  return OrbitView::from(c);
}

void expectVec(const Vec3& got, const Vec3& want, double tol = 1e-9) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tol) << "component " << k;
}

TEST(OrbitView, ReproducesTheCameraItCameFrom) {
  const OrbitView v = listingView();
  EXPECT_EQ(v.eye(), (Vec3{500, 500, -1500}));  // yaw = pitch = 0: exactly
  EXPECT_DOUBLE_EQ(v.distance, 1500.0);
  EXPECT_DOUBLE_EQ(v.yaw, 0.0);
  EXPECT_DOUBLE_EQ(v.pitch, 0.0);
}

TEST(OrbitView, OrbitPanDollyByHand) {
  OrbitView v = listingView();
  v.orbit(90.0, 0.0);  // the eye swings to +x: (500 + 1500, 500, 0)
  expectVec(v.eye(), {2000, 500, 0});
  v.orbit(-90.0, 30.0);  // back, then 30 degrees up: y 500 + 1500 sin 30, z -1500 cos 30
  expectVec(v.eye(), {500, 1250, -1500 * std::cos(std::numbers::pi / 6)});
  v.orbit(0.0, 200.0);  // pitch stops at 89
  EXPECT_DOUBLE_EQ(v.pitch, 89.0);
  OrbitView p = listingView();
  // One pixel at the target spans 2 * 1500 * tan(18 degrees) / 100.
  const double px = 2.0 * 1500.0 * std::tan(18.0 * std::numbers::pi / 180.0) / 100.0;
  EXPECT_NEAR(p.pixelAtTarget(), px, 1e-12);
  p.pan(10, 0);  // right is +x when looking down +z
  expectVec(p.target, {500 + 10 * px, 500, 0});
  expectVec(p.eye(), {500 + 10 * px, 500, -1500});
  p.dolly(0.5);
  expectVec(p.eye(), {500 + 10 * px, 500, -750});
}

// The screen point of `p` in the view's picture (column, row; centres at +0.5).
std::array<double, 2> projected(const OrbitView& v, const Vec3& p) {
  const FreeCamera c(v.camera());
  const Vec3 r = p - v.eye();
  const double z = dot(r, c.forward());
  const double pixel = 2.0 * std::tan(0.5 * v.fovY * std::numbers::pi / 180.0) / v.height;
  return {0.5 * v.width + dot(r, c.right()) / z / pixel,
          0.5 * v.height - dot(r, c.trueUp()) / z / pixel};
}

TEST(OrbitView, APivotOffTheTargetStaysOnItsPixelOverAFullOrbit) {
  // The listing's camera looking at (500, 500, 0), turning about a scene
  // whose objects are centred at (300, 400, 600), as plate 3's are off the
  // listing window's centre: the scene's centre stays where it first
  // appeared on the picture, a full turn round and up and down.
  const Vec3 centre{300, 400, 600};
  FreeCameraSettings c;
  c.eye = {500, 500, -1500};
  c.lookAt = {500, 500, 0};
  c.fovY = 36.0;
  c.width = 512;
  c.height = 384;
  OrbitView v = OrbitView::from(c, centre);
  const auto first = projected(v, centre);
  const double distance = length(c.eye - centre);
  for (int step = 0; step < 72; ++step) {
    v.orbit(5.0, step < 36 ? 1.0 : -1.5);
    const auto now = projected(v, centre);
    EXPECT_NEAR(now[0], first[0], 1e-6) << "step " << step;
    EXPECT_NEAR(now[1], first[1], 1e-6) << "step " << step;
    EXPECT_NEAR(length(v.eye() - centre), distance, 1e-6);  // a rigid turn
  }
  // The turns add up: 72 x 5 degrees of yaw is a whole turn.
  EXPECT_NEAR(std::remainder(v.yaw, 360.0), 0.0, 1e-9);
  // Panning takes the pivot along.
  const Vec3 pivotBefore = v.pivot, targetBefore = v.target;
  v.pan(10, 0);
  EXPECT_NEAR(length(v.pivot - pivotBefore), 10 * v.pixelAtTarget(), 1e-9);
  expectVec(v.pivot - pivotBefore, v.target - targetBefore);
  // Turning about the target itself is the plain orbit.
  OrbitView plain = OrbitView::from(c), pivoted = OrbitView::from(c, c.lookAt);
  plain.orbit(33.0, 12.0);
  pivoted.orbit(33.0, 12.0);
  EXPECT_EQ(plain.eye(), pivoted.eye());
  EXPECT_EQ(plain.target, pivoted.target);
}

TEST(WalkController, EveryMoveBumpsTheGenerationAndResetRestores) {
  WalkController c(listingView(), {{0, 2000, -1000}}, 2);
  std::uint64_t g = c.generation();
  c.arrows(1, 0);
  EXPECT_EQ(c.generation(), ++g);
  EXPECT_DOUBLE_EQ(c.view().yaw, WalkController::kOrbitStep);
  c.panArrows(0, 1);
  EXPECT_EQ(c.generation(), ++g);
  c.dolly(2);
  EXPECT_EQ(c.generation(), ++g);
  EXPECT_NEAR(c.view().distance, 1500 * 0.81, 1e-9);
  c.drag(true, 10, 0);  // 10 pixels right: the scene turns right, the eye left
  EXPECT_EQ(c.generation(), ++g);
  EXPECT_NEAR(c.view().yaw, WalkController::kOrbitStep - 10 * WalkController::kDragDegrees, 1e-12);
  c.arrows(0, 0);  // no move, no new frame
  EXPECT_EQ(c.generation(), g);
  c.reset();
  EXPECT_EQ(c.generation(), ++g);
  EXPECT_EQ(c.view().eye(), (Vec3{500, 500, -1500}));
}

TEST(WalkController, SelectedLightMovesInsteadOfTheCamera) {
  WalkController c(listingView(), {{0, 2000, -1000}, {100, 100, 100}}, 2);
  c.selectLight(2);
  const std::uint64_t g = c.generation();
  EXPECT_EQ(c.generation(), g);  // selecting changes nothing rendered
  c.arrows(1, 0);                // 16 pixels right at the target's distance: +x
  const double px = c.view().pixelAtTarget();
  expectVec(c.lights()[1], {100 + 16 * px, 100, 100});
  expectVec(c.lights()[0], {0, 2000, -1000});
  EXPECT_EQ(c.view().eye(), (Vec3{500, 500, -1500}));
  EXPECT_EQ(c.generation(), g + 1);
  c.dolly(1);  // a tenth of the distance along the view (+z)
  expectVec(c.lights()[1], {100 + 16 * px, 100, 250});
  c.cycleSelection();  // light 2 -> the camera
  EXPECT_EQ(c.selectedLight(), 0);
  c.selectLight(7);  // no such light: ignored
  EXPECT_EQ(c.selectedLight(), 0);
  c.reset();
  expectVec(c.lights()[1], {100, 100, 100});
}

TEST(WalkController, ProfileAndViewSwitch) {
  WalkController c(listingView(), {}, 2);
  c.nextProfile();
  EXPECT_EQ(c.profile(), 1);
  c.nextProfile();
  EXPECT_EQ(c.profile(), 0);
  c.togglePaletteView();
  EXPECT_TRUE(c.paletteView());
  EXPECT_EQ(c.generation(), 4u);  // 1 + three changes
}

TEST(Progressive, FinerPassesReuseTheCoarserGrid) {
  // Pass 8 samples everything (it is the first); pass 4 reuses the points on
  // the 8-grid; pass 1 reuses the even points.
  EXPECT_FALSE(sampledInEarlierPass(0, 0, 8, 8));
  EXPECT_TRUE(sampledInEarlierPass(8, 16, 4, 8));
  EXPECT_FALSE(sampledInEarlierPass(4, 16, 4, 8));
  EXPECT_TRUE(sampledInEarlierPass(2, 6, 1, 8));
  EXPECT_FALSE(sampledInEarlierPass(2, 5, 1, 8));
  // A 64 x 64 picture: the four passes sample 64, 192, 768 and 3072 points,
  // each pixel once.
  int total = 0;
  for (const int block : kProgressiveBlocks)
    for (int y = 0; y < 64; y += block)
      for (int x = 0; x < 64; x += block) total += !sampledInEarlierPass(y, x, block, 8);
  EXPECT_EQ(total, 64 * 64);
}

TEST(LatestJobRunner, NewerRequestAbandonsTheFrameInFlightAndSkipsStaleOnes) {
  std::mutex m;
  std::vector<std::pair<int, bool>> runs;  // request, abandoned
  std::atomic<bool> started{false};
  LatestJobRunner<int> runner([&](const int& r, std::uint64_t, const std::atomic<bool>& abandon) {
    started = true;
    // A "frame" that takes up to 5 s unless abandoned (checked like renderRows between rows).
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(r == 1 ? 5 : 0);
    while (!abandon && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::lock_guard lock(m);
    runs.emplace_back(r, abandon.load());
  });
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(runner.request(1), 1u);
  while (!started) std::this_thread::yield();
  runner.request(2);
  const std::uint64_t last = runner.request(3);
  runner.waitIdle();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(4))
      << "frame 1 was not abandoned";
  std::lock_guard lock(m);
  ASSERT_FALSE(runs.empty());
  EXPECT_EQ(runs.front(), std::make_pair(1, true));
  EXPECT_EQ(runs.back(), std::make_pair(3, false));  // the latest always runs to its end
  EXPECT_LE(runs.size(), 3u);
  EXPECT_EQ(runner.completed(), last);
}

TEST(LatestJobRunner, AnExceptionReachesWaitIdle) {
  LatestJobRunner<int> runner([](const int&, std::uint64_t, const std::atomic<bool>&) {
    throw std::runtime_error("boom");
  });
  runner.request(1);
  EXPECT_THROW(runner.waitIdle(), std::runtime_error);
}

}  // namespace
}  // namespace prime
