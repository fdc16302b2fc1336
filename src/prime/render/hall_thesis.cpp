#include "src/prime/render/hall_thesis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prime {

double etaFromF0(double f0) {
  const double r = std::sqrt(std::clamp(f0, 0.0, 1.0));
  if (r >= 1.0) return std::numeric_limits<double>::infinity();
  return (1.0 + r) / (1.0 - r);
}

namespace {

// fresnelThesis with eta = etaFromF0(f0) already at hand (one per channel,
// not one per light and term).
double fresnelWithEta(double f0, double eta, double c) {
  if (!(f0 > 0.0)) return 0.0;  // eta = 1: no boundary, nothing reflected (also NaN)
  if (f0 >= 1.0) return 1.0;
  c = std::clamp(c, 0.0, 1.0);
  const double g2 = eta * eta + c * c - 1.0;
  if (!(g2 > 0.0)) return 1.0;
  const double g = std::sqrt(g2);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return std::clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
}

}  // namespace

double fresnelThesis(double f0, double c) {
  return fresnelWithEta(f0, f0 > 0.0 && f0 < 1.0 ? etaFromF0(f0) : 1.0, c);
}

std::array<HallTerms, 3> hallTermsThesis(const HallHue& h, const Rgb& texel, const Rgb& iSR,
                                         const Rgb& iST, double sT, const Vec3& view, const Vec3& n,
                                         const Vec3& point, std::span<const ThesisLight> lights,
                                         const Rgb& ambient, bool texelInDiffuse) {
  const double kSR = 1.0 - h.kDR, kST = 1.0 - h.kDT;
  const Vec3 v = -view;  // towards the viewer
  const double nv = std::clamp(dot(n, v), 0.0, 1.0);
  std::array<double, 3> eta{};  // from F(0), per channel
  for (int c = 0; c < 3; ++c) {
    const double f0 = texel[c];
    eta[c] = c > 0 && f0 == texel[c - 1] ? eta[c - 1] : f0 > 0.0 && f0 < 1.0 ? etaFromF0(f0) : 1.0;
  }
  // fresnelWithEta is a function of F(0) (eta follows from it) and the
  // angle: a channel with the previous one's F(0) takes its value (grey
  // texels: one evaluation instead of three, the same double).
  struct FresnelMemo {
    double f0 = std::numeric_limits<double>::quiet_NaN(), cosF = 0, value = 0;
  };
  auto fresnel = [&](FresnelMemo& memo, int c, double cosF) {
    if (!(texel[c] == memo.f0 && cosF == memo.cosF))
      memo = {texel[c], cosF, fresnelWithEta(texel[c], eta[c], cosF)};
    return memo.value;
  };
  // Lights outside, channels inside: each light's geometry (L, H, the
  // power) once, not once per channel; each channel still sums its lights
  // in order, so the sums are the per-channel loop's to the bit.
  std::array<double, 3> a{}, b{}, cd{}, dd{};
  for (const ThesisLight& light : lights) {
    // A light that adds nothing to any channel (in shadow, or dark) is
    // skipped whole: its geometry and powers would only be computed.
    bool adds = false;
    for (int c = 0; c < 3; ++c) adds = adds || light.intensity[c] * light.visibility[c] != 0.0;
    if (!adds) continue;
    const Vec3 l = light.hasDir ? light.dir : normalized(light.pt - point);
    const double nl = dot(n, l);
    double cosF = 0, power = 0;  // the Fresnel term's angle, (N.H_j)^kRH or (-N.H'_j)^kTH
    bool transmits = false;
    if (nl > 0.0) {  // the light on the viewer's side: reflection
      const Vec3 hj = normalized(l + v);
      cosF = dot(v, hj);
      power = std::pow(std::max(0.0, dot(n, hj)), std::max(0.0, h.kRH));
    } else if (nl < 0.0 && h.indx != 1.0 && h.indx > 0.0) {
      // Behind the surface: transmission; H' = (V + indx L)/(indx - 1), along -n (N10).
      const Vec3 ht = normalized((v + l * h.indx) * (1.0 / (h.indx - 1.0)));
      cosF = std::abs(dot(v, ht));
      power = std::pow(std::max(0.0, -dot(n, ht)), std::max(0.0, h.kTH));
      transmits = true;
    }
    FresnelMemo memo;
    for (int c = 0; c < 3; ++c) {
      const double iL = light.intensity[c] * light.visibility[c];
      if (iL == 0.0) continue;
      if (nl > 0.0) {
        a[c] += iL * fresnel(memo, c, cosF) * power;
        cd[c] += iL * nl;
      } else if (nl < 0.0) {
        if (transmits) b[c] += iL * (1.0 - fresnel(memo, c, cosF)) * power;
        dd[c] += iL * -nl;
      }
    }
  }
  const double transmissivity = std::pow(h.tT, sT);  // tT^sT, the same for every channel
  std::array<HallTerms, 3> terms{};
  FresnelMemo memo;
  for (int c = 0; c < 3; ++c) {
    const double ia = ambient[c];
    const double colour = texelInDiffuse ? std::clamp(texel[c], 0.0, 1.0) : 1.0;
    const double fDR = h.fDR[c] * colour, fDT = (1.0 - h.fDR[c]) * colour;
    const double fsr = fresnel(memo, c, nv);
    HallTerms& t = terms[static_cast<std::size_t>(c)];
    t.specularReflection = kSR * a[c];
    t.specularTransmission = kST * b[c];
    t.diffuseReflection = h.kDR * fDR * (ia + cd[c]);
    t.diffuseTransmission = h.kDT * fDT * (ia + dd[c]);
    t.reflected = kSR * iSR[c] * fsr;
    t.transmitted = kST * iST[c] * (1.0 - fsr) * transmissivity;
  }
  return terms;
}

}  // namespace prime
