#include "legacy_io/common/text_reader.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "legacy_io/common/charconv.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"

namespace prime::io {

std::string normalizeLineBreaks(std::string text) {
  if (text.find('\r') == std::string::npos) return text;
  std::size_t out = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r') {
      text[out++] = '\n';
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;  // CR LF: one break
    } else {
      text[out++] = text[i];
    }
  }
  text.resize(out);
  return text;
}

TextReader::TextReader(std::string text, std::string display)
    : text_(normalizeLineBreaks(std::move(text))), display_(std::move(display)) {
  // M41: a ^Z ends the text (also of a text that came from no file); M35: a
  // UTF-8 byte order mark (an editor's, never the listing's) is skipped, as
  // every system's readers skip it.
  endAtDosEof(text_);
  pos_ = bomLength(text_);
}

TextReader TextReader::open(const std::string& path, const std::string& display) {
  InputFileOptions options;
  options.what = "a text input";
  options.display = display;
  return TextReader(readInputText(path, options), display);
}

void TextReader::skipBlanks() {
  while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
}

std::string TextReader::peekWord() const {
  std::size_t end = pos_;
  while (end < text_.size() && !std::isspace(static_cast<unsigned char>(text_[end])) &&
         end - pos_ < 40)
    ++end;
  if (end == pos_) return "end of file";
  // Control bytes and NUL escaped (M35): a NUL must not cut the message.
  // (In double quotes, as this reader's messages always showed words.)
  std::string word = quotedWord(std::string_view(text_).substr(pos_, end - pos_), 40);
  word.front() = word.back() = '"';
  return word;
}

void TextReader::fail(const std::string& field, const std::string& expected,
                      const std::string& found) const {
  // At the end of the file the missing value belongs after the last word read.
  const int line = pos_ >= text_.size() ? lastTokenLine_ : line_;
  throw InputError({display_, line, std::nullopt}, field, expected, found);
}

bool TextReader::atEnd() {
  skipBlanks();
  return pos_ >= text_.size();
}

std::string TextReader::token(const std::string& field) {
  skipBlanks();
  if (pos_ >= text_.size()) fail(field, "a word", "end of file");
  std::size_t end = pos_;
  while (end < text_.size() && !std::isspace(static_cast<unsigned char>(text_[end]))) ++end;
  std::string word = text_.substr(pos_, end - pos_);
  pos_ = end;
  lastTokenLine_ = line_;
  return word;
}

double TextReader::number(const std::string& field) {
  skipBlanks();
  if (pos_ >= text_.size()) fail(field, "a number", "end of file (too few numbers)");
  const char* begin = text_.data() + pos_;
  const char* end = text_.data() + text_.size();
  const bool plus = *begin == '+';
  if (plus) ++begin;  // from_chars does not take a leading '+', fscanf does
  double value = 0;
  auto [ptr, ec] = fromChars(begin, end, value);
  const bool endsCleanly = ptr == end || std::isspace(static_cast<unsigned char>(*ptr));
  // "+-5": one sign only (from_chars would read the '-' after the skipped '+').
  // M35: 1e309 and 1e-400 are numbers, out of double's range.
  if (ec == std::errc::result_out_of_range && endsCleanly && !(plus && *begin == '-'))
    fail(field, "a number within double's range (about 2.2e-308 to 1.8e308 in size, or 0)",
         peekWord() + " (out of range)");
  if (ec != std::errc() || !endsCleanly || (plus && *begin == '-'))
    fail(field, "a number", peekWord());
  if (!std::isfinite(value)) fail(field, "a finite number", peekWord() + " (NaN/Inf not allowed)");
  pos_ = static_cast<std::size_t>(ptr - text_.data());
  lastTokenLine_ = line_;
  return value;
}

std::int16_t TextReader::int16(const std::string& field) {
  skipBlanks();
  if (pos_ >= text_.size()) fail(field, "an integer", "end of file (too few numbers)");
  const char* begin = text_.data() + pos_;
  const char* end = text_.data() + text_.size();
  const bool plus = *begin == '+';
  if (plus) ++begin;
  long long value = 0;
  auto [ptr, ec] = std::from_chars(begin, end, value);
  const bool endsCleanly = ptr == end || std::isspace(static_cast<unsigned char>(*ptr));
  if (ec == std::errc::result_out_of_range && endsCleanly && !(plus && *begin == '-'))
    fail(field, "an integer in -32768..32767 (Turbo C's 16-bit int)",
         peekWord() + " (out of range)");
  if (ec != std::errc() || !endsCleanly || (plus && *begin == '-'))
    fail(field, "an integer", peekWord());
  if (value < -32768 || value > 32767)
    fail(field, "an integer in -32768..32767 (Turbo C's 16-bit int)", peekWord());
  pos_ = static_cast<std::size_t>(ptr - text_.data());
  lastTokenLine_ = line_;
  return static_cast<std::int16_t>(value);
}

char TextReader::firstChar(const std::string& field) {
  if (pos_ >= text_.size())
    fail(field, "a type letter at the very start of the file", "an empty file");
  const char c = text_[pos_];  // (after a byte order mark, M35)
  if (std::isspace(static_cast<unsigned char>(c)))
    fail(field, "a type letter as the file's first byte (the listing reads it with %c, K36)",
         "a blank");
  ++pos_;
  return c;
}

}  // namespace prime::io
