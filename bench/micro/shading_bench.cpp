// Inverse mapping (inverseMap1991 per primitive type), Hall shading
// (processColor1991 with 1 and 3 lights) and ColorNum.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "palette/prime/color_num.h"
#include "src/math/vec.h"
#include "src/prime/geom/uv_mapping_1991.h"
#include "src/prime/render/hall_1991.h"

namespace {

struct UvCase {
  const char* name;
  prime::io::PrimType type;
  prime::Vec3 point;  // a hit point on the primitive's body, in primitive space
};
const UvCase kUvCases[] = {
    {"sphere",
     prime::io::PrimType::Sphere,
     {0.48, 0.6, -0.64}},                                  // unit length, as CastRay passes it
    {"cube", prime::io::PrimType::Cube, {0.3, 0.7, 0.0}},  // the z = 0 face
    {"cylinder", prime::io::PrimType::Cylinder, {0.6, 0.8, 0.4}},  // the body
    {"cone", prime::io::PrimType::Cone, {0.3, 0.4, 0.5}},          // the body: x^2 + y^2 = z^2
    {"pyramid", prime::io::PrimType::Pyramid, {0.5, 0.4, 0.2}},    // the front face z = y/2
};

void inverseMap(benchmark::State& state, prime::io::PrimType type, prime::Vec3 p) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(p);
    auto r = prime::inverseMap1991(type, p);
    benchmark::DoNotOptimize(r);
  }
}

prime::Vec3 unit(prime::Vec3 v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}

// A glass-like surface (every term of Hall's sum is non-zero) hit head-on.
void hall(benchmark::State& state, int lights) {
  const prime::HallHue hue{0.6, 0.3, {0.8, 0.5, 0.2}, 0.9, 20.0, 10.0, 1.5};
  prime::HallGeometry g;
  g.pt = {500.0, 500.0, 300.0};
  g.v = unit({0.1, -0.2, 1.0});
  g.n = unit({0.0, 0.3, -1.0});
  g.r = unit({0.1, 0.4, -1.0});
  g.t = g.v;
  std::vector<prime::HallLight> all = {{{0.0, 1000.0, -1000.0}, {0.9, 0.9, 0.9}},
                                       {{1000.0, 800.0, -500.0}, {0.5, 0.4, 0.3}},
                                       {{500.0, -500.0, -800.0}, {0.2, 0.3, 0.6}}};
  all.resize(static_cast<std::size_t>(lights));
  const prime::Rgb surf{0.7, 0.5, 0.3}, iSR{0.2, 0.3, 0.4}, iST{0.1, 0.1, 0.1},
      ambient{0.2, 0.2, 0.2};
  for (auto _ : state) {
    benchmark::DoNotOptimize(g);
    prime::Rgb c = prime::processColor1991(hue, surf, iSR, iST, 12.5, g, all, ambient);
    benchmark::DoNotOptimize(c);
  }
}

void colorNumListing(benchmark::State& state) {
  prime::Rgb c{0.3, 0.6, 0.9};
  for (auto _ : state) {
    benchmark::DoNotOptimize(c);
    int i = prime::colorNum(c, 1);
    benchmark::DoNotOptimize(i);
  }
}

void colorNumPlate3(benchmark::State& state) {
  prime::Rgb c{0.3, 0.6, 0.9};
  for (auto _ : state) {
    benchmark::DoNotOptimize(c);
    int i = prime::colorNumPlate3(c);
    benchmark::DoNotOptimize(i);
  }
}

const int kRegistered = [] {
  for (const UvCase& c : kUvCases)
    benchmark::RegisterBenchmark((std::string("inverseMap/") + c.name).c_str(), inverseMap, c.type,
                                 c.point);
  benchmark::RegisterBenchmark("hall/processColor/1-light", hall, 1);
  benchmark::RegisterBenchmark("hall/processColor/3-lights", hall, 3);
  benchmark::RegisterBenchmark("colorNum/listing", colorNumListing);
  benchmark::RegisterBenchmark("colorNum/plate3", colorNumPlate3);
  return 0;
}();

}  // namespace
