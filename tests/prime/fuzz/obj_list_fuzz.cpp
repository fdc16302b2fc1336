// obj/List: objListFromBytes. A list that reads back encodes to the same bytes.
#include "legacy_io/prime/obj_list.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const io::ObjList f = io::objListFromBytes(bytes, "List");
    fuzz::check(io::toBytes(f) == std::vector<std::uint8_t>(data, data + size),
                "List does not encode back to its bytes");
  } catch (const io::InputError& e) {
    fuzz::checkBinaryError(e, "List", size);
  }
  return 0;
}
