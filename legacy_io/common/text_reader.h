// A scanf-like reader for PRIME's text inputs that knows where it is, so that
// every error names the file, the line, the field, what was expected and what
// was found. It reads exactly what the listing's fscanf calls read:
//   %lf -> number(), %d -> int16() (Turbo C's int is 16 bits), %s -> token(),
//   %c at byte 0 -> firstChar().
#pragma once
#include <cstdint>
#include <string>

#include "legacy_io/common/error.h"

namespace prime::io {

// Line breaks made uniform for every text reader: CR LF (DOS, Turbo C's text
// files) and a lone CR (classic Mac OS) become LF, so a file is read the same
// whatever wrote it, and line numbers in messages count its lines (M21).
std::string normalizeLineBreaks(std::string text);

class TextReader {
 public:
  // `display` is the name used in messages (e.g. "scene/prim/S1.txt").
  // Line breaks are normalized (normalizeLineBreaks).
  TextReader(std::string text, std::string display);
  static TextReader open(const std::string& path, const std::string& display);

  double number(const std::string& field);       // finite decimal number
  std::int16_t int16(const std::string& field);  // integer in -32768..32767
  std::string token(const std::string& field);   // next whitespace-separated word
  char firstChar(const std::string& field);      // byte 0, not skipping blanks (K36)
  bool atEnd();                                  // only blanks remain
  int line() const { return line_; }
  const std::string& name() const { return display_; }

  [[noreturn]] void fail(const std::string& field, const std::string& expected,
                         const std::string& found) const;

 private:
  void skipBlanks();
  std::string peekWord() const;  // the next word (for "found ..." messages)
  std::string text_, display_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int lastTokenLine_ = 1;  // where the last word read ended: blamed for "too few"
};

}  // namespace prime::io
