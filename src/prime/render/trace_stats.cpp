#include "src/prime/render/trace_stats.h"

namespace prime {

TraceStats& TraceStats::operator+=(const TraceStats& o) {
  RayCounts::operator+=(o);
  boundTests += o.boundTests;
  objectTests += o.objectTests;
  primitiveTests += o.primitiveTests;
  maskedPrimaryRays += o.maskedPrimaryRays;
  totalInternalReflections += o.totalInternalReflections;
  emptyTransmitLists += o.emptyTransmitLists;
  cappedTirLoops += o.cappedTirLoops;
  failedTexelReads += o.failedTexelReads;
  noFaceMatched += o.noFaceMatched;
  nanColours += o.nanColours;
  indicesOutOfRange += o.indicesOutOfRange;
  return *this;
}

}  // namespace prime
