// An unquantised true-colour picture, row by row from the top: what any
// system's render keeps beside its own output (PRIME: the graph file's
// palette indices), for true-colour PNGs and the bench's error metrics.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "src/math/rgb.h"
#include "src/render/picture_buffer.h"

namespace prime {

// One channel 0..1 as a byte: rounded to nearest, NaN and below 0 give 0,
// 1 and above 255 (PRIME's true-colour pictures and POV-Ray pigments, CGL's
// window). Malone's PPM rounds as its own document does (legacy_io/malone).
inline std::uint8_t channelByte(double v) {
  if (!(v > 0.0)) return 0;  // also NaN
  if (v >= 1.0) return 255;
  return static_cast<std::uint8_t>(std::lround(v * 255.0));
}
// An RGB colour as 0x00RRGGBB, each channel by channelByte (a window's row).
inline std::uint32_t xrgbOf(const Rgb& c) {
  return static_cast<std::uint32_t>(channelByte(c[0])) << 16 |
         static_cast<std::uint32_t>(channelByte(c[1])) << 8 | channelByte(c[2]);
}

struct RgbImage {
  int width = 0, height = 0;
  // width * height, or empty when not kept (in whole huge pages where the
  // system grants them: LargeBufferAllocator)
  LargeBuffer<Rgb> pixels;

  void assign(int w, int h) {
    width = w;
    height = h;
    pixels.assign(static_cast<std::size_t>(w) * h, Rgb{});
  }
  bool empty() const { return pixels.empty(); }
  Rgb& at(int row, int column) { return pixels[static_cast<std::size_t>(row) * width + column]; }
  const Rgb& at(int row, int column) const {
    return pixels[static_cast<std::size_t>(row) * width + column];
  }
};

}  // namespace prime
