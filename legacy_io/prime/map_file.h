// map/Map<n>_R.map, _G.map, _B.map: a MapHeader (uScale, vScale), then
// uScale*vScale doubles of one colour channel, row by row (index u + uScale*v).
#pragma once
#include <string>
#include <vector>

#include "legacy_io/prime/records.h"

namespace prime::io {

struct MapFile {
  MapHeader header;
  std::vector<double> texels;
};

// Largest uScale*vScale: Turbo C computed it in a 16-bit int, so anything
// larger wrapped around in the original (AddMap's numEntries).
inline constexpr int kMaxMapEntries = 32767;

std::vector<std::uint8_t> toBytes(const MapFile& f);
MapFile mapFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name);
MapFile readMapFile(const std::string& path);
void writeMapFile(const std::string& path, const MapFile& f);
// "Map<n>_R.map" etc. for channel 0, 1, 2.
std::string mapFileName(int mapNum, int channel);

}  // namespace prime::io
