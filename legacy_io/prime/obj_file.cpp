#include "legacy_io/prime/obj_file.h"

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
  if (r.remaining() % kObjSize != 0)
    throw InputError({name, std::nullopt, bytes.size()}, "file size",
                     "76-byte ObjHeader plus a whole number of 8-byte Obj records",
                     std::to_string(bytes.size()) + " bytes (" +
                         std::to_string(r.remaining() % kObjSize) + " stray bytes at the end)");
  const std::size_t count = r.remaining() / kObjSize;
  if (f.header.numEntries < 0 || static_cast<std::size_t>(f.header.numEntries) != count)
    throw InputError({name, std::nullopt, 0}, "ObjHeader.numEntries",
                     std::to_string(count) + " (the number of records in the file)",
                     std::to_string(f.header.numEntries));
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
