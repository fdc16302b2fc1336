// The real SDL window, on a real X server (Xvfb): what the server shows is
// captured with xwd (XGetImage on the window, from the server, not from our
// own memory) and compared pixel for pixel with `prime export` of the same
// graph file. Keys are typed through the XTEST extension with xdotool.
//
// Skipped (with the reason) only when Xvfb is not installed or will not
// start; a missing xwd or xdotool is a failure (./prime.sh installs them).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

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

bool onPath(const std::string& tool) {
  const char* path = std::getenv("PATH");
  std::string p = path ? path : "/usr/bin:/bin";
  for (std::size_t start = 0; start <= p.size();) {
    const std::size_t end = std::min(p.find(':', start), p.size());
    if (fs::exists(fs::path(p.substr(start, end - start)) / tool)) return true;
    start = end + 1;
  }
  return false;
}

// One Xvfb server per test suite, on a display number it picks itself
// (-displayfd), so tests can run in parallel with each other and anything else.
class XvfbTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { start("2560x2048x24"); }
  static void start(const std::string& screen) {
    if (!onPath("Xvfb")) {
      skipReason_ = "Xvfb is not installed (./prime.sh installs the xvfb package)";
      return;
    }
    int fds[2];
    if (pipe(fds) != 0) {
      skipReason_ = "pipe failed";
      return;
    }
    // 2560 x 2048: room for the 1024 x 768 screen at zoom 2.
    server_ = new ChildProcess({"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0",
                                screen, "-nolisten", "tcp", "-noreset"});
    close(fds[1]);
    std::string number;
    pollfd pfd{fds[0], POLLIN, 0};
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (number.find('\n') == std::string::npos && std::chrono::steady_clock::now() < end) {
      if (poll(&pfd, 1, 100) > 0) {
        char buf[32];
        const ssize_t n = read(fds[0], buf, sizeof buf);
        if (n <= 0) break;
        number.append(buf, static_cast<std::size_t>(n));
      }
    }
    close(fds[0]);
    if (number.find('\n') == std::string::npos) {
      server_->wait(100);
      skipReason_ = "Xvfb did not start: " + server_->err();
      delete server_;
      server_ = nullptr;
      return;
    }
    display_ = ":" + number.substr(0, number.find('\n'));
  }
  static void TearDownTestSuite() {
    if (server_ != nullptr) {
      server_->signal(SIGTERM);
      server_->wait(5000);
      delete server_;
      server_ = nullptr;
    }
  }
  void SetUp() override {
    if (!skipReason_.empty()) GTEST_SKIP() << skipReason_;
    ASSERT_TRUE(onPath("xwd")) << "xwd is not installed (package x11-apps; ./prime.sh installs it)";
    ASSERT_TRUE(onPath("xdotool")) << "xdotool is not installed (./prime.sh installs it)";
  }

  // The children's environment: our server, the window module beside
  // `prime` (whatever PRIME_WINDOW_MODULE the caller has set), and (for the
  // ASan runs) the suppressions of SDL's third-party leaks.
  std::map<std::string, std::string> env() const {
    const char* lsan = std::getenv("LSAN_OPTIONS");
    const std::string supp = (fs::path(PRIME_TEST_SUPPORT) / "lsan-sdl.supp").string();
    return {{"DISPLAY", display_},
            {"WAYLAND_DISPLAY", ""},
            {"PRIME_WINDOW_MODULE", ""},
            {"LSAN_OPTIONS", (lsan && *lsan ? std::string(lsan) + ":" : "") +
                                 "suppressions=" + supp + ":print_suppressions=0"}};
  }

  // Runs a tool against the server and returns its exit status; what it
  // said on stderr is kept in lastErr_.
  int tool(const std::vector<std::string>& argv) {
    ChildProcess p(argv, env());
    const int status = p.wait(30000).value_or(-1);
    lastErr_ = p.err();
    return status;
  }
  std::string lastErr_;
  // The same, telling on stderr when it fails.
  int toolOrSay(const std::vector<std::string>& argv) {
    const int status = tool(argv);
    if (status != 0) std::cerr << argv[0] << " exited " << status << ": " << lastErr_ << "\n";
    return status;
  }

  static inline ChildProcess* server_ = nullptr;
  static inline std::string display_, skipReason_;
};

// The window id `prime` prints ("... (window 0x1a00008 ...").
std::string windowId(const std::string& err) {
  const auto at = err.find("window 0x");
  if (at == std::string::npos) return "";
  std::size_t end = at + 9;
  while (end < err.size() && std::isxdigit(static_cast<unsigned char>(err[end]))) ++end;
  return err.substr(at + 7, end - at - 7);
}

// An XWD file (X11/XWDFile.h) of a TrueColor window as 8-bit RGB. Its
// header is big-endian CARD32s; the pixels are in the header's byte order.
prime::Image8 readXwd(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> b((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
  if (b.size() < 100) throw std::runtime_error(path + ": not an XWD file");
  auto card = [&](std::size_t i) {
    return static_cast<std::uint32_t>(b[4 * i] << 24 | b[4 * i + 1] << 16 | b[4 * i + 2] << 8 |
                                      b[4 * i + 3]);
  };
  const std::uint32_t headerSize = card(0), format = card(2), width = card(4), height = card(5),
                      byteOrder = card(7), bitsPerPixel = card(11), bytesPerLine = card(12),
                      red = card(14), green = card(15), blue = card(16), ncolors = card(19);
  if (card(1) != 7 || format != 2 || (bitsPerPixel != 32 && bitsPerPixel != 24))
    throw std::runtime_error(path + ": expected a version 7 ZPixmap of 24 or 32 bits per pixel");
  const std::size_t data = headerSize + 12u * ncolors;
  if (b.size() < data + static_cast<std::size_t>(bytesPerLine) * height)
    throw std::runtime_error(path + ": short");
  auto shift = [](std::uint32_t mask) {
    int s = 0;
    while (mask != 0 && (mask & 1) == 0) mask >>= 1, ++s;
    return s;
  };
  prime::Image8 img;
  img.width = static_cast<int>(width);
  img.height = static_cast<int>(height);
  img.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  const std::size_t bytes = bitsPerPixel / 8;
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::uint8_t* p = &b[data + static_cast<std::size_t>(y) * bytesPerLine + x * bytes];
      std::uint32_t v = 0;
      for (std::size_t k = 0; k < bytes; ++k)
        v |= static_cast<std::uint32_t>(p[k])
             << (8 * (byteOrder == 0 ? k : bytes - 1 - k));  // 0: LSBFirst
      std::uint8_t* o = &img.rgb[(static_cast<std::size_t>(y) * width + x) * 3];
      o[0] = static_cast<std::uint8_t>((v & red) >> shift(red));
      o[1] = static_cast<std::uint8_t>((v & green) >> shift(green));
      o[2] = static_cast<std::uint8_t>((v & blue) >> shift(blue));
    }
  return img;
}

// How many pixels differ, and the first one.
std::string compare(const prime::Image8& shown, const prime::Image8& want, int zoom,
                    std::size_t& differing) {
  differing = 0;
  std::string first;
  if (shown.width != want.width * zoom || shown.height != want.height * zoom)
    return "size " + std::to_string(shown.width) + "x" + std::to_string(shown.height) + " vs " +
           std::to_string(want.width * zoom) + "x" + std::to_string(want.height * zoom);
  for (int y = 0; y < shown.height; ++y)
    for (int x = 0; x < shown.width; ++x) {
      const std::uint8_t* s = &shown.rgb[(static_cast<std::size_t>(y) * shown.width + x) * 3];
      const std::uint8_t* w =
          &want.rgb[(static_cast<std::size_t>(y / zoom) * want.width + x / zoom) * 3];
      if (s[0] != w[0] || s[1] != w[1] || s[2] != w[2]) {
        if (differing++ == 0)
          first = "first at (" + std::to_string(x) + ", " + std::to_string(y) + "): shown " +
                  std::to_string(s[0]) + "," + std::to_string(s[1]) + "," + std::to_string(s[2]) +
                  ", exported " + std::to_string(w[0]) + "," + std::to_string(w[1]) + "," +
                  std::to_string(w[2]);
      }
    }
  return first;
}

// Captures the window from the server until it matches `want` (the window
// may still be catching up), or returns the last mismatch.
std::string captureMatches(const std::function<int(const std::vector<std::string>&)>& run,
                           const std::string& id, const fs::path& xwd, const prime::Image8& want,
                           int zoom) {
  std::string why = "no capture";
  for (int attempt = 0; attempt < 25; ++attempt) {
    if (run({"xwd", "-silent", "-id", id, "-out", xwd.string()}) != 0) {
      why = "xwd -id " + id + " failed";
    } else {
      std::size_t differing = 0;
      why = compare(readXwd(xwd.string()), want, zoom, differing);
      if (why.empty()) return "";
      why += " (" + std::to_string(differing) + " pixels differ)";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return why;
}

// 64 x 48 pixels whose values cover all 256 screen indices, negative and
// >255 values included (Q12): v = 71*x + 37*y - 300.
prime::io::GraphFile patternGraph() {
  prime::io::GraphFile g;
  g.numPixAcross = 63;
  g.numPixDown = 47;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      g.pixels.push_back(static_cast<std::int16_t>(71 * x + 37 * y - 300));
  return g;
}

TEST_F(XvfbTest, ViewShowsExactlyWhatExportWritesAtZoomOneAndTwo) {
  prime::test::TempScene d;
  prime::io::writeGraphFile(d.path("g").string(), patternGraph());
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  for (const std::string palette : {"listing", "plate3"}) {
    ASSERT_EQ(run({PRIME_EXE, "export", d.path("g").string(), d.path("want.png").string(), "--area",
                   "screen", "--palette", palette}),
              0);
    const prime::Image8 want = prime::readPng(d.path("want.png").string());
    for (const int zoom : {1, 2}) {
      ChildProcess view({PRIME_EXE, "view", d.path("g").string(), "--palette", palette, "--zoom",
                         std::to_string(zoom)},
                        env());
      ASSERT_TRUE(view.waitForErr("; Esc or close the window to quit\n", 30000)) << view.err();
      const std::string id = windowId(view.err());
      const std::string why = captureMatches(run, id, d.path("shown.xwd"), want, zoom);
      EXPECT_EQ(why, "") << palette << " zoom " << zoom;
      // Esc closes it, as WaitForEsc.
      EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
      const auto status = view.wait(20000);
      ASSERT_TRUE(status.has_value()) << "prime view did not quit on Esc";
      EXPECT_EQ(*status, 0) << view.err();
    }
  }
}

TEST_F(XvfbTest, ZoomAndScreenshotKeys) {
  prime::test::TempScene d;
  prime::io::writeGraphFile(d.path("g").string(), patternGraph());
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ASSERT_EQ(run({PRIME_EXE, "export", d.path("g").string(), d.path("want.png").string(), "--area",
                 "screen"}),
            0);
  const prime::Image8 want = prime::readPng(d.path("want.png").string());
  // Screenshots go to the current directory: run prime from the temp dir.
  const fs::path cwd = fs::current_path();
  fs::current_path(d.path());
  ChildProcess view({PRIME_EXE, "view", d.path("g").string()}, env());
  fs::current_path(cwd);
  ASSERT_TRUE(view.waitForErr("; Esc or close the window to quit\n", 30000)) << view.err();
  const std::string id = windowId(view.err());
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "plus"}), 0);
  EXPECT_EQ(captureMatches(run, id, d.path("z2.xwd"), want, 2), "");
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "minus", "key", "s"}), 0);
  ASSERT_TRUE(view.waitForErr("prime: screenshot ", 10000)) << view.err();
  EXPECT_TRUE(view.waitForErr(".png\n", 5000));
  const prime::Image8 shot = prime::readPng(d.path("prime-screenshot-1.png").string());
  std::size_t differing = 0;
  EXPECT_EQ(compare(shot, want, 1, differing), "");
  EXPECT_EQ(captureMatches(run, id, d.path("z1.xwd"), want, 1), "");
  view.signal(SIGTERM);  // SDL turns it into a quit, like closing the window
  EXPECT_EQ(view.wait(20000).value_or(-1), 0);
}

// The T key shows the 256 DAC entries as a chart (each a swatch, its
// index and 6-bit values) and T again the picture; the pointer over a pixel
// puts index -> DAC -> RGB in the title.
TEST_F(XvfbTest, TheDacChartKeyAndThePixelUnderThePointer) {
  prime::test::TempScene d;
  prime::io::writeGraphFile(d.path("g").string(), patternGraph());
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ASSERT_EQ(run({PRIME_EXE, "export", d.path("g").string(), d.path("want.png").string(), "--area",
                 "screen"}),
            0);
  const prime::Image8 want = prime::readPng(d.path("want.png").string());
  ChildProcess view({PRIME_EXE, "view", d.path("g").string()}, env());
  ASSERT_TRUE(view.waitForErr("; Esc or close the window to quit\n", 30000)) << view.err();
  const std::string id = windowId(view.err());
  EXPECT_EQ(captureMatches(run, id, d.path("a.xwd"), want, 1), "");
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "t"}), 0);
  // Entry 200 in the chart: column 200 / 32 = 6 of 8, row 200 % 32 = 8 of
  // 32; a swatch pixel clear of its label.
  const prime::Rgb8 entry = prime::present(prime::findBuiltinPalette("listing")->dac)[200];
  bool charted = false;
  for (int attempt = 0; attempt < 25 && !charted; ++attempt) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    if (run({"xwd", "-silent", "-id", id, "-out", d.path("c.xwd").string()}) != 0) continue;
    const prime::Image8 shot = readXwd(d.path("c.xwd").string());
    const std::uint8_t* p =
        &shot.rgb[(static_cast<std::size_t>(8 * 24 + 20) * shot.width + 6 * 128 + 124) * 3];
    charted = p[0] == entry.r && p[1] == entry.g && p[2] == entry.b;
  }
  EXPECT_TRUE(charted) << "no chart of the DAC after T";
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "t"}), 0);
  EXPECT_EQ(captureMatches(run, id, d.path("b.xwd"), want, 1), "");
  // The pixel (676, 1) of the screen: the file's (1, 1), 71 + 37 - 300 = -192,
  // index -192 & 0xFF = 64.
  EXPECT_EQ(run({"xdotool", "mousemove", "--window", id, "--sync", "676", "1"}), 0);
  std::string title;
  for (int attempt = 0; attempt < 25; ++attempt) {
    ChildProcess name({"xdotool", "getwindowname", id}, env());
    name.wait(10000);
    title = name.out();
    if (title.find("index 64 -> DAC") != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  EXPECT_THAT(title, HasSubstr("pixel (676, 1): index 64 -> DAC "));
  EXPECT_THAT(title, HasSubstr(" -> RGB "));
  view.signal(SIGTERM);
  EXPECT_EQ(view.wait(20000).value_or(-1), 0);
}

using prime::test::sphere;

TEST_F(XvfbTest, TraceDrawsEachPixelWherePutPixelPutItAndWaitsForEsc) {
  prime::test::TempScene s;
  sphere(s);
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ChildProcess trace({PRIME_EXE, "trace", "--model", s.path().string()}, env());
  ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 60000)) << trace.err();
  EXPECT_THAT(trace.out(), HasSubstr("traced 350 x 769 pixels"));
  ASSERT_EQ(run({PRIME_EXE, "export", s.path("graph_scr").string(), s.path("want.png").string(),
                 "--area", "screen"}),
            0);
  const prime::Image8 want = prime::readPng(s.path("want.png").string());
  const std::string id = windowId(trace.err());
  ASSERT_FALSE(id.empty()) << trace.err();
  EXPECT_EQ(captureMatches(run, id, s.path("shown.xwd"), want, 1), "");
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
  // The window changed nothing in the file: same bytes as a headless render.
  const auto withWindow = s.read("graph_scr");
  ASSERT_EQ(run({PRIME_EXE, "trace", "--no-window", "-q", s.path().string()}), 0);
  EXPECT_EQ(s.read("graph_scr"), withWindow);
}

// --pace 1991 in a window: the 1991 replay (minutes of it) paused with
// Space, sped up with ] until it is done, said so, and the window waits.
TEST_F(XvfbTest, PacedReplayPausesSpeedsUpAndSaysWhenItIsDone) {
  prime::test::TempScene s;
  sphere(s);
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ChildProcess trace({PRIME_EXE, "trace", "--model", "--pace", "1991", s.path().string()}, env(),
                     s.path().string());
  ASSERT_TRUE(trace.waitForErr("Space pause, [ ] slower / faster", 60000)) << trace.err();
  EXPECT_THAT(trace.err(), HasSubstr("R recording, "));
  const std::string id = windowId(trace.err());
  ASSERT_FALSE(id.empty()) << trace.err();
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "space"}), 0);
  EXPECT_TRUE(trace.waitForErr("prime: paused (Space resumes)", 10000)) << trace.err();
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "space"}), 0);
  EXPECT_TRUE(trace.waitForErr("prime: pace x1\n", 10000)) << trace.err();
  for (int i = 0; i < 13; ++i)
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "bracketright"}), 0);
  EXPECT_TRUE(trace.waitForErr("prime: pace x4096\n", 10000)) << trace.err();
  // The whole line, to its end: the test reads the pipe while it is written.
  ASSERT_TRUE(trace.waitForErr(" of 1991 time\n", 60000)) << trace.err();
  EXPECT_THAT(trace.err(), HasSubstr("prime: the replay is done: 769 rows in "));
  ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 20000)) << trace.err();
  // R: the drawing kept, in the current directory.
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "r"}), 0);
  for (int i = 0; i < 50 && !s.exists("prime-recording-1.gif"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(s.exists("prime-recording-1.gif"));
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
  EXPECT_THAT(trace.out(), HasSubstr("1991 estimate: "));
  EXPECT_THAT(trace.out(), HasSubstr("recorded prime-recording-1.gif: "));
  EXPECT_THAT(trace.out(), HasSubstr("(the 1991 estimate)"));
}

TEST_F(XvfbTest, EscAbortsTraceAndLeavesOnlyAPartialFile) {
  prime::test::TempScene s;
  sphere(s);
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ASSERT_EQ(run({PRIME_EXE, "model", s.path().string()}), 0);
  // Sixteen times the pixels on one thread (about 2 s): time to press Esc.
  ChildProcess trace(
      {PRIME_EXE, "trace", s.path().string(), "--threads", "1", "--screen", "4096", "3072"}, env());
  ASSERT_TRUE(trace.waitForErr("Esc aborts", 60000)) << trace.err();
  const std::string id = windowId(trace.err());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  const auto status = trace.wait(60000);
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(*status, 1) << trace.err();
  EXPECT_THAT(trace.err(), HasSubstr("prime: trace aborted after "));
  EXPECT_FALSE(s.exists("graph_scr"));
  ASSERT_TRUE(s.exists("graph_scr.partial"));
  const prime::io::GraphFilePrefix part =
      prime::io::readGraphFilePrefix(s.path("graph_scr.partial").string());
  EXPECT_FALSE(part.complete());
  EXPECT_EQ(part.pixelsPresent % 1394, 0u);
}

// Ctrl-C with the window open exits 130, as headless (issue 16): SDL would
// turn the signal into a quit event, which is Esc's exit 1.
TEST_F(XvfbTest, CtrlCWithTheWindowOpenExits130) {
  prime::test::TempScene s;
  sphere(s);
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ASSERT_EQ(run({PRIME_EXE, "model", s.path().string()}), 0);
  ChildProcess trace(
      {PRIME_EXE, "trace", s.path().string(), "--threads", "1", "--screen", "4096", "3072"}, env());
  ASSERT_TRUE(trace.waitForErr("Esc aborts", 60000)) << trace.err();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  trace.signal(SIGINT);
  const auto status = trace.wait(60000);
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(*status, 130) << trace.err();
  EXPECT_THAT(trace.err(), HasSubstr("prime: trace aborted after "));
  EXPECT_FALSE(s.exists("graph_scr"));
}

// The SDL2 code is a module that `prime` loads when a window opens
// (window_module_test.cpp has the headless side): without it there is no
// window, even with a display, and the render says why and runs headless;
// PRIME_WINDOW_MODULE names the module to load.
TEST_F(XvfbTest, WithoutItsWindowModuleTraceRunsHeadlessAndSaysWhy) {
  prime::test::TempScene s;
  sphere(s);
  ASSERT_EQ(toolOrSay({PRIME_EXE, "model", s.path().string()}), 0);
  const std::string missing = s.path("missing/libprime_window_sdl.so").string();
  auto e = env();
  e["PRIME_WINDOW_MODULE"] = missing;
  ChildProcess headless({PRIME_EXE, "trace", s.path().string(), "--screen", "64", "48"}, e);
  EXPECT_EQ(headless.wait(60000).value_or(-1), 0) << headless.err();
  EXPECT_THAT(headless.err(),
              HasSubstr("prime: running headless (cannot load the window module " + missing +
                        " (PRIME_WINDOW_MODULE): " + missing + ": cannot open shared object file"));
  EXPECT_TRUE(s.exists("graph_scr"));

  e["PRIME_WINDOW_MODULE"] =
      (fs::path(PRIME_EXE).parent_path() / "libprime_window_sdl.so").string();
  ChildProcess shown({PRIME_EXE, "trace", s.path().string(), "--screen", "64", "48", "--no-wait"},
                     e);
  EXPECT_EQ(shown.wait(60000).value_or(-1), 0) << shown.err();
  EXPECT_THAT(shown.err(), HasSubstr("prime: drawing in window 0x"));
  EXPECT_THAT(shown.err(), Not(HasSubstr("headless")));
}

}  // namespace

namespace {

// Malone's trace in the same window, fed through a true-colour LiveFrame:
// what the window shows is exactly the PNG the render writes.
TEST_F(XvfbTest, MaloneTraceShowsItsTrueColourPicture) {
  prime::test::TempScene s;
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  const fs::path scene = fs::path(PRIME_SCENES).parent_path() / "malone" / "doc-sphere.mal";
  ChildProcess trace({PRIME_EXE, "trace", scene.string(), "--png", s.path("want.png").string()},
                     env());
  ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 60000)) << trace.err();
  const prime::Image8 want = prime::readPng(s.path("want.png").string());
  ASSERT_EQ(want.width, 256);
  const std::string id = windowId(trace.err());
  ASSERT_FALSE(id.empty()) << trace.err();
  EXPECT_EQ(captureMatches(run, id, s.path("shown.xwd"), want, 1), "");
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
}

}  // namespace

namespace {

// Captures the window until two captures in a row agree (the last pass may
// still be on its way to the server).
prime::Image8 stableCapture(const std::function<int(const std::vector<std::string>&)>& run,
                            const std::string& id, const fs::path& xwd) {
  prime::Image8 last;
  for (int attempt = 0; attempt < 30; ++attempt) {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    if (run({"xwd", "-silent", "-id", id, "-out", xwd.string()}) != 0) continue;
    prime::Image8 now = readXwd(xwd.string());
    if (now.rgb == last.rgb && !now.rgb.empty()) return now;
    last = std::move(now);
  }
  return last;
}

std::size_t differingPixels(const prime::Image8& a, const prime::Image8& b) {
  if (a.width != b.width || a.height != b.height) return SIZE_MAX;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3)
    n += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  return n;
}

}  // namespace

// prime walk: a key and a mouse drag each turn the camera and the picture is
// rendered again; Home gives back exactly the first picture; Esc quits.
TEST_F(XvfbTest, WalkOrbitsWithKeysAndDragAndResetsWithHome) {
  prime::test::TempScene s;
  sphere(s);
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ASSERT_EQ(run({PRIME_EXE, "model", s.path().string()}), 0);
  // Turning about a point off the sphere (its own centre would show the same
  // sphere from every side).
  ChildProcess walk({PRIME_EXE, "walk", s.path().string(), "--size", "96", "72", "--threads", "2",
                     "--log-frames", "--pivot", "500", "500", "0"},
                    env());
  ASSERT_TRUE(walk.waitForErr("frame 1 done", 60000)) << walk.err();
  const std::string id = windowId(walk.err());
  ASSERT_FALSE(id.empty()) << walk.err();
  const prime::Image8 first = stableCapture(run, id, s.path("1.xwd"));
  ASSERT_EQ(first.width, 96);
  ASSERT_EQ(first.height, 72);

  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Right"}), 0);
  ASSERT_TRUE(walk.waitForErr("frame 2 done", 30000)) << walk.err();
  const prime::Image8 turned = stableCapture(run, id, s.path("2.xwd"));
  EXPECT_GT(differingPixels(first, turned), 50u) << "an orbit step changed nothing";

  EXPECT_EQ(run({"xdotool", "mousemove", "--window", id, "20", "36", "mousedown", "1", "mousemove",
                 "--window", id, "70", "40", "mouseup", "1"}),
            0);
  ASSERT_TRUE(walk.waitForErr("frame 3 done", 30000)) << walk.err();
  const prime::Image8 dragged = stableCapture(run, id, s.path("3.xwd"));
  EXPECT_GT(differingPixels(turned, dragged), 50u) << "a drag changed nothing";

  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Home"}), 0);
  const auto before = walk.err().size();
  ASSERT_TRUE(walk.readUntil(
      [&](const std::string&, const std::string& e) {
        return e.find(" done", before) != std::string::npos;
      },
      30000))
      << walk.err();
  // The same picture as at the start (a frame of the drag finishing late
  // may show first: give it a few seconds).
  std::size_t differing = SIZE_MAX;
  for (int attempt = 0; attempt < 20 && differing != 0; ++attempt)
    differing = differingPixels(first, stableCapture(run, id, s.path("4.xwd")));
  EXPECT_EQ(differing, 0u) << "Home did not give back the first picture";

  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(walk.wait(20000).value_or(-1), 0) << walk.err();
}

namespace {

// What `prime ARGS...` prints on stdout (its exit status must be 0).
std::string stdoutOf(const std::vector<std::string>& argv) {
  ChildProcess p(argv);
  EXPECT_EQ(p.wait(120000).value_or(-1), 0) << p.err();
  return p.out();
}

bool waitForOut(ChildProcess& p, const std::string& text, int ms) {
  return p.readUntil(
      [&](const std::string& o, const std::string&) { return o.find(text) != std::string::npos; },
      ms);
}

// Clicks pixel (48, 36) of a walk's window and returns what the click printed
// (the probe's text); C must come after it (its flags end the text).
void clickTheMiddle(const std::function<int(const std::vector<std::string>&)>& run,
                    ChildProcess& walk, const std::string& id) {
  EXPECT_EQ(run({"xdotool", "mousemove", "--window", id, "--sync", "48", "36", "click", "1"}), 0);
  EXPECT_TRUE(waitForOut(walk, " ray", 20000)) << walk.out();
}

// A click on a walk's pixel printed the probe of that pixel through the
// camera of the moment: `prime probe --camera FILE --pixel` (the walk's
// picture at (left, top) of probe's) says the same.
void expectClickIsProbe(const std::string& scene, const std::string& cameras,
                        const std::string& walkOut, int left, int top) {
  const std::string probe = stdoutOf({PRIME_EXE, "probe", scene, "--camera", cameras, "--pixel",
                                      std::to_string(left + 48), std::to_string(top + 36)});
  EXPECT_FALSE(probe.empty());
  EXPECT_EQ(walkOut.substr(0, walkOut.find("--eye")), probe)
      << "the click's text is not probe --camera's";
}

}  // namespace

// prime walk's C key: the camera the window shows, as flags on stdout and
// appended to the camera file; `trace --camera FILE` then renders exactly
// the frame the window showed, pixel for pixel. A click on a pixel before it
// printed what `probe --camera FILE` says of that pixel.
TEST_F(XvfbTest, WalkCameraKeyGivesFlagsThatReproduceTheFrame) {
  prime::test::TempScene s;
  sphere(s);
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  ASSERT_EQ(run({PRIME_EXE, "model", s.path().string()}), 0);
  prime::test::TempScene out;  // outside the scene: a new file there would make it stale
  const std::string cameras = out.path("cameras.txt").string();
  const std::string path = out.path("walk.path").string();
  ChildProcess walk({PRIME_EXE, "walk", s.path().string(), "--size", "96", "72", "--threads", "2",
                     "--log-frames", "--camera-file", cameras, "--path-file", path},
                    env());
  ASSERT_TRUE(walk.waitForErr("frame 1 done", 60000)) << walk.err();
  const std::string id = windowId(walk.err());
  ASSERT_FALSE(id.empty()) << walk.err();
  // Turn, raise and pan: a camera no flag of the scene's own gives.
  int frame = 1;
  for (const char* key : {"Right", "Right", "Up", "shift+Left", "i"}) {
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", key}), 0);
    const std::string done = "frame " + std::to_string(++frame) + " done";
    ASSERT_TRUE(walk.waitForErr(done, 60000)) << walk.err();
  }
  const prime::Image8 shown = stableCapture(run, id, s.path("walk.xwd"));
  clickTheMiddle(run, walk, id);
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "c"}), 0);
  ASSERT_TRUE(walk.waitForErr("camera appended to", 20000)) << walk.err();
  // K twice: the view as the first two keys of a camera path (issue 34);
  // a second press appends (the file is this run's output, not its input).
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "k"}), 0);
  ASSERT_TRUE(walk.waitForErr("key added to the camera path", 20000)) << walk.err();
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Left"}), 0);
  ASSERT_TRUE(walk.waitForErr("frame " + std::to_string(++frame) + " done", 60000)) << walk.err();
  const auto keyed = walk.err().size();
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "k"}), 0);
  ASSERT_TRUE(walk.readUntil(
      [&](const std::string&, const std::string& e) {
        return e.find("key added to the camera path", keyed) != std::string::npos;
      },
      20000))
      << walk.err();
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(walk.wait(20000).value_or(-1), 0) << walk.err();
  // stdout holds the click's probe, then the flags; the file holds them too,
  // after a comment.
  expectClickIsProbe(s.path().string(), cameras, walk.out(), 0, 0);
  const std::string flagsOut = walk.out().substr(walk.out().find("--eye"));
  const std::string flags = flagsOut.substr(0, flagsOut.find('\n'));
  EXPECT_THAT(flags, HasSubstr("--eye "));
  EXPECT_THAT(flags, HasSubstr(" --size 96 72"));
  std::ifstream in(cameras);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("# prime walk "));
  EXPECT_THAT(text, HasSubstr(flags + "\n"));
  ASSERT_EQ(run({PRIME_EXE, "trace", s.path().string(), "--camera", cameras, "--true-color-png",
                 out.path("want.png").string(), "-q", "--no-window"}),
            0);
  const prime::Image8 want = prime::readPng(out.path("want.png").string());
  ASSERT_EQ(want.width, 96);
  ASSERT_EQ(want.height, 72);
  EXPECT_EQ(differingPixels(shown, want), 0u) << "the camera file did not give the walk's frame";
  // The path's first frame is its first key, at the window's size: the frame shown.
  std::ifstream pathIn(path);
  const std::string pathText((std::istreambuf_iterator<char>(pathIn)),
                             std::istreambuf_iterator<char>());
  EXPECT_THAT(pathText, HasSubstr("size 96 72\n"));
  std::size_t keys = 0;
  for (std::size_t at = pathText.find("\nkey --eye "); at != std::string::npos;
       at = pathText.find("\nkey --eye ", at + 1))
    ++keys;
  EXPECT_EQ(keys, 2u) << pathText;
  ASSERT_EQ(run({PRIME_EXE, "trace", s.path().string(), "--camera-path", path, "--frames", "0",
                 "--out", out.path("frame0.gr").string(), "--true-color-png",
                 out.path("frame0.png").string(), "-q"}),
            0);
  EXPECT_EQ(differingPixels(shown, prime::readPng(out.path("frame0.png").string())), 0u)
      << "the path's frame 0 is not the frame the walk showed when K was pressed";
}

// Malone's and CGL's walks: the same keys, and C's camera given to `trace
// --camera` renders the frame the window showed (CGL: with --aalevel 0, the
// walk's one ray per pixel, in the --size window in the middle of its
// 512 x 512 frame). A click on a pixel printed what `probe --camera FILE`
// says of it.
TEST_F(XvfbTest, MaloneAndCglWalksHandTheirCameraToTrace) {
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  const fs::path scenes = fs::path(PRIME_SCENES).parent_path();
  struct Case {
    std::string scene;
    std::vector<std::string> traceExtra;
    int left, top;  // where the walk's picture is in trace's
  };
  const std::vector<Case> cases = {
      {(scenes / "malone" / "primitives.mal").string(), {}, 0, 0},
      {(scenes / "cgl" / "ball.cgl").string(), {"--aalevel", "0"}, 256 - 48, 511 - (220 + 71)}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.scene);
    prime::test::TempScene out;
    const std::string cameras = out.path("cameras.txt").string();
    ChildProcess walk({PRIME_EXE, "walk", c.scene, "--size", "96", "72", "--threads", "2",
                       "--log-frames", "--camera-file", cameras},
                      env());
    ASSERT_TRUE(walk.waitForErr("frame 1 done", 60000)) << walk.err();
    const std::string id = windowId(walk.err());
    ASSERT_FALSE(id.empty()) << walk.err();
    const prime::Image8 first = stableCapture(run, id, out.path("first.xwd"));
    int frame = 1;
    for (const char* key : {"Left", "Down", "o"}) {
      EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", key}), 0);
      const std::string done = "frame " + std::to_string(++frame) + " done";
      ASSERT_TRUE(walk.waitForErr(done, 60000)) << walk.err();
    }
    const prime::Image8 shown = stableCapture(run, id, out.path("walk.xwd"));
    EXPECT_GT(differingPixels(first, shown), 50u) << "the keys changed nothing";
    clickTheMiddle(run, walk, id);
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "c"}), 0);
    ASSERT_TRUE(walk.waitForErr("camera appended to", 20000)) << walk.err();
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
    EXPECT_EQ(walk.wait(20000).value_or(-1), 0) << walk.err();
    std::vector<std::string> trace = {PRIME_EXE,
                                      "trace",
                                      c.scene,
                                      "--camera",
                                      cameras,
                                      "--true-color-png",
                                      out.path("want.png").string(),
                                      "-q",
                                      "--no-window"};
    trace.insert(trace.end(), c.traceExtra.begin(), c.traceExtra.end());
    ASSERT_EQ(run(trace), 0);
    const prime::Image8 whole = prime::readPng(out.path("want.png").string());
    prime::Image8 want;
    want.width = 96;
    want.height = 72;
    for (int y = 0; y < 72; ++y)
      for (int x = 0; x < 96; ++x)
        for (int k = 0; k < 3; ++k)
          want.rgb.push_back(whole.rgb[(static_cast<std::size_t>(c.top + y) * whole.width +
                                        static_cast<std::size_t>(c.left + x)) *
                                           3 +
                                       static_cast<std::size_t>(k)]);
    EXPECT_EQ(differingPixels(shown, want), 0u) << "the camera file did not give the walk's frame";
    expectClickIsProbe(c.scene, cameras, walk.out(), c.left, c.top);
  }
}

// The C key of trace's window, for every system: the camera the render used,
// as flags on stdout and appended to prime-cameras.txt in the current
// directory; trace --camera FILE then gives the same picture. With the
// system's own camera it says that no flag is needed.
TEST_F(XvfbTest, TraceWindowCameraKeyForEverySystem) {
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  const fs::path scenes = fs::path(PRIME_SCENES).parent_path();
  prime::test::TempScene plate;
  fs::copy(scenes / "prime" / "default", plate.path(), fs::copy_options::recursive);
  ASSERT_EQ(run({PRIME_EXE, "model", plate.path().string()}), 0);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {plate.path().string(),
       {"--eye", "900", "700", "-1200", "--look-at", "500", "450", "200", "--fov", "42", "--size",
        "96", "64"}},
      {(scenes / "malone" / "primitives.mal").string(),
       {"--eye", "1.5", "1", "4", "--fov", "35", "--size", "80", "60"}},
      {(scenes / "cgl" / "ball.cgl").string(), {"--eye", "0.8", "0.5", "3", "--fov", "12"}}};
  for (const auto& [scene, camera] : cases) {
    SCOPED_TRACE(scene);
    prime::test::TempScene out;
    std::vector<std::string> argv = {PRIME_EXE, "trace", scene, "--true-color-png",
                                     out.path("first.png").string()};
    if (scene == plate.path().string())
      argv.insert(argv.end(), {"--out", out.path("first.graph").string()});
    argv.insert(argv.end(), camera.begin(), camera.end());
    ChildProcess trace(argv, env(), out.path().string());
    ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 60000)) << trace.err();
    const std::string id = windowId(trace.err());
    ASSERT_FALSE(id.empty()) << trace.err();
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "c"}), 0);
    ASSERT_TRUE(trace.waitForErr("camera appended to prime-cameras.txt", 20000)) << trace.err();
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
    EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
    EXPECT_THAT(trace.out(), HasSubstr("--eye "));
    const std::string cameras = out.path("prime-cameras.txt").string();
    std::vector<std::string> again = {PRIME_EXE,
                                      "trace",
                                      scene,
                                      "--camera",
                                      cameras,
                                      "--true-color-png",
                                      out.path("again.png").string(),
                                      "-q",
                                      "--no-window"};
    if (scene == plate.path().string())
      again.insert(again.end(), {"--out", out.path("again.graph").string()});
    ASSERT_EQ(run(again), 0);
    // The same pixels (the files' text differs: the second names its camera).
    const prime::Image8 pa = prime::readPng(out.path("first.png").string()),
                        pb = prime::readPng(out.path("again.png").string());
    EXPECT_TRUE(!pa.rgb.empty() && pa.width == pb.width && pa.rgb == pb.rgb)
        << "--camera did not give the window's picture";
  }
  // The listing's own camera: no flags to give, and it says so.
  prime::test::TempScene out;
  ChildProcess trace(
      {PRIME_EXE, "trace", plate.path().string(), "--out", out.path("listing.graph").string()},
      env(), out.path().string());
  ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 60000)) << trace.err();
  const std::string id = windowId(trace.err());
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "c"}), 0);
  EXPECT_TRUE(trace.waitForErr("renders this frame with no camera flag", 20000)) << trace.err();
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
  EXPECT_FALSE(fs::exists(out.path("prime-cameras.txt")));
}

// An 800 x 600 screen (G23): the window never grows past it, and fullscreen
// fills it with the picture at the largest whole factor, centred.
class SmallXvfbTest : public XvfbTest {
 protected:
  static void SetUpTestSuite() { start("800x600x24"); }
};

// The window's size as xwininfo reports it: "WxH+X+Y" from -geometry-ish
// fields, or "" when xwininfo fails.
std::string windowGeometry(const std::string& xwininfo) {
  const auto field = [&](const std::string& name) {
    const auto at = xwininfo.find(name);
    if (at == std::string::npos) return std::string("?");
    std::size_t b = at + name.size();
    while (b < xwininfo.size() && xwininfo[b] == ' ') ++b;
    std::size_t e = b;
    while (e < xwininfo.size() &&
           (std::isdigit(static_cast<unsigned char>(xwininfo[e])) || xwininfo[e] == '-'))
      ++e;
    return xwininfo.substr(b, e - b);
  };
  return field("Width:") + "x" + field("Height:") + "+" + field("Absolute upper-left X:") + "+" +
         field("Absolute upper-left Y:");
}

TEST_F(SmallXvfbTest, ZoomEightIsReducedToFitAndF11FillsTheScreen) {
  prime::test::TempScene s;
  sphere(s);
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  // 320 x 240 at zoom 8 would be 2560 x 1920; 2 (640 x 480) is the largest that fits.
  ChildProcess trace(
      {PRIME_EXE, "trace", "--model", s.path().string(), "--screen", "320", "240", "--zoom", "8"},
      env());
  ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 60000)) << trace.err();
  EXPECT_THAT(trace.err(), HasSubstr("--zoom 8 reduced to 2"));
  const std::string id = windowId(trace.err());
  ASSERT_FALSE(id.empty()) << trace.err();
  const auto geometry = [&] {
    ChildProcess info({"xwininfo", "-id", id}, env());
    info.wait(20000);
    return windowGeometry(info.out());
  };
  EXPECT_EQ(geometry(), "640x480+80+60");
  ASSERT_EQ(run({PRIME_EXE, "export", s.path("graph_scr").string(), s.path("want.png").string(),
                 "--area", "screen"}),
            0);
  const prime::Image8 want = prime::readPng(s.path("want.png").string());
  ASSERT_EQ(want.width, 320);
  EXPECT_EQ(captureMatches(run, id, s.path("zoom.xwd"), want, 2), "");

  // F11: the whole screen, the picture at 2x centred (80, 60), black around.
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "F11"}), 0);
  std::string g;
  for (int i = 0; i < 50 && g != "800x600+0+0"; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    g = geometry();
  }
  EXPECT_EQ(g, "800x600+0+0");
  std::size_t wrong = SIZE_MAX;
  for (int attempt = 0; attempt < 20 && wrong != 0; ++attempt) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (run({"xwd", "-silent", "-id", id, "-out", s.path("full.xwd").string()}) != 0) continue;
    const prime::Image8 shown = readXwd(s.path("full.xwd").string());
    if (shown.width != 800 || shown.height != 600) continue;
    wrong = 0;
    for (int y = 0; y < 600; ++y)
      for (int x = 0; x < 800; ++x) {
        const bool inside = x >= 80 && x < 720 && y >= 60 && y < 540;
        for (int c = 0; c < 3; ++c) {
          const std::uint8_t expect =
              inside
                  ? want.rgb[3 * (static_cast<std::size_t>((y - 60) / 2) * 320 + (x - 80) / 2) + c]
                  : 0;
          if (shown.rgb[3 * (static_cast<std::size_t>(y) * 800 + x) + c] != expect) ++wrong;
        }
      }
  }
  EXPECT_EQ(wrong, 0u) << "the fullscreen window is not the picture at 2x, centred";
  EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
}

// Malone's and CGL's windows have PRIME's --fullscreen (G23): the CGL
// package's 512 x 512 frame fills the 800 x 600 screen from the start.
TEST_F(SmallXvfbTest, CglTraceFullscreenFillsTheScreen) {
  prime::test::TempScene s;
  ChildProcess trace({PRIME_EXE, "trace", (fs::path(PRIME_SCENES) / "../cgl/ball.cgl").string(),
                      "--fullscreen", "--png", s.path("ball.png").string()},
                     env());
  ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 60000)) << trace.err();
  const std::string id = windowId(trace.err());
  ASSERT_FALSE(id.empty()) << trace.err();
  std::string g;
  for (int i = 0; i < 50 && g != "800x600+0+0"; ++i) {
    ChildProcess info({"xwininfo", "-id", id}, env());
    info.wait(20000);
    g = windowGeometry(info.out());
    if (g != "800x600+0+0") std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(g, "800x600+0+0");
  EXPECT_EQ(toolOrSay({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
  EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
}

// A click on a pixel of trace's finished window, for every system: stdout gets
// the probe's text for that pixel, and the window shows the drawing `prime
// probe --pixel X Y --overlay` writes headless, pixel for pixel (Malone's
// and CGL's windows show their picture as written; PRIME's shows the 8514/A
// screen, whose colours are the palette's: there the probed pixel is
// outlined). A right click gives back the picture.
TEST_F(XvfbTest, ClickOnAPixelOfTraceDrawsItsRaysAsProbeOverlayDoes) {
  const auto run = [this](const std::vector<std::string>& argv) { return toolOrSay(argv); };
  const fs::path scenes = fs::path(PRIME_SCENES).parent_path();
  prime::test::TempScene plate;
  fs::copy(scenes / "prime" / "plate3", plate.path(), fs::copy_options::recursive);
  ASSERT_EQ(run({PRIME_EXE, "model", plate.path().string()}), 0);
  struct Case {
    std::string scene;
    int x, y;
    bool sameAsOverlay;
  };
  const std::vector<Case> cases = {{(scenes / "malone" / "glass.mal").string(), 200, 150, true},
                                   {(scenes / "cgl" / "glass.cgl").string(), 330, 280, true},
                                   {plate.path().string(), 200, 400, false}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.scene);
    prime::test::TempScene out;
    std::vector<std::string> argv = {PRIME_EXE, "trace", c.scene, "--png",
                                     out.path("picture.png").string()};
    if (!c.sameAsOverlay)  // PRIME: not into the scene's own graph file
      argv.insert(argv.end(), {"--out", out.path("picture.graph").string()});
    ChildProcess trace(argv, env(), out.path().string());
    ASSERT_TRUE(trace.waitForErr("the window stays open until Esc", 60000)) << trace.err();
    const std::string id = windowId(trace.err());
    ASSERT_FALSE(id.empty()) << trace.err();
    const prime::Image8 before = stableCapture(run, id, out.path("before.xwd"));
    // PRIME's picture sits at its placement on the 8514/A screen, as the
    // graph file's companion records it ("at LEFT TOP").
    int left = 0, top = 0;
    if (!c.sameAsOverlay) {
      std::ifstream info(out.path("picture.graph.info"));
      for (std::string line; std::getline(info, line);)
        if (line.rfind("at ", 0) == 0) std::istringstream(line.substr(3)) >> left >> top;
    }
    const int wx = left + c.x, wy = top + c.y;
    const std::string probe =
        stdoutOf({PRIME_EXE, "probe", c.scene, "--pixel", std::to_string(c.x), std::to_string(c.y),
                  "--overlay", out.path("overlay.png").string()});
    const std::string text = probe.substr(0, probe.rfind("wrote "));
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(run({"xdotool", "mousemove", "--window", id, "--sync", std::to_string(wx),
                   std::to_string(wy), "click", "1"}),
              0);
    ASSERT_TRUE(waitForOut(trace, text, 20000)) << "stdout: " << trace.out();
    const prime::Image8 shown = stableCapture(run, id, out.path("shown.xwd"));
    if (c.sameAsOverlay) {
      EXPECT_EQ(differingPixels(shown, prime::readPng(out.path("overlay.png").string())), 0u)
          << "the window's drawing is not probe --overlay's";
    } else {
      const auto at = [&](int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * shown.width + x) * 3;
        return std::array<int, 3>{shown.rgb[i], shown.rgb[i + 1], shown.rgb[i + 2]};
      };
      EXPECT_EQ(at(wx + 3, wy), (std::array<int, 3>{255, 0, 255})) << "the pixel is outlined";
      EXPECT_EQ(at(wx - 3, wy), (std::array<int, 3>{255, 0, 255}));
    }
    EXPECT_GT(differingPixels(before, shown), 1000u);
    // S saves the window as shown: the drawing included.
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "s"}), 0);
    ASSERT_TRUE(trace.waitForErr("prime-screenshot-1.png", 10000)) << trace.err();
    for (int i = 0; i < 50 && !out.exists("prime-screenshot-1.png"); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(differingPixels(shown, prime::readPng(out.path("prime-screenshot-1.png").string())),
              0u)
        << "the screenshot is not the window as shown";
    EXPECT_EQ(run({"xdotool", "mousemove", "--window", id, "--sync", std::to_string(wx),
                   std::to_string(wy), "click", "3"}),
              0);
    EXPECT_EQ(differingPixels(before, stableCapture(run, id, out.path("after.xwd"))), 0u)
        << "a right click did not give back the picture";
    EXPECT_EQ(run({"xdotool", "windowfocus", "--sync", id, "key", "Escape"}), 0);
    EXPECT_EQ(trace.wait(20000).value_or(-1), 0) << trace.err();
  }
}
