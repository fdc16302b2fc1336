// The object BVH and the per-primitive box test must return exactly what
// the listing's linear search returns, ties included: trace the same rays
// through a random scene with and without skipping and compare the colours
// bit for bit (and count that the skipping really skips).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "src/prime/math/listing_matrix.h"
#include "src/prime/render/tracer_1991.h"

namespace prime {
namespace {

Scene randomScene(unsigned seed, int objects) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0, 1000), size(20, 120), angle(0, 90), unit(0, 1);
  Scene s;
  SceneTexture map;
  map.uScale = map.vScale = 2;
  for (auto& c : map.channel) c = {unit(rng), unit(rng), unit(rng), unit(rng)};
  s.maps.resize(2);
  s.maps[1] = map;
  s.ambient = {0.2, 0.2, 0.2};
  s.lights = {{{500, 1500, -1000}, {0.8, 0.8, 0.8}}, {{-200, 300, -500}, {0.3, 0.2, 0.1}}};
  const char types[5] = {'S', 'B', 'C', 'N', 'Y'};
  auto addPrim = [&](char type) {
    ScenePrim p;
    p.type = io::primType(type).value();
    p.transform = identity4();
    const double k = size(rng);
    transform(p.transform, {k, k * (0.5 + unit(rng)), k}, {pos(rng), pos(rng), pos(rng) * 0.5},
              {0, 0, 0}, {angle(rng), angle(rng), 0});
    EXPECT_TRUE(inverse(p.transform, p.inverse));
    for (auto& m : p.map) m = {1, 1};
    s.prims.push_back(p);
    return static_cast<int>(s.prims.size()) - 1;
  };
  for (int i = 0; i < objects; ++i) {
    SceneObject o;
    o.number = i + 1;
    o.hue = {0.3, 0.2, {0.6, 0.4, 0.2}, 0.999, 3, 3, 1.5};
    if (i % 4 == 1) o.hue.kDR = 1.0;  // kSR = 0: no reflected ray needed
    if (i % 4 == 2) o.hue.kDT = 1.0;  // kST = 0: no transmitted ray needed
    if (i % 3 == 0) {                 // a CSG object: (a op b) with a bound
      const char op = "+-&"[i % 9 / 3];
      const int a = addPrim(types[i % 5]), b = addPrim(types[(i + 2) % 5]);
      o.entries = {CsgEntry{op, 1, 2}, CsgEntry{'P', a, 0}, CsgEntry{'P', b, 0}};
      if (i % 2 == 0) o.boundPrim = addPrim('S');
    } else {
      o.entries = {CsgEntry{'P', addPrim(types[i % 5]), 0}};
    }
    s.objects.push_back(o);
  }
  // Two identical objects at the end: exact ties must go to the first.
  s.objects.push_back(s.objects[1]);
  s.objects.back().number = 900;
  s.objects.back().hue.fDR = {0.1, 0.9, 0.1};
  return s;
}

TEST(SkipEquivalence, BvhAndBoxCullingGiveTheLinearSearchColours) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Scene scene = randomScene(seed, 60);
    TraceOptions all;
    all.skipUnneededWork = false;
    const Tracer1991 linear(scene, all), fast(scene);
    std::mt19937 rng(seed * 7);
    std::uniform_real_distribution<double> u(-0.2, 1.2);
    TraceStats sLinear, sFast;
    int hits = 0, fatal = 0;
    for (int i = 0; i < 4000; ++i) {
      const Ray ray{{500, 500, -1500}, {u(rng) * 1000 - 500, u(rng) * 1000 - 500, 1500}};
      Rgb a{}, b{};
      try {
        a = linear.castRay(ray, 0, sLinear);
      } catch (const std::exception&) {
        // A fatal listing error (E57) in a subtree the skipping never
        // evaluates: documented as the one difference; not compared.
        ++fatal;
        continue;
      }
      b = fast.castRay(ray, 0, sFast);
      hits += a != scene.background ? 1 : 0;
      ASSERT_EQ(std::memcmp(a.data(), b.data(), sizeof a), 0)
          << "seed " << seed << " ray " << i << ": (" << a[0] << "," << a[1] << "," << a[2]
          << ") vs (" << b[0] << "," << b[1] << "," << b[2] << ")";
    }
    EXPECT_GT(hits, 500);  // the rays do meet objects
    EXPECT_LT(fatal, 40);  // and almost all of them are compared
    EXPECT_LT(sFast.primitiveTests, sLinear.primitiveTests / 3);  // and the skipping skips
  }
}

}  // namespace
}  // namespace prime
