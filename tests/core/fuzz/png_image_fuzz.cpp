// The PNG reader (palette/png_image.h, pngFromBytes: readPng on a file's
// bytes), the input of `prime quantize`, on any bytes. Contract: it returns,
// or throws std::runtime_error whose message starts with the file's name (as
// readPng documents; `prime quantize` turns it into an InputError naming the
// file; libpng's simplified API gives no byte offset), or, for a chunk longer
// than the rest of the file, an io::InputError with the chunk's byte offset. It allocates nothing
// for pixels a header claims but the file cannot hold. What it returns keeps
// its promises: width x height x 3 bytes of RGB, and its size within what
// the file can hold.
//
// libpng is not instrumented (the system's library): the fuzzer sees only
// this side of it. So that mutations get past the chunk CRCs to what the
// chunks say, an input of even length has each chunk's CRC recomputed before
// it is read (an odd one is read as it is).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "legacy_io/common/error.h"
#include "palette/png_image.h"

namespace {

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
  std::abort();
}
void check(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

std::uint32_t crc32(const std::uint8_t* p, std::size_t n) {
  std::uint32_t c = 0xffffffffu;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return c ^ 0xffffffffu;
}

// Rewrites the CRC of every whole chunk after the 8-byte signature.
void fixCrcs(std::vector<std::uint8_t>& b) {
  std::size_t at = 8;
  while (at + 12 <= b.size()) {
    const std::size_t length = std::size_t{b[at]} << 24 | std::size_t{b[at + 1]} << 16 |
                               std::size_t{b[at + 2]} << 8 | b[at + 3];
    if (length > b.size() - at - 12) return;
    const std::uint32_t c = crc32(&b[at + 4], 4 + length);
    const std::size_t end = at + 8 + length;
    for (int k = 0; k < 4; ++k) b[end + k] = static_cast<std::uint8_t>(c >> (24 - 8 * k));
    at = end + 4;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 200000) return 0;
  std::vector<std::uint8_t> bytes(data, data + size);
  if (size % 2 == 0) fixCrcs(bytes);
  try {
    const prime::Image8 image = prime::pngFromBytes(bytes, "fuzz.png");
    check(image.width >= 1 && image.height >= 1, "an empty image");
    const std::uint64_t rgb = static_cast<std::uint64_t>(image.width) * image.height * 3;
    check(image.rgb.size() == rgb, "RGB bytes other than width x height x 3");
    check(rgb <= 24ull * 1032ull * size, "more pixels than the file can hold");
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    check(msg.rfind("fuzz.png: ", 0) == 0 || msg.rfind("fuzz.png (byte ", 0) == 0,
          "a message that does not start with the file: " + msg);
    if (const auto* input = dynamic_cast<const prime::io::InputError*>(&e))
      check(input->where().byte.has_value() && *input->where().byte <= size,
            "an input error without a byte offset in the file: " + msg);
  }
  return 0;
}
