// PNG through libpng: 8-bit RGB, written to a temporary file and renamed
// into place; and read back (tests, comparisons).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace prime {

struct Image8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width*height*3, rows top to bottom
};

namespace io {
class OutputFile;
}

void writePng(const std::string& path, const Image8& image);
// Into `out` (one file of an io::OutputSet), which the caller commits.
void writePng(io::OutputFile& out, const Image8& image);
// Reads any PNG as 8-bit RGB (libpng's simplified API); throws
// std::runtime_error naming the file when it cannot.
Image8 readPng(const std::string& path);
// The same from the file's bytes; `display` names them in messages. A chunk
// longer than what is left of the file is refused before libpng reads it,
// with an io::InputError (a std::runtime_error) giving its byte offset.
Image8 pngFromBytes(const std::vector<std::uint8_t>& bytes, const std::string& display);

}  // namespace prime
