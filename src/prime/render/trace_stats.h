// Counters of one render: the rays cast by kind (RayCounts, shared by every
// system), the tests made, and the X3 diagnostics that show where a scene
// leaves the ground on which the 1991 program was well defined.
#pragma once
#include <cstdint>

#include "src/render/ray_counts.h"

namespace prime {

struct TraceStats : RayCounts {
  std::uint64_t boundTests = 0, objectTests = 0, primitiveTests = 0;
  std::uint64_t maskedPrimaryRays =
      0;  // primary rays answered by the mask (PrimaryRayMask), not traced
  std::uint64_t totalInternalReflections = 0;
  std::uint64_t emptyTransmitLists = 0;  // E46: CSG list empty in TransmittedRay
  std::uint64_t cappedTirLoops = 0;      // E59: TIR loop stopped at the cap
  std::uint64_t failedTexelReads = 0;    // E51: read past the end of a map -> 0.0
  std::uint64_t noFaceMatched = 0;       // E44: GetUV* matched no face -> surface 0
  std::uint64_t nanColours = 0;          // X3: a NaN reached ColorNum
  std::uint64_t indicesOutOfRange = 0;   // K15: palette index outside 0..255

  TraceStats& operator+=(const TraceStats& o);
};
// What `a` counted beyond `b` (a later and an earlier count of one tracer).
TraceStats operator-(const TraceStats& a, const TraceStats& b);

}  // namespace prime
