// The Turbo C 2.0 on-disk representation (errata E05): `int` is a 16-bit
// little-endian two's-complement integer, `double` an 8-byte little-endian
// IEEE-754 value, `char` one byte, and structures are byte-packed by default.
// Records are serialised field by field through legacy_io/common/bytes.h.
#pragma once
#include <cstddef>

#include "legacy_io/common/bytes.h"

namespace prime::io {

inline constexpr std::size_t kTurboInt = 2;
inline constexpr std::size_t kTurboDouble = 8;

}  // namespace prime::io
