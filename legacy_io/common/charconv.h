// Doubles to and from text exactly: std::from_chars (the nearest double) and
// std::to_chars (the shortest text that reads back the same). The web build's
// C++ library (emscripten 3.1.6's libc++) has neither for floating point, so
// there the same two contracts are kept with the C library's correctly
// rounded strtod and snprintf (docs/web.md): from_chars's grammar (an optional
// '-', digits with an optional point and exponent, inf, infinity, nan; no
// leading '+' or blank), and to_chars's choice of the shorter of fixed and
// scientific, fixed on a tie.
#pragma once
#include <charconv>
#include <system_error>

namespace prime::io {

// The same contracts by strtod and snprintf: what fromChars and toChars are
// where the C++ library has no floating-point charconv. Built everywhere, so
// that the native tests hold them to std::from_chars and std::to_chars.
std::from_chars_result portableFromChars(const char* first, const char* last, double& value);
std::to_chars_result portableToChars(char* first, char* last, double value);

#if defined(__cpp_lib_to_chars)
inline std::from_chars_result fromChars(const char* first, const char* last, double& value) {
  return std::from_chars(first, last, value);
}
inline std::to_chars_result toChars(char* first, char* last, double value) {
  return std::to_chars(first, last, value);
}
#else
inline std::from_chars_result fromChars(const char* first, const char* last, double& value) {
  return portableFromChars(first, last, value);
}
inline std::to_chars_result toChars(char* first, char* last, double value) {
  return portableToChars(first, last, value);
}
#endif

}  // namespace prime::io
