// render() (src/malone/render.h): the raster does not depend on the number
// of threads, and the BVH gives exactly the raster of the original's linear
// search, on every scene of scenes/malone (at a reduced resolution).
#include "src/malone/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "legacy_io/malone/ppm.h"

namespace prime::malone {
namespace {

const std::string kScenes = MALONE_SCENES;

std::vector<std::string> sceneFiles() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(kScenes))
    if (e.path().extension() == ".mal") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// The scene at most `maxSide` pixels wide or high (the same aspect ratio,
// rounded): the primary rays still cover the whole view.
Scene reduced(const std::string& path, int maxSide) {
  Scene s = buildScene(readSceneFile(path), path);
  const int big = std::max(s.viewer.xRes, s.viewer.yRes);
  if (big > maxSide) {
    s.viewer.xRes = std::max(1, s.viewer.xRes * maxSide / big);
    s.viewer.yRes = std::max(1, s.viewer.yRes * maxSide / big);
  }
  return s;
}

// Bit-for-bit equality of two rasters (NaN-safe, -0 distinct).
bool sameBits(const RgbImage& a, const RgbImage& b) {
  return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

TEST(MaloneRender, SameBytesForOneTwoThreeThreads) {
  for (const std::string& path : sceneFiles()) {
    SCOPED_TRACE(path);
    const Scene s = reduced(path, 96);
    RenderSettings settings;
    settings.threads = 1;
    const RenderResult one = render(s, settings);
    ASSERT_EQ(one.raster.width, s.viewer.xRes);
    ASSERT_EQ(one.raster.height, s.viewer.yRes);
    for (int threads : {2, 3}) {
      settings.threads = threads;
      const RenderResult many = render(s, settings);
      EXPECT_TRUE(sameBits(one.raster, many.raster)) << threads << " threads";
      EXPECT_EQ(ppmBytes(one.raster), ppmBytes(many.raster));
      // The statistics are sums over rows: the same too.
      EXPECT_EQ(one.stats.rays(), many.stats.rays());
      EXPECT_EQ(one.stats.hits, many.stats.hits);
      EXPECT_EQ(one.stats.primaryRays, static_cast<std::uint64_t>(s.viewer.xRes) * s.viewer.yRes);
    }
  }
}

TEST(MaloneRender, LinearSearchGivesTheBvhRaster) {
  int scenes = 0;
  for (const std::string& path : sceneFiles()) {
    SCOPED_TRACE(path);
    ++scenes;
    const Scene s = reduced(path, 96);
    RenderSettings bvh;
    bvh.threads = 2;
    RenderSettings linear = bvh;
    linear.trace.linearSearch = true;
    const RenderResult a = render(s, bvh), b = render(s, linear);
    EXPECT_TRUE(sameBits(a.raster, b.raster));
    // The same rays were traced; only the primitive tests differ.
    EXPECT_EQ(a.stats.rays(), b.stats.rays());
    EXPECT_EQ(a.stats.hits, b.stats.hits);
    EXPECT_LE(a.stats.primitiveTests, b.stats.primitiveTests);
    // Something was hit: the comparison is not between two black images.
    EXPECT_GT(a.stats.hits, 0u);
  }
  EXPECT_EQ(scenes, 17);
}

TEST(MaloneRender, RasterIsTracerPixels) {
  // Row 0 is the top, column X is pixel X: render() fills what Tracer::pixel
  // returns at (X, Y).
  const Scene s = reduced(kScenes + "/doc-scene.mal", 32);
  RenderSettings settings;
  settings.threads = 2;
  const RenderResult r = render(s, settings);
  const Tracer tracer(s, settings.trace);
  TraceStats stats;
  for (int Y : {0, 7, 16, 31})
    for (int X : {0, 5, 16, 31}) EXPECT_EQ(r.raster.at(Y, X), tracer.pixel(X, Y, stats));
  // The centre pixel of the 32 x 32 reduction is still the document's 0.02638.
  const double want = 5 / (33 * std::sqrt(33.0));
  EXPECT_NEAR(r.raster.at(16, 16)[0], want, 1e-15);
}

TEST(MaloneRender, RowCallbacks) {
  const Scene s = reduced(kScenes + "/doc-sphere.mal", 16);
  RenderSettings settings;
  settings.threads = 3;
  std::vector<int> seen(static_cast<std::size_t>(s.viewer.yRes), 0);
  RenderCallbacks callbacks;
  std::vector<std::vector<Rgb>> rows(static_cast<std::size_t>(s.viewer.yRes));
  callbacks.rowDone = [&](int row, std::span<const Rgb> colours) {
    ++seen[static_cast<std::size_t>(row)];
    rows[static_cast<std::size_t>(row)].assign(colours.begin(), colours.end());
  };
  const RenderResult r = render(s, settings, callbacks);
  for (int row = 0; row < s.viewer.yRes; ++row) {
    EXPECT_EQ(seen[static_cast<std::size_t>(row)], 1) << row;
    ASSERT_EQ(rows[static_cast<std::size_t>(row)].size(), static_cast<std::size_t>(s.viewer.xRes));
    for (int x = 0; x < s.viewer.xRes; ++x)
      EXPECT_EQ(rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(x)],
                r.raster.at(row, x));
  }
}

}  // namespace
}  // namespace prime::malone
