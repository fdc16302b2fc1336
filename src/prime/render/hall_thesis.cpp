#include "src/prime/render/hall_thesis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

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
  // What each light's terms need apart from the channel: the same values,
  // computed once instead of once per channel.
  struct Geometry {
    double nl = 0;     // N.L
    double cosF = 0;   // the Fresnel term's angle: V.H_j, or |V.H'_j| behind
    double power = 0;  // (N.H_j)^kRH, or (-N.H'_j)^kTH behind
    bool transmits = false;
  };
  constexpr std::size_t kStack = 16;
  std::array<Geometry, kStack> stackGeometry{};
  std::vector<Geometry> heapGeometry;  // (only for more lights than a scene can hold)
  Geometry* geometry = stackGeometry.data();
  if (lights.size() > kStack) {
    heapGeometry.resize(lights.size());
    geometry = heapGeometry.data();
  }
  for (std::size_t j = 0; j < lights.size(); ++j) {
    Geometry& g = geometry[j];
    const Vec3 l = normalized(lights[j].pt - point);
    g.nl = dot(n, l);
    if (g.nl > 0.0) {  // the light on the viewer's side: reflection
      const Vec3 hj = normalized(l + v);
      const double nh = std::max(0.0, dot(n, hj));
      g.cosF = dot(v, hj);
      g.power = std::pow(nh, std::max(0.0, h.kRH));
    } else if (g.nl < 0.0 && h.indx != 1.0 && h.indx > 0.0) {
      // Behind the surface: transmission; H' = (V + indx L)/(indx - 1), along -n (N10).
      const Vec3 ht = normalized((v + l * h.indx) * (1.0 / (h.indx - 1.0)));
      const double nht = std::max(0.0, -dot(n, ht));
      g.cosF = std::abs(dot(v, ht));
      g.power = std::pow(nht, std::max(0.0, h.kTH));
      g.transmits = true;
    }
  }
  const double transmissivity = std::pow(h.tT, sT);  // tT^sT, the same for every channel
  std::array<HallTerms, 3> terms{};
  for (int c = 0; c < 3; ++c) {
    const double f0 = texel[c];
    const double eta = f0 > 0.0 && f0 < 1.0 ? etaFromF0(f0) : 1.0;
    double a = 0, b = 0, cd = 0, dd = 0;
    for (std::size_t j = 0; j < lights.size(); ++j) {
      const ThesisLight& light = lights[j];
      const double iL = light.intensity[c] * light.visibility[c];
      if (iL == 0.0) continue;
      const Geometry& g = geometry[j];
      if (g.nl > 0.0) {
        a += iL * fresnelWithEta(f0, eta, g.cosF) * g.power;
        cd += iL * g.nl;
      } else if (g.nl < 0.0) {
        if (g.transmits) b += iL * (1.0 - fresnelWithEta(f0, eta, g.cosF)) * g.power;
        dd += iL * -g.nl;
      }
    }
    const double ia = ambient[c];
    const double colour = texelInDiffuse ? std::clamp(texel[c], 0.0, 1.0) : 1.0;
    const double fDR = h.fDR[c] * colour, fDT = (1.0 - h.fDR[c]) * colour;
    const double fsr = fresnelWithEta(f0, eta, nv);
    HallTerms& t = terms[static_cast<std::size_t>(c)];
    t.specularReflection = kSR * a;
    t.specularTransmission = kST * b;
    t.diffuseReflection = h.kDR * fDR * (ia + cd);
    t.diffuseTransmission = h.kDT * fDT * (ia + dd);
    t.reflected = kSR * iSR[c] * fsr;
    t.transmitted = kST * iST[c] * (1.0 - fsr) * transmissivity;
  }
  return terms;
}

}  // namespace prime
