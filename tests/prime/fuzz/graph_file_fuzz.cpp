// graph_scr: graphFileFromBytes. A screen that reads back has width x height
// pixels, every at(x, y) is inside them, and it encodes to the same bytes.
#include "legacy_io/prime/graph_file.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const io::GraphFile f = io::graphFileFromBytes(bytes, "graph_scr");
    fuzz::check(f.width() >= 0 && f.height() >= 0, "negative size accepted");
    fuzz::check(f.pixels.size() ==
                    static_cast<std::size_t>(f.width()) * static_cast<std::size_t>(f.height()),
                "pixel count is not width x height");
    if (!f.pixels.empty()) (void)f.at(f.width() - 1, f.height() - 1);
    fuzz::check(io::toBytes(f) == std::vector<std::uint8_t>(data, data + size),
                "graph file does not encode back to its bytes");
  } catch (const io::InputError& e) {
    fuzz::checkBinaryError(e, "graph_scr", size);
  }
  return 0;
}
