#include "palette/png_image.h"

#include <png.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"

namespace prime {

void writePng(const std::string& path, const Image8& image, const PngMeta& meta) {
  io::OutputFile out(path);  // a fresh temporary beside it, renamed into place at the end
  writePng(out, image, meta);
  out.commit();
}

void writeIndexedPng(const std::string& path, const IndexedImage8& image, const PngMeta& meta) {
  io::OutputFile out(path);
  writeIndexedPng(out, image, meta);
  out.commit();
}

namespace {

bool plainLatin1(const std::string& s) {
  for (unsigned char c : s)
    if (c >= 0x80) return false;
  return true;
}

// The header, the palette (indexed), pHYs and the text chunks, then the rows
// of `bytesPerPixel` bytes each.
void writePngFile(io::OutputFile& out, int width, int height, int colourType,
                  const std::uint8_t* pixels, int bytesPerPixel,
                  const std::vector<std::uint8_t>* palette, const PngMeta& meta) {
  const std::string& path = out.path();
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  // The texts' buffers outlive png_write_info, which copies nothing.
  std::vector<png_text> texts(meta.text.size());
  std::vector<std::string> keys(meta.text.size()), values(meta.text.size());
  std::vector<png_color> plte;  // before setjmp: a longjmp skips no destructor
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(path + ": libpng failed to write the image");
  }
  png_init_io(png, out.stream());
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               colourType, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (palette != nullptr) {
    for (std::size_t i = 0; i + 2 < palette->size(); i += 3)
      plte.push_back({(*palette)[i], (*palette)[i + 1], (*palette)[i + 2]});
    png_set_PLTE(png, info, plte.data(), static_cast<int>(plte.size()));
  }
  if (meta.aspectX > 0 && meta.aspectY > 0)
    png_set_pHYs(png, info, static_cast<png_uint_32>(meta.aspectX),
                 static_cast<png_uint_32>(meta.aspectY), PNG_RESOLUTION_UNKNOWN);
  for (std::size_t i = 0; i < meta.text.size(); ++i) {
    keys[i] = meta.text[i].keyword;
    values[i] = meta.text[i].text;
    png_text& t = texts[i];
    t = png_text{};
    const bool latin1 = plainLatin1(values[i]);
    t.compression = latin1 ? PNG_TEXT_COMPRESSION_NONE : PNG_ITXT_COMPRESSION_NONE;
    t.key = keys[i].data();
    t.text = values[i].data();
    t.text_length = latin1 ? values[i].size() : 0;
    t.itxt_length = latin1 ? 0 : values[i].size();
  }
  if (!texts.empty()) png_set_text(png, info, texts.data(), static_cast<int>(texts.size()));
  png_write_info(png, info);
  const std::size_t rowBytes = static_cast<std::size_t>(width) * bytesPerPixel;
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(pixels + static_cast<std::size_t>(y) * rowBytes));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

void checkPngSize(const std::string& path, int width, int height, std::size_t bytes,
                  int bytesPerPixel) {
  if (width <= 0 || height <= 0 ||
      bytes != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * bytesPerPixel)
    throw std::invalid_argument(path + ": a " + std::to_string(width) + " x " +
                                std::to_string(height) + " picture with " + std::to_string(bytes) +
                                " bytes of pixels");
}

}  // namespace

void writePng(io::OutputFile& out, const Image8& image, const PngMeta& meta) {
  checkPngSize(out.path(), image.width, image.height, image.rgb.size(), 3);
  writePngFile(out, image.width, image.height, PNG_COLOR_TYPE_RGB, image.rgb.data(), 3, nullptr,
               meta);
}

void writeIndexedPng(io::OutputFile& out, const IndexedImage8& image, const PngMeta& meta) {
  checkPngSize(out.path(), image.width, image.height, image.indices.size(), 1);
  if (image.palette.empty() || image.palette.size() > 256 * 3 || image.palette.size() % 3 != 0)
    throw std::invalid_argument(out.path() + ": a palette of " +
                                std::to_string(image.palette.size()) +
                                " bytes (1 to 256 entries of 3 bytes expected)");
  writePngFile(out, image.width, image.height, PNG_COLOR_TYPE_PALETTE, image.indices.data(), 1,
               &image.palette, meta);
}

Image8 colourImage(const IndexedImage8& image) {
  Image8 out;
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(image.indices.size() * 3);
  const std::size_t entries = image.palette.size() / 3;
  for (std::size_t i = 0; i < image.indices.size(); ++i) {
    const std::size_t e = image.indices[i];
    if (e >= entries) continue;  // black
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = image.palette[3 * e + c];
  }
  return out;
}

namespace {

// Each pixel of `bytes` (`n` bytes a pixel, w x h) as a k x k block.
std::vector<std::uint8_t> blockUp(const std::vector<std::uint8_t>& bytes, int w, int h, int n,
                                  int k) {
  if (k < 1) throw std::invalid_argument("upscale: a factor of " + std::to_string(k));
  const std::size_t outRow = static_cast<std::size_t>(w) * k * n;
  std::vector<std::uint8_t> out(outRow * static_cast<std::size_t>(h) * k);
  for (int y = 0; y < h; ++y) {
    std::uint8_t* row = &out[static_cast<std::size_t>(y) * k * outRow];
    for (int x = 0; x < w; ++x)
      for (int i = 0; i < k; ++i)
        std::copy_n(&bytes[(static_cast<std::size_t>(y) * w + x) * n], n,
                    row + (static_cast<std::size_t>(x) * k + i) * n);
    for (int i = 1; i < k; ++i) std::copy_n(row, outRow, row + i * outRow);
  }
  return out;
}

}  // namespace

Image8 upscale(const Image8& image, int factor) {
  Image8 out;
  out.rgb = blockUp(image.rgb, image.width, image.height, 3, factor);
  out.width = image.width * factor;
  out.height = image.height * factor;
  return out;
}

IndexedImage8 upscale(const IndexedImage8& image, int factor) {
  IndexedImage8 out;
  out.indices = blockUp(image.indices, image.width, image.height, 1, factor);
  out.width = image.width * factor;
  out.height = image.height * factor;
  out.palette = image.palette;
  return out;
}

int fitFactor(int width, int height, int maxWidth, int maxHeight) {
  if (width <= 0 || height <= 0) return 1;
  return std::max(1, std::min(maxWidth / width, maxHeight / height));
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

namespace {

struct MemoryRead {
  const std::vector<std::uint8_t>* bytes;
  std::size_t at = 0;
};

void readFromMemory(png_structp png, png_bytep out, png_size_t n) {
  auto* m = static_cast<MemoryRead*>(png_get_io_ptr(png));
  if (n > m->bytes->size() - m->at) png_error(png, "the file ends early");
  std::copy_n(m->bytes->data() + m->at, n, out);
  m->at += n;
}

}  // namespace

PngFile readPngFile(const std::string& path) {
  io::InputFileOptions options;
  options.what = "a PNG picture";
  const std::vector<std::uint8_t> bytes = io::readInputFile(path, options);
  PngFile file;
  checkChunkLengths(bytes, path);              // before libpng allocates for any chunk
  std::string why = "libpng could not start";  // libpng's message, if it stops
  png_structp png = png_create_read_struct(
      PNG_LIBPNG_VER_STRING, &why,
      [](png_structp p, png_const_charp message) {
        *static_cast<std::string*>(png_get_error_ptr(p)) = message;
        png_longjmp(p, 1);
      },
      nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  MemoryRead source{&bytes};
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error(path + ": cannot read PNG: " + why);
  }
  png_set_read_fn(png, &source, readFromMemory);
  png_read_info(png, info);
  png_uint_32 w = 0, h = 0;
  int depth = 0, type = 0;
  png_get_IHDR(png, info, &w, &h, &depth, &type, nullptr, nullptr, nullptr);
  png_colorp plte = nullptr;
  int entries = 0;
  // zlib never expands data more than 1032 times: a header that claims more
  // one-byte pixels than the file can hold is refused unallocated.
  const bool fits = static_cast<std::uint64_t>(w) * h <= 1032ull * bytes.size();
  if (type == PNG_COLOR_TYPE_PALETTE && depth == 8 && fits &&
      png_get_PLTE(png, info, &plte, &entries) != 0 &&
      png_get_interlace_type(png, info) == PNG_INTERLACE_NONE) {
    IndexedImage8& img = file.palette;
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
    for (int i = 0; i < entries; ++i)
      img.palette.insert(img.palette.end(), {plte[i].red, plte[i].green, plte[i].blue});
    img.indices.resize(static_cast<std::size_t>(w) * h);
    for (png_uint_32 y = 0; y < h; ++y)
      png_read_row(png, &img.indices[static_cast<std::size_t>(y) * w], nullptr);
    png_read_end(png, info);
    file.indexed = true;
  }
  png_textp texts = nullptr;
  const int n = png_get_text(png, info, &texts, nullptr);
  for (int i = 0; i < n; ++i)
    file.meta.text.push_back(
        {texts[i].key,
         std::string(texts[i].text,
                     texts[i].compression > 0 ? texts[i].itxt_length : texts[i].text_length)});
  png_uint_32 ax = 0, ay = 0;
  int unit = 0;
  if (png_get_pHYs(png, info, &ax, &ay, &unit) != 0) {
    file.meta.aspectX = static_cast<int>(ax);
    file.meta.aspectY = static_cast<int>(ay);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (!file.indexed) file.rgb = pngFromBytes(bytes, path);  // any other PNG, with its checks
  return file;
}

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
