// PRIME's probe of one primary ray, as `prime probe` prints it and as a click
// on a pixel of a `trace`, `walk` or `view --scene` window draws it
// (src/cli/overlay.h): the ray tree under the settings' profile, its text,
// its JSON and its segments, projected by the settings' camera.
#pragma once
#include <string>

#include "src/cli/overlay.h"
#include "src/prime/render/camera.h"
#include "src/prime/render/renderer.h"

namespace prime::cli {

// `column`, `row`: the pixel `r` is the primary ray of (-1 for a --ray).
ProbedPixel probePixel(const Scene& scene, const RenderSettings& settings, const Ray& r,
                       const std::string& where, int column, int row);
// "pixel X Y (screen SX, SY)".
std::string pixelWhere(const PrimeCamera& camera, int x, int y);

}  // namespace prime::cli
