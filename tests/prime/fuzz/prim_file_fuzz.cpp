// prim/PrimFile: primFileFromBytes (both layouts, and the layout detection).
// A file that reads back must encode to the same bytes (the word-aligned
// layout's padding byte aside).
#include "legacy_io/prime/prim_file.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const io::PrimFile f = io::primFileFromBytes(bytes, "PrimFile");
    const std::size_t record =
        f.layout == io::PrimLayout::Packed ? io::kPrimSizePacked : io::kPrimSizeAligned;
    fuzz::check(f.prims.size() * record == size, "record count does not match the file size");
    io::ByteWriter w;
    for (const auto& p : f.prims) io::encode(w, p, f.layout);
    std::vector<std::uint8_t> again = w.take();
    if (f.layout == io::PrimLayout::WordAligned)
      for (std::size_t i = 0; i < f.prims.size(); ++i) again[i * record + 1] = data[i * record + 1];
    fuzz::check(again == std::vector<std::uint8_t>(data, data + size),
                "PrimFile does not encode back to its bytes");
  } catch (const io::InputError& e) {
    fuzz::checkBinaryError(e, "PrimFile", size);
  }
  return 0;
}
