// XXH3 (64 bits, seed 0, Debian's libxxhash) of bytes, and as 16 hex digits:
// the one content hash of the render records and of a run's inputs.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace prime::io {

std::uint64_t xxh3(const void* bytes, std::size_t size);
inline std::uint64_t xxh3(std::string_view text) {
  return xxh3(text.data(), text.size());
}
std::string hex16(std::uint64_t value);

// XXH3 of bytes handed over piece by piece, in order: the same as xxh3() of
// all of them (a picture hashed as it is written, a file as it is read).
class Xxh3Stream {
 public:
  Xxh3Stream();
  ~Xxh3Stream();
  Xxh3Stream(const Xxh3Stream&) = delete;
  Xxh3Stream& operator=(const Xxh3Stream&) = delete;
  void add(std::span<const std::uint8_t> bytes);
  std::uint64_t digest() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};
// The XXH3 and size of a file's bytes (an output of the run, read back:
// not recorded as an input); nullopt when it cannot be read.
struct FileDigest {
  std::uint64_t hash = 0, bytes = 0;
};
std::optional<FileDigest> fileXxh3(const std::string& path);

}  // namespace prime::io
