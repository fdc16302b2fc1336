#include "src/prime/bench/metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prime::bench {

double metricValue(double channel) {
  if (std::isnan(channel)) return 0.0;
  return std::clamp(channel, 0.0, 1.0);
}

ImageError compareImages(std::span<const Rgb> reference,
                         std::span<const std::int16_t> referenceIndices, std::span<const Rgb> image,
                         std::span<const std::int16_t> imageIndices) {
  if (reference.size() != image.size() || referenceIndices.size() != imageIndices.size() ||
      reference.size() != referenceIndices.size())
    throw std::invalid_argument("compareImages: the pictures differ in size");
  ImageError e;
  e.pixels = reference.size();
  if (reference.empty()) return e;
  double sum = 0.0;
  std::uint64_t differ = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double d = std::abs(metricValue(image[i][k]) - metricValue(reference[i][k]));
      sum += d * d;
      e.maxError = std::max(e.maxError, d);
    }
    differ += imageIndices[i] != referenceIndices[i];
  }
  e.rmse = std::sqrt(sum / (3.0 * static_cast<double>(reference.size())));
  e.indexShare = static_cast<double>(differ) / static_cast<double>(reference.size());
  return e;
}

}  // namespace prime::bench
