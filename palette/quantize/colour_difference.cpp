#include "palette/quantize/colour_difference.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <unordered_map>

namespace prime::quantize {

namespace {

// The sRGB transfer curve inverted: 8-bit code -> linear light, as a table.
const std::array<double, 256>& linearTable() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double v = i / 255.0;
      t[static_cast<std::size_t>(i)] =
          v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    }
    return t;
  }();
  return table;
}

double labF(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
}

double degrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}
double radians(double deg) {
  return deg * std::numbers::pi / 180.0;
}

}  // namespace

Lab srgbToLab(std::uint8_t r8, std::uint8_t g8, std::uint8_t b8) {
  const auto& lin = linearTable();
  const double r = lin[r8], g = lin[g8], b = lin[b8];
  // IEC 61966-2-1 RGB -> XYZ (D65).
  const double x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
  const double fx = labF(x / 0.95047), fy = labF(y / 1.0), fz = labF(z / 1.08883);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab& p, const Lab& q) {
  // Sharma, Wu and Dalal 2005, equations (2)-(22).
  const double c1 = std::hypot(p.a, p.b), c2 = std::hypot(q.a, q.b);
  const double cBar = (c1 + c2) / 2;
  const double cBar7 = std::pow(cBar, 7);
  const double g = 0.5 * (1 - std::sqrt(cBar7 / (cBar7 + 6103515625.0)));  // 25^7
  const double a1 = (1 + g) * p.a, a2 = (1 + g) * q.a;
  const double c1p = std::hypot(a1, p.b), c2p = std::hypot(a2, q.b);
  const auto hue = [](double b, double a) {
    if (b == 0 && a == 0) return 0.0;
    const double h = degrees(std::atan2(b, a));
    return h < 0 ? h + 360 : h;
  };
  const double h1 = hue(p.b, a1), h2 = hue(q.b, a2);
  const double dL = q.L - p.L, dC = c2p - c1p;
  double dh = 0;
  if (c1p * c2p != 0) {
    dh = h2 - h1;
    if (dh > 180)
      dh -= 360;
    else if (dh < -180)
      dh += 360;
  }
  const double dH = 2 * std::sqrt(c1p * c2p) * std::sin(radians(dh / 2));
  const double lBar = (p.L + q.L) / 2, cBarP = (c1p + c2p) / 2;
  double hBar = h1 + h2;
  if (c1p * c2p != 0) {
    if (std::abs(h1 - h2) <= 180)
      hBar /= 2;
    else
      hBar = hBar < 360 ? (hBar + 360) / 2 : (hBar - 360) / 2;
  }
  const double t = 1 - 0.17 * std::cos(radians(hBar - 30)) + 0.24 * std::cos(radians(2 * hBar)) +
                   0.32 * std::cos(radians(3 * hBar + 6)) - 0.20 * std::cos(radians(4 * hBar - 63));
  const double dTheta = 30 * std::exp(-std::pow((hBar - 275) / 25, 2));
  const double cBarP7 = std::pow(cBarP, 7);
  const double rc = 2 * std::sqrt(cBarP7 / (cBarP7 + 6103515625.0));
  const double l50 = (lBar - 50) * (lBar - 50);
  const double sl = 1 + 0.015 * l50 / std::sqrt(20 + l50);
  const double sc = 1 + 0.045 * cBarP;
  const double sh = 1 + 0.015 * cBarP * t;
  const double rt = -std::sin(radians(2 * dTheta)) * rc;
  const double x = dL / sl, y = dC / sc, z = dH / sh;
  return std::sqrt(x * x + y * y + z * z + rt * y * z);
}

ImageError compareImages(const Image8& reference, const Image8& test) {
  if (reference.width != test.width || reference.height != test.height ||
      reference.rgb.size() != test.rgb.size())
    throw std::invalid_argument("compareImages: the two images differ in size");
  ImageError e;
  const std::size_t n = reference.rgb.size() / 3;
  if (n == 0) return e;
  // Renders repeat colour pairs a lot: remember each pair's difference.
  std::unordered_map<std::uint64_t, double> seen;
  double sum = 0, squares = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* a = &reference.rgb[3 * i];
    const std::uint8_t* b = &test.rgb[3 * i];
    for (int c = 0; c < 3; ++c) {
      const double d = static_cast<double>(a[c]) - b[c];
      squares += d * d;
    }
    const std::uint64_t key = (std::uint64_t{a[0]} << 40) | (std::uint64_t{a[1]} << 32) |
                              (std::uint64_t{a[2]} << 24) | (std::uint64_t{b[0]} << 16) |
                              (std::uint64_t{b[1]} << 8) | b[2];
    auto [it, fresh] = seen.try_emplace(key, 0.0);
    if (fresh) it->second = ciede2000(srgbToLab(a[0], a[1], a[2]), srgbToLab(b[0], b[1], b[2]));
    sum += it->second;
    e.maxDeltaE = std::max(e.maxDeltaE, it->second);
  }
  e.meanDeltaE = sum / static_cast<double>(n);
  const double mse = squares / (3.0 * static_cast<double>(n));
  e.psnr =
      mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
  return e;
}

}  // namespace prime::quantize
