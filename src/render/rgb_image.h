// An unquantised true-colour picture, row by row from the top: what any
// system's render keeps beside its own output (PRIME: the graph file's
// palette indices), for true-colour PNGs and the bench's error metrics.
#pragma once
#include <cstddef>
#include <vector>

#include "src/math/rgb.h"
#include "src/render/picture_buffer.h"

namespace prime {

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
