// `prime export`, `prime diff`, `prime palette`, `prime view` and the display
// side of `prime trace`, all headless (no DISPLAY): what a user and CI see.
// The real window is tested under Xvfb in window_xvfb_test.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "legacy_io/prime/graph_file.h"
#include "palette/png_image.h"
#include "palette/prime/palettes.h"
#include "tests/support/child_process.h"
#include "tests/support/temp_scene.h"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;
using prime::test::ChildProcess;

const std::map<std::string, std::string> kHeadless{{"DISPLAY", ""}, {"WAYLAND_DISPLAY", ""}};

struct Outcome {
  int status;
  std::string out, err;
};

Outcome primeHeadless(const std::vector<std::string>& args) {
  std::vector<std::string> argv{PRIME_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildProcess p(argv, kHeadless);
  const auto status = p.wait(120000);
  return {status.value_or(-1), p.out(), p.err()};
}

// A small graph file: 12 x 6 pixels (header 11 x 5), values that exercise
// the masking: v = 40*y + 23*x - 60 runs from -60 to 453.
prime::io::GraphFile smallGraph(std::int16_t graphType = 1) {
  prime::io::GraphFile g;
  g.graphType = graphType;
  g.numPixAcross = 11;
  g.numPixDown = 5;
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 12; ++x)
      g.pixels.push_back(static_cast<std::int16_t>(40 * y + 23 * x - 60));
  return g;
}

prime::Rgb8 at(const prime::Image8& img, int x, int y) {
  const std::uint8_t* p = &img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3];
  return {p[0], p[1], p[2]};
}

prime::Rgb8 shown(const std::string& palette, int value) {
  return prime::present(
      prime::findBuiltinPalette(palette)->dac)[static_cast<std::size_t>(value & 0xFF)];
}

TEST(PrimeExport, ImageScreenAndFileAreas) {
  prime::test::TempScene d;
  prime::io::writeGraphFile(d.path("g").string(), smallGraph());
  Outcome r = primeHeadless({"export", d.path("g").string(), d.path("image.png").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(
      r.out,
      HasSubstr("12 x 6 (image area; the file's 12 x 6 pixels at (675, 0) on a 1024 x 768 screen), "
                "palette listing, DAC round"));
  const prime::Image8 image = prime::readPng(d.path("image.png").string());
  EXPECT_EQ(image.width, 12);
  EXPECT_EQ(image.height, 6);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 12; ++x)
      ASSERT_EQ(at(image, x, y), shown("listing", 40 * y + 23 * x - 60)) << x << "," << y;

  ASSERT_EQ(primeHeadless(
                {"export", d.path("g").string(), d.path("screen.png").string(), "--area", "screen"})
                .status,
            0);
  const prime::Image8 screen = prime::readPng(d.path("screen.png").string());
  EXPECT_EQ(screen.width, 1024);
  EXPECT_EQ(screen.height, 768);
  EXPECT_EQ(at(screen, 675, 0), shown("listing", -60));
  EXPECT_EQ(at(screen, 674, 0), shown("listing", 0));  // the cleared screen: index 0, black
  EXPECT_EQ(at(screen, 686, 5), shown("listing", 40 * 5 + 23 * 11 - 60));

  // Placed so that it overhangs the screen: the image area is clipped, the
  // file area is not.
  r = primeHeadless(
      {"export", d.path("g").string(), d.path("clip.png").string(), "--at", "1020", "764"});
  ASSERT_EQ(r.status, 0);
  EXPECT_THAT(r.err, HasSubstr("does not fit the 1024 x 768 screen"));
  EXPECT_EQ(prime::readPng(d.path("clip.png").string()).width, 4);
  ASSERT_EQ(primeHeadless({"export", d.path("g").string(), d.path("file.png").string(), "--area",
                           "file", "--at", "1020", "764"})
                .status,
            0);
  EXPECT_EQ(prime::readPng(d.path("file.png").string()).width, 12);
}

TEST(PrimeExport, PalettesByNameByGraphTypeAndFromAFile) {
  prime::test::TempScene d;
  prime::io::writeGraphFile(d.path("vga").string(), smallGraph(0));
  ASSERT_EQ(primeHeadless({"export", d.path("vga").string(), d.path("a.png").string()}).status, 0);
  EXPECT_EQ(at(prime::readPng(d.path("a.png").string()), 3, 0),
            shown("vga", 9));  // graphType 0 -> vga
  ASSERT_EQ(primeHeadless(
                {"export", d.path("vga").string(), d.path("b.png").string(), "--palette", "plate3"})
                .status,
            0);
  EXPECT_EQ(at(prime::readPng(d.path("b.png").string()), 3, 0), shown("plate3", 9));

  d.write("grey.pal", "prime-palette 1\nbase listing\nvalues dac\n9 10 20 30\n");
  ASSERT_EQ(primeHeadless({"export", d.path("vga").string(), d.path("c.png").string(), "--palette",
                           d.path("grey.pal").string()})
                .status,
            0);
  EXPECT_EQ(at(prime::readPng(d.path("c.png").string()), 3, 0),
            (prime::Rgb8{40, 81, 121}));  // 10, 20, 30 rounded
  ASSERT_EQ(primeHeadless({"export", d.path("vga").string(), d.path("d.png").string(), "--palette",
                           d.path("grey.pal").string(), "--dac", "replicate"})
                .status,
            0);
  EXPECT_EQ(at(prime::readPng(d.path("d.png").string()), 3, 0),
            (prime::Rgb8{40, 81, 121}));  // 40|0, 80|1, 120|1

  d.write("bad.pal", "prime-palette 1\nvalues dac\n0 0 0 70\n");
  Outcome r = primeHeadless({"export", d.path("vga").string(), d.path("e.png").string(),
                             "--palette", d.path("bad.pal").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.err,
              HasSubstr("bad.pal:3: blue: expected an integer 0..63 (values dac), found \"70\""));
  EXPECT_FALSE(d.exists("e.png"));
  r = primeHeadless(
      {"export", d.path("vga").string(), d.path("e.png").string(), "--palette", "sepia"});
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(
      r.err,
      HasSubstr(
          "sepia: palette: expected a built-in palette (listing, plate3, vga) or a palette file"));
  r = primeHeadless(
      {"export", d.path("vga").string(), d.path("e.png").string(), "--dac", "nearest"});
  EXPECT_NE(r.status, 0);
}

TEST(PrimeExport, BrokenAndPartialGraphFiles) {
  prime::test::TempScene d;
  d.writeBytes("short", {1, 0, 11, 0});
  Outcome r = primeHeadless({"export", d.path("short").string(), d.path("x.png").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.err, HasSubstr("short (byte 4): numPixDown"));
  auto bytes = prime::io::toBytes(smallGraph());
  bytes.resize(6 + 2 * 12 * 2 + 2 * 5);  // two rows and five pixels
  d.writeBytes("g.partial", bytes);
  r = primeHeadless(
      {"export", d.path("g.partial").string(), d.path("p.png").string(), "--area", "file"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("partial graph file (an aborted trace): 2 of 6 rows"));
  const prime::Image8 img = prime::readPng(d.path("p.png").string());
  EXPECT_EQ(at(img, 4, 2), shown("listing", 80 + 92 - 60));
  EXPECT_EQ(at(img, 5, 2), shown("listing", 0));  // not in the file: index 0
}

// G30: a truncated graph file that is not a .partial is refused (exit 1,
// nothing written), by export and by view; a 7-byte one too.
TEST(PrimeExport, TruncatedGraphFileIsRefused) {
  prime::test::TempScene d;
  auto bytes = prime::io::toBytes(smallGraph());
  bytes.resize(6 + 2 * 12 * 2 + 2 * 5);  // two rows and five pixels of 6 x 12
  d.writeBytes("graph_scr", bytes);
  Outcome r = primeHeadless({"export", d.path("graph_scr").string(), d.path("x.png").string()});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("graph_scr (byte 64): pixel data"));
  EXPECT_THAT(r.err, HasSubstr("29 whole pixels: the file is truncated"));
  EXPECT_FALSE(std::filesystem::exists(d.path("x.png")));
  bytes.resize(7);
  d.writeBytes("seven", bytes);
  r = primeHeadless({"export", d.path("seven").string(), d.path("y.png").string()});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the file is truncated"));
  EXPECT_FALSE(std::filesystem::exists(d.path("y.png")));
  r = primeHeadless({"view", d.path("seven").string(), "--no-window"});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("the file is truncated"));
}

TEST(PrimeDiff, ExitStatusCountsAndImage) {
  prime::test::TempScene d;
  const prime::io::GraphFile a = smallGraph();
  prime::io::GraphFile b = a;
  b.pixels[13] = 300;                 // (1, 1): 300 & 0xFF = 44 vs 3
  b.pixels[14] = b.pixels[14] + 256;  // (2, 1): same on the screen
  prime::io::writeGraphFile(d.path("a").string(), a);
  prime::io::writeGraphFile(d.path("b").string(), b);
  prime::io::writeGraphFile(d.path("a2").string(), a);

  Outcome r = primeHeadless({"diff", d.path("a").string(), d.path("a2").string()});
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("pixels differing: 0 of 72 (0.0000%)"));
  EXPECT_THAT(r.out, HasSubstr("\nidentical\n"));

  r = primeHeadless(
      {"diff", d.path("a").string(), d.path("b").string(), "--image", d.path("diff.png").string()});
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_THAT(
      r.out,
      HasSubstr("pixels differing: 2 of 72 (2.7778%); 1 of them look different on the screen"));
  EXPECT_THAT(r.out, HasSubstr("first difference at (1, 1): 3 and 300"));
  // 3 is overridden (K17): (150, 239, 130) -> DAC (37, 59, 32) -> (150, 239, 130);
  // 44 = 32 + 3*4 -> (32, 96, 0) -> DAC (8, 24, 0) -> (32, 97, 0). Green: 239 - 97 = 142.
  EXPECT_THAT(
      r.out,
      HasSubstr("largest colour difference: 142 of 255 (palette listing, DAC round) at (1, 1): 3 "
                "(150, 239, 130) and 300 (32, 97, 0)"));
  EXPECT_THAT(r.out, HasSubstr("the files differ"));
  const prime::Image8 img = prime::readPng(d.path("diff.png").string());
  EXPECT_EQ(img.width, 12);
  EXPECT_EQ(at(img, 1, 1), (prime::Rgb8{255, 0, 255}));
  EXPECT_EQ(at(img, 2, 1), (prime::Rgb8{0, 255, 255}));

  r = primeHeadless({"diff", "-q", d.path("a").string(), d.path("b").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");

  prime::io::GraphFile other = a;
  other.graphType = 0;
  prime::io::writeGraphFile(d.path("c").string(), other);
  r = primeHeadless({"diff", d.path("a").string(), d.path("c").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("graphType differs: 1 and 0"));

  prime::io::GraphFile small = a;
  small.numPixDown = 4;
  small.pixels.resize(60);
  prime::io::writeGraphFile(d.path("s").string(), small);
  r = primeHeadless({"diff", d.path("a").string(), d.path("s").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("sizes differ: no pixels compared"));

  r = primeHeadless({"diff", d.path("a").string(), d.path("missing").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("missing"));
}

TEST(PrimePalette, PrintsALoadableTableAndLists) {
  prime::test::TempScene d;
  Outcome r = primeHeadless({"palette"});
  ASSERT_EQ(r.status, 0);
  EXPECT_THAT(r.out, HasSubstr("prime-palette 1\nname listing\nvalues dac\n"));
  EXPECT_THAT(r.out, HasSubstr("\n  1 20 44 15  # #51b23d\n"));
  EXPECT_THAT(r.out, HasSubstr("\n255 56 56 48  # #e3e3c2\n"));
  d.write("copy.pal", r.out);
  r = primeHeadless({"palette", d.path("copy.pal").string()});
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.out, HasSubstr("\n  1 20 44 15  # #51b23d\n"));
  r = primeHeadless({"palette", "--list"});
  EXPECT_THAT(r.out, HasSubstr("plate3\tColour Plate 3"));
}

TEST(PrimeView, HeadlessSaysSoAndSucceeds) {
  prime::test::TempScene d;
  prime::io::writeGraphFile(d.path("g").string(), smallGraph());
  Outcome r = primeHeadless({"view", d.path("g").string()});
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.err, HasSubstr("running headless (no DISPLAY): nothing to show"));
  r = primeHeadless({"view", "--no-window", d.path("g").string()});
  EXPECT_THAT(r.err, HasSubstr("running headless (--no-window)"));
}

using prime::test::sphere;

TEST(PrimeTrace, HeadlessPngTrueColourAndStalePartialRemoved) {
  prime::test::TempScene s;
  sphere(s);
  s.write("graph_scr.partial", "stale");
  Outcome r =
      primeHeadless({"trace", "--model", s.path().string(), "--png", s.path("a.png").string(),
                     "--true-color-png", s.path("t.png").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("prime: running headless (no DISPLAY)"));
  EXPECT_FALSE(s.exists("graph_scr.partial"));
  const prime::Image8 png = prime::readPng(s.path("a.png").string());
  EXPECT_EQ(png.width, 349);  // the image area: 350 x 769 less the off-screen column and row (K21)
  EXPECT_EQ(png.height, 768);
  EXPECT_EQ(at(png, 0, 0), shown("listing", 1));       // the background (K16, K17)
  EXPECT_EQ(at(png, 174, 384), shown("listing", 68));  // the sphere (replay_sphere_test)
  const prime::Image8 tc = prime::readPng(s.path("t.png").string());
  EXPECT_EQ(tc.width, 349);
  EXPECT_EQ(at(tc, 0, 0), (prime::Rgb8{0, 0, 0}));
  EXPECT_EQ(at(tc, 174, 384), (prime::Rgb8{102, 51, 26}));  // (0.4, 0.2, 0.1) * 255 = 102, 51, 25.5

  r = primeHeadless({"trace", s.path().string(), "-q", "--no-window", "--png",
                     s.path("f.png").string(), "--png-area", "file", "--palette", "plate3"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, Not(HasSubstr("headless")));  // -q
  const prime::Image8 file = prime::readPng(s.path("f.png").string());
  EXPECT_EQ(file.width, 350);
  EXPECT_EQ(file.height, 769);
  // plate 3: (0.4, 0.2) -> 16*6 + 3 = 99
  EXPECT_EQ(at(file, 174, 384), shown("plate3", 99));
}

// An interrupted re-render keeps the previous good graph file (issue 17: it
// used to be deleted) and puts the finished rows in the .partial beside it.
TEST(PrimeTrace, CtrlCAbortsHeadlessKeepsThePreviousRenderAndWritesAPartialFile) {
  prime::test::TempScene s;
  sphere(s);
  ASSERT_EQ(primeHeadless({"model", s.path().string()}).status, 0);
  s.write("graph_scr", "an older, complete-looking render");
  // Sixteen times the pixels on one thread: long enough to interrupt.
  ChildProcess p(
      {PRIME_EXE, "trace", s.path().string(), "--threads", "1", "--screen", "4096", "3072"},
      kHeadless);
  ASSERT_TRUE(p.waitForErr("running headless", 60000)) << p.err();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  p.signal(SIGINT);
  const auto status = p.wait(60000);
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(*status, 130) << p.out() << p.err();  // 128 + SIGINT, as a shell reports it
  EXPECT_THAT(p.err(), HasSubstr("prime: trace aborted after "));
  EXPECT_THAT(p.err(), HasSubstr("graph_scr not written (the previous one is kept)"));
  // The summary counts the rows rendered, as the message does (it said the
  // whole picture's size as if all were).
  const std::string said = p.err().substr(p.err().find("trace aborted after ") + 20);
  const std::string rows = said.substr(0, said.find(" rows"));
  EXPECT_THAT(rows, ::testing::EndsWith(" of 3073")) << p.err();
  EXPECT_THAT(p.out(), HasSubstr("ABORTED after " + rows + " rows of 1394 x 3073 pixels"))
      << p.out();
  ASSERT_TRUE(s.exists("graph_scr"));
  const auto previous = s.read("graph_scr");
  EXPECT_EQ(std::string(previous.begin(), previous.end()), "an older, complete-looking render");
  ASSERT_TRUE(s.exists("graph_scr.partial"));
  const prime::io::GraphFilePrefix part =
      prime::io::readGraphFilePrefix(s.path("graph_scr.partial").string());
  EXPECT_FALSE(part.complete());
  EXPECT_EQ(part.graph.numPixAcross, 1393);  // (int)(4096*1.0) - (int)(4096*0.66) = 4096 - 2703
  EXPECT_EQ(part.pixelsPresent % 1394, 0u);  // whole rows from the top
  EXPECT_THROW(prime::io::readGraphFile(s.path("graph_scr.partial").string()), std::exception);
}

}  // namespace
