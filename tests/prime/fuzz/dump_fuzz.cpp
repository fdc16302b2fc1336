// `prime dump`: dumpDatabase on any bytes, as any of the five kinds. The first
// input byte picks the kind ('p' PrimFile, 'o' O file, 'l' List, 'm' map,
// 'g' graph_scr; any other byte: its value mod 5); the rest is the file.
#include <fstream>

#include "legacy_io/prime/dump.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

static io::DatabaseKind kindOf(std::uint8_t c) {
  switch (c) {
    case 'p':
      return io::DatabaseKind::PrimFile;
    case 'o':
      return io::DatabaseKind::ObjFile;
    case 'l':
      return io::DatabaseKind::ObjList;
    case 'm':
      return io::DatabaseKind::MapFile;
    case 'g':
      return io::DatabaseKind::GraphFile;
    default:
      return static_cast<io::DatabaseKind>(c % 5);
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const fuzz::ScratchScene scratch;  // only its directory is used
  static const std::string path = [] {
    std::filesystem::create_directories(scratch.root());
    return (scratch.root() / "db").string();
  }();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    const std::string text = io::dumpDatabase(path, kindOf(data[0]));
    // The listing is for people: it must stay proportionate to the file.
    fuzz::check(text.size() < 4096 + 200 * size, "dump output out of proportion to the file: " +
                                                     std::to_string(text.size()) + " bytes");
  } catch (const io::InputError& e) {
    fuzz::checkBinaryError(e, path, size - 1);
  }
  return 0;
}
