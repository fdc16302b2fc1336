// One error type for every bad input: it names the file, the place in it
// (line for text, byte offset for binary), the field, what was expected and
// what was found, so a user can go straight to the mistake.
#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace prime::io {

struct InputLocation {
  std::string file;                                  // path as the user would recognise it
  std::optional<int> line = std::nullopt;            // 1-based, for text files
  std::optional<std::uint64_t> byte = std::nullopt;  // 0-based offset, for binary files
  std::optional<int> column = std::nullopt;          // 1-based, for token streams (with line)
  std::optional<int> token = std::nullopt;           // 1-based token number, for token streams
};

// An input's fault, as the message names it: file, line or byte, field, what
// was expected and what was found. what() shows control bytes escaped as
// \xNN (line breaks and tabs excepted), whatever the parts held.
class InputError : public std::runtime_error {
 public:
  InputError(InputLocation where, std::string field, std::string expected, std::string found);
  // For errors that are not about one field (missing file, unsafe path ...).
  InputError(InputLocation where, std::string message);

  const InputLocation& where() const { return where_; }
  const std::string& field() const { return field_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  InputLocation where_;
  std::string field_, expected_, found_;
};

// A word of an input as an error message shows it: quoted, control bytes
// escaped as \xNN (a NUL must not cut the message), cut after `maxChars`
// characters with "...".
std::string quotedWord(std::string_view word, std::size_t maxChars);

// "file:line: ", "file:line:column (token N): ", "file (byte N): " or "file: ".
std::string describe(const InputLocation& where);

}  // namespace prime::io
