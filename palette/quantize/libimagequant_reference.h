// libimagequant (pngquant's library, Debian libimagequant-dev) as the
// reference a user would pick, for comparison only (`prime quantize --method
// libimagequant`, docs/prime/quantization.md): its palette is asked for
// 6-bit precision (liq_set_min_posterization 2) and then taken to the
// nearest DAC levels, so the picture is one the same DAC could show (T58).
#pragma once
#include "palette/quantize/quantize.h"

namespace prime::quantize {

// `dither`: None or FloydSteinberg (libimagequant's own error diffusion);
// Ordered is std::invalid_argument. Errors of the library are
// std::runtime_error.
Result quantizeWithLibimagequant(const Image8& image, int colours, int dacBits, Dither dither);

}  // namespace prime::quantize
