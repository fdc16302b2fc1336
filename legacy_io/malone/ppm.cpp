#include "legacy_io/malone/ppm.h"

#include <cmath>
#include <string>

#include "legacy_io/common/bytes.h"

namespace prime::malone {

std::uint8_t toByte(double v) {
  if (!(v > 0)) return 0;  // NaN and negatives: 0
  if (v >= 1) return 255;
  return static_cast<std::uint8_t>(static_cast<int>(255.0 * v + 0.5));
}

std::vector<std::uint8_t> ppmBytes(const RgbImage& raster) {
  const std::string header =
      "P6\n" + std::to_string(raster.width) + " " + std::to_string(raster.height) + "\n255\n";
  std::vector<std::uint8_t> out(header.begin(), header.end());
  out.reserve(out.size() + raster.pixels.size() * 3);
  for (const Rgb& c : raster.pixels)
    for (int k = 0; k < 3; ++k) out.push_back(toByte(c[k]));
  return out;
}

void writePpm(const std::string& path, const RgbImage& raster) {
  io::writeFileAtomically(path, ppmBytes(raster));
}

RgbImage readPpm(const std::string& path) {
  const std::vector<std::uint8_t> bytes = io::readFileBytes(path);
  std::size_t pos = 0;
  auto fail = [&](const std::string& field, const std::string& expected, const std::string& found) {
    throw io::InputError({path, std::nullopt, pos}, field, expected, found);
  };
  auto word = [&](const std::string& field) {
    while (pos < bytes.size() && std::isspace(bytes[pos])) ++pos;
    std::string w;
    while (pos < bytes.size() && !std::isspace(bytes[pos]) && w.size() < 16)
      w += static_cast<char>(bytes[pos++]);
    if (w.empty()) fail(field, "a value", "end of file");
    return w;
  };
  auto integer = [&](const std::string& field, long lo, long hi) {
    const std::string w = word(field);
    char* end = nullptr;
    const long v = std::strtol(w.c_str(), &end, 10);
    if (*end != '\0' || v < lo || v > hi)
      fail(field, "an integer from " + std::to_string(lo) + " to " + std::to_string(hi),
           "'" + w + "'");
    return static_cast<int>(v);
  };
  if (word("magic") != "P6") fail("magic", "P6 (binary PPM)", "something else");
  RgbImage image;
  const int w = integer("width", 1, 65535), h = integer("height", 1, 65535);
  if (integer("maxval", 255, 255) != 255) fail("maxval", "255", "other");
  ++pos;  // the one whitespace byte after maxval
  const std::size_t need = static_cast<std::size_t>(w) * h * 3;
  if (bytes.size() < pos + need)
    fail("pixels", std::to_string(need) + " bytes",
         std::to_string(bytes.size() - std::min(pos, bytes.size())) + " bytes");
  image.assign(w, h);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int k = 0; k < 3; ++k) image.pixels[i][k] = bytes[pos + 3 * i + k] / 255.0;
  return image;
}

}  // namespace prime::malone
