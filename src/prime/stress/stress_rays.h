// The stress suite's random rays: a seeded generator and rays at the local
// features of the five unit primitives (faces, edges, vertices, tangents,
// origins on the surface), in primitive space. `type` is a primitive letter,
// as in reference.h.
#pragma once
#include <cmath>
#include <cstdint>

#include "src/math/vec.h"
#include "src/prime/stress/common.h"

namespace prime::stress {

struct Rng {
  std::uint64_t s;
  explicit Rng(std::uint64_t seed) : s(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
  bool coin() { return (next() & 1) != 0; }
  Vec3 unitVector() {
    for (;;) {
      const Vec3 v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      const double l = dot(v, v);
      if (l > 1e-4 && l <= 1) return v * (1 / std::sqrt(l));
    }
  }
};

// A generator's seed made from two numbers (the suite's seed and a job).
std::uint64_t mix(std::uint64_t a, std::uint64_t b);

Vec3 unitV(const Vec3& v);  // v scaled to unit length (a zero v unchanged)

struct LocalRay {
  Vec3 o, d;
};

Vec3 centreOf(char type);                 // a point well inside the solid
Vec3 interiorPoint(char type, Rng& rng);  // a random point near centreOf

LocalRay uniformRay(char type, Rng& rng);    // from outside at the solid
LocalRay grazingRay(char type, Rng& rng);    // 1e-2 .. 1e-14 rad off a tangent
LocalRay tangentRay(char type, Rng& rng);    // touching a curved surface or an edge only
LocalRay faceRay(char type, Rng& rng);       // in a face plane, along a generator
LocalRay edgeRay(char type, Rng& rng);       // along an edge, or through one
LocalRay vertexRay(char type, Rng& rng);     // through a vertex, pole or apex
LocalRay onSurfaceRay(char type, Rng& rng);  // from a point on the surface

}  // namespace prime::stress
