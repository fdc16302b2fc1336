// The Waterloo CGL package's probe of one screen point, as `prime probe`
// prints it and as a click on a pixel of a `trace` or `walk` window draws it
// (src/cli/overlay.h): the ray tree through the scene's camera, its text,
// JSON and segments.
#pragma once
#include <string>

#include "src/cgl/render.h"
#include "src/cli/overlay.h"

namespace prime::cli::cgl {

// The screen point (x, y): 0..512 from the bottom left (a pixel's ray goes
// through its corner, Figure 41); `file` and `where` as the text says them.
ProbedPixel probePoint(const prime::cgl::Scene& scene, const prime::cgl::RenderSettings& settings,
                       const std::string& file, const std::string& where, double x, double y);

}  // namespace prime::cli::cgl
