// obj/List: the object numbers to render, as 16-bit ints (AddToObjList).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "legacy_io/prime/turbo_c.h"

namespace prime::io {

struct ObjList {
  std::vector<std::int16_t> objects;
};

std::vector<std::uint8_t> toBytes(const ObjList& f);
ObjList objListFromBytes(std::span<const std::uint8_t> bytes, const std::string& name);
ObjList readObjList(const std::string& path);
void writeObjList(const std::string& path, const ObjList& f);

}  // namespace prime::io
