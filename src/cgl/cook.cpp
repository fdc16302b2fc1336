#include "src/cgl/cook.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace prime::cgl {

double beckmann(double nh, double m) {
  if (!(nh > 0.0)) return 0.0;
  const double c2 = nh * nh;
  const double tan2 = (1.0 - c2) / c2;  // tan^2(arccos(N.H))
  return std::exp(-tan2 / (m * m)) / (m * m * c2 * c2);
}

double geometricAttenuation(double nh, double nv, double nl, double vh) {
  if (!(vh > 0.0)) return 0.0;
  return std::min({1.0, 2.0 * nh * nv / vh, 2.0 * nh * nl / vh});
}

int fresnelIndex(double vh) {
  // CGL-Q101: "arccos(V.H) / (33 pi) coerced to an integer" read as
  // int(theta * 130 / pi): 90 degrees -> 65.
  const double theta = std::acos(std::clamp(vh, -1.0, 1.0));
  const int j = static_cast<int>(theta * 130.0 / std::numbers::pi);
  return std::clamp(j, 0, kFresnelLast);
}

double fresnelAngle(int j) {
  return j * (std::numbers::pi / 2.0) / kFresnelLast;
}

double effectiveIndex(double normalReflectance) {
  const double s = std::sqrt(normalReflectance);
  return (1.0 + s) / (1.0 - s);
}

double fresnelReflectance(double n, double cosTheta) {
  const double c = std::clamp(cosTheta, 0.0, 1.0);
  if (n == 1.0) return 0.0;  // CGL-Q103: no interface
  const double g = std::sqrt(n * n + c * c - 1.0);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

std::vector<Spectrum> fresnelTable(const Spectrum& normalReflectance) {
  Spectrum n{};
  for (int k = 0; k < kSpectrumSamples; ++k) {
    const double r = normalReflectance[static_cast<std::size_t>(k)];
    if (!(r >= 0.0 && r < 1.0)) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "normal reflectance at %d nm is %g: expected 0 <= R < 1",
                    380 + 10 * k, r);
      throw std::invalid_argument(buf);
    }
    n[static_cast<std::size_t>(k)] = effectiveIndex(r);
  }
  std::vector<Spectrum> table(kFresnelAngles);
  for (int j = 0; j < kFresnelAngles; ++j) {
    const double c = std::cos(fresnelAngle(j));
    for (int k = 0; k < kSpectrumSamples; ++k)
      table[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)] =
          fresnelReflectance(n[static_cast<std::size_t>(k)], c);
  }
  return table;
}

CookTerms cookTerms(const Vec3& n, const Vec3& v, const Vec3& l, double m) {
  CookTerms t;
  t.nl = dot(n, l);
  const Vec3 sum = v + l;
  const double len = length(sum);
  if (!(len > 0.0)) return t;  // V = -L: H undefined, no highlight
  t.h = sum * (1.0 / len);
  t.nh = dot(n, t.h);
  t.vh = dot(v, t.h);
  const double nv = dot(n, v);
  t.d = beckmann(t.nh, m);
  t.g = geometricAttenuation(t.nh, nv, t.nl, t.vh);
  t.fresnel = fresnelIndex(t.vh);
  if (!(t.nl > 0.0) || !(t.vh > 0.0)) return t;
  // G / (N.V) = min{1/(N.V), 2(N.H)/(V.H), 2(N.H)(N.L)/((V.H)(N.V))}:
  // finite as N.V -> 0 (CGL-Q104).
  double gOverNv = 2.0 * t.nh / t.vh;
  if (nv > 0.0) {
    gOverNv = std::min({1.0 / nv, gOverNv, gOverNv * t.nl / nv});
    t.s = t.d * t.g / (std::numbers::pi * t.nl * nv);
  }
  t.specular = t.d * gOverNv / std::numbers::pi;
  return t;
}

void addPsi(Spectrum& z, const Spectrum& intensity, double dw, const CookTerms& t, double ks,
            double kd, const Spectrum& colour, const std::vector<Spectrum>& fresnel) {
  if (!(t.nl > 0.0)) return;  // CGL-Q105
  const Spectrum& f = fresnel[static_cast<std::size_t>(t.fresnel)];
  const double spec = ks * t.specular;
  const double diff = kd * t.nl;
  for (int k = 0; k < kSpectrumSamples; ++k) {
    const auto i = static_cast<std::size_t>(k);
    z[i] += intensity[i] * dw * (spec * f[i] + diff * colour[i]);
  }
}

namespace {
void appendVector(std::string& out, const Spectrum& c) {
  char buf[16];
  for (int k = 0; k < kSpectrumSamples; ++k) {
    std::snprintf(buf, sizeof buf, "%.4f", c[static_cast<std::size_t>(k)]);
    out += buf;
    out += (k % 10 == 9 || k + 1 == kSpectrumSamples) ? '\n' : ' ';
  }
}
}  // namespace

std::string cookDescriptorText(const CookDescriptor& d) {
  const std::vector<Spectrum> table = fresnelTable(d.reflectance);
  Spectrum colour{};
  for (int k = 0; k < kSpectrumSamples; ++k)
    colour[static_cast<std::size_t>(k)] =
        d.reflectance[static_cast<std::size_t>(k)] / std::numbers::pi;  // CGL-Q106
  std::string out = "* surface: " + d.name + "\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "%d cook normal %g %g %g\n%g\n", d.count, d.reflect, d.refract,
                d.index, d.diffuse);
  out += buf;
  out += "* normal reflectance vs wavelength (R / pi)\n";
  appendVector(out, colour);
  std::snprintf(buf, sizeof buf, "%g %g\n", d.specular, d.m);
  out += buf;
  out += "* fresnel reflectance vs wavelength & angle (66 angles, j * 90/65 degrees, j = 0..65)\n";
  for (const Spectrum& row : table) appendVector(out, row);
  return out;
}

}  // namespace prime::cgl
