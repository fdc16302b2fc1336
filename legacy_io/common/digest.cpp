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

std::optional<FileDigest> fileXxh3(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  XXH3_state_t* state = XXH3_createState();
  if (state == nullptr) throw std::bad_alloc();
  XXH3_64bits_reset(state);
  FileDigest d;
  std::vector<char> buf(1 << 16);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    XXH3_64bits_update(state, buf.data(), n);
    d.bytes += n;
  }
  const bool failed = in.bad();
  d.hash = XXH3_64bits_digest(state);
  XXH3_freeState(state);
  if (failed) return std::nullopt;
  return d;
}

}  // namespace prime::io
