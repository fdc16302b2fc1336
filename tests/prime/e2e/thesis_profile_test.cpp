// `--profile thesis` from the command line (docs/prime/thesis-profile.md):
// the same bytes on one and two threads with jittered and statistical
// supersampling and soft shadows, the shadow rays in the summary and the
// probe, the thesis-only options refused elsewhere, export-pov's shadows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/run_prime.h"
#include "tests/support/temp_scene.h"

namespace {

namespace fs = std::filesystem;
using prime::test::runPrime;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Plate 3 (a glass sphere over a board, one light) copied and modelled.
struct Plate3 {
  prime::test::TempScene s;
  Plate3() {
    fs::copy(fs::path(PRIME_SCENES) / "plate3", s.path(),
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    fs::remove(s.path() / "graph_scr");
    EXPECT_EQ(runPrime("model -q " + s.path().string()).status, 0);
  }
  std::string dir() const { return s.path().string(); }
};

TEST(ThesisProfile, SameBytesOnOneAndTwoThreads) {
  const Plate3 p;
  for (const std::string mode : {"--jitter 2", "--statistical 0.05 --max-samples 16"}) {
    std::string png[2], graph[2];
    for (int t = 1; t <= 2; ++t) {
      const fs::path out = p.s.path() / ("g" + std::to_string(t));
      const fs::path pic = p.s.path() / ("c" + std::to_string(t) + ".png");
      const auto r =
          runPrime("trace -q " + p.dir() + " --profile thesis --palette plate3 " + mode +
                   " --light-radius 150 --screen 256 192 --threads " + std::to_string(t) +
                   " --out " + out.string() + " --true-color-png " + pic.string());
      ASSERT_EQ(r.status, 0) << r.output;
      graph[t - 1] = slurp(out);
      png[t - 1] = slurp(pic);
    }
    EXPECT_FALSE(png[0].empty());
    EXPECT_EQ(png[0], png[1]) << mode;
    EXPECT_EQ(graph[0], graph[1]) << mode;
  }
}

TEST(ThesisProfile, SummaryAndProbeShowTheShadowRays) {
  const Plate3 p;
  auto r = runPrime("trace " + p.dir() + " --profile thesis --screen 256 192 --out " +
                    (p.s.path() / "g").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("shadow rays: "), std::string::npos) << r.output;
  // Pixel (44, 150) of the listing's window at 256 x 192 is on the board.
  r = runPrime("probe " + p.dir() + " --profile thesis --screen 256 192 --pixel 44 150");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("(thesis profile)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("shadow ray, depth"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("shadow: light 0"), std::string::npos) << r.output;
  // The 1991 profile's summary is what it always was: no shadow line.
  r = runPrime("trace " + p.dir() + " --screen 256 192 --out " + (p.s.path() / "h").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("shadow rays"), std::string::npos) << r.output;
}

// Plate 2 under the thesis' model stays below the listing palette's first
// step: every pixel one index (docs/prime/plates.md, "Plate 2 is dark"). The
// trace says so, and what shows the picture; plate 3 (visible) says nothing.
TEST(ThesisProfile, AOneIndexPictureIsPointedOut) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "plate2", s.path(),
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  ASSERT_EQ(runPrime("model -q " + s.path().string()).status, 0);
  const std::string out = " --screen 256 192 --out " + (s.path() / "g").string();
  auto r = runPrime("trace " + s.path().string() + " --profile thesis" + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("note: every pixel has palette index 1 although rays met objects"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--true-color-png FILE or --quantize METHOD"), std::string::npos);
  r = runPrime("trace " + s.path().string() + " --profile thesis --quantize octree" + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("note: every pixel"), std::string::npos) << r.output;
  r = runPrime("trace " + s.path().string() + out);  // the 1991 profile: a visible picture
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("note: every pixel"), std::string::npos) << r.output;
  const Plate3 p;
  r = runPrime("trace " + p.dir() + " --profile thesis" + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("note: every pixel"), std::string::npos) << r.output;
}

TEST(ThesisProfile, ThesisOptionsAreUsageErrorsElsewhere) {
  const Plate3 p;
  for (const char* bad : {"--light-radius 5", "--no-shadows", "--texel fresnel",
                          "--profile modern --light-radius 5"}) {
    const auto r = runPrime("trace " + p.dir() + " " + bad);
    EXPECT_EQ(r.status, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("thesis profile"), std::string::npos) << r.output;
  }
  const auto r = runPrime("trace " + p.dir() + " --jitter 2 --samples 2");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("choose one of"), std::string::npos) << r.output;
}

TEST(ThesisProfile, ExportPovWithShadows) {
  const Plate3 p;
  const fs::path pov = p.s.path() / "out" / "s.pov";
  fs::create_directories(pov.parent_path());
  ASSERT_EQ(runPrime("export-pov -q " + p.dir() + " " + pov.string()).status, 0);
  EXPECT_NE(slurp(pov).find("shadowless"), std::string::npos);  // the listing's lights
  ASSERT_EQ(runPrime("export-pov -q " + p.dir() + " " + pov.string() + " --shadows").status, 0);
  std::string text = slurp(pov);
  EXPECT_EQ(text.find("shadowless"), std::string::npos);
  EXPECT_EQ(text.find("area_light"), std::string::npos);
  ASSERT_EQ(
      runPrime("export-pov -q " + p.dir() + " " + pov.string() + " --shadows --light-radius 150")
          .status,
      0);
  text = slurp(pov);
  EXPECT_NE(
      text.find("area_light <300, 0, 0>, <0, 0, 300>, 9, 9 adaptive 1 jitter circular orient"),
      std::string::npos)
      << text;
}

}  // namespace
