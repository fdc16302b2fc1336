// prime export-pov for Malone scenes (src/malone/pov_export.h): the text of
// every primitive, the camera, lights and finishes against hand-written
// expectations; and, where povray is installed, that POV-Ray 3.7 parses
// every shipped scene's export.
#include "src/malone/pov_export.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "legacy_io/malone/input.h"
#include "tests/support/temp_dir.h"

namespace prime::malone {
namespace {

// A viewer, the lights, a default surface, then `body` (primitives using 107).
Scene sceneWith(const std::string& body) {
  const std::string text =
      "102\n0 0 10\n0 0 0\n1 0 0\n0 0.75 0\n8 6\n"
      "101\n1 2 3\n10 20 30\n"
      "104\n0 5 0\n1 1 1\n"
      "103\n0.1 0.2 0.3\n"
      "106\n100\n1 0.5 0.25\n0.5 20\n0.8 0 0\n" +
      body;
  return buildScene(readScene(text, "test.mal"), "test.mal");
}

std::string geometryOf(const std::string& body) {
  const Scene scene = sceneWith(body);
  EXPECT_EQ(scene.primitives.size(), 1u);
  return povGeometry(scene, scene.primitives.at(0));
}

// Text equal to `expected` but for its numbers, each within 1e-12 relative:
// for the values that go through sqrt and a division (the cone's radii).
void expectNearText(const std::string& actual, const std::string& expected) {
  static const std::regex number(R"(-?[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?)");
  EXPECT_EQ(std::regex_replace(actual, number, "#"), std::regex_replace(expected, number, "#"))
      << actual;
  std::vector<double> a, e;
  for (std::sregex_iterator i(actual.begin(), actual.end(), number), end; i != end; ++i)
    a.push_back(std::stod(i->str()));
  for (std::sregex_iterator i(expected.begin(), expected.end(), number), end; i != end; ++i)
    e.push_back(std::stod(i->str()));
  ASSERT_EQ(a.size(), e.size()) << actual;
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(a[i], e[i], 1e-12 * (1 + std::fabs(e[i]))) << actual;
}

TEST(PovExport, Sphere) {
  EXPECT_EQ(geometryOf("1\n2\n1 2 3\n107\n"), "sphere { <1, 2, 3>, 2 }");
}

TEST(PovExport, PlaneIsNormalisedAsRead) {
  // 2: D n, n.x = D; (0, 2, 0) . x = 6 is y = 3.
  EXPECT_EQ(geometryOf("2\n6\n0 2 0\n107\n"), "plane { <0, 1, 0>, 3 }");
}

TEST(PovExport, DiscAndAnnulus) {
  EXPECT_EQ(geometryOf("3\n0 0 0\n0 0 2\n1.5\n107\n"), "disc { <0, 0, 0>, <0, 0, 1>, 1.5 }");
  EXPECT_EQ(geometryOf("4\n1 1 1\n0 3 0\n2\n0.5\n107\n"), "disc { <1, 1, 1>, <0, 1, 0>, 2, 0.5 }");
}

TEST(PovExport, TriangleParallelogramPolygon) {
  EXPECT_EQ(geometryOf("5\n0 0 0\n1 0 0\n0 1 0\n107\n"),
            "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }");
  // 6: a vertex and two edges; the four corners, closed.
  EXPECT_EQ(geometryOf("6\n1 0 0\n2 0 0\n0 0 3\n107\n"),
            "polygon { 5, <1, 0, 0>, <3, 0, 0>, <3, 0, 3>, <1, 0, 3>, <1, 0, 0> }");
  EXPECT_EQ(geometryOf("11\n3\n0 0 0\n1 0 0\n0 1 0\n107\n"),
            "polygon { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <0, 0, 0> }");
}

TEST(PovExport, ConeFromTheApexOverItsRange) {
  // alpha = cos(theta) = 0.8: tan(theta) = 0.75; the radius at u is u |a| tan.
  expectNearText(geometryOf("8\n0.8\n0 2\n0 0 0\n0 1 0\n107\n"),
                 "cone { <0, 0, 0>, 0, <0, 2, 0>, 1.5 open }");
  // A range through the apex: both nappes.
  expectNearText(geometryOf("8\n0.8\n-1 2\n0 0 0\n0 1 0\n107\n"),
                 "union { cone { <0, -1, 0>, 0.75, <0, 0, 0>, 0 open } "
                 "cone { <0, 0, 0>, 0, <0, 2, 0>, 1.5 open } }");
}

TEST(PovExport, CylinderOverItsRange) {
  // The document's example: from y = 2 down to y = -8 (axis (0,-1,0), 0 10).
  EXPECT_EQ(geometryOf("9\n0.5\n0 10\n0 2 0\n0 -1 0\n107\n"),
            "cylinder { <0, 2, 0>, <0, -8, 0>, 0.5 open }");
}

TEST(PovExport, TorusRotatedOntoItsAxis) {
  // y onto the axis (0, 1, 0); x onto (0, 0, 1), z onto (-1, 0, 0): det +1.
  EXPECT_EQ(geometryOf("10\n2\n0.5\n1 2 3\n0 1 0\n107\n"),
            "torus { 2, 0.5 matrix <0, 0, 1, 0, 1, 0, -1, 0, 0, 1, 2, 3> }");
  // Along x: the matrix takes y to x.
  const std::string g = geometryOf("10\n2\n0.5\n0 0 0\n3 0 0\n107\n");
  EXPECT_NE(g.find("matrix <0, 0, -1, 1, 0, 0, 0, -1, 0, 0, 0, 0>"), std::string::npos) << g;
}

TEST(PovExport, AffineIsTheMatrixOfItsAxes) {
  // world = O + (X Y Z) local: rows X, Y, Z, O.
  EXPECT_EQ(geometryOf("7\n1 0 0\n2 0 0\n0 3 0\n0 0 4\n1\n1\n0 0 0\n107\n"),
            "object { sphere { <0, 0, 0>, 1 } matrix <2, 0, 0, 0, 3, 0, 0, 0, 4, 1, 0, 0> }");
}

TEST(PovExport, Finishes) {
  const Scene scene = sceneWith("1\n1\n0 0 0\n107\n");
  EXPECT_EQ(povMaterial(scene.surfaces.at(0)),
            "texture { pigment { rgb <1, 0.5, 0.25> } finish { ambient 0.8 diffuse 0.8 phong 0.5 "
            "phong_size 20 reflection { 0.5 } } }");
  Surface glass;
  glass.colour = {1, 1, 1};
  glass.diffuse = 0.5;
  glass.kt = 0.5;
  glass.index = 1.5;
  // The pigment divided by 1 - k_t (POV-Ray scales diffuse by 1 - transmit).
  EXPECT_EQ(povMaterial(glass),
            "texture { pigment { rgb <2, 2, 2> transmit 0.5 } finish { ambient 0.5 diffuse 0.5 } "
            "} interior { ior 1.5 }");
}

TEST(PovExport, CameraUndoesThePixelCentre) {
  const Scene scene = sceneWith("1\n1\n0 0 0\n107\n");
  const PovCamera c = povCamera(scene.viewer);
  EXPECT_EQ(c.location, (Vec3{0, 0, 10}));
  EXPECT_EQ(c.right, (Vec3{2, 0, 0}));
  EXPECT_EQ(c.up, (Vec3{0, 1.5, 0}));
  EXPECT_EQ(c.direction, (Vec3{-0.125, 0.125, -1}));  // w - x/8 + y/6
  // POV-Ray's ray for pixel (X, Y): direction + ((X + .5)/W - .5) right +
  // (.5 - (Y + .5)/H) up; Malone's: w + alpha x + beta y.
  for (int X : {0, 3, 7})
    for (int Y : {0, 2, 5}) {
      const double a = (2.0 * X - 8) / 8, b = -(2.0 * Y - 6) / 6;
      const Vec3 pov = c.direction + c.right * ((X + 0.5) / 8 - 0.5) + c.up * (0.5 - (Y + 0.5) / 6);
      const Vec3 malone = Vec3{0, 0, -1} + Vec3{1, 0, 0} * a + Vec3{0, 0.75, 0} * b;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(pov[k], malone[k], 1e-15) << X << " " << Y;
    }
}

TEST(PovExport, WholeScene) {
  const Scene scene =
      sceneWith("5\n0 0 0\n1 0 0\n0 1 0\n107\n5\n0 0 0\n0 1 0\n-1 0 0\n107\n1\n1\n0 0 0\n107\n");
  PovExportOptions options;
  options.fadeDistance = 0.5;  // the colour is C / (2 f^2) = 2 C
  options.maxDepth = 5;
  const PovExport out = exportPov(scene, options);
  EXPECT_EQ(out.width, 8);
  EXPECT_EQ(out.height, 6);
  EXPECT_EQ(out.objects, 2);  // the mesh and the sphere
  EXPECT_EQ(out.lights, 2);
  const std::string& s = out.pov;
  EXPECT_NE(s.find("#version 3.7;"), std::string::npos);
  EXPECT_NE(s.find("ambient_light rgb <0.1, 0.2, 0.3>"), std::string::npos);
  EXPECT_NE(s.find("max_trace_level 5"), std::string::npos);
  EXPECT_NE(s.find("adc_bailout 3.90625e-05"), std::string::npos);
  EXPECT_NE(s.find("light_source { <1, 2, 3> rgb <20, 40, 60> fade_distance 0.5 fade_power 2 }"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("light_source { <0, 5, 0> rgb <1, 1, 1> }"), std::string::npos);
  EXPECT_NE(s.find("mesh {\n  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n"
                   "  triangle { <0, 0, 0>, <0, 1, 0>, <-1, 0, 0> }\n  texture {"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("sphere { <0, 0, 0>, 1 texture {"), std::string::npos);
}

TEST(PovExport, SampledLightAsItsSamples) {
  const Scene scene = sceneWith("105\n4\n0 0 0\n1\n8 8 8\n1\n1\n0 0 0\n107\n");
  const PovExport out = exportPov(scene);
  EXPECT_EQ(out.lights, 2 + 4);
}

// POV-Ray parses every shipped scene's export (skipped without povray).
TEST(PovExport, PovRayParsesEveryShippedScene) {
  if (std::system("command -v povray >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "povray is not installed (apt-get install povray)";
  const std::filesystem::path scenes = std::filesystem::path(PRIME_SCENES) / ".." / "malone";
  const test::TempDir temp("malone_pov_test_");
  const std::filesystem::path& dir = temp.path();
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
    if (entry.path().extension() != ".mal") continue;
    const Scene scene = buildScene(readSceneFile(entry.path().string()), entry.path().string());
    const std::filesystem::path pov = dir / (entry.path().stem().string() + ".pov");
    writePovFile(exportPov(scene).pov, pov);
    const std::filesystem::path log = dir / "povray.log";
    const std::string cmd = "cd '" + dir.string() + "' && povray +I'" + pov.filename().string() +
                            "' +W8 +H8 -A +WT1 -D -F >'" + log.string() + "' 2>&1";
    const int rc = std::system(cmd.c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(rc, 0) << entry.path() << ":\n" << text.str();
    EXPECT_EQ(text.str().find("Parse Error"), std::string::npos) << text.str();
    ++count;
  }
  EXPECT_GE(count, 10);
}

}  // namespace
}  // namespace prime::malone
