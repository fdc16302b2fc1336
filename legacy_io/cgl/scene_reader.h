// The CGL scene-description file reader's two layers, shared by its three
// files: the line layer (scene_lines.cpp: lines, tokens, comments, the OCR
// repairs CGL-E1..E10 of --lenient, located errors) and the record grammar
// (scene_records.cpp: program and display parameters, vertices, colour-vectors,
// surfaces, lights; scene_file.cpp: the sections in order, scene nodes, the
// DAG). Private to legacy_io/cgl; the interface is scene_file.h.
#pragma once
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "legacy_io/common/error.h"

namespace prime::cgl::detail {

constexpr std::uintmax_t kMaxBytes = std::uintmax_t{64} << 20;  // CGL-D2
constexpr std::string_view kBullet = "\xE2\x80\xA2";            // U+2022, the OCR's '*' (CGL-E1)

const std::vector<std::string>& programKeywords();
const std::vector<std::string>& displayKeywords();
const std::vector<std::string>& modelKeywords();
const std::vector<std::string>& lightKeywords();
const std::vector<std::string>& nodeKeywords();
bool among(const std::vector<std::string>& list, std::string_view w);
bool anyKeyword(std::string_view w);
std::string joined(const std::vector<std::string>& list);

// Control bytes escaped, long words cut, quoted: what a message shows. (legacy_io/common/error.h)
std::string shown(std::string_view word);

bool allDigits(std::string_view w);

enum class NumberStatus { Ok, NotNumber, OutOfRange, LoneSign };

// A decimal real: [+-] (digits [. digits] | . digits) [(e|E) [+-] digits].
// No hexadecimal, no nan or inf (CGL-Q13).
NumberStatus parseReal(std::string_view w, double& out);

bool isReal(std::string_view w);

struct Token {
  std::string text;
  int column = 1;
};

struct Line {
  int number = 0;
  std::string raw;
  std::vector<Token> tokens;
  bool comment = false;
};

enum class Section { First, Program, Display, Vertices, Surfaces, Ambience, Lights, Nodes };

class Reader {
 public:
  Reader(const std::string& text, const std::string& display, const ReadOptions& options)
      : display_(display), lenient_(options.lenient) {
    split(text);
  }

  SceneFile read();

  // ---- the record cursor ----------------------------------------------
  // A record starts at its header line; its fields are taken token by token.
  // When the line runs out, the lenient reader continues on the lines printed
  // before the header that belonged to no record (CGL-E8, scene nodes only)
  // and then on following lines that do not begin a record (CGL-E7).
  class Record {
   public:
    Record(Reader& r, std::size_t line, std::string name, Section section)
        : r_(r), line_(line), last_(line), name_(std::move(name)), section_(section) {}

    const std::string& name() const { return name_; }
    std::size_t lastLine() const { return last_; }

    // The next token of the record, or a located error naming `field`.
    const Token& take(const std::string& field, const std::string& expected) {
      while (tok_ >= r_.lines_[line_].tokens.size()) {
        if (!r_.lenient_ || !advance()) missing(field, expected);
      }
      last_token_ = &r_.lines_[line_].tokens[tok_];
      return r_.lines_[line_].tokens[tok_++];
    }
    // The token taken last (for a message about a value that parsed but is
    // not allowed).
    const Token& last() const { return *last_token_; }
    bool more() const { return tok_ < r_.lines_[line_].tokens.size(); }

    io::InputLocation at(const Token& t) const {
      io::InputLocation w{r_.display_, r_.lines_[line_].number};
      w.column = t.column;
      return w;
    }

    [[noreturn]] void fail(const Token& t, const std::string& field, const std::string& expected,
                           const std::string& found) const {
      throw io::InputError(at(t), name_ + ", field " + field, expected, found);
    }

    double real(const std::string& field, const std::string& expected = "a real number") {
      const Token& t = take(field, expected);
      double v = 0.0;
      switch (parseReal(t.text, v)) {
        case NumberStatus::Ok:
          return v;
        case NumberStatus::LoneSign:
          fail(t, field, expected,
               shown(t.text) +
                   " (a sign apart from its number; --lenient joins it to the number after it)");
        case NumberStatus::OutOfRange:
          fail(t, field, expected + " (finite)", shown(t.text) + " (out of range)");
        case NumberStatus::NotNumber:
          break;
      }
      fail(t, field, expected, shown(t.text));
    }
    double realIn(const std::string& field, double lo, double hi, const std::string& expected) {
      const double v = real(field, expected);
      if (!(v >= lo && v <= hi)) fail(last(), field, expected, shown(last().text));
      return v;
    }
    std::int64_t integer(const std::string& field, std::int64_t lo, std::int64_t hi,
                         const std::string& expected) {
      const Token& t = take(field, expected);
      std::string_view w = t.text;
      if (!w.empty() && w[0] == '+') w.remove_prefix(1);
      std::int64_t v = 0;
      const auto res = std::from_chars(w.data(), w.data() + w.size(), v);
      if (w.empty() || res.ec != std::errc() || res.ptr != w.data() + w.size()) {
        if (w == "l" ||
            (w.find('l') != std::string_view::npos && std::all_of(w.begin(), w.end(), [](char c) {
               return (c >= '0' && c <= '9') || c == 'l';
             })))
          fail(t, field, expected,
               shown(t.text) + " (the letter l for the digit 1? --lenient reads it as 1)");
        fail(t, field, expected, shown(t.text));
      }
      if (v < lo || v > hi) fail(t, field, expected, shown(t.text));
      return v;
    }
    // The record's number (its first field): digits only; the lenient
    // reader reads a letter l among them as the digit 1 (CGL-E4).
    int count(const std::string& expected, std::optional<int> must) {
      const Token& t = take("count", expected);
      std::string w = t.text;
      if (r_.lenient_ && !allDigits(w) && w.find('l') != std::string::npos &&
          std::all_of(w.begin(), w.end(),
                      [](char c) { return (c >= '0' && c <= '9') || c == 'l'; })) {
        std::replace(w.begin(), w.end(), 'l', '1');
        r_.repair(r_.lines_[line_].number, "read the letter 'l' of the count " + shown(t.text) +
                                               " as the digit 1: " + w + " (CGL-E4)");
      }
      if (!allDigits(w) || w.size() > 9) {
        std::string found = shown(t.text);
        if (w.find('l') != std::string::npos)
          found += " (the letter l for the digit 1? --lenient reads it as 1)";
        fail(t, "count", expected, found);
      }
      const int v = std::stoi(w);
      if (must && v != *must) fail(t, "count", expected, shown(t.text));
      return v;
    }
    std::string keyword(const std::string& field, const std::vector<std::string>& valid,
                        const std::string& hint = "") {
      const std::string expected = "one of " + joined(valid);
      const Token& t = take(field, expected);
      if (!among(valid, t.text)) fail(t, field, expected, shown(t.text) + hint);
      return t.text;
    }
    char axis(const std::string& field) { return keyword(field, {"x", "y", "z"})[0]; }

   private:
    bool advance() {
      if (section_ == Section::Nodes && !r_.orphans_.empty()) {
        const std::size_t o = r_.orphans_.front();
        r_.orphans_.pop_front();
        r_.repair(r_.lines_[o].number, "took the line " + shown(r_.lines_[o].raw) +
                                           ", printed before the header of " + name_ + " (line " +
                                           std::to_string(r_.lines_[line_].number) +
                                           "), as that record's missing fields (CGL-E8)");
        line_ = o;
        tok_ = 0;
        return true;
      }
      const std::size_t j = r_.nextContent(last_ + 1);
      if (j >= r_.lines_.size() || j >= r_.boundary_ || r_.beginsRecord(j, section_)) return false;
      r_.repair(r_.lines_[j].number, "continued " + name_ + " (header on line " +
                                         std::to_string(r_.lines_[last_].number) +
                                         ", too few fields) on this line (CGL-E7)");
      line_ = last_ = j;
      tok_ = 0;
      return true;
    }
    [[noreturn]] void missing(const std::string& field, const std::string& expected) const {
      io::InputLocation w{r_.display_, r_.lines_[line_].number};
      std::string found = "end of line";
      const std::size_t j = r_.nextContent(last_ + 1);
      if (!r_.lenient_ && j < r_.lines_.size() && !r_.beginsRecord(j, section_))
        found += " (the fields may continue on line " + std::to_string(r_.lines_[j].number) +
                 ": --lenient reads continuation lines)";
      throw io::InputError(w, name_ + ", field " + field, expected, found);
    }

    Reader& r_;
    std::size_t line_, last_;  // the current line; the last line read in file order
    std::size_t tok_ = 0;
    const Token* last_token_ = nullptr;
    std::string name_;
    Section section_;
  };

  // ---- lines ----------------------------------------------------------
  void split(const std::string& text);

  void classify(Line& l);

  std::size_t nextContent(std::size_t from) const;

  // Does line j begin a record? `<count> <keyword>` anywhere; in the vertex
  // section a line whose first word is an unsigned integer.
  bool beginsRecord(std::size_t j, Section section) const;
  bool isCount(const std::string& w) const;

  void repair(int line, std::string what);
  void warn(const io::InputLocation& where, std::string what);
  io::InputLocation lineAt(std::size_t j) const;

  // The header line of the next record, or a located error at end of file.
  std::size_t header(const std::string& what);
  void done(const Record& r) { next_ = r.lastLine() + 1; }

  // What a strict reader says about a comment the lenient one recognises.
  std::string commentHint(const Line& l) const;
  // What a strict reader says about damage the lenient one repairs.
  std::string hintFor(const Line& l) const;
  // A located error when the next line cannot begin the record expected.
  [[noreturn]] void notARecord(std::size_t j, const std::string& what, const std::string& expected);

  // ---- sections -------------------------------------------------------
  void numbersOfThings();
  void programParameter(int k);
  void displayParameter(int k);
  void vertex(int n);
  void surface(int n);
  void ambience();
  void light(int n);
  void node(int n);
  void splineNode(Record& r, NodeRecord& d, const std::string& name);
  void checkDag();
  Spectrum colourVector(const std::string& what, Section section);
  Spectrum strictColourVector(const std::string& what);
  Spectrum lenientColourVector(const std::string& what, Section section);
  Spectrum padColourVector(const std::vector<double>& values, const std::vector<int>& perLine,
                           std::size_t first, const std::string& what);
  void checkReflectance(double v, const io::InputLocation& where, const std::string& what,
                        const std::string& field, const std::string& text) const;
  std::size_t findAmbienceBoundary() const;

  std::vector<Line> lines_;
  std::string display_;
  bool lenient_;
  SceneFile scene_;
  std::size_t next_ = 0;
  std::size_t boundary_ = std::numeric_limits<std::size_t>::max();
  std::deque<std::size_t> orphans_;  // scene nodes: parameter lines printed before their header
  std::optional<std::size_t> sightTowardsLine_;
  std::string lastTexture_;
  io::InputLocation lastTextureWhere_;
};

}  // namespace prime::cgl::detail
