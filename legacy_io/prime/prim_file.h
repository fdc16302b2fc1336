// prim/PrimFile: an array of Prim records, indexed by primitive number.
#pragma once
#include <string>
#include <vector>

#include "legacy_io/prime/records.h"

namespace prime::io {

struct PrimFile {
  std::vector<PrimRecord> prims;
  PrimLayout layout = PrimLayout::Packed;  // layout the file was read in
};

std::vector<std::uint8_t> toBytes(const PrimFile& f);  // always byte-packed
// Reads either layout. How the layout is told apart: a size that is a whole
// number of records in only one layout decides; when both (or neither) fit,
// the layout whose first record has the affine column (m[0..2][3] = 0,
// m[3][3] = 1) in both matrices wins — every matrix the listing builds has it.
PrimFile primFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name);
PrimLayout detectPrimLayout(std::span<const std::uint8_t> bytes, const std::string& name);
PrimFile readPrimFile(const std::string& path);
void writePrimFile(const std::string& path, const PrimFile& f);

}  // namespace prime::io
