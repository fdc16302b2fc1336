// Modern-profile primitives: whole-line intervals with outward unit normals,
// against values worked out by hand.
#include "src/prime/geom/primitives_modern.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "src/prime/geom/csg_modern.h"

namespace prime {
namespace {

using io::PrimType;

void expectInterval(char type, const Ray& r, double tIn, double tOut, const Vec3& nIn,
                    const Vec3& nOut, double tol = 1e-12) {
  PrimHit in;
  ASSERT_TRUE(intersectModern(io::primType(type).value(), r, in)) << type;
  EXPECT_NEAR(in.tIn, tIn, tol) << type;
  EXPECT_NEAR(in.tOut, tOut, tol) << type;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(in.nIn[i], nIn[i], tol) << type << " nIn[" << i << "]";
    EXPECT_NEAR(in.nOut[i], nOut[i], tol) << type << " nOut[" << i << "]";
  }
}

TEST(SolveQuadratic, NoCancellationForTheSmallRoot) {
  // t^2 + 2e8 t + 1 = 0 (half-b form b = 1e8): roots -b +- sqrt(b^2 - 1),
  // i.e. about -2e8 and -1/(2e8) = -5e-9. The naive -b + sqrt(b^2 - 1)
  // cancels to 0; q = -(b + sqrt(D)) gives c/q = -5e-9 to full precision.
  double t0, t1;
  ASSERT_TRUE(solveQuadratic(1.0, 1e8, 1.0, t0, t1));
  EXPECT_NEAR(t0, -2e8, 1e-6);
  EXPECT_NEAR(t1, -5e-9, 5e-9 * 1e-14);
  EXPECT_FALSE(solveQuadratic(1.0, 0.0, 1.0, t0, t1));  // x^2 + 1: no real root
}

TEST(PrimitivesModern, SphereFromOutsideAndFromInside) {
  expectInterval('S', {{0, 0, -5}, {0, 0, 1}}, 4, 6, {0, 0, -1}, {0, 0, 1});
  expectInterval('S', {{0, 0, 0}, {0, 0, 2}}, -0.5, 0.5, {0, 0, -1}, {0, 0, 1});  // inside: tIn < 0
  PrimHit in;
  EXPECT_FALSE(intersectModern(PrimType::Sphere, {{0, 1.5, -5}, {0, 0, 1}}, in));
}

TEST(PrimitivesModern, CubeAndGrazingFace) {
  expectInterval('B', {{0.5, 0.5, -1}, {0, 0, 1}}, 1, 2, {0, 0, -1}, {0, 0, 1});
  // Diagonal through the corners (0,0,0) and (1,1,1): entry normal is the
  // last slab to be entered; all tie at t = 1, the first plane tested wins.
  PrimHit in;
  ASSERT_TRUE(intersectModern(PrimType::Cube, {{-1, -1, -1}, {1, 1, 1}}, in));
  EXPECT_EQ(in.tIn, 1.0);
  EXPECT_EQ(in.tOut, 2.0);
  // Sliding inside the face plane x = 0 (closed solid): inside.
  ASSERT_TRUE(intersectModern(PrimType::Cube, {{0, 0.5, -1}, {0, 0, 1}}, in));
  EXPECT_EQ(in.tIn, 1.0);
}

TEST(PrimitivesModern, CubeSlabsAreTheGenericPlaneClipBitForBit) {
  // cubeModern writes the six faces' dot products out; it must return what
  // the generic clip by half-spaces returns, to the bit, on every kind of
  // ray: random ones, axis-parallel ones (zero direction components, signed
  // zeros), rays through edges and corners, from inside and behind.
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> u(-3.0, 4.0);
  const double picks[] = {0.0, -0.0, 1.0, 0.5, -1.0, 2.0};
  std::uniform_int_distribution<int> pick(0, 5), coin(0, 3);
  int hits = 0;
  for (int k = 0; k < 200000; ++k) {
    Ray r;
    for (int i = 0; i < 3; ++i) {
      r.o[i] = coin(rng) == 0 ? picks[pick(rng)] : u(rng);
      r.d[i] = coin(rng) == 0 ? picks[pick(rng)] : u(rng);
    }
    PrimHit a{}, b{};
    const bool fa = cubeModern(r, a), fb = cubeModernByPlanes(r, b);
    ASSERT_EQ(fa, fb) << k;
    if (!fa) continue;
    ++hits;
    const double got[] = {a.tIn,    a.tOut,    a.nIn[0],  a.nIn[1],
                          a.nIn[2], a.nOut[0], a.nOut[1], a.nOut[2]};
    const double want[] = {b.tIn,    b.tOut,    b.nIn[0],  b.nIn[1],
                           b.nIn[2], b.nOut[0], b.nOut[1], b.nOut[2]};
    for (int j = 0; j < 8; ++j)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got[j]), std::bit_cast<std::uint64_t>(want[j]))
          << "ray " << k << " value " << j << ": " << got[j] << " vs " << want[j];
  }
  EXPECT_GT(hits, 10000);  // the comparison saw many hits, not only misses
}

TEST(PrimitivesModern, WithoutNormalsTheSameAnswerAndTsBitForBit) {
  // intersectModernT skips the normals; the answer and both t's must be
  // intersectModern's to the bit for every primitive, on random rays from
  // outside, inside and behind, grazing and axis-parallel ones included.
  std::mt19937_64 rng(1991);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const double picks[] = {0.0, -0.0, 1.0, 0.5, -1.0};
  std::uniform_int_distribution<int> pick(0, 4), coin(0, 4);
  for (const char type : {'S', 'B', 'C', 'N', 'Y'}) {
    const io::PrimType t = io::primType(type).value();
    int hits = 0;
    for (int k = 0; k < 50000; ++k) {
      Ray r;
      for (int i = 0; i < 3; ++i) {
        r.o[i] = coin(rng) == 0 ? picks[pick(rng)] : u(rng);
        r.d[i] = coin(rng) == 0 ? picks[pick(rng)] : u(rng);
      }
      PrimHit a{}, b{};
      const bool fa = intersectModern(t, r, a), fb = intersectModernT(t, r, b);
      ASSERT_EQ(fa, fb) << type << " ray " << k;
      if (!fa) continue;
      ++hits;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a.tIn), std::bit_cast<std::uint64_t>(b.tIn)) << type;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a.tOut), std::bit_cast<std::uint64_t>(b.tOut)) << type;
    }
    EXPECT_GT(hits, 2000) << type;  // many hits compared, not only misses
  }
}

TEST(PrimitivesModern, CylinderBodyAndCaps) {
  expectInterval('C', {{-2, 0, 0.5}, {1, 0, 0}}, 1, 3, {-1, 0, 0}, {1, 0, 0});
  expectInterval('C', {{0, 0, -1}, {0, 0, 1}}, 1, 2, {0, 0, -1}, {0, 0, 1});
  // Enters the body, leaves through the top cap: from (-2,0,0) towards
  // (1,0,1.5)... d = (1,0,0.5): x = -1 at t = 1 (z = 0.5), z = 1 at t = 2.
  expectInterval('C', {{-2, 0, 0}, {1, 0, 0.5}}, 1, 2, {-1, 0, 0}, {0, 0, 1});
}

TEST(PrimitivesModern, ConeBodyApexAndCap) {
  // At z = 0.5 the radius is 0.5: from (-2,0,0.5) along x, t = 1.5 and 2.5;
  // outward normals (x, y, -z) normalised: (-1,0,-1)/sqrt2 and (1,0,-1)/sqrt2.
  const double h = 1 / std::sqrt(2.0);
  expectInterval('N', {{-2, 0, 0.5}, {1, 0, 0}}, 1.5, 2.5, {-h, 0, -h}, {h, 0, -h});
  // Up the axis: touches the apex at t = 1, leaves through the cap at t = 2.
  expectInterval('N', {{0, 0, -1}, {0, 0, 1}}, 1, 2, {0, 0, -1}, {0, 0, 1});
  // Down the axis from above: enters the cap at t = 1, ends at the apex.
  expectInterval('N', {{0, 0, 2}, {0, 0, -1}}, 1, 2, {0, 0, 1}, {0, 0, -1});
  // The lower nappe (z < 0) is not part of the solid.
  PrimHit in;
  EXPECT_FALSE(intersectModern(PrimType::Cone, {{-2, 0, -0.5}, {1, 0, 0}}, in));
}

TEST(PrimitivesModern, PyramidFrontAndBackFaces) {
  // At y = 0.25 the section is z in [0.125, 0.875] (front 0.5y - z <= 0,
  // back 0.5y + z <= 1); normals (0,.5,-1) and (0,.5,1) normalised.
  const double k = 1 / std::sqrt(1.25);
  expectInterval('Y', {{0.5, 0.25, -1}, {0, 0, 1}}, 1.125, 1.875, {0, 0.5 * k, -k},
                 {0, 0.5 * k, k});
  // Up through the base (normal -y) to the apex region: x = z = 0.5 leaves
  // where 0.5y <= 0.5 stops holding, y = 1 (the apex; any side plane).
  PrimHit in;
  ASSERT_TRUE(intersectModern(PrimType::Pyramid, {{0.5, -1, 0.5}, {0, 1, 0}}, in));
  EXPECT_EQ(in.tIn, 1.0);
  EXPECT_EQ(in.nIn, (Vec3{0, -1, 0}));
  EXPECT_DOUBLE_EQ(in.tOut, 2.0);
}

TEST(CsgModern, DifferenceCutFaceHasTheFlippedNormal) {
  // A = cube [0,1]^3 as prim 0, B = cube shifted to [0.5,1.5] in z as prim 1.
  // Along z through (0.5,0.5): A = [1,2], B = [1.5,2.5]; A - B = [1,1.5],
  // whose exit is B's entry face with B's outward normal (0,0,-1) negated.
  const std::vector<CsgEntry> entries = {{'-', 1, 2}, {'P', 0, 0}, {'P', 1, 0}};
  const Ray ray{{0.5, 0.5, -1}, {0, 0, 1}};
  auto leaf = [&](int prim) -> std::optional<PrimHit> {
    Ray local = ray;
    if (prim == 1) local.o[Z] -= 0.5;
    PrimHit in;
    if (!intersectModern(PrimType::Cube, local, in)) return std::nullopt;
    return in;
  };
  const TList l = csgModern(entries, leaf);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].t, 1.0);
  EXPECT_EQ(l[1].t, 1.5);
  EXPECT_EQ(l[1].prim, 1);
  EXPECT_EQ(l[1].norm, (Vec3{0, 0, 1}));
}

}  // namespace
}  // namespace prime
