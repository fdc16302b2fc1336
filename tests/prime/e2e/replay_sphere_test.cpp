// End-to-end replay: `prime model` + `prime trace` of tests/prime/data/sphere,
// checked against pixels worked out by hand (and the PNG looked at).
//
// Scene: a sphere of radius 300 at (500,500,500); no lights; ambient IA = 1.
// Hue kDR = 0.5, kDT = 0, fDR = (0.8, 0.4, 0.2). Every reflected and
// transmitted ray leaves the lone convex sphere and meets the black
// background, so iSR = iST = 0 and Hall's sum (ProcessWavelength) reduces to
//   kDR*fDR*IA + kDT*(1-fDR)*IA = (0.4, 0.2, 0.1)
// ColorNum: r = floor(0.4*7) = 2, g = floor(0.2*7) = 1, b = floor(0.1*3) = 0
//   -> 2*32 + 1*4 + 0 = 68.  Background: ColorNum(0,0,0) = 0 -> 1 (K16).
//
// Camera (K21): eye (500,500,-1500), window z = 0; column j at x = j*1000/349,
// row i at y = 1000 - i*1000/768. The eye looks straight at the centre
// (distance 2000), so the silhouette on the window is a circle about
// (500,500) of radius 1500 * tan(asin(300/2000)) = 225/sqrt(1-0.0225) = 227.575.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "legacy_io/prime/graph_file.h"

namespace {

namespace fs = std::filesystem;

// A private copy of a test scene (tests may run in parallel).
fs::path copyScene(const std::string& name, const std::string& tag) {
  const fs::path dst =
      fs::temp_directory_path() / ("prime-replay-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(dst);
  fs::copy(fs::path(PRIME_TEST_DATA) / name, dst, fs::copy_options::recursive);
  return dst;
}

int run(const std::string& args) {
  return std::system((std::string(PRIME_EXE) + " " + args + " >/dev/null").c_str());
}

TEST(ReplaySphere, HandCheckedPixels) {
  const fs::path dir = copyScene("sphere", "pixels");
  ASSERT_EQ(run("model " + dir.string()), 0);
  ASSERT_EQ(run("trace " + dir.string() + " --threads 1"), 0);
  const auto g = prime::io::readGraphFile((dir / "graph_scr").string());
  EXPECT_EQ(fs::file_size(dir / "graph_scr"), 6u + 350u * 769u * 2u);
  ASSERT_EQ(g.numPixAcross, 349);
  ASSERT_EQ(g.numPixDown, 768);
  ASSERT_TRUE(g.inclusive);
  EXPECT_EQ(g.graphType, 1);

  EXPECT_EQ(g.at(174, 384), 68);  // x = 498.57, y = 500: the centre
  // Along row 384 (y = 500): x(95) = 272.21 is 0.21 outside the circle
  // (500 - 227.575 = 272.425); x(96) = 275.07 inside; x(253) = 724.93 inside;
  // x(254) = 727.79 outside (limit 727.575).
  EXPECT_EQ(g.at(95, 384), 1);
  EXPECT_EQ(g.at(96, 384), 68);
  EXPECT_EQ(g.at(253, 384), 68);
  EXPECT_EQ(g.at(254, 384), 1);
  // Along column 174 (x = 498.57, dx^2 = 2.05): |dy| <= 227.570. Row 209:
  // y = 727.86, dy = 227.86 outside; row 210: y = 726.56 inside.
  EXPECT_EQ(g.at(174, 209), 1);
  EXPECT_EQ(g.at(174, 210), 68);
  EXPECT_EQ(g.at(0, 0), 1);
  EXPECT_EQ(g.at(349, 768), 1);

  // Only the two indices occur, and the disc covers pi*227.575^2 / (2.86533 *
  // 1.30208) = 43,600 pixels of 3.7309 square units each (within 1%).
  long disc = 0;
  for (auto p : g.pixels) {
    ASSERT_TRUE(p == 1 || p == 68) << p;
    disc += p == 68;
  }
  EXPECT_NEAR(static_cast<double>(disc), 43600.0, 436.0);
  fs::remove_all(dir);
}

TEST(ReplaySphere, SameBytesForAnyThreadCount) {
  const fs::path dir = copyScene("sphere", "threads");
  ASSERT_EQ(run("model " + dir.string()), 0);
  ASSERT_EQ(run("trace " + dir.string() + " --threads 1 --out " + (dir / "one").string()), 0);
  ASSERT_EQ(run("trace " + dir.string() + " --threads 3 --out " + (dir / "three").string()), 0);
  const auto a = prime::io::readFileBytes((dir / "one").string());
  const auto b = prime::io::readFileBytes((dir / "three").string());
  EXPECT_EQ(a, b);
  fs::remove_all(dir);
}

}  // namespace
