// The normal reflectance file of `prime cook --reflectance FILE`
// (legacy_io/cgl/reflectance.h) on any bytes: readReflectance returns, or
// throws prime::io::InputError naming the file and a line of the text. What
// it returns keeps its promises: 33 samples, each 0 <= R < 1, from which the
// cook utility (src/cgl/cook.h) makes its 66 Fresnel vectors, every entry in
// [0, 1], and writes a descriptor without throwing.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "legacy_io/cgl/reflectance.h"
#include "legacy_io/common/error.h"
#include "src/cgl/cook.h"

namespace {

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
  std::abort();
}
void check(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace prime;
  if (size > 200000) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const cgl::Spectrum r = cgl::readReflectance(text, "fuzz.ref");
    for (double v : r) check(v >= 0.0 && v < 1.0, "a sample outside [0, 1)");
    for (const cgl::Spectrum& row : cgl::fresnelTable(r))
      for (double f : row) check(std::isfinite(f) && f >= 0.0 && f <= 1.0, "a bad Fresnel value");
    cgl::CookDescriptor d;
    d.reflectance = r;
    check(!cgl::cookDescriptorText(d).empty(), "an empty descriptor");
  } catch (const io::InputError& e) {
    const std::string msg = e.what();
    check(e.where().file == "fuzz.ref", "an error without the file: " + msg);
    check(e.where().line.has_value(), "an error without a line: " + msg);
    check(msg.rfind("fuzz.ref:", 0) == 0, "a message without file:line: " + msg);
    // Lines as the reader counts them: LF, CR LF and a lone CR each end one.
    std::size_t lines = 1;
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')))
        ++lines;
    check(*e.where().line >= 1 && static_cast<std::size_t>(*e.where().line) <= lines,
          "a line outside the text: " + msg);
  }
  return 0;
}
