// A render through the free camera (T30-T32): the graph file's header and
// size follow the picture, and the primary-ray mask built on the free
// camera's linear map skips only pixels the tracer would have left as
// background.
#include <gtest/gtest.h>

#include <cstring>

#include "src/prime/render/renderer.h"
#include "src/prime/render/tracer_modern.h"
#include "tests/prime/unit/render/small_scene.h"

namespace prime {
namespace {

using test::sphereScene;

TEST(FreeCameraRender, GraphFileHeaderIsTheFreeSizeInclusive_T32) {
  const Scene scene = sphereScene();
  RenderSettings settings;
  settings.camera.free = framedListingWindow(settings.camera, 7, 5);
  settings.threads = 1;
  const RenderResult r = render(scene, settings);
  EXPECT_EQ(r.graph.numPixAcross, 6);
  EXPECT_EQ(r.graph.numPixDown, 4);
  EXPECT_TRUE(r.graph.inclusive);
  EXPECT_EQ(r.graph.width(), 7);
  EXPECT_EQ(r.graph.height(), 5);
  EXPECT_EQ(r.graph.pixels.size(), 35u);
  EXPECT_EQ(r.rgb.width, 7);
  EXPECT_EQ(r.rgb.height, 5);
  // The centre pixel looks at the sphere (radius 200 at the window's centre);
  // the corner pixels look past it at the window's corners.
  const Rgb bg{0.05, 0.1, 0.15};
  EXPECT_NE(r.rgb.at(2, 3), bg);
  EXPECT_EQ(r.rgb.at(0, 0), bg);
  EXPECT_EQ(r.rgb.at(4, 6), bg);
}

TEST(FreeCameraRender, MaskedFreeRenderEqualsTracingEveryPixel) {
  const Scene scene = sphereScene();
  for (const Profile profile : {Profile::Listing1991, Profile::Modern}) {
    RenderSettings settings;
    settings.profile = profile;
    FreeCameraSettings f;
    f.eye = {1400, 900, -900};
    f.lookAt = {500, 450, 200};
    f.up = {0.1, 1, 0};
    f.fovY = 35;
    f.width = 96;
    f.height = 64;
    settings.camera.free = f;
    settings.threads = 2;
    const RenderResult r = render(scene, settings);
    EXPECT_GT(r.stats.maskedPrimaryRays, 1000u) << "the sphere fills little of the picture";
    TraceOptions all;
    all.skipUnneededWork = false;
    const Tracer1991 t1991(scene, all);
    const TracerModern tModern(scene, all);
    const FreeCamera camera(f);
    TraceStats stats;
    int hits = 0;
    for (int i = 0; i < camera.rows(); ++i)
      for (int j = 0; j < camera.columns(); ++j) {
        const Ray ray = camera.primaryRay(i, j);
        const Rgb c = profile == Profile::Modern ? tModern.castRay(ray, 0, stats)
                                                 : t1991.castRay(ray, 0, stats);
        hits += c != Rgb{0.05, 0.1, 0.15};
        ASSERT_EQ(std::memcmp(c.data(), r.rgb.at(i, j).data(), sizeof c), 0)
            << "row " << i << " column " << j;
      }
    EXPECT_GT(hits, 300);
  }
}

}  // namespace
}  // namespace prime
