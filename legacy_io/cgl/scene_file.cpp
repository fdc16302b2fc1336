// The CGL scene-description file reader (Sweeney 1985, Appendix 1). The
// choices the manual leaves open and the repairs of the lenient reader are in
// docs/cgl/deviations.md (ids CGL-E1 to CGL-E10, CGL-Q1 to CGL-Q15, CGL-D1 to CGL-D3), the
// format for users in docs/cgl/scene-format.md.
#include "legacy_io/cgl/scene_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>

#include "legacy_io/common/input_file.h"

namespace prime::cgl {

namespace {

constexpr std::uintmax_t kMaxBytes = std::uintmax_t{64} << 20;  // CGL-D2
constexpr std::string_view kBullet = "\xE2\x80\xA2";            // U+2022, the OCR's '*' (CGL-E1)

const std::vector<std::string>& programKeywords() {
  static const std::vector<std::string> k = {
      "output", "yhigh",      "ylow",       "xleft", "xright",      "depth",  "shadows",
      "memory", "brightness", "background", "quiet", "aathreshold", "aalevel"};
  return k;
}
const std::vector<std::string>& displayKeywords() {
  static const std::vector<std::string> k = {"eye", "sight", "up", "dist", "viewport"};
  return k;
}
const std::vector<std::string>& modelKeywords() {
  static const std::vector<std::string> k = {"lambert", "phong", "cook"};
  return k;
}
const std::vector<std::string>& lightKeywords() {
  static const std::vector<std::string> k = {"infinity", "inscene"};
  return k;
}
const std::vector<std::string>& nodeKeywords() {
  static const std::vector<std::string> k = {"translate", "scale",   "rotate", "sphere", "cylinder",
                                             "polygon",   "fractal", "spline", "box",    "dummy"};
  return k;
}
bool among(const std::vector<std::string>& list, std::string_view w) {
  return std::find(list.begin(), list.end(), w) != list.end();
}
bool anyKeyword(std::string_view w) {
  return among(programKeywords(), w) || among(displayKeywords(), w) || among(modelKeywords(), w) ||
         among(lightKeywords(), w) || among(nodeKeywords(), w);
}
std::string joined(const std::vector<std::string>& list) {
  std::string s;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (i) s += i + 1 == list.size() ? " or " : ", ";
    s += list[i];
  }
  return s;
}

// Control bytes escaped, long words cut, quoted: what a message shows. (legacy_io/common/error.h)
std::string shown(std::string_view word) {
  return io::quotedWord(word, 60);
}

bool allDigits(std::string_view w) {
  return !w.empty() && std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; });
}

enum class NumberStatus { Ok, NotNumber, OutOfRange, LoneSign };

// A decimal real: [+-] (digits [. digits] | . digits) [(e|E) [+-] digits].
// No hexadecimal, no nan or inf (CGL-Q13).
NumberStatus parseReal(std::string_view w, double& out) {
  if (w == "+" || w == "-") return NumberStatus::LoneSign;
  std::size_t i = 0;
  const bool plus = !w.empty() && w[0] == '+';
  if (!w.empty() && (w[0] == '+' || w[0] == '-')) ++i;
  std::size_t digits = 0;
  while (i < w.size() && w[i] >= '0' && w[i] <= '9') ++i, ++digits;
  if (i < w.size() && w[i] == '.') {
    ++i;
    while (i < w.size() && w[i] >= '0' && w[i] <= '9') ++i, ++digits;
  }
  if (digits == 0) return NumberStatus::NotNumber;
  if (i < w.size() && (w[i] == 'e' || w[i] == 'E')) {
    ++i;
    if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
    std::size_t e = 0;
    while (i < w.size() && w[i] >= '0' && w[i] <= '9') ++i, ++e;
    if (e == 0) return NumberStatus::NotNumber;
  }
  if (i != w.size()) return NumberStatus::NotNumber;
  const std::string_view body = plus ? w.substr(1) : w;
  double v = 0.0;
  const auto r = std::from_chars(body.data(), body.data() + body.size(), v);
  if (r.ec == std::errc::result_out_of_range) {
    // An underflow is a zero for every field of the format; an overflow is refused.
    bool nonzero = false;
    for (char c : body) {
      if (c == 'e' || c == 'E') break;
      if (c >= '1' && c <= '9') nonzero = true;
    }
    const auto epos = body.find_first_of("eE");
    if (nonzero && epos != std::string_view::npos && body.substr(epos + 1).starts_with('-')) {
      out = 0.0;
      return NumberStatus::Ok;
    }
    return NumberStatus::OutOfRange;
  }
  if (r.ec != std::errc() || r.ptr != body.data() + body.size() || !std::isfinite(v))
    return NumberStatus::OutOfRange;
  out = v;
  return NumberStatus::Ok;
}

bool isReal(std::string_view w) {
  double v;
  return parseReal(w, v) == NumberStatus::Ok;
}

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
  void split(const std::string& text) {
    std::size_t pos = 0;
    if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) pos = 3;
    int number = 0;
    while (pos < text.size() || (pos == text.size() && number == 0)) {
      std::size_t end = text.find_first_of("\r\n", pos);
      if (end == std::string::npos) end = text.size();
      Line l;
      l.number = ++number;
      l.raw = text.substr(pos, end - pos);
      int column = 1;
      std::size_t i = 0;
      while (i < l.raw.size()) {
        while (i < l.raw.size() &&
               (l.raw[i] == ' ' || l.raw[i] == '\t' || l.raw[i] == '\f' || l.raw[i] == '\v'))
          ++i, ++column;
        if (i >= l.raw.size()) break;
        Token t;
        t.column = column;
        while (i < l.raw.size() && l.raw[i] != ' ' && l.raw[i] != '\t' && l.raw[i] != '\f' &&
               l.raw[i] != '\v')
          t.text += l.raw[i++], ++column;
        l.tokens.push_back(std::move(t));
      }
      classify(l);
      lines_.push_back(std::move(l));
      if (end >= text.size()) break;
      pos = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
      if (pos >= text.size()) break;
    }
  }

  void classify(Line& l) {
    if (l.tokens.empty()) {
      l.comment = true;
      return;
    }
    const std::string& first = l.tokens[0].text;
    if (first[0] == '*') {
      l.comment = true;
      return;
    }
    if (!lenient_) return;
    if (std::string_view(first).starts_with(kBullet) ||
        std::string_view(first).starts_with("\\*")) {
      l.comment = true;
      repair(l.number, std::string("read '") + (first[0] == '\\' ? "\\*" : std::string(kBullet)) +
                           "' as the comment mark '*' (CGL-E1)");
      return;
    }
    if (l.tokens.size() == 1 && first == "vertices") {
      l.comment = true;
      repair(l.number, "read the bare word 'vertices' as the comment '* vertices' (CGL-E6)");
      return;
    }
    // A lone sign glued to the number after it: '+ 1.0' -> '+1.0' (CGL-E5).
    int joins = 0;
    for (std::size_t k = 0; k + 1 < l.tokens.size(); ++k) {
      const std::string& t = l.tokens[k].text;
      const std::string& n = l.tokens[k + 1].text;
      if ((t == "+" || t == "-") && !n.empty() && n[0] != '+' && n[0] != '-' && isReal(n)) {
        l.tokens[k].text += n;
        l.tokens.erase(l.tokens.begin() + static_cast<std::ptrdiff_t>(k) + 1);
        ++joins;
      }
    }
    if (joins) {
      std::string now;
      for (const auto& t : l.tokens) now += (now.empty() ? "" : " ") + t.text;
      repair(l.number, "joined " + std::to_string(joins) + " lone sign" + (joins > 1 ? "s" : "") +
                           " to the number after " + (joins > 1 ? "each" : "it") + ": " +
                           shown(now) + " (CGL-E5)");
    }
  }

  std::size_t nextContent(std::size_t from) const {
    while (from < lines_.size() && lines_[from].comment) ++from;
    return from;
  }

  // Does line j begin a record? `<count> <keyword>` anywhere; in the vertex
  // section a line whose first word is an unsigned integer.
  bool beginsRecord(std::size_t j, Section section) const {
    const Line& l = lines_[j];
    if (l.comment || l.tokens.empty()) return false;
    if (!isCount(l.tokens[0].text)) return false;
    if (section == Section::Vertices) return true;
    return l.tokens.size() >= 2 && anyKeyword(l.tokens[1].text);
  }
  bool isCount(const std::string& w) const {
    if (allDigits(w)) return true;
    return lenient_ && w.find('l') != std::string::npos &&
           std::all_of(w.begin(), w.end(),
                       [](char c) { return (c >= '0' && c <= '9') || c == 'l'; });
  }

  void repair(int line, std::string what) {
    scene_.repairs.push_back({io::InputLocation{display_, line}, std::move(what)});
  }
  void warn(const io::InputLocation& where, std::string what) {
    scene_.warnings.push_back({where, std::move(what)});
  }
  io::InputLocation lineAt(std::size_t j) const {
    return {display_, j < lines_.size() ? lines_[j].number : lines_.back().number};
  }

  // The header line of the next record, or a located error at end of file.
  std::size_t header(const std::string& what) {
    const std::size_t j = nextContent(next_);
    if (j >= lines_.size())
      throw io::InputError(io::InputLocation{display_, lines_.back().number}, what, "a record",
                           "end of file");
    if (!lenient_ && !commentHint(lines_[j]).empty())
      notARecord(j, what, "a record (or a comment, which begins with '*')");
    return j;
  }
  void done(const Record& r) { next_ = r.lastLine() + 1; }

  // What a strict reader says about a comment the lenient one recognises.
  std::string commentHint(const Line& l) const {
    if (l.tokens.empty()) return "";
    const std::string& f = l.tokens[0].text;
    if (std::string_view(f).starts_with(kBullet) || std::string_view(f).starts_with("\\*"))
      return " (a comment begins with '*'; --lenient also reads '\xE2\x80\xA2' and '\\*' as "
             "comment "
             "marks)";
    if (l.tokens.size() == 1 && f == "vertices")
      return " (a comment begins with '*'; --lenient reads a bare 'vertices' line as a comment)";
    return "";
  }
  // What a strict reader says about damage the lenient one repairs.
  std::string hintFor(const Line& l) const {
    if (l.tokens.empty()) return "";
    if (const std::string c = commentHint(l); !c.empty()) return c;
    const std::string& f = l.tokens[0].text;
    if (f.find('l') != std::string::npos &&
        std::all_of(f.begin(), f.end(), [](char c) { return (c >= '0' && c <= '9') || c == 'l'; }))
      return " (the letter l for the digit 1? --lenient reads it as 1)";
    return "";
  }
  // A located error when the next line cannot begin the record expected.
  [[noreturn]] void notARecord(std::size_t j, const std::string& what,
                               const std::string& expected) {
    const Line& l = lines_[j];
    io::InputLocation w{display_, l.number};
    w.column = l.tokens.empty() ? 1 : l.tokens[0].column;
    const std::size_t start = l.raw.find_first_not_of(" \t\f\v");
    throw io::InputError(
        w, what, expected,
        shown(start == std::string::npos ? l.raw : l.raw.substr(start)) + hintFor(l));
  }

  // ---- sections -------------------------------------------------------
  void numbersOfThings();
  void programParameter(int k);
  void displayParameter(int k);
  void vertex(int n);
  void surface(int n);
  void ambience();
  void light(int n);
  void node(int n);
  void checkDag();
  Spectrum colourVector(const std::string& what, Section section);
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
};

SceneFile Reader::read() {
  scene_.path = display_;
  numbersOfThings();
  const auto& n = scene_.numbers;
  for (int k = 0; k < n.programParameters; ++k) programParameter(k);
  for (int k = 0; k < n.displayParameters; ++k) displayParameter(k);
  for (int k = 1; k <= n.vertices; ++k) vertex(k);
  if (lenient_) boundary_ = findAmbienceBoundary();
  for (int k = 1; k <= n.surfaces; ++k) surface(k);
  boundary_ = std::numeric_limits<std::size_t>::max();
  ambience();
  for (int k = 1; k <= n.lights; ++k) light(k);
  for (int k = 1; k <= n.nodes; ++k) node(k);
  if (!orphans_.empty()) {
    const std::size_t o = orphans_.front();
    notARecord(o, "scene nodes",
               "no more lines (the parameters on this line belong to no node's header)");
  }
  const std::size_t rest = nextContent(next_);
  if (rest < lines_.size())
    notARecord(rest, "end of the scene",
               "end of file (the first record counts " + std::to_string(n.nodes) +
                   " scene nodes, all read)");
  checkDag();
  if (scene_.program.given.brightness && scene_.program.given.background)
    warn({display_, scene_.numbers.where.line},
         "both brightness and background are given; the original program accepted only one of "
         "them, depending on -Dbackground (Appendix 1 section 5; CGL-Q14)");
  return std::move(scene_);
}

void Reader::numbersOfThings() {
  const std::size_t j = header("numbers-of-things");
  Record r(*this, j, "numbers-of-things", Section::First);
  auto& n = scene_.numbers;
  n.where = lineAt(j);
  const std::string e = "a count 0 or more";
  n.programParameters = static_cast<int>(
      r.integer("number-of-program-parameters", 0, 1000000, e + " (7 integers open the file)"));
  n.displayParameters = static_cast<int>(r.integer("number-of-display-parameters", 0, 1000000, e));
  n.vertices = static_cast<int>(r.integer("number-of-vertices", 0, 100000000, e));
  n.surfaces = static_cast<int>(r.integer("number-of-surface-descriptors", 0, 100000000, e));
  n.lights = static_cast<int>(r.integer("number-of-light-sources", 0, 100000000, e));
  n.nodes = static_cast<int>(r.integer("number-of-scene-nodes", 1, 100000000,
                                       "a count 1 or more (a scene has at least its root; "
                                       "CGL-Q10)"));
  n.root = static_cast<int>(
      r.integer("DAG-root-node", 1, n.nodes, "a scene-node number 1-" + std::to_string(n.nodes)));
  done(r);
}

void Reader::programParameter(int k) {
  const std::size_t j = header("program parameter " + std::to_string(k + 1));
  const std::string name = "program parameter " + std::to_string(k + 1) + " of " +
                           std::to_string(scene_.numbers.programParameters);
  const Line& l = lines_[j];
  if (l.tokens.size() < 2 || !isCount(l.tokens[0].text))
    notARecord(j, name, "count keyword value (e.g. '1 depth 3')");
  Record r(*this, j, name, Section::Program);
  r.count("an integer", std::nullopt);  // "these restrictions are relaxed" (section 4)
  std::string hint;
  if (j < lines_.size() && l.tokens.size() >= 2 && anyKeyword(l.tokens[1].text))
    hint = " (a record of another section: the first record counts " +
           std::to_string(scene_.numbers.programParameters) + " program parameters)";
  const std::string kw = r.keyword("keyword", programKeywords(), hint);
  auto& p = scene_.program;
  auto& g = p.given;
  auto once = [&](bool& given) {
    if (given)
      warn(lineAt(j),
           "program parameter '" + kw + "' given again: the later value is used (CGL-Q4)");
    given = true;
  };
  const std::string pixel = "an integer 0-511 (Table 8)";
  if (kw == "output") {
    once(g.output);
    p.output = r.take("pathname", "a pathname").text;
  } else if (kw == "yhigh") {
    once(g.yhigh);
    p.yhigh = static_cast<int>(r.integer("yhigh", 0, 511, pixel));
  } else if (kw == "ylow") {
    once(g.ylow);
    p.ylow = static_cast<int>(r.integer("ylow", 0, 511, pixel));
  } else if (kw == "xleft") {
    once(g.xleft);
    p.xleft = static_cast<int>(r.integer("xleft", 0, 511, pixel));
  } else if (kw == "xright") {
    once(g.xright);
    p.xright = static_cast<int>(r.integer("xright", 0, 511, pixel));
  } else if (kw == "depth") {
    once(g.depth);
    p.depth = static_cast<int>(r.integer("depth", 0, 10, "an integer 0-10 (Table 8)"));
  } else if (kw == "shadows") {
    once(g.shadows);
    p.shadows = true;
  } else if (kw == "memory") {
    once(g.memory);
    p.memory = static_cast<int>(r.integer("memory", 1, 4096, "an integer, Mbytes, 1 or more"));
    if (p.memory > 24)
      warn(r.at(r.last()),
           "memory " + std::to_string(p.memory) +
               " Mbytes is above Table 8's 1-24 (the VAX's address space); a figure only "
               "in this port (CGL-Q3)");
  } else if (kw == "brightness") {
    once(g.brightness);
    p.brightness = r.realIn("brightness", 0.0, 1.0, "a real number 0.0-1.0 (Table 8)");
  } else if (kw == "background") {
    once(g.background);
    const std::string e = "an integer 0-255 (Table 8)";
    p.background[0] = static_cast<int>(r.integer("red", 0, 255, e));
    p.background[1] = static_cast<int>(r.integer("green", 0, 255, e));
    p.background[2] = static_cast<int>(r.integer("blue", 0, 255, e));
  } else if (kw == "quiet") {
    once(g.quiet);
    p.quiet = true;
  } else if (kw == "aathreshold") {
    once(g.aathreshold);
    const std::string e = "a real number above 0.0 (Table 8 advises 5.0-100.0)";
    const double v = r.realIn("aathreshold", std::numeric_limits<double>::min(),
                              std::numeric_limits<double>::max(), e);
    if (v < 5.0 || v > 100.0)
      warn(lineAt(j),
           "aathreshold " + std::to_string(v) + " is outside Table 8's 5.0-100.0 (CGL-Q2)");
    p.aathreshold = v;
  } else if (kw == "aalevel") {
    once(g.aalevel);
    const std::string e = "one of 0, 1, 2, 4 or 8 (section 5; 0 = no anti-aliasing, CGL-Q1)";
    const int v = static_cast<int>(r.integer("aalevel", 0, 8, e));
    if (v != 0 && v != 1 && v != 2 && v != 4 && v != 8)
      r.fail(r.last(), "aalevel", e, shown(r.last().text));
    p.aalevel = v;
  }
  done(r);
}

void Reader::displayParameter(int k) {
  const std::size_t j = header("display parameter " + std::to_string(k + 1));
  const std::string name = "display parameter " + std::to_string(k + 1) + " of " +
                           std::to_string(scene_.numbers.displayParameters);
  const Line& l = lines_[j];
  if (l.tokens.size() < 2 || !isCount(l.tokens[0].text))
    notARecord(j, name, "count keyword values (e.g. '1 eye 0.0 0.0 3.5')");
  Record r(*this, j, name, Section::Display);
  r.count("an integer", std::nullopt);
  std::string hint;
  if (anyKeyword(l.tokens[1].text))
    hint = " (a record of another section: the first record counts " +
           std::to_string(scene_.numbers.displayParameters) + " display parameters)";
  const std::string kw = r.keyword("keyword", displayKeywords(), hint);
  auto& d = scene_.display;
  auto xyz = [&](const std::string& what) {
    Vec3 v{};
    v[0] = r.real(what + " x");
    v[1] = r.real(what + " y");
    v[2] = r.real(what + " z");
    return v;
  };
  if (kw == "eye") {
    d.eye = xyz("eye");
    if (sightTowardsLine_)
      warn(lineAt(j), "the eye is set after 'sight towards' (line " +
                          std::to_string(lines_[*sightTowardsLine_].number) +
                          "), whose direction was taken from the eye as it was then; the manual: "
                          "\"the eye point should be set before the sight direction\" (CGL-Q5)");
  } else if (kw == "sight") {
    const std::string how = r.keyword("direction|towards", {"direction", "towards"});
    const Vec3 v = xyz(how == "towards" ? "point" : "direction");
    d.sight = how == "towards" ? v - d.eye : v;
    if (d.sight == Vec3{0, 0, 0})
      throw io::InputError(lineAt(j), name + ", field sight", "a direction other than (0, 0, 0)",
                           how == "towards" ? "the eye point itself" : "(0, 0, 0)");
    if (how == "towards") sightTowardsLine_ = j;
  } else if (kw == "up") {
    d.up = xyz("up");
    if (d.up == Vec3{0, 0, 0})
      throw io::InputError(lineAt(j), name + ", field up", "a direction other than (0, 0, 0)",
                           "(0, 0, 0)");
  } else if (kw == "dist") {
    d.dist = r.realIn("dist", std::numeric_limits<double>::min(),
                      std::numeric_limits<double>::max(), "a real number above 0.0");
  } else if (kw == "viewport") {
    const double lo = std::numeric_limits<double>::min(), hi = std::numeric_limits<double>::max();
    d.viewportHeight = r.realIn("height", lo, hi, "a real number above 0.0");
    d.viewportWidth = r.realIn("width", lo, hi, "a real number above 0.0");
  }
  done(r);
}

void Reader::vertex(int n) {
  const std::string name = "vertex " + std::to_string(n);
  const std::size_t j = header(name);
  Record r(*this, j, name, Section::Vertices);
  const std::string e = "the vertex number " + std::to_string(n) +
                        " (vertices are numbered consecutively from 1; the first record counts " +
                        std::to_string(scene_.numbers.vertices) + ")";
  if (!isCount(lines_[j].tokens[0].text)) notARecord(j, name + ", field count", e);
  r.count(e, n);
  Vec3 v{};
  v[0] = r.real("x");
  v[1] = r.real("y");
  v[2] = r.real("z");
  scene_.vertices.push_back(v);
  done(r);
}

// Lenient only (CGL-E10): the ambience descriptor is not introduced by a
// keyword, so a short colour-vector in the last surface could run on into it.
// It is found by counting back from the first light (or, with no lights, the
// first scene node): its 33 numbers come last and the one before them is k_a.
// Returns the k_a line (colour-vectors of surfaces stop before it).
std::size_t Reader::findAmbienceBoundary() const {
  std::size_t stop = lines_.size();
  for (std::size_t j = next_; j < lines_.size(); ++j) {
    const Line& l = lines_[j];
    if (l.comment || l.tokens.size() < 2 || !isCount(l.tokens[0].text)) continue;
    const std::string& kw = l.tokens[1].text;
    if ((scene_.numbers.lights > 0 && among(lightKeywords(), kw)) ||
        (scene_.numbers.lights == 0 && among(nodeKeywords(), kw))) {
      stop = j;
      break;
    }
  }
  // The nearest line before `stop` holding one number with at least 33
  // numbers after it is k_a (parameter lines of scene nodes printed before
  // their header may stand between the ambience and `stop`); failing that,
  // the line of the 34th number counted back.
  int numbers = 0;
  std::size_t fallback = std::numeric_limits<std::size_t>::max();
  for (std::size_t j = stop; j-- > next_;) {
    const Line& l = lines_[j];
    if (l.comment) continue;
    int here = 0;
    for (const auto& t : l.tokens) {
      if (!isReal(t.text)) break;
      ++here;
    }
    if (here == 1 && numbers >= kSpectrumSamples) return j;
    numbers += here;
    if (numbers >= kSpectrumSamples + 1 && fallback == std::numeric_limits<std::size_t>::max())
      fallback = j;
  }
  return fallback;
}

Spectrum Reader::colourVector(const std::string& what, Section section) {
  Spectrum s{};
  auto check = [&](double v, const io::InputLocation& where, const std::string& field,
                   const std::string& text) {
    if (v < 0.0)
      throw io::InputError(where, what + ", field " + field,
                           "a reflectance or intensity 0.0 or more (CGL-Q11)", shown(text));
  };
  const int rows[4] = {10, 10, 10, 3};
  if (!lenient_) {
    int k = 0;
    for (int row = 0; row < 4; ++row) {
      const std::string rowName = "colour-vector row " + std::to_string(row + 1) + " of 4";
      const std::size_t j = header(what + ", " + rowName);
      const Line& l = lines_[j];
      for (int c = 0; c < rows[row]; ++c, ++k) {
        const std::string field = "colour-vector sample " + std::to_string(k + 1) + " (" +
                                  std::to_string(380 + 10 * k) + " nm)";
        const std::string e =
            "a real number (a colour-vector is 33 numbers, written 10, 10, 10 "
            "and 3 to a line)";
        if (c >= static_cast<int>(l.tokens.size()))
          throw io::InputError(
              lineAt(j), what + ", field " + field, e,
              "end of line after " + std::to_string(c) + " numbers" +
                  (l.tokens.empty() ? "" : " (--lenient pads a short colour-vector)"));
        const Token& t = l.tokens[static_cast<std::size_t>(c)];
        io::InputLocation w = lineAt(j);
        w.column = t.column;
        double v = 0.0;
        const NumberStatus st = parseReal(t.text, v);
        if (st != NumberStatus::Ok)
          throw io::InputError(w, what + ", field " + field, e,
                               shown(t.text) + (c == 0 ? hintFor(l) : "") +
                                   (st == NumberStatus::LoneSign
                                        ? " (a sign apart from its number; --lenient joins it)"
                                        : ""));
        check(v, w, field, t.text);
        s[static_cast<std::size_t>(k)] = v;
      }
      next_ = j + 1;
    }
    return s;
  }
  // Lenient (CGL-E10): numbers flow over lines until 33 are read, stopping
  // at a line that begins a record, a line that is not numbers, or the
  // ambience descriptor; a short vector is padded (CGL-E2, CGL-E3).
  std::vector<double> values;
  std::vector<int> perLine;
  std::size_t first = lines_.size();
  for (;;) {
    if (values.size() == kSpectrumSamples) break;
    const std::size_t j = nextContent(next_);
    if (j >= lines_.size() || j >= boundary_ || beginsRecord(j, section)) break;
    const Line& l = lines_[j];
    int here = 0;
    for (const auto& t : l.tokens) {
      if (values.size() == kSpectrumSamples) break;
      double v = 0.0;
      if (parseReal(t.text, v) != NumberStatus::Ok) break;
      io::InputLocation w = lineAt(j);
      w.column = t.column;
      check(v, w, "colour-vector sample " + std::to_string(values.size() + 1), t.text);
      values.push_back(v);
      ++here;
    }
    if (here == 0) break;
    if (first == lines_.size()) first = j;
    perLine.push_back(here);
    next_ = j + 1;
  }
  if (values.empty()) {
    const std::size_t j = nextContent(next_);
    if (j >= lines_.size())
      throw io::InputError(lineAt(lines_.size() - 1), what + ", field colour-vector",
                           "33 real numbers", "end of file");
    notARecord(j, what + ", field colour-vector", "33 real numbers");
  }
  if (values.size() < kSpectrumSamples) {
    const int missing = kSpectrumSamples - static_cast<int>(values.size());
    std::vector<double> out;
    std::string how;
    // The layout 10/10/10/3 kept except for short rows among the first
    // three: each short row lost values at its end (CGL-E3).
    int shortfall = 0;
    if (perLine.size() == 4 && perLine[3] == 3) {
      for (int r = 0; r < 3; ++r)
        shortfall += std::max(0, 10 - perLine[static_cast<std::size_t>(r)]);
    }
    if (perLine.size() == 4 && perLine[3] == 3 && shortfall == missing &&
        std::all_of(perLine.begin(), perLine.begin() + 3, [](int c) { return c <= 10; })) {
      std::size_t k = 0;
      for (int r = 0; r < 4; ++r) {
        const int c = perLine[static_cast<std::size_t>(r)];
        for (int i = 0; i < c; ++i) out.push_back(values[k++]);
        for (int i = c; i < rows[r]; ++i) out.push_back(out.back());
        if (c < rows[r])
          how += (how.empty() ? "" : "; ") + std::string("row ") + std::to_string(r + 1) + " has " +
                 std::to_string(c) + " of " + std::to_string(rows[r]) +
                 " numbers: its last value repeated at its end";
      }
      how += " (CGL-E3)";
    } else {
      out = values;
      while (out.size() < kSpectrumSamples) out.push_back(values.back());
      char buf[64];
      std::snprintf(buf, sizeof buf, "%g", values.back());
      how = "the last value (" + std::string(buf) + ") repeated to sample 33" +
            (values.size() <= 3 ? std::string(": a flat spectrum") : std::string()) + " (CGL-E2)";
    }
    std::copy(out.begin(), out.end(), s.begin());
    repair(lines_[first].number, what + ": colour-vector of " + std::to_string(values.size()) +
                                     " numbers, not 33; padded: " + how);
  }
  if (values.size() == kSpectrumSamples &&
      !(perLine.size() == 4 && perLine[0] == 10 && perLine[1] == 10 && perLine[2] == 10)) {
    std::copy(values.begin(), values.end(), s.begin());
    repair(lines_[first].number, what + ": colour-vector read over " +
                                     std::to_string(perLine.size()) +
                                     " lines, not the 10/10/10/3 layout (CGL-E10)");
  } else if (values.size() == kSpectrumSamples) {
    std::copy(values.begin(), values.end(), s.begin());
  }
  return s;
}

void Reader::surface(int n) {
  const std::string base = "surface " + std::to_string(n);
  const std::size_t j = header(base);
  const Line& l = lines_[j];
  std::string name = base;
  if (l.tokens.size() >= 3) name += " (" + l.tokens[1].text + " " + l.tokens[2].text + ")";
  if (!isCount(l.tokens[0].text))
    notARecord(j, base + ", field count",
               "'" + std::to_string(n) +
                   " (lambert|phong|cook) (textured|normal) reflect refract "
                   "index'");
  Record r(*this, j, name, Section::Surfaces);
  r.count("the surface number " + std::to_string(n) +
              " (surfaces are numbered consecutively from 1; the first record counts " +
              std::to_string(scene_.numbers.surfaces) + ")",
          n);
  SurfaceRecord s;
  s.where = lineAt(j);
  const std::string model = r.keyword("model", modelKeywords());
  s.model = model == "lambert" ? ShadingModel::Lambert
            : model == "phong" ? ShadingModel::Phong
                               : ShadingModel::Cook;
  const std::string kind = r.keyword("textured|normal", {"textured", "normal"});
  s.textured = kind == "textured";
  if (s.model == ShadingModel::Cook && s.textured)
    throw io::InputError(s.where, name + ", field textured|normal",
                         "normal (there is no textured Cook form, Appendix 1 section 8)",
                         "'textured'");
  s.reflect = r.realIn("reflect", 0.0, 1.0, "a real number 0.0-1.0 (k_r; CGL-Q3)");
  s.refract = r.realIn("refract", 0.0, 1.0, "a real number 0.0-1.0 (k_t; CGL-Q3)");
  s.index = r.realIn("index", 0.0, std::numeric_limits<double>::max(),
                     "a real number 0.0 or more (the refractive index; present even if unused)");
  if (s.refract > 0.0 && !(s.index > 0.0))
    throw io::InputError(s.where, name + ", field index",
                         "a refractive index above 0.0 for a transparent surface (refract > 0)",
                         shown("0"));
  done(r);

  auto advise = [&](const io::InputLocation& w, const std::string& field, double v, double lo,
                    double hi) {
    if (v < lo || v > hi) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s, %s %g is outside the range %g-%g the manual advises",
                    name.c_str(), field.c_str(), v, lo, hi);
      warn(w, std::string(buf) + " (Appendix 1 section 8; CGL-Q3)");
    }
  };
  const double big = std::numeric_limits<double>::max();
  // The coefficients line.
  {
    std::size_t k = header(name + ", coefficients");
    const Line& cl = lines_[k];
    if (lenient_ && s.model == ShadingModel::Lambert && s.textured && !cl.tokens.empty() &&
        !isReal(cl.tokens[0].text) &&
        (cl.tokens[0].text[0] == '/' || cl.tokens[0].text == "last" ||
         (cl.tokens.size() >= 3 && isReal(cl.tokens[1].text) && isReal(cl.tokens[2].text)))) {
      s.diffuse = 7.0;
      repair(cl.number, name +
                            ": no diffuse line before the texture line; diffuse 7.0 assumed, "
                            "the value of the document's Figure 59 (CGL-E9)");
    } else {
      Record c(*this, k, name, Section::Surfaces);
      const std::string lo = "a real number 0.0 or more";
      std::string hint;
      if (!cl.tokens.empty() && !isReal(cl.tokens[0].text) && s.textured &&
          s.model == ShadingModel::Lambert)
        hint = " (the document's Figure 2 omits this line; --lenient assumes 7.0)";
      if (s.model == ShadingModel::Cook) {
        s.diffuse = c.realIn("diffuse", 0.0, big, lo + " (advised 0.0-1.0)");
        advise(lineAt(k), "diffuse", s.diffuse, 0.0, 1.0);
      } else {
        const Token& t = c.take("diffuse", lo);
        double v = 0.0;
        if (parseReal(t.text, v) != NumberStatus::Ok || v < 0.0)
          c.fail(t, "diffuse", lo + " (advised 0.0-20.0)", shown(t.text) + hint);
        s.diffuse = v;
        advise(lineAt(k), "diffuse", s.diffuse, 0.0, 20.0);
        if (s.model == ShadingModel::Phong) {
          s.specular = c.realIn("specular", 0.0, big, lo + " (advised 0.0-20.0)");
          advise(lineAt(k), "specular", s.specular, 0.0, 20.0);
          s.exponent = c.realIn("exponent", 0.0, big, lo + " (advised 10.0-100.0)");
          advise(lineAt(k), "exponent", s.exponent, 10.0, 100.0);
        }
      }
      done(c);
    }
  }
  if (s.textured) {
    const std::size_t k = header(name + ", texture");
    Record t(*this, k, name, Section::Surfaces);
    const Token& path = t.take("pathname|last", "a texture pathname or 'last'");
    if (path.text == "last") {
      if (lastTexture_.empty())
        t.fail(path, "pathname|last",
               "a texture pathname ('last' means the texture of an earlier textured surface, and "
               "there is none)",
               "'last'");
      s.texture = lastTexture_;
      s.textureLast = true;
    } else {
      double v;
      if (parseReal(path.text, v) == NumberStatus::Ok)
        t.fail(path, "pathname|last", "a texture pathname or 'last'", shown(path.text));
      s.texture = path.text;
      lastTexture_ = s.texture;
    }
    const double lo = std::numeric_limits<double>::min();
    s.umod = t.realIn("umod", lo, big, "a real number above 0.0 (the repeat count in u)");
    s.vmod = t.realIn("vmod", lo, big, "a real number above 0.0 (the repeat count in v)");
    done(t);
  } else {
    s.colour = colourVector(name, Section::Surfaces);
  }
  if (s.model == ShadingModel::Cook) {
    const std::size_t k = header(name + ", specular m");
    Record c(*this, k, name, Section::Surfaces);
    s.specular = c.realIn("specular", 0.0, big, "a real number 0.0 or more (advised 0.0-1.0)");
    advise(lineAt(k), "specular", s.specular, 0.0, 1.0);
    s.m = c.realIn("m", std::numeric_limits<double>::min(), big,
                   "a real number above 0.0 (the rms facet slope; advised 0.1-1.0)");
    advise(lineAt(k), "m", s.m, 0.1, 1.0);
    done(c);
    for (int a = 0; a < kFresnelAngles; ++a)
      s.fresnel.push_back(colourVector(name + ", fresnel colour-vector " + std::to_string(a + 1) +
                                           " of " + std::to_string(kFresnelAngles),
                                       Section::Surfaces));
  }
  scene_.surfaces.push_back(std::move(s));
}

void Reader::ambience() {
  const std::size_t j = header("ambience descriptor");
  Record r(*this, j, "ambience descriptor", Section::Ambience);
  auto& a = scene_.ambience;
  a.where = lineAt(j);
  {
    const Line& l = lines_[j];
    if (!l.tokens.empty() && !isReal(l.tokens[0].text) && !hintFor(l).empty())
      notARecord(j, "ambience descriptor, field k_a", "a real number 0.0 or more");
  }
  a.ka = r.realIn("k_a", 0.0, std::numeric_limits<double>::max(),
                  "a real number 0.0 or more (the ambient-reflection constant, advised 0.0-0.001)");
  if (a.ka > 0.001)
    warn(a.where,
         "ambience k_a is above the 0.0-0.001 the manual advises (Appendix 1 section "
         "10; CGL-Q3)");
  done(r);
  a.colour = colourVector("ambience descriptor", Section::Ambience);
}

void Reader::light(int n) {
  const std::string base = "light " + std::to_string(n);
  const std::size_t j = header(base);
  const Line& l = lines_[j];
  std::string name = base;
  if (l.tokens.size() >= 2) name += " (" + l.tokens[1].text + ")";
  if (!isCount(l.tokens[0].text))
    notARecord(j, base + ", field count",
               "'" + std::to_string(n) + " (infinity|inscene) x y z dw'");
  Record r(*this, j, name, Section::Lights);
  r.count("the light number " + std::to_string(n) +
              " (lights are numbered consecutively from 1; the first record counts " +
              std::to_string(scene_.numbers.lights) + ")",
          n);
  LightRecord L;
  L.where = lineAt(j);
  const std::string kind = r.keyword("infinity|inscene", lightKeywords());
  L.kind = kind == "infinity" ? LightKind::Infinity : LightKind::InScene;
  L.xyz[0] = r.real("x");
  L.xyz[1] = r.real("y");
  L.xyz[2] = r.real("z");
  if (L.kind == LightKind::Infinity && L.xyz == Vec3{0, 0, 0})
    throw io::InputError(L.where, name + ", field x y z",
                         "a direction to the light other than (0, 0, 0)", "(0, 0, 0)");
  L.dw = r.realIn("dw", 0.0, std::numeric_limits<double>::max(),
                  "a real number 0.0 or more (the solid angle, advised 0.0001-0.005)");
  if (L.dw < 0.0001 || L.dw > 0.005)
    warn(L.where, name +
                      ": dw outside the 0.0001-0.005 the manual calls useful (Appendix 1 "
                      "section 11; CGL-Q15)");
  done(r);
  L.colour = colourVector(name, Section::Lights);
  scene_.lights.push_back(L);
}

void Reader::node(int n) {
  const std::string base = "scene node " + std::to_string(n);
  std::size_t j = header(base);
  // Lines printed before the header, belonging to no record: the lenient
  // reader keeps them for the next header short of fields (CGL-E8).
  for (;;) {
    const Line& l = lines_[j];
    const bool recordLike = l.tokens.size() >= 2 && isCount(l.tokens[0].text) &&
                            std::isalpha(static_cast<unsigned char>(l.tokens[1].text[0])) &&
                            l.tokens[1].text != "x" && l.tokens[1].text != "y" &&
                            l.tokens[1].text != "z";
    if (recordLike || !lenient_) break;
    orphans_.push_back(j);
    next_ = j + 1;
    j = header(base);
  }
  const Line& l = lines_[j];
  std::string name = base;
  if (l.tokens.size() >= 2) name += " (" + l.tokens[1].text + ")";
  if (!isCount(l.tokens[0].text))
    notARecord(j, base + ", field count",
               "'" + std::to_string(n) + " keyword down right ...' (a scene node)");
  Record r(*this, j, name, Section::Nodes);
  r.count("the node number " + std::to_string(n) +
              " (scene nodes are numbered consecutively from 1; the first record counts " +
              std::to_string(scene_.numbers.nodes) + ")",
          n);
  NodeRecord d;
  d.number = n;
  d.where = lineAt(j);
  const std::string kw = r.keyword("keyword", nodeKeywords());
  const int nodes = scene_.numbers.nodes;
  const std::string link = "a scene-node number 0-" + std::to_string(nodes) + " (0 = none)";
  d.down = static_cast<int>(r.integer("down", 0, nodes, link));
  d.right = static_cast<int>(r.integer("right", 0, nodes, link));
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::min();
  // A reference into a table: 1..size, refused outright when the table is empty.
  auto reference = [&](const std::string& field, const char* table, int size) {
    const std::string e = size == 0
                              ? std::string("a ") + table + " number (the file has none)"
                              : std::string("a ") + table + " number 1-" + std::to_string(size);
    const int v = static_cast<int>(
        r.integer(field, std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), e));
    if (v < 1 || v > size) r.fail(r.last(), field, e, shown(r.last().text));
    return v;
  };
  auto surface = [&] { return reference("surface-index", "surface", scene_.numbers.surfaces); };
  auto vertexRef = [&](const std::string& field) {
    return reference(field, "vertex", scene_.numbers.vertices);
  };
  if (kw == "translate" || kw == "scale") {
    d.kind = kw == "translate" ? NodeKind::Translate : NodeKind::Scale;
    d.xyz[0] = r.real("x");
    d.xyz[1] = r.real("y");
    d.xyz[2] = r.real("z");
    if (d.kind == NodeKind::Scale && (d.xyz[0] == 0.0 || d.xyz[1] == 0.0 || d.xyz[2] == 0.0)) {
      d.ignored = true;
      warn(d.where, name +
                        ": a scale factor is 0.0: warning, node ignored (Appendix 1 section "
                        "13; CGL-Q7)");
    }
  } else if (kw == "rotate") {
    d.kind = NodeKind::Rotate;
    d.axis = r.axis("axis");
    d.theta = r.real("theta", "a real number (degrees)");
  } else if (kw == "sphere") {
    d.kind = NodeKind::Sphere;
    d.surface = surface();
    d.xyz[0] = r.real("x");
    d.xyz[1] = r.real("y");
    d.xyz[2] = r.real("z");
    d.radius = r.realIn("radius", tiny, big, "a real number above 0.0");
    d.textureAxis1 = r.axis("texture axis 1");
    d.textureAxis2 = r.axis("texture axis 2");
    if (d.textureAxis1 == d.textureAxis2)
      throw io::InputError(d.where, name + ", field texture axis 2",
                           "an axis other than texture axis 1 (CGL-Q12)",
                           std::string("'") + d.textureAxis2 + "'");
  } else if (kw == "cylinder") {
    d.kind = NodeKind::Cylinder;
    d.surface = surface();
    d.radius = r.realIn("radius", tiny, big, "a real number above 0.0");
    d.vertices.push_back(vertexRef("v1"));
    d.vertices.push_back(vertexRef("v2"));
    if (d.vertices[0] == d.vertices[1])
      throw io::InputError(d.where, name + ", field v2",
                           "a vertex other than v1 (the axis runs from v1 to v2; CGL-Q12)",
                           shown(std::to_string(d.vertices[1])));
  } else if (kw == "polygon") {
    d.kind = NodeKind::Polygon;
    d.surface = surface();
    const int count = static_cast<int>(r.integer(
        "n", 3, 4, "3 or 4 (\"only triangles and rectangles\", Appendix 1 section 13; CGL-Q8)"));
    for (int v = 1; v <= count; ++v) d.vertices.push_back(vertexRef("v" + std::to_string(v)));
  } else if (kw == "fractal") {
    d.kind = NodeKind::Fractal;
    d.surface = surface();
    d.divisions = static_cast<int>(
        r.integer("divisions", 1, 10, "an integer 1-10 (the manual: 1-9; CGL-Q9)"));
    if (d.divisions == 10)
      warn(d.where, name +
                        ": 10 divisions, above the manual's 1-9 (Figure 18 claims 10; "
                        "CGL-Q9)");
    d.h = r.real("h", "a real number (advised 0.5-1.5)");
    if (d.h < 0.5 || d.h > 1.5)
      warn(d.where, name + ": h outside the 0.5-1.5 the manual advises (CGL-Q3)");
    d.offset = r.real("offset", "a real number (advised -1.0-1.0)");
    if (d.offset < -1.0 || d.offset > 1.0)
      warn(d.where, name + ": offset outside the -1.0-1.0 the manual advises (CGL-Q3)");
    d.seed = r.integer("seed", std::numeric_limits<std::int64_t>::min(),
                       std::numeric_limits<std::int64_t>::max(), "an integer");
    d.constrained = r.keyword("constrained|free", {"constrained", "free"}) == "constrained";
  } else if (kw == "spline") {
    d.kind = NodeKind::Spline;
    d.surface = surface();
    auto end = [&](const std::string& field) {
      const std::string e = r.keyword(field, {"single", "double", "triple", "closed"});
      return e == "single"   ? EndCondition::Single
             : e == "double" ? EndCondition::Double
             : e == "triple" ? EndCondition::Triple
                             : EndCondition::Closed;
    };
    const std::string ne = "an integer 2-1000 (control vertices; CGL-Q9)";
    d.nu = static_cast<int>(r.integer("nu", 2, 1000, ne));
    d.uEnd = end("u end condition");
    d.nv = static_cast<int>(r.integer("nv", 2, 1000, ne));
    d.vEnd = end("v end condition");
    d.divisions = static_cast<int>(
        r.integer("divisions", 1, 64, "an integer 1-64 (sub-intervals per knot interval; CGL-Q9)"));
    d.overlap = r.realIn("overlap", 0.0, big, "a real number 0.0 or more");
    done(r);
    for (int v = 0; v < d.nv; ++v)
      for (int u = 0; u < d.nu; ++u) {
        const std::string cname = name + ", control vertex " + std::to_string(u + 1) +
                                  " of group " + std::to_string(v + 1) + " of " +
                                  std::to_string(d.nv);
        const std::size_t k = header(cname);
        if (!isCount(lines_[k].tokens[0].text) ||
            (lines_[k].tokens.size() >= 2 && anyKeyword(lines_[k].tokens[1].text)))
          notARecord(k, cname + ", field count",
                     "'" + std::to_string(u + 1) + " x y z' (the spline's " +
                         std::to_string(d.nu * d.nv) + " control vertices: " +
                         std::to_string(d.nv) + " groups of " + std::to_string(d.nu) + ")");
        Record c(*this, k, cname, Section::Nodes);
        c.count("the u count " + std::to_string(u + 1) +
                    " (it restarts at 1 in each group of nu = " + std::to_string(d.nu) +
                    "; CGL-Q6)",
                u + 1);
        Vec3 p{};
        p[0] = c.real("x");
        p[1] = c.real("y");
        p[2] = c.real("z");
        d.controls.push_back(p);
        done(c);
      }
    scene_.nodes.push_back(std::move(d));
    return;
  } else if (kw == "box") {
    d.kind = NodeKind::Box;
  } else {
    d.kind = NodeKind::Dummy;
  }
  done(r);
  scene_.nodes.push_back(std::move(d));
}

// The DAG: no cycle along down and right links (shared subtrees allowed),
// walked iteratively so that a long chain cannot overflow the stack (CGL-D2);
// nodes the root cannot reach are reported as warnings (CGL-Q10).
void Reader::checkDag() {
  const auto& nodes = scene_.nodes;
  const std::size_t count = nodes.size();
  std::vector<unsigned char> state(count + 1, 0);  // 0 new, 1 on the path, 2 done
  std::vector<std::pair<int, int>> stack;          // node, next link (0 down, 1 right, 2 done)
  const int root = scene_.numbers.root;
  stack.push_back({root, 0});
  state[static_cast<std::size_t>(root)] = 1;
  while (!stack.empty()) {
    auto& [node, link] = stack.back();
    if (link == 2) {
      state[static_cast<std::size_t>(node)] = 2;
      stack.pop_back();
      continue;
    }
    const NodeRecord& d = nodes[static_cast<std::size_t>(node - 1)];
    const int child = link == 0 ? d.down : d.right;
    const char* which = link == 0 ? "down" : "right";
    ++link;
    if (child == 0) continue;
    const auto c = static_cast<std::size_t>(child);
    if (state[c] == 2) continue;  // a shared subtree, already checked
    if (state[c] == 1) {
      std::vector<int> path;
      bool on = false;
      for (const auto& e : stack) {
        if (e.first == child) on = true;
        if (on) path.push_back(e.first);
      }
      path.push_back(child);
      std::string cycle;
      for (std::size_t k = 0; k < path.size(); ++k) {
        if (path.size() > 12 && k == 5) {
          cycle += "... (" + std::to_string(path.size() - 10) + " more) -> ";
          k = path.size() - 5;
        }
        cycle += std::to_string(path[k]) + (k + 1 < path.size() ? " -> " : "");
      }
      throw io::InputError(d.where, "scene node " + std::to_string(node) + ", field " + which,
                           "a node that does not lead back to node " + std::to_string(node) +
                               " (the scene nodes form a DAG)",
                           std::to_string(child) + ", closing the cycle " + cycle);
    }
    state[c] = 1;
    stack.push_back({child, 0});
  }
  std::vector<int> unreachable;
  for (std::size_t k = 1; k <= count; ++k)
    if (state[k] == 0) unreachable.push_back(static_cast<int>(k));
  if (!unreachable.empty()) {
    std::string list;
    for (std::size_t k = 0; k < unreachable.size() && k < 10; ++k)
      list += (k ? ", " : "") + std::to_string(unreachable[k]);
    if (unreachable.size() > 10) list += ", ...";
    warn(nodes[static_cast<std::size_t>(unreachable[0] - 1)].where,
         std::to_string(unreachable.size()) + " scene node" +
             (unreachable.size() > 1 ? "s are" : " is") + " not reachable from the root node " +
             std::to_string(root) + ": " + list + " (CGL-Q10)");
  }
}

}  // namespace

SceneFile readScene(const std::string& text, const std::string& display,
                    const ReadOptions& options) {
  if (text.size() > kMaxBytes)
    throw io::InputError(io::InputLocation{display, 1},
                         "larger than 64 MiB: not read as a CGL scene file (CGL-D2)");
  return Reader(text, display, options).read();
}

SceneFile readSceneFile(const std::string& path, const ReadOptions& options) {
  io::InputFileOptions input;
  input.maxBytes = kMaxBytes;  // CGL-D2
  input.what = "a CGL scene file";
  return readScene(io::readInputText(path, input), path, options);
}

bool looksLikeCgl(const std::string& text) {
  std::istringstream in(text.substr(0, 65536));
  std::string line;
  int seen = 0;
  while (std::getline(in, line) && seen < 200) {
    std::istringstream words(line);
    std::string first, second;
    if (!(words >> first)) continue;
    ++seen;
    if (seen == 1 && (first[0] == '*' || std::string_view(first).starts_with(kBullet) ||
                      std::string_view(first).starts_with("\\*")))
      return true;
    if (first[0] == '*' || std::string_view(first).starts_with(kBullet)) continue;
    if (!(words >> second)) continue;
    const bool count = allDigits(first) || first == "l";  // the OCR's 'l lambert' (CGL-E4)
    if (count && anyKeyword(second)) return true;
  }
  return false;
}

}  // namespace prime::cgl
