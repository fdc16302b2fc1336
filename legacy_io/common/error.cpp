#include "legacy_io/common/error.h"

#include <cstdio>

namespace prime::io {

std::string quotedWord(std::string_view word, std::size_t maxChars) {
  std::string out;
  for (unsigned char c : word) {
    if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (out.size() > maxChars) out = out.substr(0, maxChars) + "...";
  return "'" + out + "'";
}

std::string describe(const InputLocation& where) {
  std::string s = where.file;
  if (where.line) s += ":" + std::to_string(*where.line);
  if (where.line && where.column) s += ":" + std::to_string(*where.column);
  if (where.token) s += " (token " + std::to_string(*where.token) + ")";
  if (where.byte) s += " (byte " + std::to_string(*where.byte) + ")";
  return s;
}

// Every message, whoever composed it, shows control bytes escaped: a NUL cut
// the message short and an escape sequence drove the terminal (a CGL
// record's name quoted its keyword as written). Line breaks and tabs that a
// message lays out stay.
static std::string visible(std::string text) {
  std::string out;
  out.reserve(text.size());
  for (const unsigned char c : text) {
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

static std::string compose(const InputLocation& where, const std::string& field,
                           const std::string& expected, const std::string& found) {
  return visible(describe(where) + ": " + field + ": expected " + expected + ", found " + found);
}

InputError::InputError(InputLocation where, std::string field, std::string expected,
                       std::string found)
    : std::runtime_error(compose(where, field, expected, found)),
      where_(std::move(where)),
      field_(std::move(field)),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

InputError::InputError(InputLocation where, std::string message)
    : std::runtime_error(visible(describe(where) + ": " + message)), where_(std::move(where)) {}

}  // namespace prime::io
