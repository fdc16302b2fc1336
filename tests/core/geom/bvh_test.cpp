// The shared BVH over any boxes: exactly the boxes a linear search finds
// (entry <= limit), nearest box first along each subtree, empty boxes never.
#include "src/geom/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace prime {
namespace {

Aabb box(const Vec3& lo, const Vec3& hi) {
  Aabb b;
  b.add(lo);
  b.add(hi);
  return b;
}

// With 500 boxes, and with small sets: 1 box (the root a leaf of that one
// box, whose entry is the root's, not computed again: the same t as the
// box's own entry, bit for bit), 2, and 5, 9, 17 (leaves of 2 to 4 boxes).
TEST(Bvh, VisitsExactlyTheBoxesALinearSearchMeets) {
  for (const int count : {500, 1, 2, 5, 9, 17}) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-100, 100), size(0.1, 10), big(20, 80);
    std::vector<Aabb> boxes;
    for (int i = 0; i < count; ++i) {
      const Vec3 lo{u(rng), u(rng), u(rng)};
      // The small sets get large boxes, so that the rays meet them.
      boxes.push_back(count == 500 ? box(lo, lo + Vec3{size(rng), size(rng), size(rng)})
                                   : box(lo * 0.5, lo * 0.5 + Vec3{big(rng), big(rng), big(rng)}));
    }
    boxes.push_back(Aabb{});  // empty: never visited
    const Bvh bvh(boxes);
    std::size_t met = 0;
    for (int r = 0; r < 300; ++r) {
      Ray ray{{u(rng), u(rng), -300}, {u(rng) / 200, u(rng) / 200, 1}};
      const BoxRay prepared(ray);
      const double limit = r % 2 ? std::numeric_limits<double>::infinity() : 300.0;
      std::set<int> linear, visited;
      for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
        // A box the ray misses (entry +infinity) is not met, even with no
        // limit: before this was checked, an unlimited search visited every
        // box and node the ray missed.
        if (const double t = boxes[i].entry(prepared);
            !boxes[i].empty() && t != std::numeric_limits<double>::infinity() && t <= limit)
          linear.insert(i);
      bvh.traverse(
          prepared,
          [&](int index, double t) {
            EXPECT_TRUE(visited.insert(index).second);
            EXPECT_EQ(std::bit_cast<std::uint64_t>(t),
                      std::bit_cast<std::uint64_t>(boxes[index].entry(prepared)));
          },
          [&] { return limit; });
      EXPECT_EQ(visited, linear) << count << " boxes, ray " << r;
      if (count == 500) {  // a thin ray meets few of 500
        EXPECT_LT(visited.size(), boxes.size() / 10) << "ray " << r;
      }
      EXPECT_FALSE(visited.count(static_cast<int>(boxes.size()) - 1));
      met += visited.size();
    }
    EXPECT_GT(met, 0u) << count << " boxes: no ray met any, the test tests nothing";
  }
}

TEST(Bvh, AShrinkingLimitPrunesFartherBoxes) {
  std::vector<Aabb> boxes;
  for (int i = 0; i < 40; ++i) boxes.push_back(box({-1, -1, 10.0 * i}, {1, 1, 10.0 * i + 1}));
  const Bvh bvh(boxes);
  const BoxRay ray(Ray{{0, 0, -5}, {0, 0, 1}});
  double limit = std::numeric_limits<double>::infinity();
  std::vector<int> visited;
  bvh.traverse(
      ray,
      [&](int index, double t) {
        visited.push_back(index);
        limit = std::min(limit, t + 1);  // a "hit" inside the first box met
      },
      [&] { return limit; });
  ASSERT_FALSE(visited.empty());
  EXPECT_EQ(visited.front(), 0);
  EXPECT_LE(visited.size(), 4u);  // a leaf's worth at most, never the far boxes
}

}  // namespace
}  // namespace prime
