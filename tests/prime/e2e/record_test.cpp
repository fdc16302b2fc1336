// `prime trace --record`: the drawing of plate 2 kept as an animated GIF,
// decoded here with giflib (DGifSlurp) and composited frame by frame as a
// GIF viewer does (each frame drawn over the last): the first frame is the
// cleared screen, the screen fills from the top, the last frame is the
// final screen --png wrote, the clip is about the length asked for, and two
// runs give the same bytes. Headless: the frames' times are computed.
#include <gif_lib.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "palette/png_image.h"
#include "tests/support/child_process.h"
#include "tests/support/temp_scene.h"

namespace record_test {

namespace fs = std::filesystem;
using prime::test::ChildProcess;
using ::testing::HasSubstr;
using ::testing::Not;

struct Recording {
  int width = 0, height = 0, frames = 0;
  long hundredths = 0;               // the delays summed
  long lastDelay = 0;                // the final screen's hold
  std::vector<std::uint8_t> first;   // the first frame's RGB
  std::vector<std::uint8_t> last;    // the composited last frame's RGB
  std::vector<std::uint8_t> middle;  // composited halfway through
};

Recording decode(const fs::path& path) {
  Recording r;
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  if (gif == nullptr || DGifSlurp(gif) != GIF_OK) {
    ADD_FAILURE() << "giflib cannot read " << path;
    if (gif) DGifCloseFile(gif, &error);
    return r;
  }
  r.width = gif->SWidth;
  r.height = gif->SHeight;
  r.frames = gif->ImageCount;
  std::vector<std::uint8_t> canvas(static_cast<std::size_t>(r.width) * r.height * 3, 0);
  for (int f = 0; f < gif->ImageCount; ++f) {
    const SavedImage& img = gif->SavedImages[f];
    const GifImageDesc& d = img.ImageDesc;
    const ColorMapObject* map = d.ColorMap ? d.ColorMap : gif->SColorMap;
    for (int y = 0; y < d.Height; ++y)
      for (int x = 0; x < d.Width; ++x) {
        const GifColorType c = map->Colors[img.RasterBits[y * d.Width + x]];
        std::uint8_t* p = &canvas[(static_cast<std::size_t>(d.Top + y) * r.width + d.Left + x) * 3];
        p[0] = c.Red;
        p[1] = c.Green;
        p[2] = c.Blue;
      }
    GraphicsControlBlock gcb{};
    if (DGifSavedExtensionToGCB(gif, f, &gcb) == GIF_OK) {
      r.hundredths += gcb.DelayTime;
      r.lastDelay = gcb.DelayTime;
    }
    if (f == 0) r.first = canvas;
    if (f == gif->ImageCount / 2) r.middle = canvas;
  }
  r.last = canvas;
  DGifCloseFile(gif, &error);
  return r;
}

int runPrime(const std::vector<std::string>& args, std::string* out) {
  std::vector<std::string> argv{PRIME_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildProcess p(argv, {{"DISPLAY", ""}, {"WAYLAND_DISPLAY", ""}});
  const int status = p.wait(300000).value_or(-1);
  *out = p.out() + p.err();
  return status;
}

std::string bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Record, Plate2AtThe1991PaceInATwentySecondClipEndsOnTheFinalScreen) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "plate2", s.path(), fs::copy_options::recursive);
  const fs::path gif = s.path("drawing.gif"), png = s.path("screen.png");
  std::string out;
  ASSERT_EQ(runPrime({"trace", s.path().string(), "--model", "--pace", "1991", "--record",
                      gif.string(), "--record-length", "20", "--png", png.string(), "--png-area",
                      "screen", "--no-window"},
                     &out),
            0)
      << out;
  EXPECT_THAT(out, HasSubstr("recorded " + gif.string()));
  EXPECT_THAT(out, HasSubstr("1991 estimate: "));
  const Recording r = decode(gif);
  ASSERT_EQ(r.width, 1024);
  ASSERT_EQ(r.height, 768);
  // 20 s at 25 frames a second at most, then the 3 s hold.
  EXPECT_GE(r.frames, 100);
  EXPECT_LE(r.frames, 502);
  EXPECT_NEAR(static_cast<double>(r.hundredths - r.lastDelay), 2000.0, 10.0);
  EXPECT_EQ(r.lastDelay, 300);
  // The cleared screen first.
  EXPECT_TRUE(std::all_of(r.first.begin(), r.first.end(), [](std::uint8_t v) { return v == 0; }));
  // The last frame is the final screen, pixel for pixel.
  const prime::Image8 screen = prime::readPng(png.string());
  ASSERT_EQ(screen.width, 1024);
  EXPECT_TRUE(r.last == screen.rgb) << "the recording's last frame is not the final screen";
  // Halfway the picture is drawn from the top: its top row is there, its
  // bottom row not yet.
  const auto pixel = [&](const std::vector<std::uint8_t>& rgb, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * 1024 + x) * 3;
    return std::array<std::uint8_t, 3>{rgb[i], rgb[i + 1], rgb[i + 2]};
  };
  EXPECT_EQ(pixel(r.middle, 700, 0), pixel(screen.rgb, 700, 0));
  EXPECT_NE(pixel(r.middle, 700, 767), pixel(screen.rgb, 700, 767));
  // The same render, the same recording.
  const std::string first = bytesOf(gif);
  ASSERT_EQ(runPrime({"trace", s.path().string(), "--pace", "1991", "--record", gif.string(),
                      "--record-length", "20", "--no-window", "-q"},
                     &out),
            0)
      << out;
  EXPECT_EQ(bytesOf(gif), first);
}

// view --record of the graph file trace wrote, at the same --pace, is the
// same recording byte for byte: the drawing depends on the picture and the
// rows' times only. Headless, with no window to wait for.
TEST(Record, ViewOfTheGraphFileRecordsWhatTraceRecordedAtTheSamePace) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "plate3", s.path(), fs::copy_options::recursive);
  std::string out;
  ASSERT_EQ(runPrime({"trace", s.path().string(), "--model", "--pace", "120", "--record",
                      s.path("t.gif").string(), "--no-window", "-q"},
                     &out),
            0)
      << out;
  ASSERT_EQ(runPrime({"view", s.path("graph_scr").string(), "--pace", "120", "--record",
                      s.path("v.gif").string(), "--no-window"},
                     &out),
            0)
      << out;
  EXPECT_THAT(out, HasSubstr("recorded " + s.path("v.gif").string()));
  EXPECT_THAT(out, Not(HasSubstr("nothing to show")));
  const std::string t = bytesOf(s.path("t.gif")), v = bytesOf(s.path("v.gif"));
  EXPECT_FALSE(t.empty());
  EXPECT_EQ(t, v);
  // 769 rows at 120 a second: 6.4 s, recorded as drawn (never slowed).
  const Recording r = decode(s.path("v.gif"));
  EXPECT_NEAR(static_cast<double>(r.hundredths - r.lastDelay), 641.0, 5.0);
}

}  // namespace record_test
