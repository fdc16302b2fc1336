#include "legacy_io/prime/obj_list.h"

namespace prime::io {

std::vector<std::uint8_t> toBytes(const ObjList& f) {
  ByteWriter w;
  for (auto n : f.objects) w.putInt16(n);
  return w.take();
}

ObjList objListFromBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.size() % kTurboInt != 0)
    throw InputError({name, std::nullopt, bytes.size() - 1}, "file size",
                     "a whole number of 2-byte object numbers",
                     std::to_string(bytes.size()) + " bytes (odd)");
  ByteReader r(bytes, name);
  ObjList f;
  while (r.remaining() > 0) f.objects.push_back(r.getInt16("object number"));
  return f;
}

ObjList readObjList(const std::string& path) {
  return objListFromBytes(readFileBytes(path), path);
}

void writeObjList(const std::string& path, const ObjList& f) {
  writeFileAtomically(path, toBytes(f));
}

}  // namespace prime::io
