#include "palette/png_image.h"

#include <png.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"

namespace prime {

void writePng(const std::string& path, const Image8& image) {
  io::OutputFile out(path);  // a fresh temporary beside it, renamed into place at the end
  writePng(out, image);
  out.commit();
}

void writePng(io::OutputFile& out, const Image8& image) {
  const std::string& path = out.path();
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(path + ": libpng failed to write the image");
  }
  png_init_io(png, out.stream());
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png,
                  const_cast<png_bytep>(&image.rgb[static_cast<std::size_t>(y) * image.width * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

Image8 readPng(const std::string& path) {
  // Read as every input is (legacy_io/common/input_file.h): a FIFO, a device
  // or a directory is refused by type, an oversized file by size, and the
  // file is an input of the run (no output may replace it).
  io::InputFileOptions options;
  options.what = "a PNG picture";
  return pngFromBytes(io::readInputFile(path, options), path);
}

namespace {

// libpng allocates a chunk's declared length before it reads the chunk (a
// 52-byte file whose sPLT chunk claims 963 MB made it ask for 963 MB). So
// every chunk's length is checked against the bytes left in the file before
// libpng sees it: a chunk longer than that is a cut or damaged file, which
// libpng refuses anyway once it runs out of bytes.
void checkChunkLengths(const std::vector<std::uint8_t>& bytes, const std::string& display) {
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) return;  // libpng says why
  std::size_t at = 8;
  while (bytes.size() - at >= 8) {
    const std::uint64_t length = std::uint64_t{bytes[at]} << 24 |
                                 std::uint64_t{bytes[at + 1]} << 16 |
                                 std::uint64_t{bytes[at + 2]} << 8 | bytes[at + 3];
    const std::string type(bytes.begin() + static_cast<std::ptrdiff_t>(at) + 4,
                           bytes.begin() + static_cast<std::ptrdiff_t>(at) + 8);
    if (type == "IEND") return;  // nothing after it is read
    // The data and the 4-byte CRC after the 8-byte length and type.
    const std::uint64_t left = bytes.size() - at - 8;
    if (length + 4 > left)
      throw io::InputError({display, std::nullopt, at},
                           "chunk " + io::quotedWord(type, 16) + " length",
                           "at most " + std::to_string(left < 4 ? 0 : left - 4) +
                               " bytes (what is left of the file after its type, before its CRC)",
                           std::to_string(length) + " (a cut or damaged file)");
    at += static_cast<std::size_t>(length) + 12;
  }
}

}  // namespace

Image8 pngFromBytes(const std::vector<std::uint8_t>& bytes, const std::string& display) {
  checkChunkLengths(bytes, display);
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&img, bytes.data(), bytes.size()))
    throw std::runtime_error(display + ": cannot read PNG: " + img.message);
  // A PNG's pixels are deflated, and zlib never expands data more than
  // 1032 times; one bit a pixel (a 2-colour palette) is 24 bits of RGB. A
  // header that claims more pixels than the file can hold is refused before
  // anything is allocated for them.
  const std::uint64_t need = static_cast<std::uint64_t>(img.width) * img.height * 3;
  const std::uint64_t most = 24ull * 1032ull * bytes.size();
  if (need > most) {
    png_image_free(&img);
    throw std::runtime_error(display + ": cannot read PNG: its header says " +
                             std::to_string(img.width) + " x " + std::to_string(img.height) +
                             " pixels (" + std::to_string(need) + " bytes of RGB), more than a " +
                             std::to_string(bytes.size()) + "-byte PNG can hold (at most " +
                             std::to_string(most) + ")");
  }
  img.format = PNG_FORMAT_RGB;
  Image8 out;
  out.width = static_cast<int>(img.width);
  out.height = static_cast<int>(img.height);
  out.rgb.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.rgb.data(), 0, nullptr)) {
    const std::string message = img.message;
    png_image_free(&img);
    throw std::runtime_error(display + ": cannot read PNG: " + message);
  }
  return out;
}

}  // namespace prime
