// The rays a render cast, by kind, and how many of them hit something: the
// counts every system's tracer keeps (a system adds its own diagnostics).
#pragma once
#include <cstdint>

namespace prime {

enum class RayKind { Primary, Reflected, Transmitted, Shadow };

struct RayCounts {
  std::uint64_t primaryRays = 0, reflectedRays = 0, transmittedRays = 0, shadowRays = 0;
  std::uint64_t hits = 0;

  std::uint64_t rays() const { return primaryRays + reflectedRays + transmittedRays + shadowRays; }
  void countRay(RayKind kind) {
    switch (kind) {
      case RayKind::Primary:
        ++primaryRays;
        break;
      case RayKind::Reflected:
        ++reflectedRays;
        break;
      case RayKind::Transmitted:
        ++transmittedRays;
        break;
      case RayKind::Shadow:
        ++shadowRays;
        break;
    }
  }
  RayCounts& operator+=(const RayCounts& o) {
    primaryRays += o.primaryRays;
    reflectedRays += o.reflectedRays;
    transmittedRays += o.transmittedRays;
    shadowRays += o.shadowRays;
    hits += o.hits;
    return *this;
  }
};

}  // namespace prime
