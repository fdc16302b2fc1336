// End-to-end replay of every CGL scene (scenes/cgl/*.cgl) with the real
// `prime`: the picture must be the golden one pixel for pixel
// (tests/cgl/golden/<scene>.png, each looked at and checked before it was
// committed: tests/cgl/golden/README.md), the RLE file must hold the same
// pixels, the bytes must not depend on the thread count, the document's own
// damaged copies must read with --lenient as the repaired scene, Appendix 2's
// call statement must work, and a bad scene must exit 1 and write nothing.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "tests/support/compare_pictures.h"
#include "tests/support/run_prime.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace prime {
namespace {

using test::runPrime;

const fs::path kScenes = CGL_SCENES;
const fs::path kGolden = CGL_GOLDEN;

using test::TempDir;

std::vector<std::uint8_t> bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string scenePath(const std::string& name) {
  return (kScenes / (name + ".cgl")).string();
}

// The scenes the port renders today (the doc-* copies need --lenient and are
// compared with their repaired twin below).
std::vector<std::string> scenes() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kScenes))
    if (e.path().extension() == ".cgl" && e.path().stem().string().rfind("doc-", 0) != 0)
      names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class CglReplay : public ::testing::TestWithParam<std::string> {};

TEST_P(CglReplay, RendersTheGoldenPicture) {
  const std::string scene = GetParam();
  const fs::path golden = kGolden / (scene + ".png");
  ASSERT_TRUE(fs::exists(golden)) << "no golden for scenes/cgl/" << scene
                                  << ".cgl: add it (tests/cgl/golden/README.md)";
  TempDir dir;
  const auto r = runPrime("trace " + scenePath(scene) + " --no-window -q --threads 2 --png " +
                          (dir / "out.png").string() + " --rle " + (dir / "out.rle").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const Image8 got = readPng(dir / "out.png"), want = readPng(golden.string());
  EXPECT_EQ(test::comparePictures(got, want), "") << scene;
  // The RLE file holds the same pixels: `prime export` turns it into the same PNG.
  const auto e =
      runPrime("export " + (dir / "out.rle").string() + " " + (dir / "back.png").string() + " -q");
  ASSERT_EQ(e.status, 0) << e.output;
  EXPECT_EQ(test::comparePictures(readPng(dir / "back.png"), got), "") << scene;
  // The document's object list for every ray (--linear-search) and the BVH
  // find the same hits: the same bytes (CGL-D43).
  const auto l =
      runPrime("trace " + scenePath(scene) + " --no-window -q --threads 2 --linear-search --rle " +
               (dir / "list.rle").string());
  ASSERT_EQ(l.status, 0) << l.output;
  EXPECT_EQ(bytesOf(dir / "out.rle"), bytesOf(dir / "list.rle")) << scene;
}

INSTANTIATE_TEST_SUITE_P(Scenes, CglReplay, ::testing::ValuesIn(scenes()), [](const auto& info) {
  std::string n = info.param;
  std::replace(n.begin(), n.end(), '-', '_');
  return n;
});

TEST(CglReplay, TheSameBytesForAnyThreadCount) {
  // glass; and spline-vases, whose per-thread active lists and holes must
  // not depend on which thread traced a row.
  for (const char* scene : {"glass", "spline-vases"}) {
    TempDir dir;
    std::vector<std::vector<std::uint8_t>> pictures;
    for (int threads : {1, 2, 3}) {
      const std::string out = dir / ("t" + std::to_string(threads) + ".rle");
      const auto r = runPrime("trace " + scenePath(scene) + " --no-window -q --rle " + out +
                              " --threads " + std::to_string(threads));
      ASSERT_EQ(r.status, 0) << r.output;
      pictures.push_back(bytesOf(out));
    }
    EXPECT_FALSE(pictures[0].empty()) << scene;
    EXPECT_EQ(pictures[0], pictures[1]) << scene;
    EXPECT_EQ(pictures[0], pictures[2]) << scene;
  }
}

// The manual's hint: a super box around each cube changes no pixel, only
// the work (9 box tests per ray instead of 54 polygon tests).
TEST(CglReplay, SuperBoxesChangeNoPixel) {
  TempDir dir;
  const auto a = runPrime("trace " + scenePath("nine-cubes") + " --no-window --rle " +
                          (dir / "a.rle").string());
  const auto b = runPrime("trace " + scenePath("nine-cubes-boxed") + " --no-window --rle " +
                          (dir / "b.rle").string());
  ASSERT_EQ(a.status, 0) << a.output;
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(bytesOf(dir / "a.rle"), bytesOf(dir / "b.rle"));
  EXPECT_NE(a.output.find("0 super boxes"), std::string::npos) << a.output;
  EXPECT_NE(b.output.find("9 super boxes"), std::string::npos) << b.output;
}

// Figure 59 as printed (OCR damage and the lost texture's path) is refused
// by the strict reader with a located message, and read by --lenient as
// exactly the repaired scene (checkerboard.cgl): the same RLE bytes, with
// no --textures, as the scene's comment says (the lost path's base name finds
// textures/checkerboard.rle beside it, CGL-D41). Figure 2, the scrambled copy
// of section 1.3, too.
TEST(CglReplay, TheDocumentsCopiesReadLenientlyAsTheRepairedScene) {
  TempDir dir;
  const auto strict = runPrime("trace " + scenePath("doc-figure59") + " --no-window -q");
  EXPECT_EQ(strict.status, 1) << strict.output;
  EXPECT_NE(strict.output.find("doc-figure59.cgl:"), std::string::npos) << strict.output;
  EXPECT_NE(strict.output.find("--lenient"), std::string::npos) << strict.output;
  const auto repaired = runPrime("trace " + scenePath("checkerboard") + " --no-window -q --rle " +
                                 (dir / "a.rle").string());
  ASSERT_EQ(repaired.status, 0) << repaired.output;
  for (const std::string copy : {"doc-figure59", "doc-figure2"}) {
    const auto r = runPrime("trace " + scenePath(copy) + " --lenient --no-window --rle " +
                            (dir / "b.rle").string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("repaired:"), std::string::npos) << r.output;
    EXPECT_EQ(bytesOf(dir / "a.rle"), bytesOf(dir / "b.rle")) << copy;
  }
}

// Appendix 2: `trace -yh 300 -d 0 -a 0 -s scene` (one-dash flags that
// override the file) is the same render as the long options.
TEST(CglReplay, TheCallStatementOfAppendix2) {
  TempDir dir;
  const auto a = runPrime("trace -yh 300 -xl 100 -d 0 -a 0 -s -q " + scenePath("glass") +
                          " --no-window -o " + (dir / "a.rle").string());
  ASSERT_EQ(a.status, 0) << a.output;
  const auto b =
      runPrime("trace " + scenePath("glass") + " --yhigh 300 --xleft 100 --max-depth 0 " +
               "--aalevel 0 --shadows --quiet --no-window --rle " + (dir / "b.rle").string());
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(bytesOf(dir / "a.rle"), bytesOf(dir / "b.rle"));
  const auto c =
      runPrime("trace " + scenePath("glass") + " -q --no-window --rle " + (dir / "c.rle").string());
  ASSERT_EQ(c.status, 0) << c.output;
  EXPECT_NE(bytesOf(dir / "a.rle"), bytesOf(dir / "c.rle")) << "the overrides changed nothing";
}

TEST(CglReplay, ABadSceneExitsOneAndWritesNothing) {
  TempDir dir;
  const std::string scene = dir / "bad.cgl", out = dir / "out.rle";
  std::ofstream(scene) << "* a sphere with a surface that does not exist\n"
                          "0 0 0 0 0 1 1\n0.0005\n"
                          "1 1 1 1 1 1 1 1 1 1\n1 1 1 1 1 1 1 1 1 1\n1 1 1 1 1 1 1 1 1 1\n1 1 1\n"
                          "1 sphere 00 00 2 0.0 0.0 0.0 0.1 x y\n";
  const auto r = runPrime("trace " + scene + " --no-window --rle " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("bad.cgl:8"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("surface"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

// A FIFO or a device given as the scene is refused at once, by type (it
// used to block, or to be read until memory ran out).
TEST(CglReplay, AFifoOrADeviceIsRefusedAtOnce) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "scene.cgl").c_str(), 0600), 0);
  const auto r = runPrime("trace --format cgl " + (dir / "scene.cgl").string() + " --no-window -q");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("is a FIFO (named pipe), not a CGL scene file"), std::string::npos)
      << r.output;
  const auto z = runPrime("trace --format cgl /dev/zero --no-window -q");
  EXPECT_EQ(z.status, 1) << z.output;
  EXPECT_NE(z.output.find("/dev/zero: is a character device"), std::string::npos) << z.output;
}

// The document's lost absolute texture path is never opened (CGL-D62): its
// base name finds the port's stand-in in the scene's textures/, as the scene's
// comment promises; without one, the message names every place looked.
TEST(CglReplay, AMissingTextureNamesEveryPlaceLooked) {
  TempDir dir;
  const auto found = runPrime("trace " + scenePath("doc-figure59") +
                              " --lenient --no-window -q --rle " + (dir / "a.rle").string());
  EXPECT_EQ(found.status, 0) << found.output;
  const std::string copy = (dir / "figure59.cgl").string();
  std::filesystem::copy_file(scenePath("doc-figure59"), copy);
  const auto r = runPrime("trace " + copy + " --lenient --no-window -q");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("/u/majsweeney/textures/checkerboard"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("leads outside the scene's directory"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((dir / "textures" / "checkerboard.rle").string()), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--textures"), std::string::npos) << r.output;
}

TEST(CglReplay, AFractalNodeIsTraced) {
  TempDir dir;
  const std::string scene = dir / "fractal.cgl";
  std::ofstream(scene) << "0 0 0 1 0 1 1\n1 lambert normal 0.0 0.0 0.0\n7.0\n"
                          "0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
                          "0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
                          "0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n0.5 0.5 0.5\n0.0005\n"
                          "1 1 1 1 1 1 1 1 1 1\n1 1 1 1 1 1 1 1 1 1\n1 1 1 1 1 1 1 1 1 1\n1 1 1\n"
                          "1 fractal 00 00 1 5 1.3 0.5 9772 constrained\n";
  // The document's own fractal node (Appendix 1 section 13).
  const auto r = runPrime("trace " + scene + " --no-window -q");
  EXPECT_EQ(r.status, 0) << r.output;
}

// The probe traces what aalevel 0 traces for a pixel: its RGB is the pixel's.
TEST(CglProbe, ThePixelsColourAndItsRays) {
  TempDir dir;
  const auto t = runPrime("trace " + scenePath("checkerboard") +
                          " --aalevel 0 --no-window -q --png " + (dir / "a.png").string());
  ASSERT_EQ(t.status, 0) << t.output;
  const Image8 img = readPng(dir / "a.png");
  // The mirror ball: pixel (200, 240) (y from the bottom), image row 511 - 240.
  const auto p = runPrime("probe " + scenePath("checkerboard") + " --point 200 240");
  ASSERT_EQ(p.status, 0) << p.output;
  const std::size_t at = (static_cast<std::size_t>(511 - 240) * 512 + 200) * 3;
  const std::string rgb =
      "RGB (ToRGB: (1/15) M^-1 XYZ, clipped, truncated): " + std::to_string(img.rgb[at]) + " " +
      std::to_string(img.rgb[at + 1]) + " " + std::to_string(img.rgb[at + 2]);
  EXPECT_NE(p.output.find(rgb), std::string::npos) << p.output;
  EXPECT_NE(p.output.find("hits object 1 (sphere, scene node 4, surface 2)"), std::string::npos)
      << p.output;
  EXPECT_NE(p.output.find("reflected ray, level 1"), std::string::npos) << p.output;
}

}  // namespace
}  // namespace prime
