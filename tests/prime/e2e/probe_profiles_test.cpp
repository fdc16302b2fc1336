// `prime probe --profile modern` traces the modern profile's ray tree, not
// the 1991 one: on a shipped scene there is a pixel where the two probes see
// different hits, each probe's palette index is the one its profile's render
// wrote, and the modern probe names its profile.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>

#include "legacy_io/prime/graph_file.h"
#include "tests/support/run_prime.h"
#include "tests/support/temp_scene.h"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

using prime::test::CommandResult;
using prime::test::runPrime;

// The first hit of a probe's --json output (the primary ray's), if any.
struct FirstHit {
  int object = 0, prim = 0;
  double t = 0;
};
std::optional<FirstHit> firstHit(const std::string& json) {
  static const std::regex re(
      R"re("event":"hit","data":\{"object":(\d+),"prim":(\d+),"t":([-+0-9.eE]+))re");
  std::smatch m;
  if (!std::regex_search(json, m, re)) return std::nullopt;
  return FirstHit{std::stoi(m[1]), std::stoi(m[2]), std::stod(m[3])};
}
int paletteIndex(const std::string& json) {
  static const std::regex re(R"("index":(-?\d+))");
  std::smatch m;
  return std::regex_search(json, m, re) ? std::stoi(m[1]) : -1;
}

TEST(PrimeProbe, ModernProfileIsProbedForReal) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "csg-operators", s.path(),
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  const std::string dir = s.path().string(), screen = " --screen 512 384";
  ASSERT_EQ(runPrime("model " + dir).status, 0);
  ASSERT_EQ(
      runPrime("trace -q --no-window" + screen + " --out " + s.path("g1991").string() + " " + dir)
          .status,
      0);
  ASSERT_EQ(runPrime("trace -q --no-window --profile modern" + screen + " --out " +
                     s.path("gmodern").string() + " " + dir)
                .status,
            0);
  const auto g1991 = prime::io::readGraphFile(s.path("g1991").string());
  const auto gModern = prime::io::readGraphFile(s.path("gmodern").string());

  // The first pixel of a coarse grid where both profiles hit something but
  // not the same surface point: the 1991 profile takes the first node of the
  // object's list (K30), the modern one the nearest surface ahead. Only the
  // pixels the two renders colour differently are probed (two processes per
  // pixel: slow under the sanitizers).
  int x = -1, y = -1;
  std::string p1991, pModern;
  for (int j = 0; j < g1991.height() && x < 0; j += 16)
    for (int i = 0; i < g1991.width() && x < 0; i += 16) {
      if (g1991.at(i, j) == gModern.at(i, j)) continue;
      const std::string at = " --pixel " + std::to_string(i) + " " + std::to_string(j);
      const CommandResult a = runPrime("probe --json" + screen + at + " " + dir);
      const CommandResult b = runPrime("probe --json --profile modern" + screen + at + " " + dir);
      ASSERT_EQ(a.status, 0) << a.output;
      ASSERT_EQ(b.status, 0) << b.output;
      const auto ha = firstHit(a.output), hb = firstHit(b.output);
      if (ha && hb && std::abs(ha->t - hb->t) > 1.0) {
        x = i;
        y = j;
        p1991 = a.output;
        pModern = b.output;
      }
    }
  ASSERT_GE(x, 0) << "no pixel where the profiles' first hits differ";
  const FirstHit h1991 = *firstHit(p1991), hModern = *firstHit(pModern);
  EXPECT_GT(std::abs(h1991.t - hModern.t), 1.0) << "pixel " << x << " " << y;

  // Each probe explains the pixel its own profile rendered.
  EXPECT_EQ(paletteIndex(p1991), g1991.at(x, y)) << "pixel " << x << " " << y;
  EXPECT_EQ(paletteIndex(pModern), gModern.at(x, y)) << "pixel " << x << " " << y;

  // The modern probe names its profile; the 1991 output stays as it was.
  EXPECT_THAT(pModern, HasSubstr("\"profile\":\"modern\""));
  EXPECT_THAT(p1991, Not(HasSubstr("\"profile\"")));
  const std::string at = " --pixel " + std::to_string(x) + " " + std::to_string(y);
  const CommandResult text = runPrime("probe --profile modern" + screen + at + " " + dir);
  EXPECT_EQ(text.status, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("(modern profile)\n"));
  EXPECT_THAT(text.output, HasSubstr("nearest: object " + std::to_string(hModern.object)));
  EXPECT_THAT(runPrime("probe" + screen + at + " " + dir).output, Not(HasSubstr("modern")));
}

}  // namespace
