// The object BVH and the per-primitive box test must return exactly what
// the listing's linear search returns, ties included: trace the same rays
// through a random scene with and without skipping and compare the colours
// bit for bit (and count that the skipping really skips).
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <random>
#include <vector>

#include "src/prime/math/listing_matrix.h"
#include "src/prime/render/probe.h"
#include "src/prime/render/tracer_1991.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/render/tracer_thesis.h"

namespace prime {
namespace {

Scene randomScene(unsigned seed, int objects) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(0, 1000), size(20, 120), angle(0, 90), unit(0, 1);
  Scene s;
  SceneTexture map;
  map.uScale = map.vScale = 2;
  for (auto& c : map.channel) c = {unit(rng), unit(rng), unit(rng), unit(rng)};
  s.maps.resize(5);
  s.maps[1] = map;
  // Maps of one colour (TracerModern's plain primitives skip the inverse
  // mapping): 2 and 3 the same colour (1 x 1 and 2 x 2), 4 another.
  auto plain = [](int size, double r, double g, double b) {
    SceneTexture t;
    t.uScale = t.vScale = size;
    const std::size_t n = static_cast<std::size_t>(size) * size;
    t.channel = {std::vector<double>(n, r), std::vector<double>(n, g), std::vector<double>(n, b)};
    t.constant = true;
    return t;
  };
  s.maps[2] = plain(1, 0.7, 0.25, 0.4);
  s.maps[3] = plain(2, 0.7, 0.25, 0.4);
  s.maps[4] = plain(1, 0.1, 0.8, 0.3);
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
    // By turns: the 2 x 2 map; one colour; one colour from two maps; and
    // one colour outside, another inside (not plain).
    const std::size_t turn = s.prims.size() % 4;
    for (std::size_t k = 0; k < p.map.size(); ++k)
      p.map[k] = turn == 0   ? std::array<int, 2>{1, 1}
                 : turn == 1 ? std::array<int, 2>{2, 2}
                 : turn == 2 ? std::array<int, 2>{k % 2 == 0 ? 2 : 3, 3}
                             : std::array<int, 2>{2, 4};
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

// The modern and thesis profiles' shortcuts (N18: box culling, a union's or
// a lone primitive's nearest entry without the list, tests without normals
// and the normal recovered from a marker) against the full evaluation a
// probe sees: the same colour bit for bit, for rays from outside every
// object and for rays that start inside one (a lone primitive's exit, a
// union's general way).
TEST(SkipEquivalence, ModernShortcutsGiveTheProbesFullEvaluation) {
  for (unsigned seed : {4u, 5u}) {
    const Scene scene = randomScene(seed, 60);
    const TracerModern modern(scene);
    const TracerThesis thesis(scene);
    std::mt19937 rng(seed * 11);
    std::uniform_real_distribution<double> u(-0.2, 1.2), unit(0, 1), dir(-1, 1);
    TraceStats fast, full;
    int hits = 0, inside = 0;
    for (int i = 0; i < 3000; ++i) {
      Ray ray{{500, 500, -1500}, {u(rng) * 1000 - 500, u(rng) * 1000 - 500, 1500}};
      if (i % 2 == 1) {  // from a point in or on a random primitive, any way
        const ScenePrim& p = scene.prims[rng() % scene.prims.size()];
        const Vec3 local{0.2 + 0.6 * unit(rng), 0.2 + 0.6 * unit(rng), 0.2 + 0.6 * unit(rng)};
        ray.o = pointMatrixMul(p.type == io::PrimType::Cube ? local : Vec3{0, 0, 0.5}, p.transform);
        ray.d = {dir(rng), dir(rng), dir(rng)};
        ++inside;
      }
      Probe probe;
      const Rgb a = modern.castRay(ray, 0, fast), b = modern.castRay(ray, 0, full, &probe);
      hits += a != scene.background ? 1 : 0;
      ASSERT_EQ(std::memcmp(a.data(), b.data(), sizeof a), 0)
          << "modern, seed " << seed << " ray " << i << ": (" << a[0] << "," << a[1] << "," << a[2]
          << ") vs (" << b[0] << "," << b[1] << "," << b[2] << ")";
      Probe probe2;
      const Rgb c = thesis.castRay(ray, 0, fast, SampleId{}),
                d = thesis.castRay(ray, 0, full, SampleId{}, &probe2);
      ASSERT_EQ(std::memcmp(c.data(), d.data(), sizeof c), 0)
          << "thesis, seed " << seed << " ray " << i << ": (" << c[0] << "," << c[1] << "," << c[2]
          << ") vs (" << d[0] << "," << d[1] << "," << d[2] << ")";
    }
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(inside, 1500);
    EXPECT_LT(fast.primitiveTests, full.primitiveTests);  // the shortcuts skip work
  }
}

}  // namespace
}  // namespace prime
