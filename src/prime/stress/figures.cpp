// The stress suite's figures: error histograms, per-class counts and the list
// of ray classes (see stress.h and docs/prime/numerics.md).
#include <algorithm>
#include <cmath>

#include "src/prime/stress/stress.h"

namespace prime::stress {

void ErrorHistogram::add(double e) {
  ++count;
  if (!(e > 0)) {
    if (e == 0) ++zeros;
    return;
  }
  max = std::max(max, e);
  int bin = static_cast<int>(std::floor((std::log10(e) + 20.0) * 10.0));
  bins[static_cast<std::size_t>(std::clamp(bin, 0, kBins - 1))]++;
}

double ErrorHistogram::quantile(double q) const {
  if (count == 0) return 0;
  const auto want = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count)));
  std::uint64_t seen = zeros;
  if (seen >= want) return 0;
  for (int i = 0; i < kBins; ++i) {
    seen += bins[static_cast<std::size_t>(i)];
    if (seen >= want) return std::min(max, std::pow(10.0, (i + 1) / 10.0 - 20.0));
  }
  return max;
}

ErrorHistogram& ErrorHistogram::operator+=(const ErrorHistogram& o) {
  for (int i = 0; i < kBins; ++i)
    bins[static_cast<std::size_t>(i)] += o.bins[static_cast<std::size_t>(i)];
  count += o.count;
  zeros += o.zeros;
  max = std::max(max, o.max);
  return *this;
}

Figures& Figures::operator+=(const Figures& o) {
  rays += o.rays, refHits += o.refHits, compared += o.compared;
  wrongHitMiss += o.wrongHitMiss, ambiguousHitMiss += o.ambiguousHitMiss;
  wrongInOut += o.wrongInOut, ambiguousInOut += o.ambiguousInOut;
  wrongSurface += o.wrongSurface, ambiguousSurface += o.ambiguousSurface;
  nanInf += o.nanInf, uvNan += o.uvNan;
  secondary += o.secondary, selfHits += o.selfHits, wrongSide += o.wrongSide;
  semanticK7 += o.semanticK7, semanticCsg += o.semanticCsg, semanticK4 += o.semanticK4;
  listingErrors += o.listingErrors, uvFaceChanges += o.uvFaceChanges, refDisagree += o.refDisagree;
  chains += o.chains, chainSteps += o.chainSteps, chainsComplete += o.chainsComplete;
  tRel += o.tRel, normalAngle += o.normalAngle, uv += o.uv;
  return *this;
}

const std::vector<ClassInfo>& stressClasses() {
  static const std::vector<ClassInfo> classes{
      {"uniform", "baseline: random rays from outside at the solid, moderate transforms"},
      {"grazing", "rays meeting a surface at 1e-2..1e-14 rad off tangent"},
      {"tangent", "rays tangent to a curved surface, or touching a polyhedron at an edge only"},
      {"face", "rays lying in a face plane, along a cylinder/cone generator, in a cap plane"},
      {"edge", "rays along an edge, or through an edge point from outside"},
      {"vertex", "rays through a vertex (corners, apex, poles, rim points)"},
      {"on-surface", "origins on the surface (as secondary rays have), any direction"},
      {"scale", "uniform rays and grazing rays, the solid scaled by 1e-6 .. 1e6"},
      {"translate", "the solid translated by up to 1e6, rays from nearby"},
      {"near-singular", "axis scales in a ratio of 1e4 .. 1e9, then rotated"},
      {"rot90", "rotations by multiples of 90 degrees (K3: not snapped), face/edge/vertex rays"},
      {"coincident", "CSG operands with coincident faces (shared, touching, identical)"},
      {"tir-chain", "chains of 16 internal reflections inside the solid"},
      {"mirrors", "two parallel mirrors 1e-3 .. 1e3 apart, 16 bounces"},
  };
  return classes;
}
}  // namespace prime::stress
