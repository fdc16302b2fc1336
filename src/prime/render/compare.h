// `prime compare`'s arithmetic (T35-T37): how two renders of the same size
// differ, pixel by pixel, and where two probed ray trees part.
#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "src/prime/render/probe.h"
#include "src/prime/render/renderer.h"

namespace prime {

struct RenderComparison {
  std::size_t pixels = 0;
  std::size_t differing = 0;       // unquantised colours not bit-identical
  std::size_t indexDiffering = 0;  // palette indices (the graph files) differing
  double maxDifference = 0.0;      // largest |a - b| of a channel, colours clamped to 0..1
  double meanDifference = 0.0;     // that per pixel, averaged over every pixel
  int maxRow = -1, maxColumn = -1;
  // Up to the requested number of differing pixels (row, column), evenly
  // spread through them in row order (the first always among them).
  std::vector<std::pair<int, int>> sample;
  double share() const { return pixels ? static_cast<double>(differing) / pixels : 0.0; }
};

// Both renders must have kept their colours and be the same size (throws
// std::invalid_argument otherwise).
RenderComparison compareRenders(const RenderResult& a, const RenderResult& b, int sampleSize);

// The largest channel difference of two colours clamped to 0..1 (NaN as 0).
double colourDifference(const Rgb& a, const Rgb& b);

// Where two ray trees part: the probe's "ray" events in order, compared by
// kind, depth and their printed origin and direction (fmt's digits, so
// rounding noise below them does not count).
struct RayDivergence {
  int raysA = 0, raysB = 0;
  int firstDiffering = -1;  // index of the first ray that differs; -1: the rays agree
  std::string rayA, rayB;   // that ray's line in each ("" when the tree has no such ray)
  // Where the trees part, by kind (kDivergenceClasses): the first differing
  // ray's kind (primary, reflected, transmitted; "tir" when it is a
  // transmitted ray whose walk out reflected internally a different number
  // of times), else "shadow" when only the shadow rays' verdicts differ,
  // else "shading" (the same rays, other colours).
  std::string kind;
  // Every kind whose rays differ at the shallowest depth where any differ,
  // rays matched by kind, depth and their order among those (so a tree that
  // casts a reflected ray first does not hide a transmitted one that differs
  // too), in kDivergenceClasses' order; {kind} when no ray differs.
  std::vector<std::string> kinds;
  // For each of `kinds`, its first differing pair of rays (lines as rayA,
  // rayB; "" for a ray the tree lacks).
  std::map<std::string, std::pair<std::string, std::string>> rays;
};
inline constexpr const char* kDivergenceClasses[] = {"primary", "reflected", "transmitted",
                                                     "tir",     "shadow",    "shading"};
RayDivergence firstDivergence(const std::vector<ProbeEvent>& a, const std::vector<ProbeEvent>& b);

}  // namespace prime
