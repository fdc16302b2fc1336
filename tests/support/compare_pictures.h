// Two pictures compared pixel for pixel, for the replay tests of every
// system: "" when they are the same, else their sizes or how many pixels
// differ and where the first one is.
#pragma once
#include <string>

#include "palette/png_image.h"

namespace prime::test {

inline std::string comparePictures(const Image8& got, const Image8& want) {
  if (got.width != want.width || got.height != want.height)
    return "size " + std::to_string(got.width) + "x" + std::to_string(got.height) + ", golden " +
           std::to_string(want.width) + "x" + std::to_string(want.height);
  long differ = 0, first = -1;
  for (std::size_t i = 0; i + 2 < got.rgb.size(); i += 3)
    if (got.rgb[i] != want.rgb[i] || got.rgb[i + 1] != want.rgb[i + 1] ||
        got.rgb[i + 2] != want.rgb[i + 2]) {
      if (first < 0) first = static_cast<long>(i / 3);
      ++differ;
    }
  if (differ == 0) return "";
  return std::to_string(differ) + " pixels differ, the first at (" +
         std::to_string(first % got.width) + ", " + std::to_string(first / got.width) + ")";
}

}  // namespace prime::test
