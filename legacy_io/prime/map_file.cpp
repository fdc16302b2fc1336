#include "legacy_io/prime/map_file.h"

namespace prime::io {

std::vector<std::uint8_t> toBytes(const MapFile& f) {
  ByteWriter w;
  encode(w, f.header);
  for (double t : f.texels) w.putDouble(t);
  return w.take();
}

MapFile mapFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
  ByteReader r(bytes, name);
  MapFile f;
  f.header = decodeMapHeader(r);
  const long long entries = static_cast<long long>(f.header.uScale) * f.header.vScale;
  if (f.header.uScale <= 0 || f.header.vScale <= 0)
    throw InputError({name, std::nullopt, 0}, "MapHeader.uScale/vScale", "two positive sizes",
                     std::to_string(f.header.uScale) + " x " + std::to_string(f.header.vScale));
  if (r.remaining() != static_cast<std::size_t>(entries) * kTurboDouble)
    throw InputError({name, std::nullopt, bytes.size()}, "file size",
                     std::to_string(4 + entries * 8) + " bytes (4-byte header + " +
                         std::to_string(entries) + " doubles)",
                     std::to_string(bytes.size()) + " bytes");
  f.texels.reserve(static_cast<std::size_t>(entries));
  while (r.remaining() > 0) f.texels.push_back(r.getDouble("texel"));
  return f;
}

MapFile readMapFile(const std::string& path) {
  return mapFileFromBytes(readFileBytes(path), path);
}

void writeMapFile(const std::string& path, const MapFile& f) {
  writeFileAtomically(path, toBytes(f));
}

std::string mapFileName(int mapNum, int channel) {
  static const char kChannel[3] = {'R', 'G', 'B'};
  return "Map" + std::to_string(mapNum) + "_" + kChannel[channel] + ".map";
}

}  // namespace prime::io
