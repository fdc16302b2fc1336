// A Waterloo CGL scene (M. A. J. Sweeney, "The Waterloo CGL Ray Tracing
// Package", University of Waterloo CS-85-35, 1985), after Preprocess
// (src/cgl/scene.h), as POV-Ray 3.7 scene language (`prime export-pov
// SCENE.cgl OUT.pov`): for a modern re-render of a scene and for timing the
// port against POV-Ray on the same geometry (bench/cgl/pov_compare.sh,
// docs/cgl/benchmarks.md).
//
// What is exact, close and different (CGL-D60):
//   exact   the geometry, in world space as the object list holds it
//           (spheres, open cylinders, triangles, rectangles: every polygon is
//           the region its edge tests accept); the primary rays (explicit
//           camera vectors, see povCamera); the diffuse and Phong terms and
//           the reflected and transmitted shares (k_r R, k_t T) of the
//           scene's main light, before ToRGB's clip; shadows (transparent
//           objects cast none: `no_shadow`) and `shadowless` lights when the
//           shadows parameter is off; the depth limit (max_trace_level =
//           depth + 1); no weight cut-off (adc_bailout 0); the texture
//           mappings, which are all affine projections (a planar image_map
//           with a matrix) up to the texel rounding at texel edges;
//   close   colour: spectra become RGB under the main light (see
//           pigmentUnder), exact for that light and approximate for lights
//           of another spectrum; the improved ambience k_a((N.V)+0.5) I_a pi
//           D is the constant `ambient` of PovExportOptions::ambientFactor
//           (N.V is not available to POV-Ray's ambient); POV-Ray rounds a
//           channel to 8 bits, ToRGB truncates;
//   differs a cylinder seen through its open end (CGL-Q46: the port keeps the
//           document's miss, POV-Ray shows the inside), total internal
//           reflection (CGL-Q45: the background times k_t; POV-Ray reflects
//           the transmitted share), a ray stopped by the depth limit
//           (CGL-E42: k_r and k_t times the background; POV-Ray's is black,
//           the same for the shipped scenes, whose background is black),
//           anti-aliasing (Subdivid's corner table against POV-Ray's method
//           1, see PovExport::povArgs); Cook-Torrance surfaces, approximated
//           by a metallic highlight and a coloured reflection (CGL-D101).
// Super boxes are not written: POV-Ray bounds every object itself (its own
// bounding hierarchy), so a box would only add a test.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "legacy_io/cgl/frame.h"
#include "legacy_io/common/pov_text.h"
#include "src/cgl/scene.h"

namespace prime::cgl {

struct PovExportOptions {
  ProgramParameters program;  // depth, shadows, background, window, aalevel, aathreshold
  Phosphors phosphors = Phosphors::Electrohome;
  // Texture images are written beside the .pov as <stem>-texture<k>.png.
  std::string textureStem = "scene";
  // k_a((N.V) + 0.5) with N.V in [0, 1] becomes a constant: 1.0, the middle
  // of its range 0.5..1.5 (a sphere's disc averages 1.17).
  double ambientFactor = 1.0;
};

// A texture map as POV-Ray reads it: an 8-bit PNG (the caller writes `frame`
// to `file`, beside the .pov), each channel the texel's pigment (see
// pigmentUnder) divided by `scale` (the largest channel of any texel, at
// least 1) and clamped to 0..255; the finish multiplies `scale` back.
struct PovImage {
  std::string file;  // a base name: <stem>-texture<k>.png
  Frame frame;       // row 0 (the frame's top scanline) is the image's top row
  double scale = 1.0;
};

struct PovExport {
  std::string pov;  // the scene file's text
  std::vector<PovImage> images;
  // The command-line options that go with the file: +W512 +H512, the
  // window (+SC/+EC/+SR/+ER as fractions) and the anti-aliasing (-A, or
  // +A<aathreshold/255> +AM1 +R<aalevel + 1>).
  std::string povArgs;
  int objects = 0;       // POV-Ray objects written
  int lights = 0;        // light_source statements
  int boxesOmitted = 0;  // super boxes not written
  int mainLight = -1;    // the light whose spectrum the colours are taken under (-1: none)
};

// The camera whose ray for an image pixel is the CGL ray (Figure 40, section
// 8.2): location V, right = 512 X, up = 512 Y, and direction S, or S - X/2 -
// Y/2 when `pixelCorners`. POV-Ray shoots pixel column i, row r (from the
// top) through direction + ((i + 0.5)/512 - 0.5) right + (0.5 - (r + 0.5)/512)
// up: the centre of the pixel square that CGL's anti-aliasing subdivides
// (corners x..x+1, y..y+1 with y = 511 - r). Without anti-aliasing (aalevel
// 0) CGL traces the pixel's corner (x, y) itself, half a pixel left and down:
// `pixelCorners` moves the direction by that half pixel. POV-Ray uses
// explicit vectors as given; CGL's screen-right is up x sight in a
// left-handed space, as POV-Ray's.
struct PovCamera {
  Vec3 location{}, direction{}, right{}, up{};
};
PovCamera povCamera(const Camera& camera, bool pixelCorners);

// The linear monitor RGB of a spectrum on POV-Ray's scale (ToRGB's
// (1/15) M^-1 (X Y Z) divided by 255, unclipped).
Rgb povRgb(const Spectrum& c, Phosphors phosphors);

// A reflectance D as a POV-Ray pigment under the spectrum `light`: per
// channel L(D * light) / L(light), L = povRgb, so that pigment * povRgb(light)
// is exactly the RGB of D * light (what CGL's diffuse term adds for that
// light before ToRGB's clip). A channel the light lacks (L(light) <= 0)
// gives 0.
Rgb pigmentUnder(const Spectrum& reflectance, const Spectrum& light, Phosphors phosphors);

// A polygon object's corners: the region its edge tests accept (section
// 4.2), corner k the meeting point of edge k - 1 and edge k in the plane.
std::array<Vec3, 4> polygonCorners(const Object& polygon);

// Shortest decimal that reads back as the same double; -0 and non-finite
// values as 0.
// POV-Ray text: the shared writers (legacy_io/common/pov_text.h).
using prime::povNumber;
using prime::povVector;

// One object node's geometry (no texture); "" for a box.
std::string povGeometry(const Object& object);

PovExport exportPov(const Scene& scene, const PovExportOptions& options);

}  // namespace prime::cgl
