// The quantizers of thesis 4.4 for every system's commands (palette/quantize):
// `--quantize METHOD [--dither D]` on `prime trace` (PRIME, CGL, Malone), and
// the methods of `prime quantize`, including the two that are not ours: the
// listing's fixed palette (ColorNum, the baseline) and libimagequant (the
// reference). docs/prime/quantization.md.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "palette/png_image.h"
#include "palette/quantize/quantize.h"

namespace prime::cli {

struct QuantizeOptions {
  std::string method;  // empty: no quantization
  std::string dither = "none";
  int colours = 256;
};

// --quantize METHOD (popularity, median-cut, octree), --dither D,
// --colours N (`what` names the output that is quantized).
void addQuantizeOptions(CLI::App* cmd, QuantizeOptions& o, const std::string& what);
quantize::Settings settingsOf(const QuantizeOptions& o);  // 6-bit DAC
// `image` through --quantize and --dither as the DAC would show it; `image`
// itself when --quantize is not given.
Image8 quantizedImage(const Image8& image, const QuantizeOptions& o);

// Every method `prime quantize` knows: ours, "listing" (ColorNum and the
// listing's DAC, the 1991 baseline) and "libimagequant" (the reference).
quantize::Result quantizeBy(const Image8& image, const std::string& method, quantize::Dither dither,
                            int colours);

}  // namespace prime::cli
