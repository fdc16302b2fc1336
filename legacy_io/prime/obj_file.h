// obj/O<n>: an ObjHeader, then numEntries Obj records (entry 0 is the CSG root).
#pragma once
#include <string>
#include <vector>

#include "legacy_io/prime/records.h"

namespace prime::io {

struct ObjFile {
  ObjHeader header;
  std::vector<ObjRecord> entries;
};

std::vector<std::uint8_t> toBytes(const ObjFile& f);
// Checks that the size is 76 + 8*k bytes and that k equals numEntries.
ObjFile objFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name);
ObjFile readObjFile(const std::string& path);
void writeObjFile(const std::string& path, const ObjFile& f);

}  // namespace prime::io
