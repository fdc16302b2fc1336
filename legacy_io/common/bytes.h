// Little-endian byte records, read and written field by field: a reader that
// names the file, the byte offset and the field when the data runs short, a
// writer, and whole-file helpers (an atomic write through a temporary). No
// C++ struct is ever written to a file as raw memory. Any system's binary
// formats build on these; PRIME's Turbo C layout is legacy_io/prime/turbo_c.h.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "legacy_io/common/error.h"

namespace prime::io {

class ByteWriter {
 public:
  void putChar(std::uint8_t c) { bytes_.push_back(c); }
  void putInt16(std::int16_t v);
  // putInt16 of each value in turn, in one pass (a graph file's pixels).
  void putInt16s(std::span<const std::int16_t> values);
  void putDouble(double v);
  void putZeros(std::size_t n) { bytes_.insert(bytes_.end(), n, 0); }
  void reserve(std::size_t n) { bytes_.reserve(n); }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

// Reads from a byte span; every read checks the length and reports a
// truncated file with the byte offset and the field being read.
class ByteReader {
 public:
  ByteReader(std::span<const std::uint8_t> bytes, std::string file, std::size_t base = 0)
      : bytes_(bytes), file_(std::move(file)), base_(base) {}
  std::uint8_t getChar(const std::string& field);
  std::int16_t getInt16(const std::string& field);
  double getDouble(const std::string& field);
  void skip(std::size_t n, const std::string& field);
  std::size_t offset() const { return base_ + pos_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  const std::string& file() const { return file_; }

 private:
  void need(std::size_t n, const std::string& field);
  std::span<const std::uint8_t> bytes_;
  std::string file_;
  std::size_t base_ = 0, pos_ = 0;
};

// Whole-file helpers. readFileBytes is readInputFile (legacy_io/common/input_file.h)
// with the default cap: a missing file, a directory, a FIFO or a device is an InputError.
std::vector<std::uint8_t> readFileBytes(const std::string& path);
// Writes through a temporary file in the same directory and renames it into
// place, so an interrupted write never leaves a half-written file behind
// (legacy_io/common/output_file.h: no planted link followed, no device or
// FIFO replaced).
void writeFileAtomically(const std::string& path, std::span<const std::uint8_t> bytes);

}  // namespace prime::io
