// The CGL package's colour (Sweeney 1985, sections 9.1 and 10): spectra of 33
// samples (380-700 nm every 10 nm) turned into CIE XYZ with the 1931 2-degree
// colour-matching functions and the factor 1360, then into monitor RGB with
// (1/15) M^-1, M the Electrohome ECM 1301's phosphor chromaticities (or the
// NTSC ones: the `ntsc` compile option), clipped to 0..255 and truncated as C
// does; and back (a texture's RGB to a spectrum with only its 450, 550 and
// 600 nm samples set, by Cramer's rule).
#pragma once
#include <array>

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

// CIE 1931 2-degree observer, x-bar, y-bar, z-bar at 380, 390, ..., 700 nm.
const std::array<std::array<double, 3>, kSpectrumSamples>& colourMatching();

// 1360 * sum over the 33 samples of c * (x-bar, y-bar, z-bar).
Xyz spectrumToXyz(const Spectrum& c);
// (1/15) M^-1 (X Y Z), unclipped.
std::array<double, 3> xyzToMonitor(const Xyz& xyz, Phosphors phosphors);
// ToRGB: the above, each channel clipped to [0, 255] and truncated.
Rgb8 toRgb(const Spectrum& c, Phosphors phosphors);
// Section 10: (X Y Z) = 15 M (r g b), then D_450, D_550, D_600 from
// X = 1360 (D_450 x_450 + D_550 x_550 + D_600 x_600) (and Y, Z likewise); every
// other sample 0.
Spectrum rgbToSpectrum(const Rgb8& rgb, Phosphors phosphors);

}  // namespace prime::cgl
