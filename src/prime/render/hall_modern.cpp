#include "src/prime/render/hall_modern.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace prime {

std::array<HallTerms, 3> hallTermsModern(const HallHue& h, const Rgb& surfColor, const Rgb& iSR,
                                         const Rgb& iST, double sT, const Vec3& point,
                                         const Vec3& view, const Vec3& n, const Vec3& refl,
                                         std::span<const HallLight> lights, const Rgb& ambient) {
  const double kSR = 1.0 - h.kDR, kST = 1.0 - h.kDT;
  const Vec3 v = -view;  // towards the viewer
  // Each light's geometry does not depend on the channel: computed once
  // (the same values the per-channel loop computed three times).
  struct Geometry {
    double nl = 0, nh = 0, powerR = 0, nht = 0, powerT = 0;
  };
  constexpr std::size_t kStack = 16;
  std::array<Geometry, kStack> stackGeometry{};
  std::vector<Geometry> heapGeometry;  // (only for more lights than a scene can hold)
  Geometry* geometry = stackGeometry.data();
  if (lights.size() > kStack) {
    heapGeometry.resize(lights.size());
    geometry = heapGeometry.data();
  }
  const bool transmission = h.indx != 1.0;  // H' = (V + indx L)/(indx - 1), along -n
  for (std::size_t j = 0; j < lights.size(); ++j) {
    Geometry& g = geometry[j];
    const Vec3 l = normalized(lights[j].pt - point);
    const Vec3 hj = normalized(l + v);
    g.nl = dot(n, l);
    g.nh = std::max(0.0, dot(n, hj));
    g.powerR = std::pow(g.nh, std::max(0.0, h.kRH));
    if (transmission) {
      const Vec3 ht = normalized((v + l * h.indx) * (1.0 / (h.indx - 1.0)));
      g.nht = std::max(0.0, -dot(n, ht));
      g.powerT = std::pow(g.nht, std::max(0.0, h.kTH));
    }
  }
  const double cosR = std::clamp(dot(n, refl), -1.0, 1.0);
  const double transmissivity = std::pow(h.tT, sT);
  std::array<HallTerms, 3> terms{};
  for (int c = 0; c < 3; ++c) {
    double a = 0, b = 0, cd = 0, dd = 0;
    for (std::size_t j = 0; j < lights.size(); ++j) {
      const Geometry& g = geometry[j];
      const double iL = lights[j].intensity[c];
      a += iL * fsrFromCos1991(surfColor[c], iL, g.nh) * g.powerR;
      if (transmission) b += iL * (1.0 - fsrFromCos1991(surfColor[c], iL, g.nht)) * g.powerT;
      cd += iL * std::max(0.0, g.nl);
      dd += iL * std::max(0.0, -g.nl);
    }
    const double ia = ambient[c];
    const double fDR = h.fDR[c], fDT = 1.0 - fDR;
    HallTerms& t = terms[static_cast<std::size_t>(c)];
    t.specularReflection = kSR * a;
    t.specularTransmission = kST * b;
    t.diffuseReflection = h.kDR * fDR * (ia + cd);
    t.diffuseTransmission = h.kDT * fDT * (ia + dd);
    t.reflected = kSR * iSR[c] * fsrFromCos1991(surfColor[c], ia, cosR);
    t.transmitted = kST * iST[c] * (1.0 - fsrFromCos1991(surfColor[c], ia, 1.0)) * transmissivity;
  }
  return terms;
}

Rgb hallColourModern(const std::array<HallTerms, 3>& terms, std::uint64_t& nonFinite) {
  Rgb color{};
  for (int c = 0; c < 3; ++c) {
    const double sum = terms[static_cast<std::size_t>(c)].sum();
    if (!std::isfinite(sum)) ++nonFinite;
    color[c] = std::isfinite(sum) ? std::clamp(sum, 0.0, 0.999999) : 0.0;
  }
  return color;
}

}  // namespace prime
