// obj/O<n>: objFileFromBytes. A file that reads back encodes to the same bytes.
#include "legacy_io/prime/obj_file.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const io::ObjFile f = io::objFileFromBytes(bytes, "O1");
    fuzz::check(static_cast<std::size_t>(f.header.numEntries) == f.entries.size(), "numEntries");
    fuzz::check(io::toBytes(f) == std::vector<std::uint8_t>(data, data + size),
                "O file does not encode back to its bytes");
  } catch (const io::InputError& e) {
    fuzz::checkBinaryError(e, "O1", size);
  }
  return 0;
}
