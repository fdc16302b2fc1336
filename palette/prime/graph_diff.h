// `prime diff`: how two graph files differ, pixel by pixel.
//
// A pixel differs when its raw 16-bit values differ (the file's "index",
// Q12). Its colour difference is the largest per-channel difference, 0..255,
// between the two values' screen colours (`value & 0xFF` through the
// palette); two values can differ and still look the same (-146 and 110 are
// both index 110 on the screen), which the counts tell apart.
#pragma once
#include <cstddef>
#include <string>

#include "legacy_io/prime/graph_file.h"
#include "palette/png_image.h"
#include "palette/prime/dac.h"

namespace prime {

struct GraphDiff {
  bool sameSize = false;  // same pixel grid; nothing else is compared otherwise
  bool sameGraphType = false;
  std::size_t pixels = 0;         // pixels compared
  std::size_t differing = 0;      // raw values differ
  std::size_t lookDifferent = 0;  // ... and their screen colours differ too
  int maxColourDifference = 0;    // 0..255, over all pixels and channels
  int maxX = -1, maxY = -1;       // the first pixel (row by row) with that difference (-1: none)
  int firstX = -1, firstY = -1;   // the first differing pixel (-1: none)

  bool identical() const { return sameSize && sameGraphType && differing == 0; }
  double share() const {
    return pixels ? static_cast<double>(differing) / static_cast<double>(pixels) : 0.0;
  }
};

GraphDiff diffGraphs(const io::GraphFile& a, const io::GraphFile& b, const Rgb8Table& colours);

// The highlight image, one pixel per graph-file pixel (both must be the same
// size): equal pixels as dim grey (64 + luma/4 of A's colour), differing
// pixels whose colours differ in magenta (255, 0, 255), differing pixels that
// look the same on the screen in cyan (0, 255, 255).
Image8 diffImage(const io::GraphFile& a, const io::GraphFile& b, const Rgb8Table& colours);

}  // namespace prime
