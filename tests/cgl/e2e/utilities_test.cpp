// The Waterloo CGL package's utilities (Sweeney 1985, Appendix 1 section 9)
// through the real `prime`: `prime cook` writes the cook surface descriptor
// that tools/cgl/scenes.py put in scenes/cgl/metals.cgl (the two generators
// agree number for number), its reflectance from a file or the command line,
// and refuses a reflectance of 1 or more; `prime tovector` prints a colour-
// vector on stdout and the RGB it converts back to on stderr.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_prime.h"

namespace fs = std::filesystem;

namespace prime {
namespace {

using test::runPrime;

// The document's copper (Appendix 1 section 8): its first Fresnel vector, the
// normal reflectance its table was made from (CGL-Q106).
const char* kCopper =
    "0.0700 0.0760 0.0820 0.0880 0.0950 0.1060 0.1170 0.1280 0.1400 0.1560 "
    "0.1720 0.1890 0.2050 0.2200 0.2350 0.2500 0.2650 0.3000 0.3350 0.4120 "
    "0.4900 0.5520 0.6150 0.6420 0.6700 0.6830 0.6970 0.7110 0.7250 0.7320 "
    "0.7400 0.7480 0.7550";

fs::path tempPath(const std::string& name) {
  return fs::temp_directory_path() / ("prime-cgl-utilities-" + std::to_string(::getpid()) + name);
}

// The words of the lines that are not comments, from the line starting with
// `header` on, `count` lines (comments not counted).
std::vector<std::string> recordWords(const std::string& text, const std::string& header,
                                     int count) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> words;
  bool on = false;
  while (std::getline(in, line) && count > 0) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '*') continue;
    if (!on && line.rfind(header, 0) != 0) continue;
    on = true;
    --count;
    std::istringstream w(line);
    std::string word;
    while (w >> word) words.push_back(word);
  }
  return words;
}

std::string fileText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expectSameNumbers(const std::vector<std::string>& got, const std::vector<std::string>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (got[i] == want[i]) continue;
    // "0" and "0.0", "1" and "1.0": the same number.
    EXPECT_DOUBLE_EQ(std::stod(got[i]), std::stod(want[i])) << "word " << i;
  }
}

TEST(CglUtilities, CookWritesTheMetalsCopper) {
  const fs::path out = tempPath("-copper.txt");
  const auto r = runPrime("cook " + out.string() + " --count 5 --reflect 0.8 --name copper " +
                          "--reflectance " + kCopper);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string text = fileText(out);
  fs::remove(out);
  // header, diffuse, 4 lines of D, specular m, 66 * 4 lines of F.
  const int lines = 1 + 1 + 4 + 1 + 66 * 4;
  const auto got = recordWords(text, "5 cook", lines);
  const auto want = recordWords(fileText(fs::path(CGL_SCENES) / "metals.cgl"), "5 cook", lines);
  EXPECT_EQ(got.size(), 6u + 1u + 33u + 2u + 66u * 33u);  // header, diffuse, D, specular m, F
  expectSameNumbers(got, want);
  // The document's printed normal-colour-vector: 0.0223 first, 0.2403 last.
  EXPECT_EQ(got[7], "0.0223");
  EXPECT_EQ(got[7 + 32], "0.2403");
}

TEST(CglUtilities, CookReadsTheReflectanceFromAFileAndRefusesOne) {
  const fs::path in = tempPath("-r.txt"), out = tempPath("-r-out.txt");
  {
    std::ofstream f(in);
    f << "* a grey metal\n";
    for (int k = 0; k < 33; ++k) f << (k == 20 ? "1.0" : "0.5") << (k % 10 == 9 ? "\n" : " ");
    f << "\n";
  }
  const auto bad = runPrime("cook " + out.string() + " --reflectance " + in.string());
  EXPECT_EQ(bad.status, 1) << bad.output;
  EXPECT_NE(bad.output.find("580 nm"), std::string::npos) << bad.output;
  {
    std::ofstream f(in);
    for (int k = 0; k < 33; ++k) f << "0.5\n";
  }
  const auto good = runPrime("cook " + out.string() + " --reflectance " + in.string() +
                             " --m 0.2 --specular 0.7");
  EXPECT_EQ(good.status, 0) << good.output;
  const auto words = recordWords(fileText(out), "1 cook", 7);
  ASSERT_GE(words.size(), 42u);
  EXPECT_EQ(words[7], "0.1592");  // 0.5 / pi, after the header's 6 words and the diffuse
  EXPECT_EQ(words[40], "0.7");
  EXPECT_EQ(words[41], "0.2");
  fs::remove(in);
  fs::remove(out);
}

TEST(CglUtilities, TovectorPrintsTheVectorAndTheCheck) {
  // Section 10: only the 450, 550 and 600 nm samples are set; the check on
  // stderr is ToRGB of that vector.
  const fs::path err = tempPath("-err.txt");
  std::string out;
  FILE* p = popen((std::string(PRIME_EXE) + " tovector 200 100 50 2>" + err.string()).c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::array<char, 4096> buf;
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
  EXPECT_EQ(WEXITSTATUS(pclose(p)), 0);
  std::istringstream in(out);
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  ASSERT_EQ(v.size(), 33u);
  for (int k = 0; k < 33; ++k) {
    if (k != 7 && k != 17 && k != 22) {
      EXPECT_EQ(v[static_cast<std::size_t>(k)], 0.0) << k;
    }
  }
  EXPECT_GT(v[22], 0.0);  // 600 nm: the red
  const std::string check = fileText(err);
  fs::remove(err);
  int r = -1, g = -1, b = -1;
  ASSERT_EQ(std::sscanf(check.c_str(), "%d %d %d", &r, &g, &b), 3) << check;
  EXPECT_NEAR(r, 200, 1);
  EXPECT_NEAR(g, 100, 1);
  EXPECT_NEAR(b, 50, 1);
}

}  // namespace
}  // namespace prime
