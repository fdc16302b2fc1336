// prime walk's passes (src/prime/render/walk_render.h) and prime compare's
// arithmetic (src/prime/render/compare.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "src/geom/orbit_view.h"
#include "src/prime/render/compare.h"
#include "src/prime/render/walk_render.h"
#include "src/prime/scene/object_bvh.h"
#include "src/render/progressive.h"
#include "tests/prime/unit/render/small_scene.h"

namespace prime {
namespace {

using test::sphereScene;

TEST(WalkRenderer, LastPassEqualsTheRenderAndCoarsePassesFillBlocks) {
  const Scene scene = sphereScene();
  for (const Profile profile : {Profile::Listing1991, Profile::Modern}) {
    RenderSettings settings;
    settings.profile = profile;
    settings.camera.free = framedListingWindow(settings.camera, 45, 37);  // not multiples of 8
    settings.threads = 2;
    const RenderResult full = render(scene, settings);
    const FreeCamera camera(*settings.camera.free);
    const WalkRenderer walk(scene, profile, settings.trace);
    RgbImage img;
    img.assign(45, 37);
    TraceStats stats;
    int rowsReported = 0;
    ASSERT_TRUE(walk.pass(
        camera, 8, 8, img, 2, nullptr, [&](int, int rows) { rowsReported += rows; }, stats));
    EXPECT_EQ(rowsReported, 37);
    EXPECT_EQ(stats.primaryRays, 6u * 5u);  // ceil(45/8) x ceil(37/8) block corners
    // A whole 8 x 8 block has its top-left pixel's colour.
    for (int y = 8; y < 16; ++y)
      for (int x = 16; x < 24; ++x) EXPECT_EQ(img.at(y, x), full.rgb.at(8, 16));
    for (const int block : {4, 2, 1})
      ASSERT_TRUE(walk.pass(camera, block, 8, img, 2, nullptr, {}, stats));
    EXPECT_EQ(stats.primaryRays, 45u * 37u);  // every pixel traced once over the passes
    for (int y = 0; y < 37; ++y)
      for (int x = 0; x < 45; ++x)
        ASSERT_EQ(std::memcmp(img.at(y, x).data(), full.rgb.at(y, x).data(), sizeof(Rgb)), 0)
            << y << " " << x;
  }
}

// prime walk turns about the centre of the scene's objects: a sphere far off
// the listing window's centre (as plate 3's are) stays in the picture over a
// whole turn, where turning about the look-at point loses it.
TEST(WalkRenderer, TurningAboutTheObjectsCentreKeepsTheSceneInFrame) {
  test::SmallScene small;
  const int p = small.prim('S', {120, 120, 120}, {150, 250, 900});
  small.object(0.6, {0.9, 0.3, 0.2}, p);
  const Scene& scene = small.scene;
  const Aabb box = ObjectBvh(scene, ObjectBvh::ObjectBoxes::kSolid).objectsBox();
  ASSERT_FALSE(box.empty());
  EXPECT_NEAR(box.centre()[0], 150.0, 1.0);  // the sphere's box, as tight as it is
  EXPECT_NEAR(box.centre()[2], 900.0, 1.0);
  const FreeCameraSettings first = framedListingWindow(CameraSettings{}, 48, 48);
  const WalkRenderer walk(scene, Profile::Listing1991, {});
  // Pixels showing the sphere (anything but the background) after each of
  // 36 turns of 10 degrees.
  auto coverage = [&](OrbitView view) {
    std::vector<int> shown;
    for (int step = 0; step < 36; ++step) {
      view.orbit(10.0, step < 18 ? 1.0 : -1.0);
      RgbImage img;
      img.assign(48, 48);
      TraceStats stats;
      EXPECT_TRUE(walk.pass(FreeCamera(view.camera()), 1, 1, img, 1, nullptr, {}, stats));
      int n = 0;
      for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) n += img.at(y, x) != scene.background;
      shown.push_back(n);
    }
    return shown;
  };
  const std::vector<int> aboutCentre = coverage(OrbitView::from(first, box.centre()));
  for (std::size_t k = 0; k < aboutCentre.size(); ++k)
    EXPECT_GT(aboutCentre[k], 20) << "turn " << k << ": the sphere left the picture";
  // The old pivot, the listing window's centre, loses it (so the check above can fail).
  const std::vector<int> aboutLookAt = coverage(OrbitView::from(first));
  EXPECT_EQ(*std::min_element(aboutLookAt.begin(), aboutLookAt.end()), 0);
}

TEST(WalkRenderer, AnAbandonedPassStopsAtOnce) {
  const Scene scene = sphereScene();
  const WalkRenderer walk(scene, Profile::Listing1991, {});
  const FreeCamera camera(framedListingWindow(CameraSettings{}, 64, 64));
  RgbImage img;
  img.assign(64, 64);
  TraceStats stats;
  const std::atomic<bool> abandon{true};
  EXPECT_FALSE(walk.pass(camera, 1, 1, img, 1, &abandon, {}, stats));
  EXPECT_EQ(stats.primaryRays, 0u);
}

RenderResult tiny(std::vector<Rgb> colours, std::vector<std::int16_t> indices) {
  RenderResult r;
  r.rgb.assign(2, 2);
  r.rgb.pixels.assign(colours.begin(), colours.end());
  r.graph.pixels.assign(indices.begin(), indices.end());
  return r;
}

TEST(CompareRenders, CountsAndDifferencesOfTwoKnownRenders) {
  // Pixel (0, 1) differs by 0.5 in red; pixel (1, 1) by 1e-17 in green
  // (bit-different, its clamped difference tiny); the indices differ at one.
  const RenderResult a =
      tiny({{0, 0, 0}, {0.2, 0.5, 0.5}, {1, 1, 1}, {0.3, 0.3, 0.3}}, {1, 2, 3, 4});
  const RenderResult b =
      tiny({{0, 0, 0}, {0.7, 0.5, 0.5}, {1, 1, 1}, {0.3, 0.3 + 1e-16, 0.3}}, {1, 9, 3, 4});
  const RenderComparison c = compareRenders(a, b, 5);
  EXPECT_EQ(c.pixels, 4u);
  EXPECT_EQ(c.differing, 2u);
  EXPECT_EQ(c.indexDiffering, 1u);
  EXPECT_DOUBLE_EQ(c.share(), 0.5);
  EXPECT_NEAR(c.maxDifference, 0.5, 1e-15);
  EXPECT_EQ(c.maxRow, 0);
  EXPECT_EQ(c.maxColumn, 1);
  EXPECT_NEAR(c.meanDifference, (0.5 + 1e-16) / 4, 1e-15);
  ASSERT_EQ(c.sample.size(), 2u);
  EXPECT_EQ(c.sample[0], std::make_pair(0, 1));
  EXPECT_EQ(c.sample[1], std::make_pair(1, 1));
  // Clamped: an out-of-range red of 3 against 1 is no difference on a screen.
  EXPECT_DOUBLE_EQ(colourDifference({3, 0, 0}, {1, 0, 0}), 0.0);
  EXPECT_THROW(compareRenders(a, RenderResult{}, 1), std::invalid_argument);
}

ProbeEvent rayEvent(int depth, std::string text) {
  return {depth, "ray", std::move(text), "{}"};
}

TEST(FirstDivergence, FirstRayWhoseLineDiffers) {
  const std::vector<ProbeEvent> a{rayEvent(0, "primary from 0 dir 1"),
                                  {0, "hit", "x", "{}"},
                                  rayEvent(1, "reflected from 2 dir 3"),
                                  rayEvent(1, "transmitted from 2 dir 4")};
  std::vector<ProbeEvent> b{rayEvent(0, "primary from 0 dir 1"),
                            {0, "hit", "y", "{}"},
                            rayEvent(1, "reflected from 2 dir 3"),
                            rayEvent(1, "transmitted from 2 dir 5")};
  RayDivergence d = firstDivergence(a, b);
  EXPECT_EQ(d.firstDiffering, 2);  // the hit events do not count; ray 2 is the third ray
  EXPECT_EQ(d.rayA, "transmitted from 2 dir 4");
  EXPECT_EQ(d.rayB, "transmitted from 2 dir 5");
  b.pop_back();  // B has no transmitted ray at all
  d = firstDivergence(a, b);
  EXPECT_EQ(d.firstDiffering, 2);
  EXPECT_EQ(d.raysA, 3);
  EXPECT_EQ(d.raysB, 2);
  EXPECT_EQ(d.rayB, "");
  EXPECT_EQ(firstDivergence(a, a).firstDiffering, -1);
}

// A ray event as the probe writes it, with its kind in the JSON.
ProbeEvent kindRay(int depth, const std::string& kind, const std::string& where) {
  return {depth, "ray", kind + " ray from " + where, R"({"kind":")" + kind + R"(","depth":1})"};
}

// The classes of T37: a tree that casts its reflected ray first does not
// hide a transmitted ray that differs; a transmitted ray after a different
// number of internal reflections is "tir"; equal rays with other shadow
// verdicts are "shadow", else "shading".
TEST(FirstDivergence, ClassifiesWhereTheTreesPart) {
  const std::vector<ProbeEvent> a{kindRay(0, "primary", "eye"),
                                  kindRay(1, "reflected", "p1"),
                                  {0, "transmit", "", R"({"steps":1})"},
                                  kindRay(1, "transmitted", "q1")};
  std::vector<ProbeEvent> b{kindRay(0, "primary", "eye"),
                            kindRay(1, "reflected", "p2"),
                            {0, "transmit", "", R"({"steps":1})"},
                            kindRay(1, "transmitted", "q2")};
  RayDivergence d = firstDivergence(a, b);
  EXPECT_EQ(d.kind, "reflected");  // the first ray that differs
  EXPECT_EQ(d.kinds, (std::vector<std::string>{"reflected", "transmitted"}));
  EXPECT_EQ(d.rays.at("transmitted").second, "transmitted ray from q2");
  b[1] = a[1];  // only the transmitted ray differs
  d = firstDivergence(a, b);
  EXPECT_EQ(d.kinds, (std::vector<std::string>{"transmitted"}));
  b[2] = {0, "transmit", "", R"({"steps":3})"};  // after two internal reflections
  EXPECT_EQ(firstDivergence(a, b).kind, "tir");
  std::vector<ProbeEvent> c = a, e = a;
  c.push_back({1, "shadow", "light 1 lit", "{}"});
  e.push_back({1, "shadow", "light 1 in shadow", "{}"});
  EXPECT_EQ(firstDivergence(c, e).kind, "shadow");
  EXPECT_EQ(firstDivergence(a, a).kind, "shading");
}

}  // namespace
}  // namespace prime
