// Parsers for PRIME's text inputs, each reading exactly the fields the
// listing's readers read, in their order:
//   prim/<T><n>.txt  AddPrim:  type letter (byte 0), s, t, r, pivot, one
//                              out/in map pair per surface, priority
//   bound/<T><n>.txt AddBound: type letter, s, t, r, pivot
//   prim/A<n>.txt, obj/Copy/<f>  CopyPrim/CopyObj: s, t, r, pivot
//   obj/H<n>.txt     AddObj:   kDR kDT fDR[3] tT kRH kTH indx
//   obj/D<n>.txt     AddObj:   numEntries, entries, then NULL or a bound
//   map/<file>       AddMap:   mapNum, uScale vScale, then R, G, B planes
//   light/light.txt  InitLighting: ambient RGB, count, per light x y z r g b
//   Model.txt        (ours) one Model.c call per line
// Note the code's order s, t, r, pivot (errata Q2), not section 5.3.1's t, s.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "legacy_io/common/text_reader.h"
#include "legacy_io/prime/records.h"
#include "src/math/vec.h"

namespace prime::io {

struct Placement {
  Vec3 s{1, 1, 1}, t{}, r{}, pivot{};
};

struct PrimText {
  char type = 0;
  Placement place;
  std::array<std::array<std::int16_t, 2>, kMaxSurface> map{};  // unused slots stay 0
  std::int16_t priority = 0;
};

struct BoundText {
  char type = 0;
  Placement place;
};

struct CsgEntryText {
  char op = 0;  // '+', '-', '&'; a leaf letter C B S N T Y; or 'O' (object copy)
  std::int16_t l = 0, r = 0;
  int line = 0;
};

struct ObjText {
  std::vector<CsgEntryText> entries;
  std::optional<std::pair<char, std::int16_t>> bound;  // letter and number, or NULL
  int boundLine = 0;
};

struct MapText {
  std::int16_t mapNum = 0;
  MapHeader header;
  std::array<std::vector<double>, 3> planes;  // R, G, B; uScale*vScale each
};

struct LightSource {
  Vec3 pt{};
  Vec3 rgb{};
};

struct LightText {
  Vec3 ambient{};
  std::vector<LightSource> lights;
};

inline constexpr int kMaxLights = 10;  // Global.c: Light light[10] (K40)

struct ModelCall {
  std::string name;               // AddObj, AddToObjList, CopyObj, AddMap
  std::vector<std::string> args;  // as written
  int line = 0;
};

bool isPrimTypeLetter(char c);  // S B C N Y
bool isLeafOpcode(char c);      // C B S N T Y (AddObj's switch)

PrimText parsePrimText(TextReader& in);
BoundText parseBoundText(TextReader& in);
Placement parsePlacement(TextReader& in);  // s, t, r, pivot
Hue parseHueText(TextReader& in);
ObjText parseObjText(TextReader& in);  // also checks child indices and cycles
MapText parseMapText(TextReader& in);
LightText parseLightText(TextReader& in);
// A word of an input as PRIME's messages show it: "word", control bytes
// escaped (\x1A), cut after 40 characters.
std::string doubleQuoted(std::string_view word);
// One call per line; '#' starts a comment; blank lines are ignored.
std::vector<ModelCall> parseModelText(const std::string& text, const std::string& display);

}  // namespace prime::io
