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

TraceStats operator-(const TraceStats& a, const TraceStats& b) {
  TraceStats d;
  d.primaryRays = a.primaryRays - b.primaryRays;
  d.reflectedRays = a.reflectedRays - b.reflectedRays;
  d.transmittedRays = a.transmittedRays - b.transmittedRays;
  d.shadowRays = a.shadowRays - b.shadowRays;
  d.hits = a.hits - b.hits;
  d.boundTests = a.boundTests - b.boundTests;
  d.objectTests = a.objectTests - b.objectTests;
  d.primitiveTests = a.primitiveTests - b.primitiveTests;
  d.maskedPrimaryRays = a.maskedPrimaryRays - b.maskedPrimaryRays;
  d.totalInternalReflections = a.totalInternalReflections - b.totalInternalReflections;
  d.emptyTransmitLists = a.emptyTransmitLists - b.emptyTransmitLists;
  d.cappedTirLoops = a.cappedTirLoops - b.cappedTirLoops;
  d.failedTexelReads = a.failedTexelReads - b.failedTexelReads;
  d.noFaceMatched = a.noFaceMatched - b.noFaceMatched;
  d.nanColours = a.nanColours - b.nanColours;
  d.indicesOutOfRange = a.indicesOutOfRange - b.indicesOutOfRange;
  return d;
}

}  // namespace prime
