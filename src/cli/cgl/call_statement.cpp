// Appendix 2 of Sweeney (1985), "The Program Call Statement":
//   trace [-o pathname] [-yh n] [-yl n] [-xl n] [-xr n] [-d n] [-s] [-m n]
//         [-b real | -b r g b] [-q] [-t real] [-a n] scene-file
// Options "may be in any order" and override the scene file. The OCR prints
// the shadows flag as -S and loses the quiet flag's letter (-q is read;
// docs/cgl/deviations.md CGL-E80). -o names the output file: the usual build
// encoded it (-Dencode), so it is --rle here.
#include <cctype>
#include <map>

#include "src/cli/cgl/commands.h"
#include "src/cli/option_values.h"

namespace prime::cli::cgl {

namespace {

bool isInteger(const std::string& s) {
  if (s.empty()) return false;
  std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

}  // namespace

void translateCallStatement(std::vector<std::string>& args, std::size_t first) {
  // Each flag, the port's name for it, and whether a value follows it.
  struct Flag {
    const char* port;
    bool value;
  };
  static const std::map<std::string, Flag> kFlags = {
      {"-o", {"--rle", true}},      {"-yh", {"--yhigh", true}},      {"-yl", {"--ylow", true}},
      {"-xl", {"--xleft", true}},   {"-xr", {"--xright", true}},     {"-d", {"--max-depth", true}},
      {"-s", {"--shadows", false}}, {"-S", {"--shadows", false}},    {"-m", {"--memory", true}},
      {"-q", {"--quiet", false}},   {"-t", {"--aathreshold", true}}, {"-a", {"--aalevel", true}}};
  // The value of a flag: the next word, which must be there and must not be
  // another flag (`-o -q` named the output `--quiet`).
  const auto valueOf = [&args](std::size_t i, const std::string& flag) {
    if (i + 1 >= args.size() || args[i + 1] == "--" ||
        (args[i + 1].size() > 1 && args[i + 1][0] == '-' && !isNumber(args[i + 1])))
      throw CLI::ValidationError(
          flag, "expected " + std::string(flag == "-o" ? "a path name" : "a number") +
                    " after it (Sweeney, Appendix 2), got " +
                    (i + 1 < args.size() ? "'" + args[i + 1] + "'" : "nothing"));
  };
  for (std::size_t i = first; i < args.size(); ++i) {
    const std::string a = args[i];
    if (a == "--") break;
    if (a == "-b") {
      valueOf(i, a);
      // Three integers: the uniform background colour; else the brightness.
      const bool rgb = i + 3 < args.size() && isInteger(args[i + 1]) && isInteger(args[i + 2]) &&
                       isInteger(args[i + 3]);
      args[i] = rgb ? "--background" : "--brightness";
      i += rgb ? 3 : 1;
      continue;
    }
    const auto f = kFlags.find(a);
    if (f == kFlags.end()) continue;
    if (f->second.value) valueOf(i, a);
    args[i] = f->second.port;
    if (f->second.value) ++i;  // the value is the next word, whatever it spells
  }
}

}  // namespace prime::cli::cgl
