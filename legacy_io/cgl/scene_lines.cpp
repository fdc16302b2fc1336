// The CGL scene file's line layer (scene_reader.h): keywords, numbers,
// lines and tokens, comment lines, the OCR repairs of --lenient (CGL-E1 to
// CGL-E10, docs/cgl/deviations.md), and the hints of located errors.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "legacy_io/cgl/scene_reader.h"
#include "legacy_io/common/charconv.h"

namespace prime::cgl::detail {

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
std::string shown(std::string_view word) {
  return io::quotedWord(word, 60);
}
bool allDigits(std::string_view w) {
  return !w.empty() && std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; });
}
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
  const auto r = io::fromChars(body.data(), body.data() + body.size(), v);
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

void Reader::split(const std::string& text) {
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

void Reader::classify(Line& l) {
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
  if (std::string_view(first).starts_with(kBullet) || std::string_view(first).starts_with("\\*")) {
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
                         " to the number after " + (joins > 1 ? "each" : "it") + ": " + shown(now) +
                         " (CGL-E5)");
  }
}

std::size_t Reader::nextContent(std::size_t from) const {
  while (from < lines_.size() && lines_[from].comment) ++from;
  return from;
}

bool Reader::beginsRecord(std::size_t j, Section section) const {
  const Line& l = lines_[j];
  if (l.comment || l.tokens.empty()) return false;
  if (!isCount(l.tokens[0].text)) return false;
  if (section == Section::Vertices) return true;
  return l.tokens.size() >= 2 && anyKeyword(l.tokens[1].text);
}

bool Reader::isCount(const std::string& w) const {
  if (allDigits(w)) return true;
  return lenient_ && w.find('l') != std::string::npos &&
         std::all_of(w.begin(), w.end(), [](char c) { return (c >= '0' && c <= '9') || c == 'l'; });
}

void Reader::repair(int line, std::string what) {
  scene_.repairs.push_back({io::InputLocation{display_, line}, std::move(what)});
}

void Reader::warn(const io::InputLocation& where, std::string what) {
  scene_.warnings.push_back({where, std::move(what)});
}

io::InputLocation Reader::lineAt(std::size_t j) const {
  return {display_, j < lines_.size() ? lines_[j].number : lines_.back().number};
}

std::size_t Reader::header(const std::string& what) {
  const std::size_t j = nextContent(next_);
  if (j >= lines_.size())
    throw io::InputError(io::InputLocation{display_, lines_.back().number}, what, "a record",
                         "end of file");
  if (!lenient_ && !commentHint(lines_[j]).empty())
    notARecord(j, what, "a record (or a comment, which begins with '*')");
  return j;
}

std::string Reader::commentHint(const Line& l) const {
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

std::string Reader::hintFor(const Line& l) const {
  if (l.tokens.empty()) return "";
  if (const std::string c = commentHint(l); !c.empty()) return c;
  const std::string& f = l.tokens[0].text;
  if (f.find('l') != std::string::npos &&
      std::all_of(f.begin(), f.end(), [](char c) { return (c >= '0' && c <= '9') || c == 'l'; }))
    return " (the letter l for the digit 1? --lenient reads it as 1)";
  return "";
}

void Reader::notARecord(std::size_t j, const std::string& what, const std::string& expected) {
  const Line& l = lines_[j];
  io::InputLocation w{display_, l.number};
  w.column = l.tokens.empty() ? 1 : l.tokens[0].column;
  const std::size_t start = l.raw.find_first_not_of(" \t\f\v");
  throw io::InputError(
      w, what, expected,
      shown(start == std::string::npos ? l.raw : l.raw.substr(start)) + hintFor(l));
}

}  // namespace prime::cgl::detail
