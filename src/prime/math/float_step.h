// std::nextafter(x, +infinity) and std::nextafter(x, -infinity), bit for bit,
// written out: no call into libm (a secondary ray's origin is rounded away
// from its surface on every axis, several times a ray).
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace prime {

// The next double after x towards +infinity (up) or -infinity (down).
inline double stepAway(double x, bool up) {
  if (std::isnan(x)) return x;
  if (x == 0.0)
    return up ? std::numeric_limits<double>::denorm_min()
              : -std::numeric_limits<double>::denorm_min();
  if (std::isinf(x)) {
    if ((x > 0.0) == up) return x;
    return up ? std::numeric_limits<double>::lowest() : std::numeric_limits<double>::max();
  }
#if defined(__cpp_lib_bit_cast)
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>((x > 0.0) == up ? bits + 1 : bits - 1);
#else  // the web build's libc++ (docs/web.md): the same, by the builtin std::bit_cast is
  const auto bits = __builtin_bit_cast(std::uint64_t, x);
  return __builtin_bit_cast(double, (x > 0.0) == up ? bits + 1 : bits - 1);
#endif
}

}  // namespace prime
