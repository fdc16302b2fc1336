#include "legacy_io/prime/text_inputs.h"

#include <cstring>
#include <sstream>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/prime/map_file.h"

namespace prime::io {

bool isPrimTypeLetter(char c) {
  return primType(c).has_value();
}
bool isLeafOpcode(char c) {
  return c && std::strchr("CBSNTY", c) != nullptr;
}

static std::string quoted(char c) {
  return std::string("'") + c + "'";
}

static Vec3 vec3(TextReader& in, const char* what) {
  const std::string f(what);
  Vec3 v{};
  v[0] = in.number(f + " x");
  v[1] = in.number(f + " y");
  v[2] = in.number(f + " z");
  return v;
}

Placement parsePlacement(TextReader& in) {
  Placement p;
  p.s = vec3(in, "scale");
  p.t = vec3(in, "translate");
  p.r = vec3(in, "rotate");
  p.pivot = vec3(in, "pivot");
  return p;
}

static char typeLetter(TextReader& in) {
  const char c = in.firstChar("type letter");
  if (!isPrimTypeLetter(c))
    in.fail("type letter", "one of S (sphere), B (cube), C (cylinder), N (cone), Y (pyramid)",
            quoted(c));
  return c;
}

PrimText parsePrimText(TextReader& in) {
  PrimText p;
  p.type = typeLetter(in);
  p.place = parsePlacement(in);
  for (int i = 0; i < surfaceCount(p.type); ++i) {
    const std::string s = "surface " + std::to_string(i) + " ";
    p.map[i][kOut] = in.int16(s + "outside map");
    p.map[i][kIn] = in.int16(s + "inside map");
  }
  p.priority = in.int16("priority");
  return p;
}

BoundText parseBoundText(TextReader& in) {
  BoundText b;
  b.type = typeLetter(in);
  b.place = parsePlacement(in);
  return b;
}

Hue parseHueText(TextReader& in) {
  Hue h;
  h.kDR = in.number("kDR");
  h.kDT = in.number("kDT");
  h.fDR[0] = in.number("fDR[R]");
  h.fDR[1] = in.number("fDR[G]");
  h.fDR[2] = in.number("fDR[B]");
  h.tT = in.number("tT");
  h.kRH = in.number("kRH");
  h.kTH = in.number("kTH");
  h.indx = in.number("indx");
  return h;
}

// Child indices must name entries of this file, and following them from the
// root (entry 0) must never come back to an entry on the current path: the
// listing's CSG() would recurse for ever.
static void checkTree(TextReader& in, const std::vector<CsgEntryText>& entries) {
  const int n = static_cast<int>(entries.size());
  for (const auto& e : entries) {
    if (e.op != '+' && e.op != '-' && e.op != '&') continue;
    for (int child : {e.l, e.r})
      if (child < 0 || child >= n)
        throw InputError({in.name(), e.line, std::nullopt},
                         std::string("child index of '") + e.op + "'",
                         "an entry number 0.." + std::to_string(n - 1), std::to_string(child));
  }
  // Depth first from the root with an explicit stack: a chain of 32767
  // entries is a legal file and must not overflow the call stack.
  std::vector<int> state(n, 0);           // 0 unvisited, 1 on path, 2 done
  std::vector<std::pair<int, int>> path;  // entry, how many children followed
  if (n > 0) {
    state[0] = 1;
    path.push_back({0, 0});
  }
  while (!path.empty()) {
    const int i = path.back().first;
    const auto& e = entries[i];
    if ((e.op == '+' || e.op == '-' || e.op == '&') && path.back().second < 2) {
      const int child = path.back().second++ == 0 ? e.l : e.r;
      if (state[child] == 1)
        throw InputError({in.name(), e.line, std::nullopt}, "child index",
                         "a tree (no entry may contain itself)",
                         "entry " + std::to_string(i) + " leads back to entry " +
                             std::to_string(child) + " (a cycle)");
      if (state[child] == 0) {
        state[child] = 1;
        path.push_back({child, 0});
      }
      continue;
    }
    state[i] = 2;
    path.pop_back();
  }
}

ObjText parseObjText(TextReader& in) {
  ObjText o;
  const std::int16_t count = in.int16("numEntries");
  if (count < 1) in.fail("numEntries", "at least 1 entry", std::to_string(count));
  // A numEntries larger than the entries listed runs into the bounding
  // volume's line, or off the end: said so, not taken for a glued "N ULL".
  const auto tooMany = [&](int listed) {
    return " (numEntries is " + std::to_string(count) + " but the file lists " +
           std::to_string(listed) + " entr" + (listed == 1 ? "y" : "ies") + ")";
  };
  for (int i = 0; i < count; ++i) {
    const std::string field = "entry " + std::to_string(i) + " opcode";
    if (in.atEnd()) in.fail(field, "one of + - & C B S N T Y O", "end of file" + tooMany(i));
    const std::string word = in.token(field);
    if (word == "NULL")
      in.fail(field, "one of + - & C B S N T Y O",
              "\"NULL\", the bounding volume's word" + tooMany(i));
    CsgEntryText e;
    e.line = in.line();
    if (word.size() != 1) {
      const bool glued = word.size() > 1 && isLeafOpcode(word[0]);
      in.fail(field, "one of + - & C B S N T Y O as a word of its own",
              "\"" + word + "\"" +
                  (glued ? " (write the letter and the number apart, e.g. \"" +
                               std::string(1, word[0]) + " " + word.substr(1) + "\"; errata K35)"
                         : ""));
    }
    e.op = word[0];
    const std::string num = "entry " + std::to_string(i) + " ";
    if (e.op == '+' || e.op == '-' || e.op == '&') {
      e.l = in.int16(num + "left child");
      e.r = in.int16(num + "right child");
    } else if (isLeafOpcode(e.op)) {
      e.l = in.int16(num + "primitive file number");
    } else if (e.op == 'O') {
      e.l = in.int16(num + "source object number");
      e.r = in.int16(num + "copy transform file number");
    } else {
      in.fail(field, "one of + - & C B S N T Y O", "\"" + word + "\"");
    }
    o.entries.push_back(e);
  }
  checkTree(in, o.entries);
  if (in.atEnd())
    in.fail("bounding volume", "NULL, or one of C B S N T Y followed by a number",
            "end of file (if the last entry was meant as the bounding volume, numEntries " +
                std::to_string(count) + " counts one entry too many)");
  const std::string word = in.token("bounding volume (NULL or a type letter and number)");
  o.boundLine = in.line();
  if (word != "NULL") {
    if (word.size() != 1 || !isLeafOpcode(word[0]))
      in.fail("bounding volume", "NULL, or one of C B S N T Y followed by a number",
              "\"" + word + "\"");
    o.bound = std::make_pair(word[0], in.int16("bounding volume file number"));
  }
  return o;
}

MapText parseMapText(TextReader& in) {
  MapText m;
  m.mapNum = in.int16("mapNum");
  if (m.mapNum < 0) in.fail("mapNum", "a map number >= 0", std::to_string(m.mapNum));
  m.header.uScale = in.int16("uScale");
  m.header.vScale = in.int16("vScale");
  const int line = in.line();
  const long long entries = static_cast<long long>(m.header.uScale) * m.header.vScale;
  if (m.header.uScale <= 0 || m.header.vScale <= 0)
    throw InputError({in.name(), line, std::nullopt}, "uScale vScale", "two sizes > 0",
                     std::to_string(m.header.uScale) + " " + std::to_string(m.header.vScale));
  if (entries > kMaxMapEntries)
    throw InputError({in.name(), line, std::nullopt}, "uScale vScale",
                     "uScale*vScale <= 32767 (AddMap counts entries in a 16-bit int)",
                     std::to_string(m.header.uScale) + " x " + std::to_string(m.header.vScale) +
                         " = " + std::to_string(entries));
  static const char* kPlane[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    m.planes[c].reserve(static_cast<std::size_t>(entries));
    for (long long k = 0; k < entries; ++k)
      m.planes[c].push_back(in.number(std::string(kPlane[c]) + " texel " + std::to_string(k) +
                                      " (u " + std::to_string(k % m.header.uScale) + ", v " +
                                      std::to_string(k / m.header.uScale) + ")"));
  }
  return m;
}

LightText parseLightText(TextReader& in) {
  LightText l;
  l.ambient = vec3(in, "ambient");
  const std::int16_t count = in.int16("number of lights");
  if (count < 0 || count > kMaxLights)
    in.fail("number of lights", "0..10 (the listing keeps lights in light[10], K40)",
            std::to_string(count));
  for (int i = 0; i < count; ++i) {
    LightSource s;
    const std::string n = "light " + std::to_string(i) + " ";
    s.pt = vec3(in, (n + "position").c_str());
    s.rgb = vec3(in, (n + "intensity").c_str());
    l.lights.push_back(s);
  }
  return l;
}

std::string doubleQuoted(std::string_view word) {
  // As PRIME's readers show words: in double quotes, control bytes escaped.
  std::string q = quotedWord(word, 40);
  q.front() = q.back() = '"';
  return q;
}

std::vector<ModelCall> parseModelText(const std::string& text, const std::string& display) {
  // Model.txt is line oriented: one call of Model.c's main() per line.
  static const struct {
    const char* name;
    std::size_t args;
    const char* usage;
  } kCalls[] = {
      {"AddObj", 1, "AddObj <object text file, e.g. d1.txt>"},
      {"AddToObjList", 1, "AddToObjList <object number>"},
      {"CopyObj", 3, "CopyObj <source object file> <destination object file> <copy file>"},
      {"AddMap", 1, "AddMap <map text file>"}};
  std::vector<ModelCall> calls;
  // CR-only is lines too (M21); a ^Z ends the text (M41), a leading byte
  // order mark is skipped (M35).
  std::string body = normalizeLineBreaks(text);
  endAtDosEof(body);
  std::istringstream lines(body.substr(bomLength(body)));
  std::string raw;
  int lineNo = 0;
  while (std::getline(lines, raw)) {
    ++lineNo;
    if (auto hash = raw.find('#'); hash != std::string::npos) raw.erase(hash);
    std::istringstream words(raw);
    ModelCall call;
    call.line = lineNo;
    if (!(words >> call.name)) continue;  // blank or comment line
    for (std::string w; words >> w;) call.args.push_back(w);
    bool known = false;
    for (const auto& k : kCalls) {
      if (call.name != k.name) continue;
      known = true;
      if (call.args.size() != k.args)
        throw InputError({display, lineNo, std::nullopt}, call.name + " arguments",
                         std::to_string(k.args) + " (" + k.usage + ")",
                         std::to_string(call.args.size()));
    }
    if (!known)
      throw InputError({display, lineNo, std::nullopt}, "call",
                       "one of AddObj, AddToObjList, CopyObj, AddMap", doubleQuoted(call.name));
    calls.push_back(std::move(call));
  }
  return calls;
}

}  // namespace prime::io
