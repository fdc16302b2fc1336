// The text inputs: TextReader and every parser of text_inputs.h. The first
// input byte picks the reader, the rest is the file's text:
//   'p' parsePrimText (prim/<T><n>.txt)   'b' parseBoundText (bound/...)
//   'a' parsePlacement (prim/A<n>.txt, obj/Copy/<f>)
//   'h' parseHueText (obj/H<n>.txt)       'd' parseObjText (obj/D<n>.txt)
//   'm' parseMapText (map/<file>)         'l' parseLightText (light/light.txt)
//   'M' parseModelText (Model.txt)        'C' parseModelC (a 1991 Model.c)
//   'r' TextReader alone, word by word
// (any other byte: its value mod 10). Errors must name the file and a line of
// it; what a parser returns must keep the limits it promises.
#include <cmath>

#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/model_c.h"
#include "legacy_io/prime/text_inputs.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

namespace {

const std::string kName = "scene/fuzz.txt";

bool finite(const Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void checkPlacement(const io::Placement& p) {
  fuzz::check(finite(p.s) && finite(p.t) && finite(p.r) && finite(p.pivot), "non-finite placement");
}

// TextReader on its own: every kind of read, in a fixed rotation, until the
// text is used up (a failed number falls back to a word, which always moves on).
void readWords(io::TextReader& in) {
  try {
    (void)in.firstChar("first");
  } catch (const io::InputError&) {
  }
  for (int i = 0; !in.atEnd(); ++i) {
    try {
      if (i % 3 == 0) {
        fuzz::check(std::isfinite(in.number("n")), "non-finite number");
        continue;
      }
      if (i % 3 == 1) {
        (void)in.int16("i");
        continue;
      }
    } catch (const io::InputError& e) {
      (void)e;
    }
    fuzz::check(!in.token("w").empty(), "empty word");
  }
}

void parse(char which, io::TextReader& in, const std::string& text) {
  switch (which) {
    case 'p': {
      const io::PrimText p = io::parsePrimText(in);
      fuzz::check(io::isPrimTypeLetter(p.type), "bad type letter accepted");
      checkPlacement(p.place);
      break;
    }
    case 'b': {
      const io::BoundText b = io::parseBoundText(in);
      fuzz::check(io::isPrimTypeLetter(b.type), "bad type letter accepted");
      checkPlacement(b.place);
      break;
    }
    case 'a':
      checkPlacement(io::parsePlacement(in));
      break;
    case 'h':
      (void)io::parseHueText(in);
      break;
    case 'd': {
      const io::ObjText o = io::parseObjText(in);
      fuzz::check(!o.entries.empty(), "object without entries accepted");
      const int n = static_cast<int>(o.entries.size());
      for (const auto& e : o.entries)
        if (e.op == '+' || e.op == '-' || e.op == '&')
          fuzz::check(e.l >= 0 && e.l < n && e.r >= 0 && e.r < n,
                      "child index out of range accepted");
      break;
    }
    case 'm': {
      const io::MapText m = io::parseMapText(in);
      const long long entries = static_cast<long long>(m.header.uScale) * m.header.vScale;
      fuzz::check(m.mapNum >= 0 && m.header.uScale > 0 && m.header.vScale > 0 &&
                      entries <= io::kMaxMapEntries,
                  "map limits not kept");
      for (const auto& plane : m.planes)
        fuzz::check(static_cast<long long>(plane.size()) == entries,
                    "plane size is not uScale*vScale");
      break;
    }
    case 'l': {
      const io::LightText l = io::parseLightText(in);
      fuzz::check(l.lights.size() <= io::kMaxLights, "more than 10 lights accepted");
      break;
    }
    case 'M': {
      for (const auto& call : io::parseModelText(text, kName))
        fuzz::check(!call.name.empty() && call.line >= 1, "bad model call");
      break;
    }
    case 'C': {
      for (const auto& call : io::parseModelC(text, kName)) {
        fuzz::check(call.line >= 1, "a Model.c call without a line");
        const std::size_t n = call.name == "CopyObj" ? 3 : 1;
        fuzz::check((call.name == "AddObj" || call.name == "AddToObjList" ||
                     call.name == "CopyObj" || call.name == "AddMap") &&
                        call.args.size() == n,
                    "a Model.c call that is not one of the scene's four, with its arguments");
      }
      break;
    }
    default:
      readWords(in);
      break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char kReaders[] = {'p', 'b', 'a', 'h', 'd', 'm', 'l', 'M', 'C', 'r'};
  char which = static_cast<char>(data[0]);
  if (std::string_view("pbahdmlMCr").find(which) == std::string_view::npos)
    which = kReaders[data[0] % sizeof kReaders];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  io::TextReader in(text, kName);
  try {
    parse(which, in, text);
  } catch (const io::InputError& e) {
    fuzz::checkTextError(e, kName, text);
  }
  return 0;
}
