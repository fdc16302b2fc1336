// The CGL package's pictures (Sweeney 1985, Appendix 1 section 5, "output",
// and Appendix 3, `encode`): the run-length encoded file and the raw frame
// buffer image. The conventions the manual leaves open are docs/cgl/
// deviations.md CGL-Q23 (the count), CGL-Q24 (byte order, no header) and
// CGL-Q25 (scanline order, the whole padded frame); docs/cgl/picture-files.md
// describes both formats with an example.
#include "legacy_io/cgl/frame.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "legacy_io/common/bytes.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"

namespace prime::cgl {
namespace {

constexpr std::size_t kWords = static_cast<std::size_t>(Frame::kSize) * Frame::kSize;
constexpr std::size_t kRawBytes = kWords * 4;  // 1 MiB
constexpr std::uint32_t kColourMask = 0x00ffffffu;
constexpr int kMaxRun = 255;  // the count's 8 bits; 0 is not a count (CGL-Q23)
// Reading: a valid RLE file is at most one word per pixel (1 MiB); anything
// past 4 MiB is refused unread.
constexpr std::uintmax_t kRleFileCap = 4u << 20;

void putWord(std::vector<std::uint8_t>& out, std::uint32_t w) {
  // Little-endian, the VAX's order (CGL-Q24).
  out.push_back(static_cast<std::uint8_t>(w));
  out.push_back(static_cast<std::uint8_t>(w >> 8));
  out.push_back(static_cast<std::uint8_t>(w >> 16));
  out.push_back(static_cast<std::uint8_t>(w >> 24));
}

std::uint32_t getWord(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return static_cast<std::uint32_t>(bytes[at]) | static_cast<std::uint32_t>(bytes[at + 1]) << 8 |
         static_cast<std::uint32_t>(bytes[at + 2]) << 16 |
         static_cast<std::uint32_t>(bytes[at + 3]) << 24;
}

std::string hexWord(std::uint32_t w) {
  static const char* digits = "0123456789abcdef";
  std::string s = "0x";
  for (int shift = 28; shift >= 0; shift -= 4) s += digits[(w >> shift) & 0xf];
  return s;
}

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Reads a whole file of at most `cap` bytes; a larger one, or one that is not
// a regular file, is refused before it is read.
std::vector<std::uint8_t> readCapped(const std::string& path, std::uintmax_t cap,
                                     const char* what) {
  io::InputFileOptions input;
  input.maxBytes = cap;
  input.what = what;
  return io::readInputFile(path, input);
}

}  // namespace

std::vector<std::uint8_t> encodeRle(const Frame& frame) {
  std::vector<std::uint8_t> out;
  out.reserve(Frame::kSize * 4 * 16);
  // Rows as held: the first is scanline 511, the top (CGL-Q25). Each scanline
  // is encoded on its own, so no run crosses the end of a line; a run longer
  // than 255 pixels is split (the count has 8 bits). The unused top byte of a
  // pixel word is not kept.
  for (int row = 0; row < Frame::kSize; ++row) {
    const std::uint32_t* line = frame.words.data() + static_cast<std::size_t>(row) * Frame::kSize;
    int x = 0;
    while (x < Frame::kSize) {
      const std::uint32_t colour = line[x] & kColourMask;
      int n = 1;
      while (x + n < Frame::kSize && n < kMaxRun && (line[x + n] & kColourMask) == colour) ++n;
      putWord(out, static_cast<std::uint32_t>(n) << 24 | colour);
      x += n;
    }
  }
  return out;
}

Frame decodeRle(const std::vector<std::uint8_t>& bytes, const std::string& display) {
  Frame frame;
  auto fail = [&](std::size_t at, const std::string& field, const std::string& expected,
                  const std::string& found) {
    throw io::InputError({display, std::nullopt, at}, field, expected, found);
  };
  int row = 0, x = 0;  // row 0 is scanline 511
  std::size_t at = 0;
  for (; at < bytes.size(); at += 4) {
    if (bytes.size() - at < 4)
      fail(at, "word", "a whole 32-bit word (4 bytes)",
           plural(bytes.size() - at, "byte", "bytes") + " at the end of the file");
    const std::uint32_t w = getWord(bytes, at);
    if (row == Frame::kSize)
      fail(at, "scanlines", "512 scanlines and the end of the file",
           "more words after the last scanline (" + hexWord(w) + ")");
    const int count = static_cast<int>(w >> 24);
    if (count == 0)
      fail(at, "run count", "a count of 1 to 255 pixels in the word's high 8 bits",
           "0 (" + hexWord(w) + ")");
    if (x + count > Frame::kSize)
      fail(at, "run",
           "a run that ends within its scanline (scanline " +
               std::to_string(Frame::kSize - 1 - row) + ", " +
               plural(static_cast<std::size_t>(Frame::kSize - x), "pixel", "pixels") + " left)",
           "a run of " + std::to_string(count) + " from x = " + std::to_string(x));
    std::uint32_t* out = frame.words.data() + static_cast<std::size_t>(row) * Frame::kSize + x;
    for (int i = 0; i < count; ++i) out[i] = w & kColourMask;
    x += count;
    if (x == Frame::kSize) {
      x = 0;
      ++row;
    }
  }
  if (row < Frame::kSize)
    fail(at, "scanlines", "512 scanlines",
         plural(static_cast<std::size_t>(row), "whole scanline", "whole scanlines") +
             (x > 0 ? " and " + plural(static_cast<std::size_t>(x), "pixel", "pixels") +
                          " of the next"
                    : std::string()) +
             " at the end of the file");
  return frame;
}

std::vector<std::uint8_t> encodeRaw(const Frame& frame) {
  std::vector<std::uint8_t> out;
  out.reserve(kRawBytes);
  for (std::uint32_t w : frame.words) putWord(out, w);
  return out;
}

Frame decodeRaw(const std::vector<std::uint8_t>& bytes, const std::string& display) {
  // Always the whole padded frame (CGL-Q25): exactly 512 * 512 * 4 bytes.
  if (bytes.size() != kRawBytes)
    throw io::InputError({display, std::nullopt, std::min(bytes.size(), kRawBytes)}, "file size",
                         std::to_string(kRawBytes) + " bytes (512 x 512 32-bit words)",
                         std::to_string(bytes.size()) + " bytes");
  Frame frame;
  for (std::size_t i = 0; i < kWords; ++i) frame.words[i] = getWord(bytes, 4 * i);
  return frame;
}

void writeRleFile(const std::string& path, const Frame& frame) {
  io::writeFileAtomically(path, encodeRle(frame));
}

void writeRawFile(const std::string& path, const Frame& frame) {
  io::writeFileAtomically(path, encodeRaw(frame));
}

Frame readRleFile(const std::string& path) {
  return decodeRle(readCapped(path, kRleFileCap, "a run-length encoded CGL picture"), path);
}

Frame readRawFile(const std::string& path) {
  const std::vector<std::uint8_t> bytes = readCapped(path, kRawBytes, "a raw CGL picture");
  return decodeRaw(bytes, path);
}

RgbImage toRgbImage(const Frame& frame) {
  RgbImage image;
  image.assign(Frame::kSize, Frame::kSize);
  for (int row = 0; row < Frame::kSize; ++row)
    for (int x = 0; x < Frame::kSize; ++x) {
      const std::uint32_t w = frame.words[static_cast<std::size_t>(row) * Frame::kSize + x];
      image.at(row, x) = {redOf(w) / 255.0, greenOf(w) / 255.0, blueOf(w) / 255.0};
    }
  return image;
}

}  // namespace prime::cgl
