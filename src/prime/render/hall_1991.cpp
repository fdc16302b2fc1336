#include "src/prime/render/hall_1991.h"

#include <algorithm>
#include <cmath>

#include "src/prime/math/listing_math.h"
#include "src/prime/math/listing_vec.h"

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

namespace {

// pow(x, y) for x = N.H in [-1, 1] and a finite y >= 0 is finite unless x is
// negative and y not an integer (NaN); x outside [-1, 1] (including NaN)
// also makes ACos NaN. Anything else (y < 0, y not finite) is not decided here.
bool powAndAcosFinite(double x, double y) {
  if (!(x >= -1.0 && x <= 1.0) || !(y >= 0.0 && std::isfinite(y))) return false;
  return x >= 0.0 || std::floor(y) == y;
}

// pow(x, y) without the call for the two exponents whose result is exact
// for every x: pow(x, +-0) = 1 (C99 F.9.4.4, NaN included) and x^1 = x
// (representable, so any pow with an error under 1 ulp returns it).
double powShortcut(double x, double y) {
  if (y == 0.0) return 1.0;
  if (y == 1.0) return x;
  return std::pow(x, y);
}

constexpr double kBound = 1e100;
bool bounded(double v) {
  return v >= -kBound && v <= kBound;
}  // false for NaN and +-inf

}  // namespace

HallSkipping HallSkipping::forScene(std::span<const HallLight> lights, const Rgb& ambient) {
  HallSkipping s;
  s.on_ = bounded(ambient[0]) && bounded(ambient[1]) && bounded(ambient[2]);
  for (const HallLight& l : lights)
    for (double v : l.intensity) s.on_ = s.on_ && bounded(v);
  return s;
}

bool hallHitInputsBounded(const Rgb& surfColor, const Rgb& iSR, const Rgb& iST) {
  for (std::size_t k = 0; k < 3; ++k)
    if (!bounded(surfColor[k]) || !bounded(iSR[k]) || !bounded(iST[k])) return false;
  return true;
}

HallPrepared prepareHall1991(const HallGeometry& geom, std::span<const HallLight> lights,
                             double indx, double kRH, double kTH, double tT, double sT,
                             HallShortcut shortcut) {
  HallPrepared p;
  p.count = static_cast<int>(std::min(lights.size(), p.light.size()));
  const Vec3& n = geom.n;
  std::array<double, 10> dotHj{}, dotHj_{};
  bool zeroA = shortcut.zeroSpecularReflection, zeroB = shortcut.zeroSpecularTransmission;
  for (int i = 0; i < p.count; ++i) {  // calculate summations
    const auto k = static_cast<std::size_t>(i);
    // MakeVector(light[i].pt, pt, l): l = pt - light (K10), then UnitVector;
    // a zero l (light at the point) stays zero.
    Vec3 l = geom.towardsLight ? lights[k].pt - geom.pt : geom.pt - lights[k].pt;
    unitVector(l, l);
    dotHj[k] = dot(n, hj1991(l, geom.v));
    dotHj_[k] = dot(n, hjPrime1991(l, geom.v, indx));
    p.light[k].vD = dot(n, l);  // E16: a double
    zeroA = zeroA && powAndAcosFinite(dotHj[k], kRH);
    zeroB = zeroB && powAndAcosFinite(dotHj_[k], kTH);
  }
  p.zeroSpecularReflection = zeroA;
  p.zeroSpecularTransmission = zeroB;
  for (int i = 0; i < p.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    HallPrepared::Light& out = p.light[k];
    if (!zeroA) {
      out.cosHj = cosDeg(acosDeg(dotHj[k]));  // FSR's Cos(ACos(N.Hj))
      out.powHj = powShortcut(dotHj[k], kRH);
    }
    if (!zeroB) {
      out.cosHj_ = cosDeg(acosDeg(dotHj_[k]));
      out.powHj_ = powShortcut(dotHj_[k], kTH);
    }
  }
  const double dotR = dot(n, geom.r);
  p.zeroReflected = shortcut.zeroReflected && dotR >= -1.0 && dotR <= 1.0;
  if (!p.zeroReflected) p.cosReflected = cosDeg(acosDeg(dotR));
  p.cosZero = cosDeg(0.0);
  p.transmissivity = powShortcut(tT, sT);
  p.zeroTransmitted = shortcut.zeroTransmitted && std::isfinite(p.transmissivity);
  return p;
}

HallTerms hallTermsPrepared1991(int lambda, double surfColor, double kDR, double kDT, double iSR,
                                double iST, double fDR, const HallPrepared& prepared,
                                std::span<const HallLight> lights, const Rgb& ambient) {
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
    if (!prepared.zeroSpecularReflection)
      a += iL * fsrFromCos1991(surfColor, iL, g.cosHj) * g.powHj;
    if (!prepared.zeroSpecularTransmission)
      b += iL * (1.0 - fsrFromCos1991(surfColor, iL, g.cosHj_)) * g.powHj_;  // FST
    c += iL * g.vD;
    d += iL * -g.vD;
  }
  const double ia = ambient[lam];
  HallTerms t;
  t.specularReflection = prepared.zeroSpecularReflection ? 0.0 : kSR * a;
  t.specularTransmission = prepared.zeroSpecularTransmission ? 0.0 : kST * b;
  t.diffuseReflection = kDR * fDR * (ia + c);
  t.diffuseTransmission = kDT * fDT * (ia + d);
  t.reflected = prepared.zeroReflected
                    ? 0.0
                    : kSR * iSR * fsrFromCos1991(surfColor, ia, prepared.cosReflected);
  // E17/Q8: `FST(surfColor,IA[lambda],0.0) * pow(tT,sT)`.
  t.transmitted = prepared.zeroTransmitted
                      ? 0.0
                      : kST * iST * (1.0 - fsrFromCos1991(surfColor, ia, prepared.cosZero)) *
                            prepared.transmissivity;
  return t;
}

HallTerms hallTerms1991(int lambda, double surfColor, double kDR, double kDT, double iSR,
                        double iST, double fDR, double tT, double sT, double kRH, double kTH,
                        double indx, const HallGeometry& geom, std::span<const HallLight> lights,
                        const Rgb& ambient) {
  return hallTermsPrepared1991(lambda, surfColor, kDR, kDT, iSR, iST, fDR,
                               prepareHall1991(geom, lights, indx, kRH, kTH, tT, sT), lights,
                               ambient);
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
                                          std::span<const HallLight> lights, const Rgb& ambient,
                                          HallSkipping skipping) {
  // The per-light vectors, dot products, angles and powers do not depend on
  // the wavelength: computed once per hit (the listing did it per channel).
  HallShortcut shortcut;
  // kSR and kST bounded too: 0 * kSR is then 0 as well.
  if (skipping.on() && hallHitInputsBounded(surfColor, iSR, iST) && bounded(hue.kDR) &&
      bounded(hue.kDT)) {
    auto zero = [](const Rgb& c) { return c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0; };
    shortcut.zeroSpecularReflection = 1.0 - hue.kDR == 0.0;
    shortcut.zeroSpecularTransmission = 1.0 - hue.kDT == 0.0;
    shortcut.zeroReflected = shortcut.zeroSpecularReflection || zero(iSR);
    shortcut.zeroTransmitted = shortcut.zeroSpecularTransmission || zero(iST);
  }
  const HallPrepared prepared =
      prepareHall1991(geom, lights, hue.indx, hue.kRH, hue.kTH, hue.tT, sT, shortcut);
  std::array<HallTerms, 3> terms;
  for (int i = 0; i < 3; i++) {
    const auto k = static_cast<std::size_t>(i);
    terms[k] = hallTermsPrepared1991(i, surfColor[k], hue.kDR, hue.kDT, iSR[k], iST[k], hue.fDR[k],
                                     prepared, lights, ambient);
  }
  return terms;
}

Rgb processColor1991(const HallHue& hue, const Rgb& surfColor, const Rgb& iSR, const Rgb& iST,
                     double sT, const HallGeometry& geom, std::span<const HallLight> lights,
                     const Rgb& ambient, HallSkipping skipping, bool clampNegative) {
  const auto terms =
      hallTermsRgb1991(hue, surfColor, iSR, iST, sT, geom, lights, ambient, skipping);
  Rgb color{};
  for (std::size_t k = 0; k < 3; k++) {
    color[k] = terms[k].sum();
    if (color[k] >= 1.0) {  // K15: only >= 1.0 is clamped
      color[k] = 0.999999;
    }
    if (clampNegative && color[k] < 0.0) color[k] = 0.0;  // --fix K15
  }
  return color;
}

}  // namespace prime
