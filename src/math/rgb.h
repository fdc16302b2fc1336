// A colour as three doubles (red, green, blue), unquantised: what a system's
// tracer returns for a ray before its own film turns it into bytes. One
// definition for every system (PRIME's Define.h: RGB is double[3]).
#pragma once
#include <array>

namespace prime {

using Rgb = std::array<double, 3>;

}  // namespace prime
