// The CGL package's colour conversions (Sweeney 1985, sections 9.1 and 10).
// Every table and matrix is a constant: nothing here allocates or reads a file
// except colourVectorText, so ToRGB and the texture lookup are cheap per ray.
#include "src/cgl/colour.h"

#include <cmath>
#include <cstdio>

namespace prime::cgl {
namespace {

// CIE 1931 2-degree standard colorimetric observer: x-bar, y-bar, z-bar at
// 380, 390, ..., 700 nm, the 10 nm rows of CIE 15:2004 Table T.4 (the same
// values as Wyszecki & Stiles, Color Science, 2nd ed. 1982, Table I(3.3.1)).
// The document used the 5 nm table of the Handbook of Optics (1972, p. 6-189)
// at 10 nm and cut at 700 nm (section 9.1); that is the 1931 observer too, but
// its printed digits are not available to us (CGL-Q20).
constexpr std::array<std::array<double, 3>, kSpectrumSamples> kCie1931 = {{
    {0.001368, 0.000039, 0.006450},  // 380
    {0.004243, 0.000120, 0.020050},  // 390
    {0.014310, 0.000396, 0.067850},  // 400
    {0.043510, 0.001210, 0.207400},  // 410
    {0.134380, 0.004000, 0.645600},  // 420
    {0.283900, 0.011600, 1.385600},  // 430
    {0.348280, 0.023000, 1.747060},  // 440
    {0.336200, 0.038000, 1.772110},  // 450
    {0.290800, 0.060000, 1.669200},  // 460
    {0.195360, 0.090980, 1.287640},  // 470
    {0.095640, 0.139020, 0.812950},  // 480
    {0.032010, 0.208020, 0.465180},  // 490
    {0.004900, 0.323000, 0.272000},  // 500
    {0.009300, 0.503000, 0.158200},  // 510
    {0.063270, 0.710000, 0.078250},  // 520
    {0.165500, 0.862000, 0.042160},  // 530
    {0.290400, 0.954000, 0.020300},  // 540
    {0.433450, 0.994950, 0.008750},  // 550
    {0.594500, 0.995000, 0.003900},  // 560
    {0.762100, 0.952000, 0.002100},  // 570
    {0.916300, 0.870000, 0.001650},  // 580
    {1.026300, 0.757000, 0.001100},  // 590
    {1.062200, 0.631000, 0.000800},  // 600
    {1.002600, 0.503000, 0.000340},  // 610
    {0.854450, 0.381000, 0.000190},  // 620
    {0.642400, 0.265000, 0.000050},  // 630
    {0.447900, 0.175000, 0.000020},  // 640
    {0.283500, 0.107000, 0.000000},  // 650
    {0.164900, 0.061000, 0.000000},  // 660
    {0.087400, 0.032000, 0.000000},  // 670
    {0.046770, 0.017000, 0.000000},  // 680
    {0.022700, 0.008210, 0.000000},  // 690
    {0.011359, 0.004102, 0.000000},  // 700
}};

constexpr double kTristimulusScale = 1360.0;  // section 9.1
constexpr double kMonitorScale = 15.0;        // sections 9.1 and 10

// Columns: the chromaticities (x, y, z) of the red, green and blue phosphors.
// Electrohome ECM 1301: section 9.1 as printed (each column sums to 1).
constexpr Matrix3 kElectrohome = {{
    {0.62, 0.21, 0.15},
    {0.33, 0.675, 0.06},
    {0.05, 0.115, 0.79},
}};
// NTSC (Appendix 3's `ntsc` option; the matrix is not printed): the 1953 NTSC
// primaries R (0.67, 0.33), G (0.21, 0.71), B (0.14, 0.08), z = 1 - x - y,
// in the same form as the Electrohome matrix (CGL-Q21).
constexpr Matrix3 kNtsc = {{
    {0.67, 0.21, 0.14},
    {0.33, 0.71, 0.08},
    {0.00, 0.08, 0.78},
}};

constexpr double determinant(const Matrix3& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The adjugate over the determinant.
constexpr Matrix3 inverse(const Matrix3& m) {
  const double d = determinant(m);
  Matrix3 r{};
  r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / d;
  r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / d;
  r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / d;
  r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / d;
  r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / d;
  r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / d;
  r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / d;
  r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / d;
  r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / d;
  return r;
}

constexpr Matrix3 kElectrohomeInverse = inverse(kElectrohome);
constexpr Matrix3 kNtscInverse = inverse(kNtsc);

// Section 10's three samples, "the maxima of the colour matching functions".
constexpr int kSample450 = (450 - 380) / 10;  // 7
constexpr int kSample550 = (550 - 380) / 10;  // 17
constexpr int kSample600 = (600 - 380) / 10;  // 22

// The system X = 1360 (D_450 x_450 + D_550 x_550 + D_600 x_600), Y, Z: row k
// is the tristimulus value, column j the sample.
constexpr Matrix3 cramerSystem() {
  Matrix3 a{};
  const int samples[3] = {kSample450, kSample550, kSample600};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) a[k][j] = kTristimulusScale * kCie1931[samples[j]][k];
  return a;
}
constexpr Matrix3 kCramer = cramerSystem();
constexpr double kCramerDeterminant = determinant(kCramer);
static_assert(kCramerDeterminant * kCramerDeterminant > 1e12,
              "section 10's system is far from singular");

}  // namespace

const std::array<std::array<double, 3>, kSpectrumSamples>& colourMatching() {
  return kCie1931;
}

const Matrix3& phosphorMatrix(Phosphors phosphors) {
  return phosphors == Phosphors::Ntsc ? kNtsc : kElectrohome;
}

const Matrix3& inversePhosphorMatrix(Phosphors phosphors) {
  return phosphors == Phosphors::Ntsc ? kNtscInverse : kElectrohomeInverse;
}

Xyz spectrumToXyz(const Spectrum& c) {
  double x = 0, y = 0, z = 0;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    x += c[i] * kCie1931[i][0];
    y += c[i] * kCie1931[i][1];
    z += c[i] * kCie1931[i][2];
  }
  return {kTristimulusScale * x, kTristimulusScale * y, kTristimulusScale * z};
}

std::array<double, 3> xyzToMonitor(const Xyz& xyz, Phosphors phosphors) {
  const Matrix3& m = inversePhosphorMatrix(phosphors);
  std::array<double, 3> rgb{};
  for (int k = 0; k < 3; ++k)
    rgb[k] = (m[k][0] * xyz.x + m[k][1] * xyz.y + m[k][2] * xyz.z) / kMonitorScale;
  return rgb;
}

int toChannel(double v) {
  // Section 9.1: "simply clipped to be within the range [0,255]", then stored
  // in 8 bits: a C (int) conversion, which truncates toward zero (CGL-Q22). NaN (which C
  // leaves undefined) is taken as 0 (CGL-D20).
  if (!(v > 0)) return 0;
  if (v >= 255) return 255;
  return static_cast<int>(v);
}

Rgb8 toRgb(const Spectrum& c, Phosphors phosphors) {
  const std::array<double, 3> rgb = xyzToMonitor(spectrumToXyz(c), phosphors);
  return {toChannel(rgb[0]), toChannel(rgb[1]), toChannel(rgb[2])};
}

Spectrum rgbToSpectrum(const Rgb8& rgb, Phosphors phosphors) {
  const Matrix3& m = phosphorMatrix(phosphors);
  const double in[3] = {static_cast<double>(rgb.r), static_cast<double>(rgb.g),
                        static_cast<double>(rgb.b)};
  double xyz[3];
  for (int k = 0; k < 3; ++k)
    xyz[k] = kMonitorScale * (m[k][0] * in[0] + m[k][1] * in[1] + m[k][2] * in[2]);
  // Cramer's rule: D_j = det(A with column j replaced by (X Y Z)) / det(A).
  Spectrum d{};
  const int samples[3] = {kSample450, kSample550, kSample600};
  for (int j = 0; j < 3; ++j) {
    Matrix3 a = kCramer;
    for (int k = 0; k < 3; ++k) a[k][j] = xyz[k];
    d[samples[j]] = determinant(a) / kCramerDeterminant;
  }
  return d;
}

std::string colourVectorText(const Spectrum& c) {
  std::string out;
  char buffer[32];
  for (int i = 0; i < kSpectrumSamples; ++i) {
    std::snprintf(buffer, sizeof buffer, "%.6g", c[i]);
    out += buffer;
    out += (i % 10 == 9 || i == kSpectrumSamples - 1) ? '\n' : ' ';
  }
  return out;
}

}  // namespace prime::cgl
