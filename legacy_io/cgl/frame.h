// The Waterloo CGL package's pictures (Sweeney 1985, Appendix 1 section 5 and
// Appendix 3): a 512 x 512 frame of 32-bit pixel words, low 8 bits red, then
// green, then blue, the top 8 unused; written either run-length encoded
// (`-Dencode`: each word's high 8 bits count the pixels that follow in the
// colour of its low 24 bits, each scanline encoded separately) or raw (the
// frame buffer image). Texture maps are RLE files too (section 10).
//
// The manual leaves the count convention, the byte order and the window's
// storage open; the port's choices (docs/cgl/deviations.md): the count is the
// number of pixels (1..255; 0 is refused: CGL-Q23), words are little-endian
// (the VAX's order) with no header (CGL-Q24), scanlines from the top (511)
// down (left to right within each), and both files always hold the whole padded
// 512 x 512 frame (CGL-Q25). docs/cgl/picture-files.md has an example.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "src/render/picture_buffer.h"
#include "src/render/rgb_image.h"

namespace prime::cgl {

struct Frame {
  static constexpr int kSize = 512;
  // kSize * kSize words, index (kSize - 1 - scanline) * kSize + x: the first
  // row held is scanline 511, the top of the picture.
  // (Allocated in whole huge pages where the system grants them: see
  // LargeBufferAllocator.)
  using Words = LargeBuffer<std::uint32_t>;
  Words words = Words(kSize * kSize, 0u);

  std::uint32_t& at(int scanline, int x) {
    return words[static_cast<std::size_t>(kSize - 1 - scanline) * kSize + x];
  }
  std::uint32_t at(int scanline, int x) const {
    return words[static_cast<std::size_t>(kSize - 1 - scanline) * kSize + x];
  }
};

inline std::uint32_t packPixel(int red, int green, int blue) {
  return static_cast<std::uint32_t>(red & 0xff) | static_cast<std::uint32_t>(green & 0xff) << 8 |
         static_cast<std::uint32_t>(blue & 0xff) << 16;
}
inline int redOf(std::uint32_t w) {
  return static_cast<int>(w & 0xff);
}
inline int greenOf(std::uint32_t w) {
  return static_cast<int>(w >> 8 & 0xff);
}
inline int blueOf(std::uint32_t w) {
  return static_cast<int>(w >> 16 & 0xff);
}

// RLE: encode a whole frame; decode bytes (`display` names them in errors,
// with the byte offset of the bad word: a zero count, a run crossing the end
// of a scanline, a truncated word, too few or too many scanlines).
std::vector<std::uint8_t> encodeRle(const Frame& frame);
Frame decodeRle(const std::vector<std::uint8_t>& bytes, const std::string& display);
// Raw: 512 * 512 little-endian words, top scanline first (exactly 1 MiB); the
// words are kept whole, the unused top byte too. encodeRle drops that byte.
std::vector<std::uint8_t> encodeRaw(const Frame& frame);
Frame decodeRaw(const std::vector<std::uint8_t>& bytes, const std::string& display);

// Files: written atomically through legacy_io/common/output_file.h; read with
// a size cap (RLE 4 MiB, raw exactly 1 MiB; a larger file is refused unread).
// Throw io::InputError (reading) or std::runtime_error (writing).
void writeRleFile(const std::string& path, const Frame& frame);
void writeRawFile(const std::string& path, const Frame& frame);
Frame readRleFile(const std::string& path);
Frame readRawFile(const std::string& path);

// The frame as true colour (each byte / 255, row 0 at the top), for PNG, the
// window and PRIME's 8514/A view.
RgbImage toRgbImage(const Frame& frame);

}  // namespace prime::cgl
