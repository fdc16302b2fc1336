// A CGL frame as the bytes a PNG holds: each pixel word's red, green and blue
// (low byte red), rows from the top. For `prime trace --png` and `prime export`.
#pragma once
#include <cstdint>

#include "legacy_io/cgl/frame.h"
#include "palette/png_image.h"

namespace prime::cli::cgl {

inline Image8 frameImage(const prime::cgl::Frame& frame) {
  Image8 img;
  img.width = img.height = prime::cgl::Frame::kSize;
  img.rgb.reserve(frame.words.size() * 3);
  for (std::uint32_t w : frame.words) {
    img.rgb.push_back(static_cast<std::uint8_t>(prime::cgl::redOf(w)));
    img.rgb.push_back(static_cast<std::uint8_t>(prime::cgl::greenOf(w)));
    img.rgb.push_back(static_cast<std::uint8_t>(prime::cgl::blueOf(w)));
  }
  return img;
}

}  // namespace prime::cli::cgl
