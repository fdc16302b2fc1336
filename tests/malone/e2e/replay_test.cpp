// End-to-end replay of every Malone scene (scenes/malone/*.mal) with the real
// `prime`: the picture must be the golden one pixel for pixel
// (tests/malone/golden/<scene>.png, each looked at and checked by hand before
// it was committed: tests/malone/golden/README.md), the same for any thread
// count, and a bad scene must exit 1 and leave no picture behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "tests/support/compare_pictures.h"
#include "tests/support/run_prime.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace prime {
namespace {

const fs::path kScenes = MALONE_SCENES;
const fs::path kGolden = MALONE_GOLDEN;

using test::CommandResult;
using test::runPrime;
using test::TempDir;

std::vector<std::string> scenes() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kScenes))
    if (e.path().extension() == ".mal") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class MaloneReplay : public ::testing::TestWithParam<std::string> {};

TEST_P(MaloneReplay, RendersTheGoldenPicture) {
  const std::string scene = GetParam();
  const fs::path golden = kGolden / (scene + ".png");
  ASSERT_TRUE(fs::exists(golden)) << "no golden for scenes/malone/" << scene
                                  << ".mal: add it (tests/malone/golden/README.md)";
  TempDir dir;
  const fs::path png = dir.path() / "out.png", ppm = dir.path() / "out.ppm";
  const CommandResult r =
      runPrime("trace " + (kScenes / (scene + ".mal")).string() + " --no-window -q --png " +
               png.string() + " --ppm " + ppm.string() + " --threads 2");
  ASSERT_EQ(r.status, 0) << r.output;
  const Image8 got = readPng(png.string()), want = readPng(golden.string());
  EXPECT_EQ(test::comparePictures(got, want), "") << scene;
  // The PPM holds the same bytes as the PNG, after its P6 header.
  std::ifstream in(ppm, std::ios::binary);
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                std::istreambuf_iterator<char>()};
  const std::string header =
      "P6\n" + std::to_string(got.width) + " " + std::to_string(got.height) + "\n255\n";
  ASSERT_EQ(bytes.size(), header.size() + got.rgb.size());
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + static_cast<long>(header.size())), header);
  EXPECT_TRUE(std::equal(got.rgb.begin(), got.rgb.end(),
                         reinterpret_cast<const unsigned char*>(bytes.data()) + header.size()));
}

INSTANTIATE_TEST_SUITE_P(Scenes, MaloneReplay, ::testing::ValuesIn(scenes()), [](const auto& info) {
  std::string n = info.param;
  for (char& c : n)
    if (c == '-') c = '_';
  return n;
});

TEST(MaloneReplay, TheSameBytesForAnyThreadCount) {
  TempDir dir;
  std::vector<std::vector<std::uint8_t>> pictures;
  for (int threads : {1, 2, 3}) {
    const fs::path out = dir.path() / ("t" + std::to_string(threads) + ".ppm");
    const CommandResult r =
        runPrime("trace " + (kScenes / "glass.mal").string() + " --no-window -q --ppm " +
                 out.string() + " --threads " + std::to_string(threads));
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(out, std::ios::binary);
    pictures.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  EXPECT_EQ(pictures[0], pictures[1]);
  EXPECT_EQ(pictures[0], pictures[2]);
}

// The document's own scene (section 1.2), by hand: the centre pixel's ray
// (alpha = beta = 0) from (0,2,3) towards the origin meets the plane y = 0 at
// the origin; the light at (-2,5,2) is l = sqrt(33) away, d.s = 5/sqrt(33);
// k_s = 0, no ambient: 1 * 1 * (5/sqrt(33)) / 33 = 0.026376, byte
// round(6.726) = 7.
TEST(MaloneReplay, TheDocumentsSceneCentrePixelByHand) {
  const Image8 want = readPng((kGolden / "doc-scene.png").string());
  const std::size_t at = (static_cast<std::size_t>(128) * want.width + 128) * 3;
  EXPECT_EQ(want.rgb[at], 7);
  EXPECT_EQ(want.rgb[at + 1], 7);
  EXPECT_EQ(want.rgb[at + 2], 7);
}

TEST(MaloneReplay, ABadSceneExitsOneAndWritesNothing) {
  TempDir dir;
  const fs::path scene = dir.path() / "bad.mal", out = dir.path() / "out.ppm";
  std::ofstream(scene) << "102 0 2 3 0 0 0 1 0 0 0 1 0 64 64\n1 0.5 0 0\n";  // ends inside a sphere
  const CommandResult r =
      runPrime("trace " + scene.string() + " --no-window --ppm " + out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("bad.mal:2:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("sphere, field centre z"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("end of file"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(MaloneReplay, TheFormatIsDetectedOrNamed) {
  TempDir dir;
  // A Malone scene under a name that says nothing, and --format malone.
  const fs::path scene = dir.path() / "scene.txt";
  fs::copy_file(kScenes / "doc-scene.mal", scene);
  const CommandResult a = runPrime("trace " + scene.string() + " --no-window -q");
  EXPECT_EQ(a.status, 0) << a.output;
  const CommandResult b = runPrime("trace --format malone " + scene.string() + " --no-window -q");
  EXPECT_EQ(b.status, 0) << b.output;
  const CommandResult probe = runPrime("probe " + scene.string() + " --pixel 128 128");
  EXPECT_EQ(probe.status, 0) << probe.output;
  EXPECT_NE(probe.output.find("bytes 7 7 7"), std::string::npos) << probe.output;
}

}  // namespace
}  // namespace prime

namespace prime {
namespace {

TEST(MaloneBench, TimesAMaloneScene) {
  TempDir dir;
  const fs::path csv = dir.path() / "bench.csv";
  const CommandResult r = runPrime("bench " + (kScenes / "doc-sphere.mal").string() +
                                   " --runs 1 --threads 1 --csv " + csv.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("doc-sphere.mal"), std::string::npos) << r.output;
  std::ifstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  // The shared bench table (src/cli/bench_table.h): tests are primitive tests.
  EXPECT_EQ(header, "scene,pixels,read_ms,build_ms,cpu_s_1,wall_s_1,rays,tests,hits");
  EXPECT_NE(row.find(",65536,"), std::string::npos) << row;  // 256 x 256 pixels
}

}  // namespace
}  // namespace prime

namespace prime {
namespace {

TEST(MaloneView8514, ThePictureThroughPrimesPalette) {
  TempDir dir;
  const fs::path png = dir.path() / "p.png", view = dir.path() / "v.png";
  const CommandResult r =
      runPrime("trace " + (kScenes / "doc-sphere.mal").string() + " --no-window -q --png " +
               png.string() + " --png-8514 " + view.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Image8 truecolour = readPng(png.string()), shown = readPng(view.string());
  EXPECT_EQ(shown.width, truecolour.width);
  EXPECT_EQ(shown.height, truecolour.height);
  // 256 colours at most, and not the true-colour picture.
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < shown.rgb.size(); i += 3)
    colours.insert(static_cast<std::uint32_t>(shown.rgb[i]) << 16 | shown.rgb[i + 1] << 8 |
                   shown.rgb[i + 2]);
  EXPECT_LE(colours.size(), 256u);
  EXPECT_NE(shown.rgb, truecolour.rgb);
}

}  // namespace
}  // namespace prime

namespace prime {
namespace {

TEST(MaloneReplay, AMissingOutputDirectoryIsFoundBeforeRendering) {
  TempDir dir;
  const fs::path out = dir.path() / "no-such-dir" / "x.ppm";
  const CommandResult r = runPrime("trace " + (kScenes / "doc-sphere.mal").string() +
                                   " --no-window --ppm " + out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("no-such-dir does not exist"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("traced"), std::string::npos) << r.output;  // nothing rendered
}

}  // namespace
}  // namespace prime
