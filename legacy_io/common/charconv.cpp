#include "legacy_io/common/charconv.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace prime::io {

namespace {

bool same(const char* a, const char* last, const char* word) {
  const std::size_t n = std::strlen(word);
  if (static_cast<std::size_t>(last - a) < n) return false;
  for (std::size_t i = 0; i < n; ++i)
    if ((a[i] | 0x20) != word[i]) return false;
  return true;
}

bool digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

std::from_chars_result portableFromChars(const char* first, const char* last, double& value) {
  const char* p = first;
  const bool minus = p < last && *p == '-';
  if (minus) ++p;
  if (same(p, last, "inf")) {
    p += same(p, last, "infinity") ? 8 : 3;
    value = minus ? -HUGE_VAL : HUGE_VAL;
    return {p, std::errc()};
  }
  if (same(p, last, "nan")) {
    p += 3;
    if (p < last && *p == '(') {  // nan(n-char-sequence)
      const char* q = p + 1;
      while (q < last && (digit(*q) || ((*q | 0x20) >= 'a' && (*q | 0x20) <= 'z') || *q == '_'))
        ++q;
      if (q < last && *q == ')') p = q + 1;
    }
    value = minus ? -NAN : NAN;
    return {p, std::errc()};
  }
  const char* start = p;
  int digits = 0;
  while (p < last && digit(*p)) ++p, ++digits;
  if (p < last && *p == '.') {
    ++p;
    while (p < last && digit(*p)) ++p, ++digits;
  }
  if (digits == 0) return {first, std::errc::invalid_argument};
  if (p < last && (*p == 'e' || *p == 'E')) {
    const char* q = p + 1;
    if (q < last && (*q == '+' || *q == '-')) ++q;
    if (q < last && digit(*q)) {
      while (q < last && digit(*q)) ++q;
      p = q;
    }
  }
  const std::string text = (minus ? "-" : "") + std::string(start, p);
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  // Out of range as libstdc++ says it: an overflow, or an underflow to zero
  // (a subnormal result is a value).
  if (errno == ERANGE && (std::isinf(v) || v == 0)) return {p, std::errc::result_out_of_range};
  value = v;
  return {p, std::errc()};
}

std::to_chars_result portableToChars(char* first, char* last, double value) {
  std::string out;
  if (std::signbit(value)) out += '-';
  if (std::isnan(value)) {
    out += "nan";
  } else if (std::isinf(value)) {
    out += "inf";
  } else if (value == 0) {
    out += '0';
  } else {
    // The fewest significant digits that read back as the value.
    char sci[64];
    for (int precision = 0; precision <= 16; ++precision) {
      std::snprintf(sci, sizeof sci, "%.*e", precision, std::fabs(value));
      if (std::strtod(sci, nullptr) == std::fabs(value)) break;
    }
    // sci: d[.ddd]e[+-]xx
    const char* e = std::strchr(sci, 'e');
    std::string digits(1, sci[0]);
    if (sci[1] == '.') digits.append(sci + 2, static_cast<std::size_t>(e - (sci + 2)));
    const int exponent = std::atoi(e + 1);
    const int n = static_cast<int>(digits.size());
    std::string scientific = digits.substr(0, 1);
    if (n > 1) scientific += "." + digits.substr(1);
    char exp[16];
    std::snprintf(exp, sizeof exp, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
    scientific += exp;
    std::string fixed;
    if (exponent >= n - 1) {
      // A whole number: its exact digits, as to_chars writes them (not the
      // shortest digits padded with zeros).
      char whole[400];
      std::snprintf(whole, sizeof whole, "%.0f", std::fabs(value));
      fixed = whole;
    } else if (exponent < 0) {
      fixed = "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    } else {
      fixed = digits.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
              digits.substr(static_cast<std::size_t>(exponent + 1));
    }
    out += fixed.size() <= scientific.size() ? fixed : scientific;
  }
  if (static_cast<std::size_t>(last - first) < out.size())
    return {last, std::errc::value_too_large};
  std::memcpy(first, out.data(), out.size());
  return {first + out.size(), std::errc()};
}

}  // namespace prime::io
