#include "src/prime/render/compare.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <tuple>

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

namespace {

std::vector<const ProbeEvent*> eventsOf(const std::vector<ProbeEvent>& all, const char* kind) {
  std::vector<const ProbeEvent*> out;
  for (const ProbeEvent& e : all)
    if (e.kind == kind) out.push_back(&e);
  return out;
}

// The value of "key": in a probe event's JSON (a word or a number), or "".
std::string field(const ProbeEvent* e, const std::string& key) {
  return e == nullptr ? "" : jsonField(e->json, key);
}

// The steps (TIR loops + 1) of the walk out that made a transmitted ray: the
// last transmit event before it one level up (the reflected ray's subtree,
// traced in between, is deeper), or "".
std::string stepsBefore(const std::vector<ProbeEvent>& all, const ProbeEvent* ray) {
  const ProbeEvent* last = nullptr;
  for (const ProbeEvent& e : all) {
    if (&e == ray) return field(last, "steps");
    if (e.kind == "transmit" && e.depth == ray->depth - 1) last = &e;
  }
  return "";
}

bool sameEvents(const std::vector<const ProbeEvent*>& x, const std::vector<const ProbeEvent*>& y) {
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i]->depth != y[i]->depth || x[i]->text != y[i]->text) return false;
  return true;
}

// The class of a differing ray pair (either may be missing).
std::string classOf(const std::vector<ProbeEvent>& a, const std::vector<ProbeEvent>& b,
                    const ProbeEvent* x, const ProbeEvent* y) {
  std::string kind = field(x ? x : y, "kind");
  if (kind == "transmitted" && x && y && stepsBefore(a, x) != stepsBefore(b, y)) kind = "tir";
  return kind;
}

void differingKinds(const std::vector<ProbeEvent>& a, const std::vector<ProbeEvent>& b,
                    const std::vector<const ProbeEvent*>& ra,
                    const std::vector<const ProbeEvent*>& rb, RayDivergence& d) {
  // Rays keyed by (depth, kind, their order among that depth and kind).
  auto keyed = [](const std::vector<const ProbeEvent*>& rays) {
    std::map<std::tuple<int, std::string, int>, const ProbeEvent*> out;
    std::map<std::pair<int, std::string>, int> seen;
    for (const ProbeEvent* e : rays) {
      const std::string kind = field(e, "kind");
      out[{e->depth, kind, seen[{e->depth, kind}]++}] = e;
    }
    return out;
  };
  const auto ka = keyed(ra), kb = keyed(rb);
  int shallowest = INT_MAX;
  std::map<std::string, std::pair<std::string, std::string>> kinds;
  auto consider = [&](const auto& key, const ProbeEvent* x, const ProbeEvent* y) {
    if (x && y && x->text == y->text) return;
    const int depth = std::get<0>(key);
    if (depth > shallowest) return;
    if (depth < shallowest) kinds.clear();
    shallowest = depth;
    kinds.emplace(classOf(a, b, x, y), std::pair{x ? x->text : "", y ? y->text : ""});
  };
  for (const auto& [key, x] : ka) {
    const auto it = kb.find(key);
    consider(key, x, it == kb.end() ? nullptr : it->second);
  }
  for (const auto& [key, y] : kb)
    if (!ka.count(key)) consider(key, nullptr, y);
  for (const char* k : kDivergenceClasses)
    if (kinds.count(k)) d.kinds.push_back(k);
  d.rays = std::move(kinds);
}

}  // namespace

RayDivergence firstDivergence(const std::vector<ProbeEvent>& a, const std::vector<ProbeEvent>& b) {
  const std::vector<const ProbeEvent*> ra = eventsOf(a, "ray"), rb = eventsOf(b, "ray");
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
    d.kind = classOf(a, b, x, y);
    differingKinds(a, b, ra, rb, d);
    return d;
  }
  d.kind = sameEvents(eventsOf(a, "shadow"), eventsOf(b, "shadow")) ? "shading" : "shadow";
  d.kinds = {d.kind};
  return d;
}

}  // namespace prime
