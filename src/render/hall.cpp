#include "src/render/hall.h"

#include <algorithm>
#include <cmath>

#include "src/math/listing_math.h"

namespace prime {

double fsrFromCos1991(double surfColor, double iL, double cosAng) {
  double tmp;
  double f;
  const double f0 = surfColor;  // fresnel value at 0 degrees
  const double f90 = 0.0;       // 90 degrees
  const double fAng = cosAng * surfColor;
  if ((f90 - f0) == 0.0) {
    tmp = 0.0;
  } else {
    tmp = (fAng - f0) / (f90 - f0);
  }
  if (tmp < 0.0) {
    f = iL * f0;
  } else {
    f = iL * (f0 + (1.0 - f0) * tmp);
  }
  return f;
}

double fsr1991(double surfColor, double iL, double ang) {
  return fsrFromCos1991(surfColor, iL, cosDeg(ang));
}

double fst1991(double surfColor, double iL, double ang) {
  return 1.0 - fsr1991(surfColor, iL, ang);
}

Vec3 hj1991(const Vec3& l, const Vec3& v) {
  Vec3 h{};
  const double tmp = std::sqrt(sqr(l[X] + v[X]) + sqr(l[Y] + v[Y]) + sqr(l[Z] + v[Z]));
  for (int i = X; i < W; i++) {  // E18: `i < M` read as `i < W`
    h[i] = (l[i] + v[i]) / tmp;
  }
  unitVector(h, h);
  return h;
}

Vec3 hjPrime1991(const Vec3& l, const Vec3& v, double indx) {
  Vec3 h{};
  const double tmp = indx - 1.0;  // K13: indx == 1 divides by zero
  for (int i = X; i < W; i++) {   // E18
    h[i] = (v[i] + indx * l[i]) / tmp;
  }
  unitVector(h, h);
  return h;
}

HallPrepared prepareHall1991(const HallGeometry& geom, std::span<const HallLight> lights,
                             double indx, double kRH, double kTH) {
  HallPrepared p;
  p.count = static_cast<int>(std::min(lights.size(), p.light.size()));
  const Vec3& n = geom.n;
  for (int i = 0; i < p.count; ++i) {  // calculate summations
    // MakeVector(light[i].pt, pt, l): l = pt - light (K10), then UnitVector;
    // a zero l (light at the point) stays zero.
    Vec3 l = geom.pt - lights[i].pt;
    unitVector(l, l);
    const Vec3 h = hj1991(l, geom.v);
    const Vec3 h_ = hjPrime1991(l, geom.v, indx);
    const double dotHj = dot(n, h);
    const double dotHj_ = dot(n, h_);
    HallPrepared::Light& out = p.light[static_cast<std::size_t>(i)];
    out.cosHj = cosDeg(acosDeg(dotHj));    // FSR's Cos(ACos(N.Hj))
    out.cosHj_ = cosDeg(acosDeg(dotHj_));
    out.powHj = std::pow(dotHj, kRH);
    out.powHj_ = std::pow(dotHj_, kTH);
    out.vD = dot(n, l);  // E16: a double
  }
  p.cosReflected = cosDeg(acosDeg(dot(n, geom.r)));
  p.cosZero = cosDeg(0.0);
  return p;
}

HallTerms hallTermsPrepared1991(int lambda, double surfColor, double kDR, double kDT, double iSR,
                                double iST, double fDR, double tT, double sT,
                                const HallPrepared& prepared, std::span<const HallLight> lights,
                                const Rgb& ambient) {
  const auto lam = static_cast<std::size_t>(lambda);
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double d = 0.0;
  const double kSR = 1.0 - kDR;
  const double kST = 1.0 - kDT;
  const double fDT = 1.0 - fDR;
  for (int i = 0; i < prepared.count; ++i) {
    const HallPrepared::Light& g = prepared.light[static_cast<std::size_t>(i)];
    const double iL = lights[static_cast<std::size_t>(i)].intensity[lam];
    a += iL * fsrFromCos1991(surfColor, iL, g.cosHj) * g.powHj;
    b += iL * (1.0 - fsrFromCos1991(surfColor, iL, g.cosHj_)) * g.powHj_;  // FST
    c += iL * g.vD;
    d += iL * -g.vD;
  }
  const double ia = ambient[lam];
  HallTerms t;
  t.specularReflection = kSR * a;
  t.specularTransmission = kST * b;
  t.diffuseReflection = kDR * fDR * (ia + c);
  t.diffuseTransmission = kDT * fDT * (ia + d);
  t.reflected = kSR * iSR * fsrFromCos1991(surfColor, ia, prepared.cosReflected);
  // E17/Q8: `FST(surfColor,IA[lambda],0.0) * pow(tT,sT)`.
  t.transmitted = kST * iST * (1.0 - fsrFromCos1991(surfColor, ia, prepared.cosZero)) * std::pow(tT, sT);
  return t;
}

HallTerms hallTerms1991(int lambda, double surfColor, double kDR, double kDT, double iSR, double iST,
                        double fDR, double tT, double sT, double kRH, double kTH, double indx,
                        const HallGeometry& geom, std::span<const HallLight> lights,
                        const Rgb& ambient) {
  return hallTermsPrepared1991(lambda, surfColor, kDR, kDT, iSR, iST, fDR, tT, sT,
                               prepareHall1991(geom, lights, indx, kRH, kTH), lights, ambient);
}

double processWavelength1991(int lambda, double surfColor, double kDR, double kDT, double iSR,
                             double iST, double fDR, double tT, double sT, double kRH, double kTH,
                             double indx, const HallGeometry& geom,
                             std::span<const HallLight> lights, const Rgb& ambient) {
  return hallTerms1991(lambda, surfColor, kDR, kDT, iSR, iST, fDR, tT, sT, kRH, kTH, indx, geom,
                       lights, ambient)
      .sum();
}

std::array<HallTerms, 3> hallTermsRgb1991(const HallHue& hue, const Rgb& surfColor, const Rgb& iSR,
                                          const Rgb& iST, double sT, const HallGeometry& geom,
                                          std::span<const HallLight> lights, const Rgb& ambient) {
  // The per-light vectors, dot products, angles and powers do not depend on
  // the wavelength: computed once per hit (the listing did it per channel).
  const HallPrepared prepared = prepareHall1991(geom, lights, hue.indx, hue.kRH, hue.kTH);
  std::array<HallTerms, 3> terms;
  for (int i = 0; i < 3; i++) {
    const auto k = static_cast<std::size_t>(i);
    terms[k] = hallTermsPrepared1991(i, surfColor[k], hue.kDR, hue.kDT, iSR[k], iST[k], hue.fDR[k],
                                     hue.tT, sT, prepared, lights, ambient);
  }
  return terms;
}

Rgb processColor1991(const HallHue& hue, const Rgb& surfColor, const Rgb& iSR, const Rgb& iST,
                     double sT, const HallGeometry& geom, std::span<const HallLight> lights,
                     const Rgb& ambient) {
  const auto terms = hallTermsRgb1991(hue, surfColor, iSR, iST, sT, geom, lights, ambient);
  Rgb color{};
  for (std::size_t k = 0; k < 3; k++) {
    color[k] = terms[k].sum();
    if (color[k] >= 1.0) {  // K15: only >= 1.0 is clamped
      color[k] = 0.999999;
    }
  }
  return color;
}

}  // namespace prime
