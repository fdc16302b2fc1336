// A Malone scene as POV-Ray 3.7 scene language (`prime export-pov SCENE.mal
// OUT.pov`): every primitive as the POV-Ray object with the same surface
// points, the viewer as a perspective camera whose ray for pixel (X, Y) is
// Malone's, the lights, and a finish per surface. For a modern re-render of a
// scene and for timing this port against POV-Ray on the same geometry
// (bench/malone/pov_compare.sh).
//
// What is exact and what is approximate (docs/malone/benchmarks.md):
//   exact   geometry (sphere, plane, disc, annulus, triangle, parallelogram,
//           polygon, finite open cone and cylinder, torus, affine), the
//           camera rays, the ambient, diffuse and Phong terms of one light,
//           the light spectra, 104's constant intensity, 105's samples,
//           the depth limit (max_trace_level) and the weight cut-off
//           (adc_bailout);
//   close   101's r^-2 law: POV-Ray's fade gives C / (d^2 + f^2) with the
//           fade distance f = 1e-3 (a relative error of f^2/d^2);
//   differs shadows behind a transparent surface (Malone: black, POV-Ray:
//           the light passes, times transmit), total internal reflection
//           (Malone adds k_t to k_s' at the surface, POV-Ray reflects the
//           transmitted share), and a transparent surface's diffuse and
//           ambient terms (POV-Ray scales them by 1 - transmit: the pigment
//           is divided by 1 - k_t to undo it, for k_t < 1).
#pragma once
#include <filesystem>
#include <string>

#include "legacy_io/common/pov_text.h"
#include "src/malone/scene.h"

namespace prime::malone {

struct PovExportOptions {
  int maxDepth = 7;                 // --max-depth: max_trace_level
  double minWeight = 0.01 / 256.0;  // MIN_WEIGHT: adc_bailout
  double fadeDistance = 1e-3;       // 101's r^-2 law through fade_power 2
};

struct PovExport {
  std::string pov;            // the scene file's text
  int width = 0, height = 0;  // +W +H: X_RES, Y_RES
  int objects = 0;            // POV-Ray objects written (a mesh counts once)
  int lights = 0;             // light_source statements (a 105 light gives its samples)
};

// The perspective camera whose ray for pixel (X, Y) of an X_RES x Y_RES image
// is Malone's ray through e + (l-e)/|l-e| + alpha x + beta y,
// alpha = (2X - X_RES)/X_RES, beta = -(2Y - Y_RES)/Y_RES.
struct PovCamera {
  Vec3 location{}, direction{}, right{}, up{};
};
PovCamera povCamera(const Viewer& viewer);

// Shortest decimal that reads back as the same double; -0 as 0.
// POV-Ray text: the shared writers (legacy_io/common/pov_text.h).
using prime::povNumber;
using prime::povVector;

// One primitive's geometry, without its texture (an affine primitive's
// embedded one with its matrix). Meshes are the exporter's: a single
// triangle here is a `triangle`.
std::string povGeometry(const Scene& scene, const Primitive& p);

// The texture { pigment finish } of a surface, and its interior when k_t > 0.
std::string povMaterial(const Surface& s);

PovExport exportPov(const Scene& scene, const PovExportOptions& options = {});

// Writes the text through a temporary file renamed into place; throws
// std::runtime_error naming the file on failure.
void writePovFile(const std::string& text, const std::filesystem::path& file);

}  // namespace prime::malone
