#include "src/prime/render/hall_modern.h"

#include <algorithm>
#include <cmath>

namespace prime {

std::array<HallTerms, 3> hallTermsModern(const HallHue& h, const Rgb& surfColor, const Rgb& iSR,
                                         const Rgb& iST, double sT, const Vec3& point,
                                         const Vec3& view, const Vec3& n, const Vec3& refl,
                                         std::span<const HallLight> lights, const Rgb& ambient) {
  const double kSR = 1.0 - h.kDR, kST = 1.0 - h.kDT;
  const Vec3 v = -view;  // towards the viewer
  // Lights outside, channels inside: each light's geometry (L, H, H', the
  // powers) once, not once per channel; each channel still sums its lights
  // in order, so the sums are the per-channel loop's to the bit.
  const bool transmission = h.indx != 1.0;  // H' = (V + indx L)/(indx - 1), along -n
  std::array<double, 3> a{}, b{}, cd{}, dd{};
  for (const HallLight& light : lights) {
    const Vec3 l = normalized(light.pt - point);
    const Vec3 hj = normalized(l + v);
    const double nl = dot(n, l);
    const double nh = std::max(0.0, dot(n, hj));
    const double powerR = std::pow(nh, std::max(0.0, h.kRH));
    double nht = 0, powerT = 0;
    if (transmission) {
      const Vec3 ht = normalized((v + l * h.indx) * (1.0 / (h.indx - 1.0)));
      nht = std::max(0.0, -dot(n, ht));
      powerT = std::pow(nht, std::max(0.0, h.kTH));
    }
    for (int c = 0; c < 3; ++c) {
      const double iL = light.intensity[c];
      a[c] += iL * fsrFromCos1991(surfColor[c], iL, nh) * powerR;
      if (transmission) b[c] += iL * (1.0 - fsrFromCos1991(surfColor[c], iL, nht)) * powerT;
      cd[c] += iL * std::max(0.0, nl);
      dd[c] += iL * std::max(0.0, -nl);
    }
  }
  const double cosR = std::clamp(dot(n, refl), -1.0, 1.0);
  const double transmissivity = std::pow(h.tT, sT);
  std::array<HallTerms, 3> terms{};
  for (int c = 0; c < 3; ++c) {
    const double ia = ambient[c];
    const double fDR = h.fDR[c], fDT = 1.0 - fDR;
    HallTerms& t = terms[static_cast<std::size_t>(c)];
    t.specularReflection = kSR * a[c];
    t.specularTransmission = kST * b[c];
    t.diffuseReflection = h.kDR * fDR * (ia + cd[c]);
    t.diffuseTransmission = h.kDT * fDT * (ia + dd[c]);
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
