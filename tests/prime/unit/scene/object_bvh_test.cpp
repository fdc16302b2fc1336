// The object boxes of the shared BVH (src/prime/scene/object_bvh.h): the
// 1991 profile's (every leaf's box) and the modern profile's (the solid's
// box by the set operations, N18), checked on boxes worked by hand.
#include "src/prime/scene/object_bvh.h"

#include <gtest/gtest.h>

#include "src/prime/math/listing_matrix.h"

namespace prime {
namespace {

// A unit cube scaled by `size` and moved to `at`: its box is [at, at + size]
// padded by 1e-7 of its size (prim_boxes.h): the checks allow 1e-4.
ScenePrim cube(Vec3 at, Vec3 size) {
  ScenePrim p;
  p.type = io::PrimType::Cube;
  p.transform = identity4();
  transform(p.transform, size, at, {0, 0, 0}, {0, 0, 0});
  EXPECT_TRUE(inverse(p.transform, p.inverse));
  return p;
}

// Three cubes: A = [0,10]^3, B = [5,20] x [0,10] x [0,10], C = [100,110]^3.
Scene threeCubes(std::vector<CsgEntry> entries) {
  Scene s;
  s.prims = {cube({0, 0, 0}, {10, 10, 10}), cube({5, 0, 0}, {15, 10, 10}),
             cube({100, 100, 100}, {10, 10, 10})};
  SceneObject o;
  o.entries = std::move(entries);
  s.objects.push_back(o);
  return s;
}

void expectNear(const Aabb& box, Vec3 lo, Vec3 hi) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(box.lo[i], lo[i], 1e-4) << "axis " << i;
    EXPECT_NEAR(box.hi[i], hi[i], 1e-4) << "axis " << i;
  }
}

using Boxes = ObjectBvh::ObjectBoxes;

TEST(ObjectBvh, TheSolidsBoxFollowsTheSetOperations) {
  // A - B: inside A.  A & B: [5,10] x [0,10]^2.  A + C: both.
  const Scene diff = threeCubes({{'-', 1, 2}, {'P', 0, 0}, {'P', 1, 0}});
  expectNear(ObjectBvh(diff, Boxes::kSolid).objectBox(0), {0, 0, 0}, {10, 10, 10});
  expectNear(ObjectBvh(diff, Boxes::kLeaves).objectBox(0), {0, 0, 0}, {20, 10, 10});
  const Scene inter = threeCubes({{'&', 1, 2}, {'P', 0, 0}, {'P', 1, 0}});
  expectNear(ObjectBvh(inter, Boxes::kSolid).objectBox(0), {5, 0, 0}, {10, 10, 10});
  const Scene uni = threeCubes({{'+', 1, 2}, {'P', 0, 0}, {'P', 2, 0}});
  expectNear(ObjectBvh(uni, Boxes::kSolid).objectBox(0), {0, 0, 0}, {110, 110, 110});
  // (A & C) is empty: the solid cannot be hit, and so (A & C) + B is B.
  const Scene empty = threeCubes({{'+', 1, 4}, {'&', 2, 3}, {'P', 0, 0}, {'P', 2, 0}, {'P', 1, 0}});
  expectNear(ObjectBvh(empty, Boxes::kSolid).objectBox(0), {5, 0, 0}, {20, 10, 10});
  // The mask's leaf boxes lie within the solid's box: B's cut face of A - B
  // is seen only inside A.
  const std::vector<Aabb> leaves = ObjectBvh(diff, Boxes::kSolid).primitiveBoxesOfObjects(diff);
  ASSERT_EQ(leaves.size(), 2u);
  expectNear(leaves[0], {0, 0, 0}, {10, 10, 10});
  expectNear(leaves[1], {5, 0, 0}, {10, 10, 10});
}

TEST(ObjectBvh, SharedCyclicAndDeepTreesAreBoxedWithoutRecursion) {
  // A shared subtree: (A - B) & (A - B).
  const Scene shared = threeCubes({{'&', 1, 1}, {'-', 2, 3}, {'P', 0, 0}, {'P', 1, 0}});
  expectNear(ObjectBvh(shared, Boxes::kSolid).objectBox(0), {0, 0, 0}, {10, 10, 10});
  // A cycle (the loader refuses it; the box falls back to the union of the leaves).
  const Scene cyclic = threeCubes({{'-', 1, 0}, {'P', 0, 0}, {'P', 1, 0}});
  expectNear(ObjectBvh(cyclic, Boxes::kSolid).objectBox(0), {0, 0, 0}, {20, 10, 10});
  // A left chain of 200,000 differences: ((A - B) - B) - ... is inside A.
  std::vector<CsgEntry> chain;
  const int n = 200000;
  for (int i = 0; i < n; ++i) chain.push_back({'-', i + 1, n + 1});
  chain.push_back({'P', 0, 0});
  chain.push_back({'P', 1, 0});
  const Scene deep = threeCubes(chain);
  expectNear(ObjectBvh(deep, Boxes::kSolid).objectBox(0), {0, 0, 0}, {10, 10, 10});
}

}  // namespace
}  // namespace prime
