// Error of a rendered picture against a reference picture of the same size.
//
// Colours are compared in linear RGB, the renderer's own unquantised values
// (RenderResult::rgb). The 1991 shading does not keep colours in [0, 1]:
// ProcessColor clamps only >= 1.0 to 0.999999 and lets negatives and NaN
// through (K15, S19). For the metric every channel is clamped to [0, 1] first
// and NaN counts as 0, as ColorNum's level 0 does (S10), so one wild pixel
// cannot dominate the RMSE beyond what the screen could show.
#pragma once
#include <cstdint>
#include <span>

#include "palette/prime/color_num.h"

namespace prime::bench {

struct ImageError {
  double rmse = 0;        // sqrt(mean over pixels and channels of (a - b)^2), clamped values
  double maxError = 0;    // largest |a - b| over pixels and channels, clamped values
  double indexShare = 0;  // share of pixels whose palette index differs, 0..1
  std::uint64_t pixels = 0;
};

// The channel value the metric uses: clamped to [0, 1], NaN -> 0.
double metricValue(double channel);

// Throws std::invalid_argument when the sizes differ.
ImageError compareImages(std::span<const Rgb> reference,
                         std::span<const std::int16_t> referenceIndices, std::span<const Rgb> image,
                         std::span<const std::int16_t> imageIndices);

}  // namespace prime::bench
