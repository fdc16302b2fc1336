// The CGL package's picture readers (legacy_io/cgl/frame.h) on any bytes:
// decodeRle and decodeRaw return, or throw prime::io::InputError naming the
// file and a byte offset inside (or just past) the input. A decoded RLE frame
// keeps its promises: pixel words use only their low 24 bits, and it encodes
// to bytes that decode to the same frame (and, the encoder's runs being
// maximal, encode again to the same bytes).
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "legacy_io/cgl/frame.h"
#include "legacy_io/common/error.h"

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}
void check(bool ok, const char* what) {
  if (!ok) fail(what);
}
void checkError(const prime::io::InputError& e, std::size_t size) {
  check(e.where().file == "fuzz.pic", "an error without the file");
  check(e.where().byte.has_value(), "an error without a byte offset");
  check(*e.where().byte <= size, "a byte offset past the end of the input");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace prime;
  if (size > (2u << 20)) return 0;
  const std::vector<std::uint8_t> bytes(data, data + size);
  try {
    const cgl::Frame frame = cgl::decodeRle(bytes, "fuzz.pic");
    check(frame.words.size() == 512u * 512, "a frame of the wrong size");
    for (std::uint32_t w : frame.words) check((w >> 24) == 0, "a pixel word with its top byte set");
    const std::vector<std::uint8_t> again = cgl::encodeRle(frame);
    check(again.size() <= bytes.size(), "re-encoding grew (the encoder's runs are maximal)");
    const cgl::Frame back = cgl::decodeRle(again, "again.rle");
    check(back.words == frame.words, "re-encoded bytes decode to another frame");
    check(cgl::encodeRle(back) == again, "encoding is not stable");
  } catch (const io::InputError& e) {
    checkError(e, size);
  }
  try {
    const cgl::Frame frame = cgl::decodeRaw(bytes, "fuzz.pic");
    check(cgl::encodeRaw(frame) == bytes, "a raw frame does not encode to its bytes");
  } catch (const io::InputError& e) {
    checkError(e, size);
  }
  return 0;
}
