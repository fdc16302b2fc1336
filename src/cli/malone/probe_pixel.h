// Malone's probe of one pixel, as `prime probe` prints it and as a click on a
// pixel of a `trace` or `walk` window draws it (src/cli/overlay.h): the ray
// tree through the scene's viewer, its text, JSON and segments.
#pragma once
#include <string>

#include "src/cli/overlay.h"
#include "src/malone/tracer.h"

namespace prime::cli::malone {

// `file`: the scene as named on the command line (the text's first line).
ProbedPixel probePixel(const prime::malone::Scene& scene, const prime::malone::TraceSettings& trace,
                       const std::string& file, int x, int y);

}  // namespace prime::cli::malone
