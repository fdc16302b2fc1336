#include "legacy_io/common/bytes.h"

#include <unistd.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"

namespace prime::io {

void ByteWriter::putInt16(std::int16_t v) {
  const auto u = static_cast<std::uint16_t>(v);
  bytes_.push_back(static_cast<std::uint8_t>(u & 0xFF));
  bytes_.push_back(static_cast<std::uint8_t>(u >> 8));
}

void ByteWriter::putInt16s(std::span<const std::int16_t> values) {
  const std::size_t at = bytes_.size();
  bytes_.resize(at + 2 * values.size());
  std::uint8_t* out = bytes_.data() + at;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto u = static_cast<std::uint16_t>(values[i]);
    out[2 * i] = static_cast<std::uint8_t>(u & 0xFF);
    out[2 * i + 1] = static_cast<std::uint8_t>(u >> 8);
  }
}

void ByteWriter::putDouble(double v) {
#if defined(__cpp_lib_bit_cast)
  const auto u = std::bit_cast<std::uint64_t>(v);
#else  // the web build's libc++ (docs/web.md): the builtin std::bit_cast is
  const auto u = __builtin_bit_cast(std::uint64_t, v);
#endif
  for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
}

void ByteReader::need(std::size_t n, const std::string& field) {
  if (remaining() < n)
    throw InputError({file_, std::nullopt, offset()}, field, std::to_string(n) + " more byte(s)",
                     "end of file after " + std::to_string(remaining()) + " byte(s) (truncated)");
}

std::uint8_t ByteReader::getChar(const std::string& field) {
  need(1, field);
  return bytes_[pos_++];
}

std::int16_t ByteReader::getInt16(const std::string& field) {
  need(2, field);
  const auto u = static_cast<std::uint16_t>(bytes_[pos_] | (bytes_[pos_ + 1] << 8));
  pos_ += 2;
  return static_cast<std::int16_t>(u);
}

double ByteReader::getDouble(const std::string& field) {
  need(8, field);
  std::uint64_t u = 0;
  for (int i = 0; i < 8; ++i) u |= static_cast<std::uint64_t>(bytes_[pos_ + i]) << (8 * i);
  pos_ += 8;
#if defined(__cpp_lib_bit_cast)
  return std::bit_cast<double>(u);
#else
  return __builtin_bit_cast(double, u);
#endif
}

void ByteReader::skip(std::size_t n, const std::string& field) {
  need(n, field);
  pos_ += n;
}

std::vector<std::uint8_t> readFileBytes(const std::string& path) {
  return readInputFile(path);
}

void writeFileAtomically(const std::string& path, std::span<const std::uint8_t> bytes) {
  OutputFile out(path);
  out.write(bytes);
  out.commit();
}

}  // namespace prime::io
