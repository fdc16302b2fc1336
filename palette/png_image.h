// PNG through libpng: 8-bit RGB or 8-bit palette indices, with what the
// picture is (tEXt: the program, the scene, the settings; pHYs: the pixel's
// shape) and no time stamp, so one render gives the same bytes every time;
// written to a temporary file and renamed into place; and read back (tests,
// comparisons).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace prime {

struct Image8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width*height*3, rows top to bottom
};

// Palette indices, as a 256-colour screen holds them (PNG colour type 3).
struct IndexedImage8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> indices;  // width*height, rows top to bottom
  std::vector<std::uint8_t> palette;  // r, g, b of each entry: 1..256 entries
};

// One tEXt chunk: a keyword (1..79 printable Latin-1 characters) and its
// text. A text with a byte above 127 (a UTF-8 file name) is written as an
// uncompressed iTXt chunk instead, which PNG defines for UTF-8.
struct PngText {
  std::string keyword, text;
};

// What a PNG says besides its pixels. No tIME: the same picture gives the
// same bytes.
struct PngMeta {
  std::vector<PngText> text;     // in this order
  int aspectX = 0, aspectY = 0;  // pHYs, unit unknown: a pixel's width : height as shown
                                 // (0: no pHYs)
};

namespace io {
class OutputFile;
}

void writePng(const std::string& path, const Image8& image, const PngMeta& meta = {});
// Into `out` (one file of an io::OutputSet), which the caller commits.
void writePng(io::OutputFile& out, const Image8& image, const PngMeta& meta = {});
// Colour type 3: bit depth 8, PLTE of image.palette, the indices as they are.
// Throws std::invalid_argument for a palette of 0 or more than 256 entries.
void writeIndexedPng(const std::string& path, const IndexedImage8& image, const PngMeta& meta = {});
void writeIndexedPng(io::OutputFile& out, const IndexedImage8& image, const PngMeta& meta = {});

// The colours an indexed picture shows (an index past the palette: black).
Image8 colourImage(const IndexedImage8& image);
// Nearest neighbour, every pixel `factor` x `factor` (factor >= 1).
Image8 upscale(const Image8& image, int factor);
IndexedImage8 upscale(const IndexedImage8& image, int factor);
// The largest whole factor k >= 1 with width*k <= maxWidth and height*k <=
// maxHeight (1 when even 1 does not fit): an integer-upscaled copy's factor.
int fitFactor(int width, int height, int maxWidth, int maxHeight);
// Reads any PNG as 8-bit RGB (libpng's simplified API); throws
// std::runtime_error naming the file when it cannot.
Image8 readPng(const std::string& path);
// A PNG as it was written: an 8-bit palette PNG keeps its indices and
// palette, anything else is read as 8-bit RGB; the text chunks (tEXt, iTXt,
// zTXt) and pHYs with it. Throws like readPng.
struct PngFile {
  bool indexed = false;
  Image8 rgb;             // when not indexed
  IndexedImage8 palette;  // when indexed
  PngMeta meta;
};
PngFile readPngFile(const std::string& path);

// The same from the file's bytes; `display` names them in messages. A chunk
// longer than what is left of the file is refused before libpng reads it,
// with an io::InputError (a std::runtime_error) giving its byte offset.
Image8 pngFromBytes(const std::vector<std::uint8_t>& bytes, const std::string& display);

}  // namespace prime
