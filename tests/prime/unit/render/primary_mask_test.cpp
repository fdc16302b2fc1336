// The primary-ray mask may answer "background" only for pixels whose rays
// no box test can accept. Checked by brute force: every pixel's primary ray
// (normalised as CastRay does) against every box, over random boxes and
// cameras; and end to end, a masked render against the listing's linear
// search, pixel for pixel.
#include "src/prime/render/primary_mask.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

#include "src/prime/geom/primitives_modern.h"
#include "src/prime/math/listing_vec.h"
#include "src/prime/render/renderer.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/render/tracer_thesis.h"
#include "src/prime/scene/object_bvh.h"
#include "src/prime/scene/prim_boxes.h"
#include "tests/prime/unit/render/small_scene.h"

namespace prime {
namespace {

Aabb box(const Vec3& lo, const Vec3& hi) {
  Aabb b;
  b.add(lo);
  b.add(hi);
  return b;
}

bool anyBoxAccepts(const std::vector<Aabb>& boxes, Ray ray) {
  unitVector(ray.d, ray.d);  // E41: CastRay's normalisation comes before the box tests
  const Vec3 inv = reciprocal(ray.d);
  for (const Aabb& b : boxes)
    if (!b.empty() && b.entry(ray, inv) != std::numeric_limits<double>::infinity()) return true;
  return false;
}

// A random view of the scene space from in front: the window's corner
// fractions start below maxStart and span at least minSpan (up to 0.4 more).
CameraSettings randomCamera(std::mt19937& rng, double maxStart, double minSpan, int width,
                            int height) {
  std::uniform_real_distribution<double> u(0, 1);
  CameraSettings s;
  s.eye = {u(rng) * 1000, u(rng) * 1000, -500 - u(rng) * 3000};
  s.windowLeft = {u(rng) * 200 - 100, 800 + u(rng) * 400, u(rng) * 200 - 100};
  s.windowRight = {900 + u(rng) * 200, s.windowLeft[1] + u(rng) * 100 - 50, u(rng) * 200 - 100};
  s.xMin = u(rng) * maxStart;
  s.yMin = u(rng) * maxStart;
  s.xMax = s.xMin + minSpan + u(rng) * 0.4;
  s.yMax = s.yMin + minSpan + u(rng) * 0.4;
  s.screenWidth = width;
  s.screenHeight = height;
  return s;
}

TEST(PrimaryRayMask, ListingCameraOneBoxInFront) {
  const ListingCamera camera{CameraSettings{}};  // 350 x 769 pixels
  const std::vector<Aabb> boxes = {box({400, 400, 100}, {600, 600, 300})};
  const PrimaryRayMask mask(camera, boxes);
  int accepted = 0, masked = 0;
  for (int i = 0; i < camera.rows(); ++i)
    for (int j = 0; j < camera.columns(); ++j) {
      const bool accepts = anyBoxAccepts(boxes, camera.primaryRay(i, j));
      accepted += accepts;
      ASSERT_TRUE(!accepts || mask.mayHit(i, j)) << "row " << i << " column " << j;
      masked += !mask.mayHit(i, j);
    }
  EXPECT_GT(accepted, 1000);
  // The box covers about a fifth of the window each way; the rectangle is
  // tight up to the 2-pixel margin, so most of the image is masked.
  EXPECT_GT(masked, camera.rows() * camera.columns() / 2);
  EXPECT_LT(mask.coverage(), 0.5);
}

TEST(PrimaryRayMask, BoxReachingBehindTheEyeCoversEverything) {
  const ListingCamera camera{CameraSettings{}};
  const std::vector<Aabb> boxes = {box({400, 400, 100}, {600, 600, 300}),
                                   box({0, 0, -2000}, {10, 10, 0})};
  const PrimaryRayMask mask(camera, boxes);
  EXPECT_EQ(mask.coverage(), 1.0);
  EXPECT_TRUE(mask.mayHit(0, 0));
}

TEST(PrimaryRayMask, NoBoxesMasksEverything) {
  const ListingCamera camera{CameraSettings{}};
  const PrimaryRayMask mask(
      camera, std::vector<Aabb>{Aabb{}});  // one empty box: an object with no primitive
  EXPECT_EQ(mask.coverage(), 0.0);
}

TEST(PrimaryRayMask, RandomBoxesAndCamerasNeverMaskAnAcceptedRay) {
  std::mt19937 rng(1991);
  std::uniform_real_distribution<double> u(0, 1);
  int accepted = 0, masked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const CameraSettings s = randomCamera(rng, 0.5, 0.1, 320, 240);
    const ListingCamera camera(s);
    std::vector<Aabb> boxes;
    for (int k = 0, n = 1 + trial % 6; k < n; ++k) {
      const Vec3 c{u(rng) * 1400 - 200, u(rng) * 1400 - 200, u(rng) * 2000 - 200};
      const double h = 30 + u(rng) * 300;
      boxes.push_back(
          box({c[0] - h, c[1] - h * u(rng), c[2] - h}, {c[0] + h * u(rng), c[1] + h, c[2] + h}));
    }
    const PrimaryRayMask mask(camera, boxes);
    for (int i = 0; i < camera.rows(); ++i)
      for (int j = 0; j < camera.columns(); ++j) {
        const bool accepts = anyBoxAccepts(boxes, camera.primaryRay(i, j));
        accepted += accepts;
        masked += !mask.mayHit(i, j);
        ASSERT_TRUE(!accepts || mask.mayHit(i, j))
            << "trial " << trial << " row " << i << " column " << j;
        // Supersampling offsets stay inside the margin.
        for (double f : {-0.5, 0.5})
          ASSERT_TRUE(mask.mayHit(i, j) || !anyBoxAccepts(boxes, camera.sampleRay(i, j, f, -f)))
              << "trial " << trial << " sample of row " << i << " column " << j;
      }
  }
  EXPECT_GT(accepted, 10000);  // the trials do see boxes ...
  EXPECT_GT(masked, 10000);    // ... and the mask does skip pixels
}

// The modern and thesis profiles' mask narrows each primitive's box to the
// hull of points around it (primitiveHullPoints: a turned cube's corners, a
// polyhedron circumscribing a round primitive). Over
// random scenes of turned, stretched primitives of every type and random
// cameras: no ray of a masked pixel (its primary ray, or a sample at the
// pixel's edge) meets any primitive; and the narrowed mask keeps no pixel
// the box mask rules out.
TEST(PrimaryRayMask, HullsOfTurnedPrimitivesNeverMaskARayThatMeetsOne) {
  std::mt19937 rng(1985);
  std::uniform_real_distribution<double> u(0, 1);
  const char types[5] = {'S', 'B', 'C', 'N', 'Y'};
  int hits = 0;
  double boxCoverage = 0, hullCoverage = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const CameraSettings s = randomCamera(rng, 0.3, 0.3, 240, 180);
    const PrimeCamera camera(s);
    test::SmallScene small;
    for (int k = 0, n = 1 + trial % 5; k < n; ++k) {
      const Vec3 at{u(rng) * 1000, u(rng) * 1000, u(rng) * 600};
      const int p = small.prim(types[(trial + k) % 5],
                               {40 + u(rng) * 200, 40 + u(rng) * 200, 40 + u(rng) * 200}, at);
      ScenePrim& prim = small.scene.prims[static_cast<std::size_t>(p)];
      // Turned some more about its own place.
      transform(prim.transform, {1, 1, 1}, at, at, {u(rng) * 90, u(rng) * 90, u(rng) * 90});
      ASSERT_TRUE(inverse(prim.transform, prim.inverse));
      small.object(0.5, {0.5, 0.5, 0.5}, p);
    }
    const Scene& scene = small.scene;
    const ObjectBvh bvh(scene, ObjectBvh::ObjectBoxes::kSolid);
    const std::vector<Aabb> boxes = bvh.primitiveBoxesOfObjects(scene);
    const PrimaryRayMask byBoxes(camera, boxes);
    const PrimaryRayMask byHulls(camera, boxes, bvh.primitiveHullsOfObjects(scene));
    boxCoverage += byBoxes.coverage();
    hullCoverage += byHulls.coverage();
    auto meetsOne = [&](Ray ray) {
      ray.d = normalized(ray.d);
      for (const ScenePrim& p : scene.prims) {
        PrimHit h;
        if (intersectModern(p.type, transformRay(ray, accurateInverse(p.transform)), h) &&
            h.tOut > 0.0)
          return true;
      }
      return false;
    };
    for (int i = 0; i < camera.rows(); ++i)
      for (int j = 0; j < camera.columns(); ++j) {
        ASSERT_FALSE(byHulls.mayHit(i, j) && !byBoxes.mayHit(i, j))
            << "trial " << trial << " row " << i << " column " << j;
        const bool meets = meetsOne(camera.primaryRay(i, j));
        hits += meets;
        if (byHulls.mayHit(i, j)) continue;
        ASSERT_FALSE(meets) << "trial " << trial << " row " << i << " column " << j;
        for (double f : {-0.5, 0.5})
          ASSERT_FALSE(meetsOne(camera.sampleRay(i, j, f, -f)))
              << "trial " << trial << " sample of row " << i << " column " << j;
      }
  }
  EXPECT_GT(hits, 20000);                      // the trials do see primitives ...
  EXPECT_LT(hullCoverage, 0.9 * boxCoverage);  // ... and the hulls mask more than the boxes
}

// Round primitives are masked by a circumscribed polyhedron, not their box:
// over random turned spheres, cylinders and cones, the pixels the mask lets
// through whose rays then miss are far fewer than with the hull of the box's
// corners (the margin's ring is left in both).
TEST(PrimaryRayMask, RoundPrimitivesAreMaskedCloseToTheirOutline) {
  std::mt19937 rng(1995);
  std::uniform_real_distribution<double> u(0, 1);
  for (const char type : {'S', 'C', 'N'}) {
    long hits = 0, wastedByPolyhedron = 0, wastedByBox = 0;
    for (int trial = 0; trial < 8; ++trial) {
      const CameraSettings s = randomCamera(rng, 0.3, 0.3, 240, 180);
      const PrimeCamera camera(s);
      test::SmallScene small;
      const Vec3 at{300 + u(rng) * 400, 300 + u(rng) * 400, u(rng) * 400};
      const int p =
          small.prim(type, {250 + u(rng) * 200, 250 + u(rng) * 200, 250 + u(rng) * 200}, at);
      ScenePrim& prim = small.scene.prims[static_cast<std::size_t>(p)];
      transform(prim.transform, {1, 1, 1}, at, at, {u(rng) * 90, u(rng) * 90, u(rng) * 90});
      ASSERT_TRUE(inverse(prim.transform, prim.inverse));
      small.object(0.5, {0.5, 0.5, 0.5}, p);
      const ObjectBvh bvh(small.scene, ObjectBvh::ObjectBoxes::kSolid);
      const std::vector<Aabb> boxes = bvh.primitiveBoxesOfObjects(small.scene);
      const std::array<Vec3, 8> corners = primitiveCorners(prim);
      const std::vector<std::vector<Vec3>> boxHull{{corners.begin(), corners.end()}};
      const PrimaryRayMask byPolyhedron(camera, boxes, bvh.primitiveHullsOfObjects(small.scene));
      const PrimaryRayMask byBox(camera, boxes, boxHull);
      const Matrix4 inv = accurateInverse(prim.transform);
      for (int i = 0; i < camera.rows(); ++i)
        for (int j = 0; j < camera.columns(); ++j) {
          Ray ray = camera.primaryRay(i, j);
          ray.d = normalized(ray.d);
          PrimHit h;
          const bool meets = intersectModern(prim.type, transformRay(ray, inv), h) && h.tOut > 0;
          ASSERT_TRUE(!meets || byPolyhedron.mayHit(i, j)) << type << " " << trial;
          hits += meets;
          wastedByPolyhedron += !meets && byPolyhedron.mayHit(i, j);
          wastedByBox += !meets && byBox.mayHit(i, j);
        }
    }
    EXPECT_GT(hits, 10000) << type;
    EXPECT_LT(wastedByPolyhedron, 0.6 * wastedByBox)
        << type << ": " << wastedByPolyhedron << " rays to miss against " << wastedByBox;
    std::printf("%c: %ld hits, %ld rays let through to miss (box hull: %ld)\n", type, hits,
                wastedByPolyhedron, wastedByBox);
  }
}

// A small scene: a sphere and a CSG difference in the middle of the window.
Scene sceneOfTwo() {
  test::SmallScene small;
  small.object(0.3, {0.6, 0.4, 0.2}, small.prim('S', {150, 150, 150}, {350, 600, 200}));
  const int a = small.prim('B', {200, 200, 200}, {600, 300, 100});
  const int b = small.prim('S', {120, 120, 120}, {700, 400, 100});
  small.object(1.0, {0.2, 0.7, 0.4},
               {CsgEntry{'-', 1, 2}, CsgEntry{'P', a, 0}, CsgEntry{'P', b, 0}});
  // Two small spheres far apart in one union: most of the object's box is
  // empty, and the mask keeps only the two spheres' own boxes.
  const int p1 = small.prim('S', {40, 40, 40}, {150, 150, 50});
  const int p2 = small.prim('S', {40, 40, 40}, {850, 850, 450});
  small.object(0.5, {0.9, 0.9, 0.2},
               {CsgEntry{'+', 1, 2}, CsgEntry{'P', p1, 0}, CsgEntry{'P', p2, 0}});
  return small.scene;
}

TEST(PrimaryRayMask, MaskedRenderEqualsTheListingsLinearSearch) {
  const Scene scene = sceneOfTwo();
  RenderSettings settings;
  settings.threads = 2;
  const RenderResult r = render(scene, settings);
  EXPECT_GT(r.stats.maskedPrimaryRays, 100000u);  // most of the window is empty
  TraceOptions listing;
  listing.skipUnneededWork = false;  // obj/List searched linearly, every ray traced
  const Tracer1991 tracer(scene, listing);
  const ListingCamera camera(settings.camera);
  TraceStats stats;
  int hits = 0;
  for (int i = 0; i < camera.rows(); ++i)
    for (int j = 0; j < camera.columns(); ++j) {
      const Rgb c = tracer.castRay(camera.primaryRay(i, j), 0, stats);
      const Rgb& m = r.rgb.at(i, j);
      hits += c != Rgb{0.05, 0.1, 0.15};
      ASSERT_EQ(std::memcmp(c.data(), m.data(), sizeof c), 0) << "row " << i << " column " << j;
    }
  EXPECT_GT(hits, 10000);
  // Every pixel is one primary ray (the masked ones counted, not traced), and
  // its index is the palette's for its colour: the masked runs are filled
  // with what each of their pixels would have been given.
  EXPECT_EQ(r.stats.primaryRays, static_cast<std::uint64_t>(camera.rows()) * camera.columns());
  for (int i = 0; i < camera.rows(); ++i)
    for (int j = 0; j < camera.columns(); ++j) {
      TraceStats unused;
      ASSERT_EQ(r.graph.at(j, i), paletteIndex(r.rgb.at(i, j), settings, unused))
          << "row " << i << " column " << j;
    }
}

// The modern and thesis profiles always mask; their Single-mode renders
// against every pixel's primary ray traced by the profile's tracer.
TEST(PrimaryRayMask, MaskedModernAndThesisRendersEqualEveryRayTraced) {
  const Scene scene = sceneOfTwo();
  for (const Profile profile : {Profile::Modern, Profile::Thesis}) {
    RenderSettings settings;
    settings.threads = 2;
    settings.profile = profile;
    const RenderResult r = render(scene, settings);
    EXPECT_GT(r.stats.maskedPrimaryRays, 100000u);
    const PrimeCamera camera(settings.camera);
    EXPECT_EQ(r.stats.primaryRays, static_cast<std::uint64_t>(camera.rows()) * camera.columns());
    const TracerModern modern(scene, settings.trace);
    const TracerThesis thesis(scene, settings.trace, settings.thesis);
    TraceStats stats;
    for (int i = 0; i < camera.rows(); ++i)
      for (int j = 0; j < camera.columns(); ++j) {
        const PixelKey key{settings.sampling.seed, static_cast<std::uint32_t>(i),
                           static_cast<std::uint32_t>(j)};
        const Rgb c = profile == Profile::Modern
                          ? modern.castRay(camera.primaryRay(i, j), 0, stats)
                          : thesis.castRay(camera.primaryRay(i, j), 0, stats, SampleId{key, 0});
        ASSERT_EQ(std::memcmp(c.data(), r.rgb.at(i, j).data(), sizeof c), 0)
            << "row " << i << " column " << j;
        TraceStats unused;
        ASSERT_EQ(r.graph.at(j, i), paletteIndex(c, settings, unused));
      }
  }
}

}  // namespace
}  // namespace prime
