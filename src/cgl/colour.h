// The CGL package's colour (Sweeney 1985, sections 9.1 and 10): spectra of 33
// samples (380-700 nm every 10 nm) turned into CIE XYZ with the 1931 2-degree
// colour-matching functions and the factor 1360, then into monitor RGB with
// (1/15) M^-1, M the Electrohome ECM 1301's phosphor chromaticities (or the
// NTSC ones: the `ntsc` compile option), clipped to 0..255 and truncated as C
// does; and back (a texture's RGB to a spectrum with only its 450, 550 and
// 600 nm samples set, by Cramer's rule). docs/cgl/colour.md shows the numbers.
#pragma once
#include <array>
#include <string>

#include "legacy_io/cgl/scene_file.h"

namespace prime::cgl {

enum class Phosphors { Electrohome, Ntsc };

struct Xyz {
  double x = 0, y = 0, z = 0;
};
struct Rgb8 {
  int r = 0, g = 0, b = 0;  // 0..255
  bool operator==(const Rgb8&) const = default;
};

using Matrix3 = std::array<std::array<double, 3>, 3>;

// CIE 1931 2-degree observer, x-bar, y-bar, z-bar at 380, 390, ..., 700 nm
// (CIE 15:2004 Table T.4, its 10 nm rows; CGL-Q20).
const std::array<std::array<double, 3>, kSpectrumSamples>& colourMatching();

// M: rows X, Y, Z; columns the red, green and blue phosphors' chromaticities
// (x, y, z). Electrohome as printed in section 9.1; NTSC the 1953 primaries
// (CGL-Q21). And its inverse.
const Matrix3& phosphorMatrix(Phosphors phosphors);
const Matrix3& inversePhosphorMatrix(Phosphors phosphors);

// 1360 * sum over the 33 samples of c * (x-bar, y-bar, z-bar).
Xyz spectrumToXyz(const Spectrum& c);
// (1/15) M^-1 (X Y Z), unclipped.
std::array<double, 3> xyzToMonitor(const Xyz& xyz, Phosphors phosphors);
// One channel as ToRGB stores it: clipped to [0, 255], then truncated toward
// zero as C's (int) cast does (CGL-Q22); NaN gives 0 (CGL-D20).
int toChannel(double v);
// ToRGB: xyzToMonitor(spectrumToXyz(c)), each channel through toChannel.
Rgb8 toRgb(const Spectrum& c, Phosphors phosphors);
// Section 10: (X Y Z) = 15 M (r g b), then D_450, D_550, D_600 from
// X = 1360 (D_450 x_450 + D_550 x_550 + D_600 x_600) (and Y, Z likewise); every
// other sample 0. Samples may come out negative (section 10 does not clip them).
Spectrum rgbToSpectrum(const Rgb8& rgb, Phosphors phosphors);

// The package's `tovector r g b` utility (Appendix 1, "Utilities"): the colour-
// vector of an RGB triple as a scene file writes one, 3 lines of 10 numbers and
// a line of 3, each number "%.6g" and the lines ending in '\n'.
std::string colourVectorText(const Spectrum& c);

}  // namespace prime::cgl
