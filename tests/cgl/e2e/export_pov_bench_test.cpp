// End-to-end: `prime export-pov` and `prime bench` on the shipped CGL scenes
// with the real `prime`. Every scene the port renders exports (its texture
// maps as PNG files beside the .pov, 512 x 512); where povray is installed,
// POV-Ray 3.7 renders every export without an error (at 64 x 64, with the
// options the export prints); `prime bench` prints a row per scene and writes
// its CSV with the render's counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "tests/support/run_prime.h"

namespace fs = std::filesystem;

namespace prime {
namespace {

using test::runPrime;

const fs::path kShippedScenes = CGL_SCENES;

fs::path tempDir() {
  std::random_device rd;
  const fs::path p = fs::temp_directory_path() / ("prime-cgl-pov-" + std::to_string(rd()));
  fs::create_directories(p);
  return p;
}

std::vector<std::string> shippedScenes() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(kShippedScenes))
    if (e.path().extension() == ".cgl" && e.path().stem().string().rfind("doc-", 0) != 0)
      out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(CglExportPov, EveryShippedSceneExportsAndPovRayRendersIt) {
  const fs::path dir = tempDir();
  const bool havePovray = std::system("command -v povray >/dev/null 2>&1") == 0;
  int textured = 0;
  const auto names = shippedScenes();
  ASSERT_GE(names.size(), 5u);
  for (const std::string& name : names) {
    const fs::path pov = dir / (name + ".pov");
    const auto r =
        runPrime("export-pov " + (kShippedScenes / (name + ".cgl")).string() + " " + pov.string());
    ASSERT_EQ(r.status, 0) << name << ": " << r.output;
    ASSERT_TRUE(fs::exists(pov)) << name;
    // The million-facet fractals (fractal-9, fractal-10) export meshes of
    // tens of megabytes: their head is checked, POV-Ray is not run on them
    // here (their mesh is tested in tests/cgl/unit/fractal_test.cpp), so the
    // test stays quick under the sanitizers.
    const bool large = fs::file_size(pov) > (8u << 20);
    std::ifstream in(pov);
    std::stringstream text;
    if (large) {
      std::string head(65536, '\0');
      in.read(head.data(), static_cast<std::streamsize>(head.size()));
      text << head;
    } else {
      text << in.rdbuf();
    }
    EXPECT_NE(text.str().find("#version 3.7;"), std::string::npos) << name;
    // The textures named in the file were written beside it.
    static const std::regex png(R"(png \"([^\"]+)\")");
    const std::string s = text.str();
    for (std::sregex_iterator i(s.begin(), s.end(), png), end; i != end; ++i) {
      const Image8 img = readPng((dir / (*i)[1].str()).string());
      EXPECT_EQ(img.width, 512) << name;
      EXPECT_EQ(img.height, 512) << name;
      ++textured;
    }
    // The options to render with: "+W512 +H512 ...", printed by the export.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(\+W512 \+H512([^\n]*) File_Gamma)")))
        << r.output;
    if (!havePovray || large) continue;
    const std::string cmd = "cd " + dir.string() + " && povray +I" + name + ".pov" + m[1].str() +
                            " +W64 +H64 -D -F -GA >" + name + ".log 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << name << ": see " << (dir / (name + ".log"));
  }
  EXPECT_GE(textured, 1);  // checkerboard, glass and textures use texture maps
  if (!havePovray) GTEST_SKIP() << "povray is not installed: exports checked, not rendered";
  std::error_code ec;
  fs::remove_all(dir, ec);
}

TEST(CglBench, PrintsARowAndWritesTheCsv) {
  const fs::path dir = tempDir();
  const fs::path csv = dir / "bench.csv";
  const auto r =
      runPrime("bench " + (kShippedScenes / "ball.cgl").string() + " " +
               (kShippedScenes / "nine-cubes-boxed.cgl").string() +
               " --runs 1 --threads 1 --aalevel 0 --linear-search --csv " + csv.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("# prime bench (Waterloo CGL)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ball.cgl"), std::string::npos);
  std::ifstream in(csv);
  std::string header, ball, cubes;
  std::getline(in, header);
  std::getline(in, ball);
  std::getline(in, cubes);
  EXPECT_EQ(header,
            "scene,pixels,aalevel,depth,read_ms,build_ms,cpu_s_1,wall_s_1,rays,tests,primary,"
            "shadow,reflected,refracted,sphere_tests,cylinder_tests,polygon_tests,box_tests,"
            "shade_lambert,shade_phong");
  // The ball's window is 121 x 121 pixels (xleft 196 .. xright 316, ylow
  // 196 .. yhigh 316); aalevel 0: one primary ray per pixel, no shadows.
  EXPECT_NE(ball.find(",14641,0,"), std::string::npos) << ball;
  // The boxed cubes test super boxes.
  std::vector<std::string> f;
  std::stringstream ss(cubes);
  for (std::string c; std::getline(ss, c, ',');) f.push_back(c);
  ASSERT_EQ(f.size(), 20u) << cubes;
  EXPECT_GT(std::stoull(f[17]), 0u) << cubes;  // box_tests
  std::error_code ec;
  fs::remove_all(dir, ec);
}

// CGL-D180 through the command line: `--profile modern` renders the donut,
// close to the document's picture, and `prime cgl-splines --profile modern
// --holes` counts the modern path's holes against the dense reference.
TEST(CglModernSplines, TraceAndHoleCount) {
  const fs::path dir = tempDir();
  const std::string donut = (kShippedScenes / "spline-donut.cgl").string();
  const auto doc = runPrime("trace " + donut + " --aalevel 0 --threads 2 --no-window -q --png " +
                            (dir / "document.png").string());
  ASSERT_EQ(doc.status, 0) << doc.output;
  const auto mod = runPrime("trace " + donut + " --aalevel 0 --threads 2 --no-window -q --png " +
                            (dir / "modern.png").string() + " --profile modern");
  ASSERT_EQ(mod.status, 0) << mod.output;
  const Image8 a = readPng((dir / "document.png").string());
  const Image8 b = readPng((dir / "modern.png").string());
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  std::size_t differ = 0;
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t k = 0; k < pixels; ++k)
    differ += a.rgb[3 * k] != b.rgb[3 * k] || a.rgb[3 * k + 1] != b.rgb[3 * k + 1] ||
              a.rgb[3 * k + 2] != b.rgb[3 * k + 2];
  // The same surface: only pixels along silhouettes and the document's
  // farther hits differ (measured: under 1 %).
  EXPECT_LT(differ, pixels / 100) << differ;
  EXPECT_GT(differ, 0u) << "two intersectors, not one";
  const auto holes = runPrime("cgl-splines " + donut + " --profile modern --holes 8");
  ASSERT_EQ(holes.status, 0) << holes.output;
  EXPECT_NE(holes.output.find("modern path hits"), std::string::npos) << holes.output;
  const auto bad = runPrime("trace " + donut + " --profile 1991 --no-window -q");
  EXPECT_EQ(bad.status, 2) << bad.output;
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace prime
