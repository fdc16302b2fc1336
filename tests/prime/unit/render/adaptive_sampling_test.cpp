// Whitted's adaptive supersampling (thesis 2.6.1) traces each shared point of
// a pixel's subdivision once. The pixels must be exactly those of the plain
// recursion, which casts all five rays of every square afresh; written out
// here as the reference, independently of the renderer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "src/prime/render/renderer.h"
#include "tests/prime/unit/render/small_scene.h"

namespace prime {
namespace {

Scene twoObjects() {
  test::SmallScene small;
  small.object(0.3, {0.6, 0.4, 0.2}, small.prim('S', {250, 250, 250}, {400, 600, 200}));
  small.object(0.5, {0.2, 0.7, 0.4}, small.prim('B', {300, 300, 300}, {550, 200, 100}));
  return small.scene;
}

Rgb average(const Rgb* c, int n) {
  Rgb sum{};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) sum[k] += c[i][k];
  for (auto& v : sum) v /= n;
  return sum;
}

// The plain recursion: five rays per square, four children where the five
// colours differ by more than the tolerance in some channel.
Rgb reference(const Tracer1991& tracer, const ListingCamera& camera, int i, int j, double fx,
              double fy, double h, int level, const Sampling& s, TraceStats& stats) {
  Rgb c[5];
  const double off[5][2] = {{0, 0}, {-h, -h}, {h, -h}, {-h, h}, {h, h}};
  for (int k = 0; k < 5; ++k)
    c[k] = tracer.castRay(camera.sampleRay(i, j, fx + off[k][0], fy + off[k][1]), 0, stats);
  double spread = 0.0;
  for (int ch = 0; ch < 3; ++ch) {
    double lo = c[0][ch], hi = c[0][ch];
    for (int k = 1; k < 5; ++k) {
      lo = std::min(lo, c[k][ch]);
      hi = std::max(hi, c[k][ch]);
    }
    spread = std::max(spread, hi - lo);
  }
  if (level >= s.maxLevel || !(spread > s.tolerance)) return average(c, 5);
  Rgb q[4];
  for (int k = 0; k < 4; ++k)
    q[k] = reference(tracer, camera, i, j, fx + off[k + 1][0] / 2, fy + off[k + 1][1] / 2, h / 2,
                     level + 1, s, stats);
  return average(q, 4);
}

TEST(AdaptiveSampling, SharedPointsTracedOnceSamePixels) {
  const Scene scene = twoObjects();
  for (int levels : {1, 2, 3}) {
    RenderSettings settings;
    settings.camera.screenWidth = 256;  // 89 x 193 pixels
    settings.camera.screenHeight = 192;
    settings.sampling.mode = Sampling::Mode::Adaptive;
    settings.sampling.tolerance = 0.02;
    settings.sampling.maxLevel = levels;
    settings.threads = 2;
    const RenderResult r = render(scene, settings);
    const Tracer1991 tracer(scene);
    const ListingCamera camera(settings.camera);
    TraceStats plain;
    for (int i = 0; i < camera.rows(); ++i)
      for (int j = 0; j < camera.columns(); ++j) {
        const Rgb want =
            reference(tracer, camera, i, j, 0.0, 0.0, 0.5, 0, settings.sampling, plain);
        const Rgb& got = r.rgb.at(i, j);
        ASSERT_EQ(std::memcmp(want.data(), got.data(), sizeof want), 0)
            << "levels " << levels << " row " << i << " column " << j;
      }
    // Fewer primary rays: at least 5 per pixel, and every subdivided square
    // reuses its parent's corner and centre.
    const auto pixels = static_cast<std::uint64_t>(camera.rows() * camera.columns());
    EXPECT_GE(r.stats.primaryRays, 5 * pixels);
    EXPECT_LT(r.stats.primaryRays, plain.primaryRays) << "levels " << levels;
    EXPECT_GT(plain.primaryRays, 5 * pixels + 1000);  // some squares were subdivided
  }
}

}  // namespace
}  // namespace prime
