#include "src/prime/render/compare.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace prime {

double colourDifference(const Rgb& a, const Rgb& b) {
  const auto clamp01 = [](double v) { return std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0); };
  double d = 0.0;
  for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(clamp01(a[k]) - clamp01(b[k])));
  return d;
}

RenderComparison compareRenders(const RenderResult& a, const RenderResult& b, int sampleSize) {
  if (a.rgb.width != b.rgb.width || a.rgb.height != b.rgb.height)
    throw std::invalid_argument("the two renders differ in size: " + std::to_string(a.rgb.width) +
                                " x " + std::to_string(a.rgb.height) + " and " +
                                std::to_string(b.rgb.width) + " x " + std::to_string(b.rgb.height));
  if (a.rgb.pixels.size() != static_cast<std::size_t>(a.rgb.width) * a.rgb.height ||
      b.rgb.pixels.size() != a.rgb.pixels.size() || a.graph.pixels.size() != a.rgb.pixels.size() ||
      b.graph.pixels.size() != a.rgb.pixels.size())
    throw std::invalid_argument("compareRenders: both renders must keep their colours");
  RenderComparison c;
  c.pixels = a.rgb.pixels.size();
  std::vector<std::size_t> differing;
  double sum = 0.0;
  for (std::size_t i = 0; i < c.pixels; ++i) {
    const Rgb& x = a.rgb.pixels[i];
    const Rgb& y = b.rgb.pixels[i];
    if (a.graph.pixels[i] != b.graph.pixels[i]) ++c.indexDiffering;
    if (std::memcmp(x.data(), y.data(), sizeof x) == 0) continue;
    differing.push_back(i);
    const double d = colourDifference(x, y);
    sum += d;
    if (d > c.maxDifference) {
      c.maxDifference = d;
      c.maxRow = static_cast<int>(i / a.rgb.width);
      c.maxColumn = static_cast<int>(i % a.rgb.width);
    }
  }
  c.differing = differing.size();
  c.meanDifference = c.pixels ? sum / static_cast<double>(c.pixels) : 0.0;
  const std::size_t n = std::min<std::size_t>(differing.size(), std::max(sampleSize, 0));
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = differing[k * differing.size() / n];
    c.sample.emplace_back(static_cast<int>(i / a.rgb.width), static_cast<int>(i % a.rgb.width));
  }
  return c;
}

RayDivergence firstDivergence(const std::vector<ProbeEvent>& a, const std::vector<ProbeEvent>& b) {
  std::vector<const ProbeEvent*> ra, rb;
  for (const ProbeEvent& e : a)
    if (e.kind == "ray") ra.push_back(&e);
  for (const ProbeEvent& e : b)
    if (e.kind == "ray") rb.push_back(&e);
  RayDivergence d;
  d.raysA = static_cast<int>(ra.size());
  d.raysB = static_cast<int>(rb.size());
  const std::size_t n = std::max(ra.size(), rb.size());
  for (std::size_t i = 0; i < n; ++i) {
    const ProbeEvent* x = i < ra.size() ? ra[i] : nullptr;
    const ProbeEvent* y = i < rb.size() ? rb[i] : nullptr;
    if (x && y && x->depth == y->depth && x->text == y->text) continue;
    d.firstDiffering = static_cast<int>(i);
    d.rayA = x ? x->text : "";
    d.rayB = y ? y->text : "";
    break;
  }
  return d;
}

}  // namespace prime
