#include "legacy_io/prime/prim_file.h"

namespace prime::io {

std::vector<std::uint8_t> toBytes(const PrimFile& f) {
  ByteWriter w;
  for (const auto& p : f.prims) encode(w, p, PrimLayout::Packed);
  return w.take();
}

static bool looksAffine(std::span<const std::uint8_t> bytes, PrimLayout layout) {
  const std::size_t size = layout == PrimLayout::Packed ? kPrimSizePacked : kPrimSizeAligned;
  if (bytes.size() < size) return false;
  ByteReader r(bytes.first(size), "");
  const PrimRecord p = decodePrim(r, layout);
  for (const auto* m : {&p.transform, &p.inverse})
    if ((*m)[0][3] != 0.0 || (*m)[1][3] != 0.0 || (*m)[2][3] != 0.0 || (*m)[3][3] != 1.0)
      return false;
  return true;
}

PrimLayout detectPrimLayout(std::span<const std::uint8_t> bytes, const std::string& name) {
  const bool packedFits = bytes.size() % kPrimSizePacked == 0;
  const bool alignedFits = bytes.size() % kPrimSizeAligned == 0;
  if (packedFits && !alignedFits) return PrimLayout::Packed;
  if (alignedFits && !packedFits) return PrimLayout::WordAligned;
  if (bytes.empty() || looksAffine(bytes, PrimLayout::Packed)) {
    if (packedFits) return PrimLayout::Packed;
  }
  if (alignedFits && looksAffine(bytes, PrimLayout::WordAligned)) return PrimLayout::WordAligned;
  if (packedFits) return PrimLayout::Packed;
  throw InputError({name, std::nullopt, bytes.size()}, "file size",
                   "a whole number of Prim records (291 bytes packed, or 292 word-aligned)",
                   std::to_string(bytes.size()) + " bytes (" +
                       std::to_string(bytes.size() / kPrimSizePacked) + " records and " +
                       std::to_string(bytes.size() % kPrimSizePacked) + " extra bytes)");
}

PrimFile primFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name) {
  PrimFile f;
  f.layout = detectPrimLayout(bytes, name);
  ByteReader r(bytes, name);
  while (r.remaining() > 0) f.prims.push_back(decodePrim(r, f.layout));
  return f;
}

PrimFile readPrimFile(const std::string& path) {
  return primFileFromBytes(readFileBytes(path), path);
}

void writePrimFile(const std::string& path, const PrimFile& f) {
  writeFileAtomically(path, toBytes(f));
}

}  // namespace prime::io
