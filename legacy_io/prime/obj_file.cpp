#include "legacy_io/prime/obj_file.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace prime::io {

std::vector<std::uint8_t> toBytes(const ObjFile& f) {
  ByteWriter w;
  encode(w, f.header);
  for (const auto& e : f.entries) encode(w, e);
  return w.take();
}

ObjFile objFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
  ByteReader r(bytes, name);
  ObjFile f;
  f.header = decodeObjHeader(r);
  if (f.header.numEntries < 0)
    throw InputError({name, std::nullopt, 0}, "ObjHeader.numEntries",
                     "the number of Obj records, 0 or more", std::to_string(f.header.numEntries));
  // The header says how long the file is: a file cut short and one with
  // bytes after its records are both told as what they are.
  const std::uint64_t count = static_cast<std::uint64_t>(f.header.numEntries);
  const std::uint64_t want = kObjHeaderSize + count * kObjSize;
  const std::uint64_t have = bytes.size();
  const auto bytesText = [](std::uint64_t n) {
    return std::to_string(n) + (n == 1 ? " byte" : " bytes");
  };
  if (have != want)
    throw InputError({name, std::nullopt, std::min(have, want)}, "file size",
                     bytesText(want) + " (the " + std::to_string(kObjHeaderSize) +
                         "-byte ObjHeader and the " + std::to_string(count) + " " +
                         std::to_string(kObjSize) + "-byte Obj records its numEntries counts)",
                     bytesText(have) + " (" +
                         (have < want ? "cut short by " + bytesText(want - have)
                                      : bytesText(have - want) + " after the last record") +
                         ")");
  while (r.remaining() > 0) f.entries.push_back(decodeObj(r));
  return f;
}

ObjFile readObjFile(const std::string& path) {
  return objFileFromBytes(readFileBytes(path), path);
}

void writeObjFile(const std::string& path, const ObjFile& f) {
  writeFileAtomically(path, toBytes(f));
}

}  // namespace prime::io
