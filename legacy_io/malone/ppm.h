// raster2ppm: the raster as a binary PPM (P6, maxval 255), rows from the
// top, each channel round(255 * clamp(v, 0, 1)) (MAL-Q7). The file is
// written through a temporary and renamed, so an error never leaves half a
// picture.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "src/render/rgb_image.h"

namespace prime::malone {

// One channel as a byte.
std::uint8_t toByte(double v);
std::vector<std::uint8_t> ppmBytes(const RgbImage& raster);
void writePpm(const std::string& path, const RgbImage& raster);

// Reads a P6 file with maxval 255 (for tests and `prime diff`); throws
// io::InputError.
RgbImage readPpm(const std::string& path);

}  // namespace prime::malone
