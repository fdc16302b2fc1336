// Shared by the stress suite's sources (not part of its interface, stress.h).
#pragma once
#include <limits>

namespace prime::stress {

using LD = long double;
inline constexpr double kU = std::numeric_limits<double>::epsilon() / 2;  // unit roundoff
inline constexpr LD kPi = 3.141592653589793238462643383279502884L;

}  // namespace prime::stress
