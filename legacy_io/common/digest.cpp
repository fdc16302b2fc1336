#include "legacy_io/common/digest.h"

#include <xxhash.h>

#include <cstdio>
#include <fstream>
#include <new>
#include <vector>

namespace prime::io {

std::uint64_t xxh3(const void* bytes, std::size_t size) {
  return XXH3_64bits(bytes, size);
}

std::string hex16(std::uint64_t value) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(value));
  return buf;
}

struct Xxh3Stream::State {
  XXH3_state_t* s = XXH3_createState();
  ~State() { XXH3_freeState(s); }
};

Xxh3Stream::Xxh3Stream() : state_(std::make_unique<State>()) {
  if (state_->s == nullptr) throw std::bad_alloc();
  XXH3_64bits_reset(state_->s);
}
Xxh3Stream::~Xxh3Stream() = default;

void Xxh3Stream::add(std::span<const std::uint8_t> bytes) {
  XXH3_64bits_update(state_->s, bytes.data(), bytes.size());
}

std::uint64_t Xxh3Stream::digest() const {
  return XXH3_64bits_digest(state_->s);
}

std::optional<FileDigest> fileXxh3(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  Xxh3Stream hash;
  FileDigest d;
  std::vector<char> buf(1 << 16);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    hash.add({reinterpret_cast<const std::uint8_t*>(buf.data()), n});
    d.bytes += n;
  }
  if (in.bad()) return std::nullopt;
  d.hash = hash.digest();
  return d;
}

}  // namespace prime::io
