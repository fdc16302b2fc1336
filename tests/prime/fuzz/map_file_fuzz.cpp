// map/Map<n>_R.map (_G, _B): mapFileFromBytes. A map that reads back has
// uScale*vScale texels and encodes to the same bytes.
#include "legacy_io/prime/map_file.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const io::MapFile f = io::mapFileFromBytes(bytes, "Map1_R.map");
    fuzz::check(f.header.uScale > 0 && f.header.vScale > 0, "non-positive map size accepted");
    fuzz::check(f.texels.size() == static_cast<std::size_t>(f.header.uScale) *
                                       static_cast<std::size_t>(f.header.vScale),
                "texel count is not uScale*vScale");
    fuzz::check(io::toBytes(f) == std::vector<std::uint8_t>(data, data + size),
                "map does not encode back to its bytes");
  } catch (const io::InputError& e) {
    fuzz::checkBinaryError(e, "Map1_R.map", size);
  }
  return 0;
}
