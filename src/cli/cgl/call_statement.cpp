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
  static const std::map<std::string, std::string> kFlags = {
      {"-o", "--rle"},     {"-yh", "--yhigh"},    {"-yl", "--ylow"},       {"-xl", "--xleft"},
      {"-xr", "--xright"}, {"-d", "--max-depth"}, {"-s", "--shadows"},     {"-S", "--shadows"},
      {"-m", "--memory"},  {"-q", "--quiet"},     {"-t", "--aathreshold"}, {"-a", "--aalevel"}};
  for (std::size_t i = first; i < args.size(); ++i) {
    const std::string a = args[i];
    if (a == "--") break;
    if (a == "-b") {
      // Three integers: the uniform background colour; else the brightness.
      const bool rgb = i + 3 < args.size() && isInteger(args[i + 1]) && isInteger(args[i + 2]) &&
                       isInteger(args[i + 3]);
      args[i] = rgb ? "--background" : "--brightness";
      continue;
    }
    const auto f = kFlags.find(a);
    if (f != kFlags.end()) args[i] = f->second;
  }
}

}  // namespace prime::cli::cgl
