// intersectPrimitive1991 and boundHit1991 per primitive type, for a ray that
// hits and one that misses (rays in primitive space, as IntersectPrim gets them),
// and the packet path (intersect4) four rays per call.
#include <benchmark/benchmark.h>

#include <array>
#include <string>

#include "src/prime/geom/primitives_1991.h"
#include "src/prime/geom/primitives_1991_packet.h"

namespace {

using prime::PrimHit;
using prime::Ray;
using prime::io::PrimType;

struct Case {
  const char* name;
  PrimType type;
  Ray hit, miss;
};

// Every hit ray crosses the primitive's body away from edges; every miss
// ray passes 5 units beside it.
const Case kCases[] = {
    {"sphere",
     PrimType::Sphere,
     {{0.1, 0.2, -5.0}, {0.01, 0.02, 1.0}},
     {{5.0, 0.2, -5.0}, {0.01, 0.02, 1.0}}},
    {"cube",
     PrimType::Cube,
     {{0.5, 0.4, -5.0}, {0.01, 0.02, 1.0}},
     {{5.5, 0.4, -5.0}, {0.01, 0.02, 1.0}}},
    {"cylinder",
     PrimType::Cylinder,
     {{-5.0, 0.1, 0.5}, {1.0, 0.01, 0.02}},
     {{-5.0, 5.1, 0.5}, {1.0, 0.01, 0.02}}},
    {"cone",
     PrimType::Cone,
     {{-5.0, 0.1, 0.7}, {1.0, 0.01, 0.01}},
     {{-5.0, 5.1, 0.7}, {1.0, 0.01, 0.01}}},
    {"pyramid",
     PrimType::Pyramid,
     {{0.5, 0.3, -5.0}, {0.0, 0.01, 1.0}},
     {{5.5, 0.3, -5.0}, {0.0, 0.01, 1.0}}},
};

void intersect(benchmark::State& state, PrimType type, Ray ray, bool expectHit) {
  PrimHit hit;
  if (prime::intersectPrimitive1991(type, ray, hit) != expectHit) {
    state.SkipWithError("the ray does not do what the benchmark expects");
    return;
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(ray);
    const bool h = prime::intersectPrimitive1991(type, ray, hit);
    benchmark::DoNotOptimize(h);
    benchmark::DoNotOptimize(hit);
  }
}

void bound(benchmark::State& state, PrimType type, Ray ray, bool expectHit) {
  if (prime::boundHit1991(type, ray) != expectHit) {
    state.SkipWithError("the ray does not do what the benchmark expects");
    return;
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(ray);
    const bool h = prime::boundHit1991(type, ray);
    benchmark::DoNotOptimize(h);
  }
}

// The packet path (primitives_1991_packet.h): four rays per call, the hit
// ray and three variants of it nudged by 1e-3 (a coherent packet). Compare
// its time per call with four scalar calls.
void intersect4(benchmark::State& state, PrimType type, Ray ray, bool expectHit) {
  prime::RayPacket packet;
  for (int l = 0; l < prime::kPacketLanes; ++l) {
    Ray r = ray;
    r.o[0] += 1e-3 * l;
    packet.set(l, r);
  }
  std::array<PrimHit, prime::kPacketLanes> hits;
  const unsigned all = (1u << prime::kPacketLanes) - 1;
  if (prime::intersectPrimitive1991x4(type, packet, hits) != (expectHit ? all : 0u)) {
    state.SkipWithError("the rays do not do what the benchmark expects");
    return;
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(packet);
    const unsigned h = prime::intersectPrimitive1991x4(type, packet, hits);
    benchmark::DoNotOptimize(h);
    benchmark::DoNotOptimize(hits);
  }
}

const int kRegistered = [] {
  for (const Case& c : kCases) {
    const std::string n = c.name;
    benchmark::RegisterBenchmark(("intersect/" + n + "/hit").c_str(), intersect, c.type, c.hit,
                                 true);
    benchmark::RegisterBenchmark(("intersect/" + n + "/miss").c_str(), intersect, c.type, c.miss,
                                 false);
    benchmark::RegisterBenchmark(("intersect4/" + n + "/hit").c_str(), intersect4, c.type, c.hit,
                                 true);
    benchmark::RegisterBenchmark(("intersect4/" + n + "/miss").c_str(), intersect4, c.type, c.miss,
                                 false);
    benchmark::RegisterBenchmark(("bound/" + n + "/hit").c_str(), bound, c.type, c.hit, true);
    benchmark::RegisterBenchmark(("bound/" + n + "/miss").c_str(), bound, c.type, c.miss, false);
  }
  return 0;
}();

}  // namespace
