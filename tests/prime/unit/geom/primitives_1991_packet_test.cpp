// The packet path of the 1991 primitives (src/prime/geom/primitives_1991_packet.h)
// against the scalar path, bit for bit: for each primitive class, 10^6 random
// rays in packets of four, each lane's hit flag, t values and normals compared
// as bit patterns (so -0.0 against +0.0 or one NaN against another counts as a
// difference), the bound tests the same way, and the packet's TransformRay.
//
// The rays mix three kinds, so the scalar functions' every branch is reached:
//  - aimed: an origin in a box about the primitive, the direction towards a
//    random point near it (mostly hits, entries from every side);
//  - lattice: origins and directions on a coarse grid (0, +-0.5, +-1, ...),
//    so directions parallel to faces (d == 0), rays along edges and through
//    corners (two faces at the same t) and origins on the surface occur;
//  - wide: directions of very different magnitudes (1e-6 to 1e6 per
//    component), as unnormalised primitive-space rays are.
#include "src/prime/geom/primitives_1991_packet.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

#include "src/prime/geom/primitives_1991.h"

namespace prime {
namespace {

using io::PrimType;

constexpr int kRays = 1'000'000;

class RayMaker {
 public:
  // Aimed rays go towards points within `spread` of `centre` (per axis).
  RayMaker(std::uint64_t seed, const Vec3& centre, double spread)
      : rng_(seed), centre_(centre), spread_(spread) {}

  Ray next() {
    switch (kind_(rng_)) {
      case 0:
        return lattice();
      case 1:
        return wide();
      default:
        return aimed();
    }
  }

 private:
  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng_); }
  Ray aimed() {
    Ray r;
    Vec3 target{};
    for (int a = 0; a < 3; ++a) {
      r.o[a] = centre_[a] + uniform(-3.5, 3.5);
      target[a] = centre_[a] + uniform(-spread_, spread_);
      r.d[a] = (target[a] - r.o[a]) * uniform(0.2, 3.0);
    }
    return r;
  }
  Ray lattice() {
    static constexpr double kO[] = {-2.0, -1.0, -0.5, 0.0, 0.25, 0.5, 1.0, 1.5, 2.0};
    static constexpr double kD[] = {-1.0, -0.5, 0.0, 0.0, 0.5, 1.0, 2.0};
    std::uniform_int_distribution<int> io(0, 8), id(0, 6);
    Ray r;
    for (int a = 0; a < 3; ++a) {
      r.o[a] = kO[io(rng_)];
      r.d[a] = kD[id(rng_)];
    }
    return r;
  }
  Ray wide() {
    Ray r = aimed();
    for (int a = 0; a < 3; ++a) r.d[a] *= std::pow(10.0, uniform(-6.0, 6.0));
    return r;
  }

  std::mt19937_64 rng_;
  Vec3 centre_;
  double spread_;
  std::uniform_int_distribution<int> kind_{0, 3};
};

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool sameBits(const Vec3& a, const Vec3& b) {
  return sameBits(a[X], b[X]) && sameBits(a[Y], b[Y]) && sameBits(a[Z], b[Z]);
}
std::string describe(const Ray& r) {
  std::ostringstream s;
  s.precision(17);
  s << "o (" << r.o[X] << ", " << r.o[Y] << ", " << r.o[Z] << ") d (" << r.d[X] << ", " << r.d[Y]
    << ", " << r.d[Z] << ")";
  return s.str();
}

struct Counts {
  int hits = 0, bounds = 0, mismatches = 0;
};

// Where each unit primitive lies (primitives_1991.h): its centre and a
// half-width a little beyond it.
RayMaker makerFor(PrimType type, std::uint64_t seed) {
  switch (type) {
    case PrimType::Sphere:
      return RayMaker(seed, {0.0, 0.0, 0.0}, 1.2);
    case PrimType::Cylinder:
    case PrimType::Cone:
      return RayMaker(seed, {0.0, 0.0, 0.5}, 1.1);
    case PrimType::Cube:
      return RayMaker(seed, {0.5, 0.5, 0.5}, 0.7);
    case PrimType::Pyramid:
      return RayMaker(seed, {0.5, 0.4, 0.5}, 0.55);
  }
  return RayMaker(seed, {0.0, 0.0, 0.0}, 1.0);
}

Counts comparePackets(PrimType type, std::uint64_t seed) {
  RayMaker maker = makerFor(type, seed);
  Counts counts;
  for (int done = 0; done < kRays; done += kPacketLanes) {
    RayPacket packet;
    for (int l = 0; l < kPacketLanes; ++l) packet.set(l, maker.next());
    std::array<PrimHit, kPacketLanes> hits;
    const unsigned hitLanes = intersectPrimitive1991x4(type, packet, hits);
    const unsigned boundLanes = boundHit1991x4(type, packet);
    for (int l = 0; l < kPacketLanes; ++l) {
      const Ray ray = packet.lane(l);
      PrimHit scalar;
      const bool hit = intersectPrimitive1991(type, ray, scalar);
      const bool bound = boundHit1991(type, ray);
      bool same = hit == ((hitLanes >> l) & 1u) && bound == ((boundLanes >> l) & 1u);
      if (same && hit)
        same = sameBits(scalar.tIn, hits[l].tIn) && sameBits(scalar.tOut, hits[l].tOut) &&
               sameBits(scalar.nIn, hits[l].nIn) && sameBits(scalar.nOut, hits[l].nOut);
      counts.hits += hit;
      counts.bounds += bound;
      if (!same && ++counts.mismatches <= 5)
        ADD_FAILURE() << "lane " << l << " of ray " << done + l << ", " << describe(ray)
                      << ": scalar hit " << hit << " bound " << bound << ", packet hit "
                      << ((hitLanes >> l) & 1u) << " bound " << ((boundLanes >> l) & 1u);
    }
  }
  return counts;
}

class PrimitivePacket1991 : public ::testing::TestWithParam<PrimType> {};

TEST_P(PrimitivePacket1991, EveryLaneIsTheScalarResultBitForBitOnAMillionRays) {
  const Counts c = comparePackets(GetParam(), 0x5eed0000u + static_cast<unsigned>(GetParam()));
  EXPECT_EQ(c.mismatches, 0);
  // The rays reach both outcomes often, so the comparison covers hits (with
  // their t values and normals) as well as misses.
  EXPECT_GT(c.hits, kRays / 10);
  EXPECT_LT(c.hits, kRays * 9 / 10);
  EXPECT_GT(c.bounds, kRays / 10);
}

INSTANTIATE_TEST_SUITE_P(EveryClass, PrimitivePacket1991,
                         ::testing::Values(PrimType::Sphere, PrimType::Cube, PrimType::Cylinder,
                                           PrimType::Cone, PrimType::Pyramid),
                         [](const auto& info) {
                           switch (info.param) {
                             case PrimType::Sphere:
                               return std::string("Sphere");
                             case PrimType::Cube:
                               return std::string("Cube");
                             case PrimType::Cylinder:
                               return std::string("Cylinder");
                             case PrimType::Cone:
                               return std::string("Cone");
                             case PrimType::Pyramid:
                               return std::string("Pyramid");
                           }
                           return std::string("Unknown");
                         });

TEST(PrimitivePacket1991, EdgeAndCornerRaysTieAsTheScalarSwapDoes) {
  // Rays through edges and corners, where two faces lie at the same t
  // (Swap's `t >= tIn` branch). Each lane must equal the scalar result.
  RayPacket p;
  p.set(0, {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}});  // the cube's diagonal, corner to corner
  p.set(1, {{-1.0, 1.0, 0.5}, {1.0, -1.0, 0.0}});   // touches the cube's edge x = y = 0 only
  p.set(2, {{0.5, 0.5, -1.0}, {0.0, 0.0, 1.0}});
  p.set(3, {{0.5, 2.0, 0.5}, {0.0, -1.0, 0.0}});
  for (const PrimType type : {PrimType::Cube, PrimType::Pyramid, PrimType::Cylinder}) {
    std::array<PrimHit, kPacketLanes> hits;
    const unsigned lanes = intersectPrimitive1991x4(type, p, hits);
    for (int l = 0; l < kPacketLanes; ++l) {
      PrimHit scalar;
      const bool hit = intersectPrimitive1991(type, p.lane(l), scalar);
      ASSERT_EQ(hit, ((lanes >> l) & 1u) != 0) << "lane " << l;
      if (!hit) continue;
      EXPECT_TRUE(sameBits(scalar.tIn, hits[l].tIn) && sameBits(scalar.tOut, hits[l].tOut))
          << "lane " << l;
      EXPECT_TRUE(sameBits(scalar.nIn, hits[l].nIn) && sameBits(scalar.nOut, hits[l].nOut))
          << "lane " << l;
    }
  }
  // Lane 1 meets the face x = 0 at t = 1 (the point (0, 0, 0.5), tIn), misses
  // x = 1 (y = -1 there), and meets y = 0 at the same t = 1: Swap's tie makes
  // it the exit, with minus y = 0's outward normal (K6).
  std::array<PrimHit, kPacketLanes> hits;
  ASSERT_TRUE(intersectPrimitive1991x4(PrimType::Cube, p, hits) & 2u);
  EXPECT_EQ(hits[1].tIn, 1.0);
  EXPECT_EQ(hits[1].tOut, 1.0);
  EXPECT_EQ(hits[1].nIn, (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(hits[1].nOut, (Vec3{0.0, 1.0, 0.0}));
}

TEST(PrimitivePacket1991, TransformRayPacketIsTransformRayPerLane) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<> u(-5.0, 5.0);
  RayMaker maker(8, {0.0, 0.0, 0.0}, 1.0);
  for (int round = 0; round < 10'000; ++round) {
    Matrix4 m{};
    for (auto& row : m)
      for (double& x : row) x = u(rng);
    RayPacket p;
    for (int l = 0; l < kPacketLanes; ++l) p.set(l, maker.next());
    const RayPacket t = transformRayPacket(p, m);
    for (int l = 0; l < kPacketLanes; ++l) {
      const Ray scalar = transformRay(p.lane(l), m);
      ASSERT_TRUE(sameBits(scalar.o, t.lane(l).o) && sameBits(scalar.d, t.lane(l).d))
          << "round " << round << " lane " << l;
    }
  }
}

}  // namespace
}  // namespace prime
