// Colour Plate 1's drawing (src/prime/plate1/plate1.h): the projection through the
// listing's camera by hand, the knot file reader, and a small wireframe whose
// pixels are known.
#include "src/prime/plate1/plate1.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "legacy_io/common/error.h"

namespace prime::spline {
namespace {

// The listing's camera (K21): column j at x = 1000 j / 349 on the window plane
// z = 0, row i at y = 1000 - 1000 i / 768, screen column 675 + j.
TEST(Projection, WindowPointsLandOnTheirPixels) {
  const Projection proj{CameraSettings{}};
  double x = 0, y = 0;
  ASSERT_TRUE(proj.project({0.0, 1000.0, 0.0}, x, y));
  EXPECT_NEAR(x, 675.0, 1e-9);
  EXPECT_NEAR(y, 0.0, 1e-9);
  ASSERT_TRUE(proj.project({1000.0, 0.0, 0.0}, x, y));
  EXPECT_NEAR(x, 675.0 + 349.0, 1e-9);
  EXPECT_NEAR(y, 768.0, 1e-9);
  // (500, 500, 1500) is twice as far from the eye as the window: it lands
  // where (500, 500, 0) does, the eye's own axis: column 174.5, row 384.
  ASSERT_TRUE(proj.project({500.0, 500.0, 1500.0}, x, y));
  EXPECT_NEAR(x, 675.0 + 174.5, 1e-9);
  EXPECT_NEAR(y, 384.0, 1e-9);
  // (1000, 0, 1500): halfway from the axis on the window, (750, 250, 0).
  ASSERT_TRUE(proj.project({1000.0, 0.0, 1500.0}, x, y));
  EXPECT_NEAR(x, 675.0 + 0.75 * 349.0, 1e-9);
  EXPECT_NEAR(y, 0.75 * 768.0, 1e-9);
  EXPECT_FALSE(proj.project({500.0, 500.0, -2000.0}, x, y));  // behind the eye
}

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::ofstream(p) << text;
  return p;
}

TEST(KnotFile, ReadsThePlate1Scene) {
  const std::string path = std::string(PRIME_SCENES) + "/plate1/knots.txt";
  const KnotFile k = readKnotFile(path, path);
  EXPECT_EQ(k.grid.rows(), 8);
  EXPECT_EQ(k.grid.cols(), 8);
  EXPECT_EQ(k.shape.beta1, 1.0);  // "skew and tension are set to 1 at every knot"
  EXPECT_EQ(k.shape.beta2, 1.0);
}

TEST(KnotFile, ErrorsNameTheField) {
  const auto p = writeTemp("knots-short", "4 4\n1 1\n0 0 0\n");
  try {
    readKnotFile(p.string(), "short.txt");
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("knot 0,1 x"), std::string::npos) << e.what();
  }
  const auto q = writeTemp("knots-three", "3 4\n1 1\n");
  EXPECT_THROW(readKnotFile(q.string(), "three.txt"), io::InputError);
  std::filesystem::remove(p);
  std::filesystem::remove(q);
}

// A flat 4 x 4 grid in the window plane, uniform B-spline (b1 = 1, b2 = 0):
// one patch, x = 100(1 + u) + 200 .. , the surface spans the middle third of
// each knot row. Knots V(r, c) = (300 + 100c, 700 - 100r, 0), so the patch
// covers x 400..500, y 600..500 (window units) and, being in the window
// plane, lands exactly on the camera's pixel grid.
TEST(DrawPlate1, OnePatchInTheWindowPlane) {
  std::vector<Vec3> knots;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) knots.push_back({300.0 + 100 * c, 700.0 - 100 * r, 0.0});
  const KnotFile k{BetaShape{1, 0}, KnotGrid(4, 4, knots)};
  WireframeOptions o;
  o.curvesPerPatch = 1;  // the patch's four edges only
  o.segmentsPerPatch = 4;
  const Plate1Picture pic = drawPlate1(k, o);
  EXPECT_EQ(pic.lines, 4 * 4);  // 2 curves each way, 4 segments each
  ASSERT_EQ(pic.graph.width(), 350);
  ASSERT_EQ(pic.graph.height(), 769);
  EXPECT_EQ(pic.graph.numPixAcross, 349);
  EXPECT_EQ(pic.graph.numPixDown, 768);
  // Top edge v = 0: y = 600, row (1000-600)*768/1000 = 307.2 -> 307; it runs
  // from x = 400 (column 139.6 -> 140) to x = 500 (174.5 -> 175, lround).
  EXPECT_EQ(pic.graph.at(150, 307), 5);  // yellow: a curve of constant v
  // Left edge u = 0: x = 400, column 140, from row 307 to row 384 (y = 500).
  EXPECT_EQ(pic.graph.at(140, 350), 2);  // red: constant u
  EXPECT_EQ(pic.graph.at(150, 350), 0);  // inside the patch: cleared screen
  EXPECT_EQ(pic.graph.at(0, 0), 0);
  EXPECT_EQ(pic.screen.getPixel(675 + 150, 307), 5);
  // Column 349 is screen column 1024, off the 8514/A: always 0 (K21).
  for (int i = 0; i < 769; ++i) EXPECT_EQ(pic.graph.at(349, i), 0);
}

TEST(DrawPlate1, Plate1SceneDrawsInsideTheListingViewport) {
  const std::string path = std::string(PRIME_SCENES) + "/plate1/knots.txt";
  const KnotFile k = readKnotFile(path, path);
  const Plate1Picture pic = drawPlate1(k, WireframeOptions{});
  int yellow = 0, green = 0;
  for (auto v : pic.graph.pixels) {
    ASSERT_TRUE(v == 0 || v == 2 || v == 5) << v;
    yellow += v == 5;
    green += v == 2;
  }
  EXPECT_GT(yellow, 1000);
  EXPECT_GT(green, 1000);
}

}  // namespace
}  // namespace prime::spline
