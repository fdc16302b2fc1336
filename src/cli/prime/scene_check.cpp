#include "src/cli/prime/scene_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "legacy_io/common/error.h"
#include "legacy_io/common/text_reader.h"
#include "palette/prime/color_num.h"

namespace prime::cli {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string show(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

struct Field {
  const char* name;
  double value = 0;
  int line = 0;
};

void checkHueFile(const io::SceneDir& scene, const fs::path& path, std::vector<SceneProblem>& out) {
  const std::string shown = scene.display(path);
  auto problem = [&](const Field& f, const std::string& expected, const std::string& found) {
    out.push_back({io::InputError({shown, f.line, std::nullopt}, f.name, expected, found).what()});
  };
  // The nine numbers of parseHueText, in its order, each with its line.
  Field f[9] = {{"kDR"}, {"kDT"}, {"fDR[R]"}, {"fDR[G]"}, {"fDR[B]"},
                {"tT"},  {"kRH"}, {"kTH"},    {"indx"}};
  try {
    io::TextReader in = io::TextReader::open(path.string(), shown);
    for (Field& x : f) {
      x.value = in.number(x.name);
      x.line = in.line();
    }
  } catch (const io::InputError& e) {
    out.push_back({e.what()});
    return;
  }
  const Field &kDT = f[1], &tT = f[5], &kRH = f[6], &kTH = f[7], &indx = f[8];
  for (const Field* k : {&kRH, &kTH})
    if (k->value != std::floor(k->value))
      problem(*k,
              "an integer (K10: the listing raises a negative cosine to this power, and a "
              "non-integer power of a negative number is NaN)",
              show(k->value));
  if (indx.value == 1.0 && kDT.value < 1.0)
    problem(indx,
            "not exactly 1 (K13: Hj_ divides by indx - 1, which gives Inf/NaN whenever the "
            "transmission weight 1 - kDT is not 0); 1.0001 is a clear glass",
            show(indx.value));
  if (tT.value >= 1.0)
    problem(tT,
            "below 1, close to it (K14: light through the object is multiplied by tT to the "
            "power of the path length in world units, so tT >= 1 never fades and above 1 "
            "grows without bound); 0.999 is usual",
            show(tT.value));
  // The colour the tutorial's recipe shows (kDR 0, kDT 1): 1 - fDR, the
  // diffuse transmission colour (K10). ColorNum (K16) sends colours with red
  // below 1/7 and green below 3/7 to indices 0-9, which InitPalette overwrites
  // with fixed colours (K17): "blue" (0, 0, 1) is entry 3, a pale green.
  if (kDT.value > 0.0) {
    const Rgb c{1.0 - f[2].value, 1.0 - f[3].value, 1.0 - f[4].value};
    const int index = colorNum(c, 1);
    if (index >= 0 && index <= 9) {
      const PaletteRgb p = initPalette()[static_cast<std::size_t>(index)];
      std::string colour = "(" + show(c[0]) + ", " + show(c[1]) + ", " + show(c[2]) + ")";
      problem(f[2],
              "an fDR whose colour 1 - fDR ColorNum does not send to the fixed palette entries "
              "0-9 (K16, K17: red below 1/7 with green below 3/7)",
              "1 - fDR = " + colour + ", palette index " + std::to_string(index) +
                  ", which the 8514/A shows as (" + std::to_string(p.r) + ", " +
                  std::to_string(p.g) + ", " + std::to_string(p.b) + ")" +
                  (index == 1 ? ": the background's green" : ""));
    }
  }
}

}  // namespace

std::vector<SceneProblem> checkHues(const io::SceneDir& scene) {
  std::vector<SceneProblem> out;
  const fs::path obj = scene.find("obj", ".");
  std::vector<fs::path> hues;
  std::error_code ec;
  for (fs::directory_iterator it(obj, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = lower(it->path().filename().string());
    if (name.size() > 5 && name[0] == 'h' && name.compare(name.size() - 4, 4, ".txt") == 0 &&
        std::isdigit(static_cast<unsigned char>(name[1])) && it->is_regular_file())
      hues.push_back(it->path());
  }
  std::sort(hues.begin(), hues.end());
  for (const fs::path& p : hues) checkHueFile(scene, p, out);
  return out;
}

}  // namespace prime::cli
