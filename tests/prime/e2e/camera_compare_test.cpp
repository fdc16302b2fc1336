// The free camera through `prime trace` (its graph file header and PNG size,
// the options' errors) and `prime compare` on a small scene (T30-T37).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "legacy_io/prime/graph_file.h"
#include "palette/png_image.h"
#include "tests/support/run_prime.h"
#include "tests/support/temp_scene.h"

namespace {

using ::testing::HasSubstr;
using ::testing::MatchesRegex;
namespace fs = std::filesystem;
using prime::test::runPrime;

std::string modelledSphere(const prime::test::TempScene& s) {
  prime::test::sphere(s);
  const auto r = runPrime("model " + s.path().string());
  EXPECT_EQ(r.status, 0) << r.output;
  return s.path().string();
}

TEST(FreeCameraTrace, HeaderAndPngFollowTheSize_T32) {
  prime::test::TempScene s;
  const std::string dir = modelledSphere(s);
  const auto r =
      runPrime("trace --no-window -q " + dir + " --frame-listing-window --size 120 90 " + "--png " +
               s.path("shot.png").string() + " --true-color-png " + s.path("tc.png").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const prime::io::GraphFile g = prime::io::readGraphFile(s.path("graph_scr").string());
  EXPECT_EQ(g.numPixAcross, 119);  // inclusive, as the listing's 349 x 768 header
  EXPECT_EQ(g.numPixDown, 89);
  EXPECT_EQ(g.pixels.size(), 120u * 90u);
  for (const char* png : {"shot.png", "tc.png"}) {
    const prime::Image8 img = prime::readPng(s.path(png).string());
    EXPECT_EQ(img.width, 120) << png;
    EXPECT_EQ(img.height, 90) << png;
  }
}

TEST(FreeCameraTrace, ListingDefaultIsUnchangedAndBadCamerasAreUsageErrors) {
  prime::test::TempScene s;
  const std::string dir = modelledSphere(s);
  ASSERT_EQ(runPrime("trace --no-window -q " + dir).status, 0);
  const prime::io::GraphFile g = prime::io::readGraphFile(s.path("graph_scr").string());
  EXPECT_EQ(g.numPixAcross, 349);
  EXPECT_EQ(g.numPixDown, 768);
  auto r = runPrime("trace --no-window -q " + dir + " --look-at 500 500 -1500");  // at the eye
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("free camera: the eye is the point it looks at, (500, 500, "
                                  "-1500): give another --look-at or --eye"));
  // Without --look-at the camera looks at the listing window's centre: an
  // eye put there is told so (not "give --fov", which cannot help).
  r = runPrime("trace --no-window -q " + dir + " --eye 500 500 0 --size 64 64");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("(500, 500, 0), the listing window's centre (looked at without "
                                  "--look-at): give another --look-at or --eye"));
  r = runPrime("trace --no-window -q " + dir + " --size 64 64 --up 0 0 1");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("up vector"));
  r = runPrime("trace --no-window -q " + dir + " --size 64 64 --viewport 0 0 1 1");
  EXPECT_EQ(r.status, 2) << r.output;
  // Looking away from the listing's window: it cannot be framed.
  r = runPrime("trace --no-window -q " + dir + " --eye 500 500 500 --look-at 500 500 1000");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("give --fov"));
  EXPECT_EQ(runPrime("trace --no-window -q " + dir +
                     " --eye 500 500 500 --look-at 500 500 1000 --fov 40 --size 32 24")
                .status,
            0);
}

TEST(Compare, ReportsDifferencesAndWritesThreePicturesSideBySide_T36) {
  prime::test::TempScene s;
  const std::string dir = modelledSphere(s);
  const std::string png = s.path("cmp.png").string();
  auto r = runPrime("compare " + dir + " --b=\"--profile modern\" --png " + png +
                    " --divergence-samples 3 --frame-listing-window --size 80 60");
  // --frame-listing-window is not compare's own option: settings go in --a / --b.
  EXPECT_EQ(r.status, 2) << r.output;
  // The shipped default scene (the sphere scene has no light), B the 1991
  // profile with Hall's l and v turned round (--fix in compare's settings).
  prime::test::TempScene lit;
  std::filesystem::copy(std::filesystem::path(PRIME_SCENES) / "default", lit.path(),
                        std::filesystem::copy_options::recursive);
  r = runPrime(
      "compare " + lit.path().string() +
      " --model --a=\"--profile 1991 --size 80 60\" --b=\"--fix K10 --size 80 60\" --png " + png +
      " --divergence-samples 3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr(": 80 x 60 pixels"));
  EXPECT_THAT(r.output, HasSubstr("pixels differing: "));
  EXPECT_THAT(r.output, HasSubstr("wrote " + png));
  // Each ray tree sampled says where it parts, by class (T37).
  EXPECT_THAT(r.output,
              testing::ContainsRegex(
                  R"(pixel [0-9]+ [0-9]+ \[(primary|reflected|transmitted|tir|shadow|shading))"));
  EXPECT_THAT(r.output, HasSubstr("pixels by where their trees part"));
  EXPECT_THAT(r.output, testing::Not(HasSubstr("pixels differing: 0 ")));
  const prime::Image8 img = prime::readPng(png);
  EXPECT_EQ(img.width, 3 * 80 + 2 * 4);
  EXPECT_EQ(img.height, 48 + 60);  // three caption lines over the panels (T36)
  // Captions are drawn over every panel: light text on the dark strip.
  for (int panel = 0; panel < 3; ++panel) {
    int ink = 0;
    for (int y = 0; y < 48; ++y)
      for (int x = panel * 84; x < panel * 84 + 80; ++x)
        ink += img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3] == 235;
    EXPECT_GT(ink, 20) << "panel " << panel << " has no caption";
  }
  // A differing pixel is not grey in the difference panel: a heat colour.
  int coloured = 0;
  for (int y = 48; y < 48 + 60; ++y)
    for (int x = 2 * 84; x < 2 * 84 + 80; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 3;
      coloured += img.rgb[i] != img.rgb[i + 1] || img.rgb[i] != img.rgb[i + 2];
    }
  EXPECT_GT(coloured, 0);
  // The same settings twice: nothing differs, and the difference panel is grey.
  r = runPrime("compare " + dir + " --a=\"--size 40 30\" --b=\"--size 40 30\" --png " + png);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("pixels differing: 0 of 1200 (0.00%); palette indices differing: 0"));
  const prime::Image8 same = prime::readPng(png);
  for (int y = 48; y < 48 + 30; ++y)
    for (int x = 2 * 44; x < 2 * 44 + 40; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * same.width + x) * 3;
      EXPECT_EQ(same.rgb[i], same.rgb[i + 2]);  // grey: no heat colour anywhere
      EXPECT_EQ(same.rgb[i], same.rgb[i + 1]);
    }
  r = runPrime("compare " + dir + " --a=\"--size 40 30\" --b=\"--size 41 30\"");
  EXPECT_EQ(r.status, 2) << r.output;
  r = runPrime("compare " + dir + " --a=\"--no-such-option\"");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--no-such-option"));
}

TEST(WalkBench, RunsHeadlessAndPrintsFrameRates) {
  prime::test::TempScene s;
  const std::string dir = modelledSphere(s);
  const auto r = runPrime("walk " + dir + " --bench 2 --size 64 48 --threads 1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("walk bench: "));
  EXPECT_THAT(r.output, HasSubstr("64 x 48, profile 1991, 2 frames"));
  EXPECT_THAT(r.output, HasSubstr("first coarse pass (8 x 8 blocks): median "));
  EXPECT_THAT(r.output, HasSubstr(" fps"));
  EXPECT_THAT(r.output, HasSubstr("threads of the full-resolution pass: 1"));
  EXPECT_THAT(r.output, HasSubstr("  thread 0: 48.0 rows"));
  // Two threads: their rows, and the speed-up from one thread.
  const auto t = runPrime("walk " + dir + " --bench 2 --size 64 48 --threads 2 --pin");
  ASSERT_EQ(t.status, 0) << t.output;
  EXPECT_THAT(t.output, HasSubstr("threads of the full-resolution pass: 2, pinned"));
  EXPECT_THAT(t.output, HasSubstr("  thread 1: "));
  EXPECT_THAT(t.output, HasSubstr("speed-up 1 -> 2 threads "));
  // Without a display and without --bench: a usage error saying why.
  const auto w = runPrime("walk " + dir);
  EXPECT_EQ(w.status, 2) << w.output;
  EXPECT_THAT(w.output, HasSubstr("needs a window"));
}

}  // namespace
