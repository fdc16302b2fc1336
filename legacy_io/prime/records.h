// The records of PRIME's binary databases (listing headers, lines 2380-2510),
// in memory as plain C++ values, with their Turbo C byte layouts.
//
//   Hue        72 bytes  9 doubles: kDR kDT fDR[3] tT kRH kTH indx
//   Obj         8 bytes  char opCode[4]; int l, r
//   ObjHeader  76 bytes  int numEntries, boundVol; Hue hue
//   Prim      291 bytes  char type; Matrix transform, inverse; int map[6][2],
//                        priority; double indx   (292 when word-aligned, -a)
//   MapHeader   4 bytes  int uScale, vScale
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "legacy_io/prime/turbo_c.h"
#include "src/math/matrix.h"

namespace prime::io {

inline constexpr int kMaxSurface = 6;  // Define.h MaxSurface
inline constexpr int kOut = 0, kIn = 1;

// The five primitive types (thesis Sec. 5.3.1). Each value is the type letter
// stored in Prim.type, which stays a char on disk and in PrimRecord: a loader
// turns it into a PrimType once, with primType(), and the code that traces a
// primitive switches on PrimType (every switch names all five).
enum class PrimType : char { Sphere = 'S', Cube = 'B', Cylinder = 'C', Cone = 'N', Pyramid = 'Y' };

// The type whose letter is `c` (case sensitive, as the listing's switches),
// or nothing for any other byte.
constexpr std::optional<PrimType> primType(char c) {
  switch (c) {
    case 'S':
      return PrimType::Sphere;
    case 'B':
      return PrimType::Cube;
    case 'C':
      return PrimType::Cylinder;
    case 'N':
      return PrimType::Cone;
    case 'Y':
      return PrimType::Pyramid;
    default:
      return std::nullopt;
  }
}

struct Hue {
  double kDR = 0, kDT = 0;
  std::array<double, 3> fDR{};
  double tT = 0, kRH = 0, kTH = 0, indx = 0;
  bool operator==(const Hue&) const = default;
};

struct ObjRecord {
  std::array<char, 4> opCode{};  // "+", "-", "&", "P" or "O", NUL-terminated, zero-padded
  std::int16_t l = 0, r = 0;
  char op() const { return opCode[0]; }
  bool operator==(const ObjRecord&) const = default;
};

struct ObjHeader {
  std::int16_t numEntries = 0;
  std::int16_t boundVol = -1;  // primitive number of the bounding volume, or -1
  Hue hue;
  bool operator==(const ObjHeader&) const = default;
};

struct PrimRecord {
  char type = 0;  // the byte on disk: a PrimType letter when valid (see primType)
  Matrix4 transform = identity4();
  Matrix4 inverse = identity4();
  std::array<std::array<std::int16_t, 2>, kMaxSurface> map{};  // [surface][Out/In]
  std::int16_t priority = 0;
  double indx = 0;  // never set by the listing; written as zero (K34)
  bool operator==(const PrimRecord&) const = default;
};

struct MapHeader {
  std::int16_t uScale = 0, vScale = 0;
  bool operator==(const MapHeader&) const = default;
};

enum class PrimLayout { Packed, WordAligned };

inline constexpr std::size_t kHueSize = 72, kObjSize = 8, kObjHeaderSize = 76,
                             kPrimSizePacked = 291, kPrimSizeAligned = 292, kMapHeaderSize = 4;

// Surfaces per primitive type (AddPrim's switch): S 1, B 6, C 3, N 2, Y 5.
int surfaceCount(PrimType type);
const char* primTypeName(PrimType type);  // "sphere", "cube", ...
// The same for a type byte as read: 0 and "unknown" for a byte primType()
// does not know.
int surfaceCount(char type);
const char* primTypeName(char type);

void encode(ByteWriter& w, const Hue& h);
void encode(ByteWriter& w, const ObjRecord& o);
void encode(ByteWriter& w, const ObjHeader& h);
void encode(ByteWriter& w, const PrimRecord& p, PrimLayout layout = PrimLayout::Packed);
void encode(ByteWriter& w, const MapHeader& h);

Hue decodeHue(ByteReader& r);
ObjRecord decodeObj(ByteReader& r);
ObjHeader decodeObjHeader(ByteReader& r);
PrimRecord decodePrim(ByteReader& r, PrimLayout layout = PrimLayout::Packed);
MapHeader decodeMapHeader(ByteReader& r);

}  // namespace prime::io
