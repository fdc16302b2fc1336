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

double fresnelThesis(double f0, double c) {
  if (!(f0 > 0.0)) return 0.0;  // eta = 1: no boundary, nothing reflected (also NaN)
  if (f0 >= 1.0) return 1.0;
  c = std::clamp(c, 0.0, 1.0);
  const double eta = etaFromF0(f0);
  const double g2 = eta * eta + c * c - 1.0;
  if (!(g2 > 0.0)) return 1.0;
  const double g = std::sqrt(g2);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return std::clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
}

std::array<HallTerms, 3> hallTermsThesis(const HallHue& h, const Rgb& texel, const Rgb& iSR,
                                         const Rgb& iST, double sT, const Vec3& view, const Vec3& n,
                                         const Vec3& point, std::span<const ThesisLight> lights,
                                         const Rgb& ambient, bool texelInDiffuse) {
  const double kSR = 1.0 - h.kDR, kST = 1.0 - h.kDT;
  const Vec3 v = -view;  // towards the viewer
  const double nv = std::clamp(dot(n, v), 0.0, 1.0);
  std::array<HallTerms, 3> terms{};
  for (int c = 0; c < 3; ++c) {
    const double f0 = texel[c];
    double a = 0, b = 0, cd = 0, dd = 0;
    for (const ThesisLight& light : lights) {
      const double iL = light.intensity[c] * light.visibility[c];
      if (iL == 0.0) continue;
      const Vec3 l = normalized(light.pt - point);
      const double nl = dot(n, l);
      if (nl > 0.0) {  // the light on the viewer's side: reflection
        const Vec3 hj = normalized(l + v);
        const double nh = std::max(0.0, dot(n, hj));
        a += iL * fresnelThesis(f0, dot(v, hj)) * std::pow(nh, std::max(0.0, h.kRH));
        cd += iL * nl;
      } else if (nl < 0.0) {                  // behind the surface: transmission
        if (h.indx != 1.0 && h.indx > 0.0) {  // H' = (V + indx L)/(indx - 1), along -n (N10)
          const Vec3 ht = normalized((v + l * h.indx) * (1.0 / (h.indx - 1.0)));
          const double nht = std::max(0.0, -dot(n, ht));
          b += iL * (1.0 - fresnelThesis(f0, std::abs(dot(v, ht)))) *
               std::pow(nht, std::max(0.0, h.kTH));
        }
        dd += iL * -nl;
      }
    }
    const double ia = ambient[c];
    const double colour = texelInDiffuse ? std::clamp(texel[c], 0.0, 1.0) : 1.0;
    const double fDR = h.fDR[c] * colour, fDT = (1.0 - h.fDR[c]) * colour;
    const double fsr = fresnelThesis(f0, nv);
    HallTerms& t = terms[static_cast<std::size_t>(c)];
    t.specularReflection = kSR * a;
    t.specularTransmission = kST * b;
    t.diffuseReflection = h.kDR * fDR * (ia + cd);
    t.diffuseTransmission = h.kDT * fDT * (ia + dd);
    t.reflected = kSR * iSR[c] * fsr;
    t.transmitted = kST * iST[c] * (1.0 - fsr) * std::pow(h.tT, sT);
  }
  return terms;
}

}  // namespace prime
