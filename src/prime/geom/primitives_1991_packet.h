// Four rays at a time through the 1991 primitives (primitives_1991.h): the
// packet path of coherent rays (a 2 x 2 or 4 x 1 block of primary rays).
//
// Lane-exact: every lane computes exactly the scalar function's operations in
// the same order (the same sums, the same Sqr() squares, the same divisions,
// -ffp-contract=off), only four at once; the faces' sequencing (Swap, K6/K7)
// and the pyramid's crossing-number test are then run per lane on the lanes'
// own values. So a lane's result is bit for bit what the scalar function gives
// for that lane's ray; tests/prime/unit/geom/primitives_1991_packet_test.cpp
// checks it on 10^6 random rays per primitive class.
//
// The arithmetic is written with the compiler's vector extension (GCC and
// Clang): SSE2 on x86-64, which every such machine has, so there is no CPU
// dispatch and no second path to keep equal; WebAssembly gets scalar code.
//
// Not used by the renderers, because it measured slower: four rays through
// this path cost more than four scalar calls for every class but the sphere
// (prime_micro's intersect4 against intersect, docs/prime/benchmarks.md),
// and wired into the 1991 profile's primary rays (one BVH walk per packet,
// each leaf tested for the four lanes at once, the CSG walks and shading per
// lane) it raised the walk's CPU per frame on plate 2 by 16 % (paired runs).
// The scalar functions end a face search at the second face found and test
// only what their branches reach; the packet computes every face for every
// lane. It stays as the tested ground for a packet renderer: what a faster
// one must equal, bit for bit.
#pragma once
#include <array>

#include "legacy_io/prime/records.h"
#include "src/geom/ray.h"
#include "src/math/matrix.h"
#include "src/prime/geom/prim_hit.h"

namespace prime {

inline constexpr int kPacketLanes = 4;

// Four rays, coordinates by lane (structure of arrays): lane l's ray is
// o[axis][l] + t * d[axis][l]. Unused lanes may hold any finite ray (a copy
// of a used one is usual); their results are simply not read.
struct RayPacket {
  alignas(32) double o[3][kPacketLanes]{};
  alignas(32) double d[3][kPacketLanes]{};

  void set(int lane, const Ray& r) {
    for (int a = 0; a < 3; ++a) {
      o[a][lane] = r.o[a];
      d[a][lane] = r.d[a];
    }
  }
  Ray lane(int lane) const {
    return {{o[0][lane], o[1][lane], o[2][lane]}, {d[0][lane], d[1][lane], d[2][lane]}};
  }
};

// transformRay for each lane (pointMatrixMul and vectorMatrixMul's sums).
RayPacket transformRayPacket(const RayPacket& world, const Matrix4& inverse);

// intersectPrimitive1991 for each lane: bit l of the result is set when lane
// l's ray hits, and hits[l] then holds exactly what the scalar function fills
// in. For a lane that misses, hits[l] is unspecified.
unsigned intersectPrimitive1991x4(io::PrimType type, const RayPacket& local,
                                  std::array<PrimHit, kPacketLanes>& hits);

// boundHit1991 for each lane: bit l set when lane l's ray meets the bound.
unsigned boundHit1991x4(io::PrimType type, const RayPacket& local);

}  // namespace prime
