// The SDL2 window is a module (libprime_window_sdl.so beside `prime`) that
// `prime` loads with dlopen() only when a window opens: the executable does
// not need libSDL2, a headless run never loads it, and a module that cannot
// be loaded means a headless run with a message that says why. No X server
// here: DISPLAY is set to one that does not exist when a window must be tried.
// (The module opening real windows is tested in window_xvfb_test.cpp.)
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/child_process.h"
#include "tests/support/temp_scene.h"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;
using prime::test::ChildProcess;

constexpr const char* kModule = "libprime_window_sdl.so";

struct Outcome {
  int status;
  std::string out, err;
};

Outcome run(const std::vector<std::string>& argv, std::map<std::string, std::string> env) {
  // For the ASan run: SDL's third-party leaks, if SDL gets as far as
  // starting (window_xvfb_test.cpp, tests/support/lsan-sdl.supp).
  const char* lsan = std::getenv("LSAN_OPTIONS");
  env.emplace("LSAN_OPTIONS", (lsan && *lsan ? std::string(lsan) + ":" : "") + "suppressions=" +
                                  (fs::path(PRIME_TEST_SUPPORT) / "lsan-sdl.supp").string() +
                                  ":print_suppressions=0");
  env.emplace("WAYLAND_DISPLAY", "");
  env.emplace("PRIME_WINDOW_MODULE", "");  // unless a test sets it
  ChildProcess p(argv, env);
  const auto status = p.wait(60000);  // nullopt (-1) if it hangs
  return {status.value_or(-1), p.out(), p.err()};
}

// A display that is not there, and SDL told to try X11 only (not, say, a
// console's KMS/DRM): opening a window fails without ever showing one.
const std::map<std::string, std::string> kNoSuchDisplay{{"DISPLAY", ":65533"},
                                                        {"SDL_VIDEODRIVER", "x11"}};

using prime::test::sphere;

// Which shared objects the dynamic loader opened, as LD_DEBUG=files tells
// it on stderr ("file=libc.so.6 [0];  needed by ...", "file=... [0];
// dynamically loaded by ...").
bool loaded(const std::string& ldDebug, const std::string& library) {
  for (std::size_t at = ldDebug.find("file="); at != std::string::npos;
       at = ldDebug.find("file=", at + 5)) {
    const std::size_t end = ldDebug.find_first_of(" \t\n", at);
    if (ldDebug.substr(at + 5, end - at - 5).find(library) != std::string::npos) return true;
  }
  return false;
}

TEST(WindowModule, PrimeDoesNotNeedLibSdlItsModuleDoes) {
  const fs::path module = fs::path(PRIME_EXE).parent_path() / kModule;
  ASSERT_TRUE(fs::exists(module)) << module << " is not beside " << PRIME_EXE;
  const Outcome exe = run({"readelf", "-d", PRIME_EXE}, {});
  ASSERT_EQ(exe.status, 0) << "readelf (binutils) failed: " << exe.err;
  EXPECT_THAT(exe.out, HasSubstr("(NEEDED)"));
  EXPECT_THAT(exe.out, HasSubstr("[libc.so.6]"));
  EXPECT_THAT(exe.out, Not(HasSubstr("libSDL2")));
  // The same check does see libSDL2 where it is needed.
  const Outcome mod = run({"readelf", "-d", module.string()}, {});
  ASSERT_EQ(mod.status, 0) << mod.err;
  EXPECT_THAT(mod.out, HasSubstr("[libSDL2-2.0.so.0]"));
}

TEST(WindowModule, HeadlessRunsNeverLoadLibSdl) {
  prime::test::TempScene s;
  sphere(s);
  const std::map<std::string, std::string> ldDebug{{"LD_DEBUG", "files"}};
  Outcome r = run({PRIME_EXE, "model", s.path().string()}, ldDebug);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(loaded(r.err, "libc.so.6")) << "LD_DEBUG=files said nothing:\n" << r.err;
  EXPECT_FALSE(loaded(r.err, "libSDL2"));
  EXPECT_FALSE(loaded(r.err, kModule));

  // --no-window, even with a DISPLAY; and no DISPLAY at all.
  for (const bool noWindow : {true, false}) {
    std::map<std::string, std::string> env = ldDebug;
    env.emplace("DISPLAY", noWindow ? ":65533" : "");
    std::vector<std::string> argv{PRIME_EXE, "trace", s.path().string(), "--screen", "64", "48"};
    if (noWindow) argv.push_back("--no-window");
    r = run(argv, env);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr(noWindow ? "running headless (--no-window)"
                                          : "running headless (no DISPLAY)"));
    ASSERT_TRUE(loaded(r.err, "libc.so.6")) << r.err;
    EXPECT_FALSE(loaded(r.err, "libSDL2")) << (noWindow ? "--no-window" : "no DISPLAY");
    EXPECT_FALSE(loaded(r.err, kModule)) << (noWindow ? "--no-window" : "no DISPLAY");
  }

  // The check is not blind: trying a window loads the module and libSDL2
  // (and, with no X server there, SDL says so and the render runs headless).
  std::map<std::string, std::string> env = ldDebug;
  env.insert(kNoSuchDisplay.begin(), kNoSuchDisplay.end());
  r = run({PRIME_EXE, "trace", s.path().string(), "--screen", "64", "48"}, env);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(loaded(r.err, kModule)) << r.err;
  EXPECT_TRUE(loaded(r.err, "libSDL2")) << r.err;
  EXPECT_THAT(r.err, HasSubstr("prime: running headless (SDL cannot start video: "));
}

TEST(WindowModule, AModuleThatCannotBeLoadedMeansHeadlessAndSaysWhy) {
  prime::test::TempScene s;
  sphere(s);
  ASSERT_EQ(run({PRIME_EXE, "model", s.path().string()}, {}).status, 0);
  const std::string missing = s.path("no-such-dir/libprime_window_sdl.so").string();
  std::map<std::string, std::string> env = kNoSuchDisplay;
  env["PRIME_WINDOW_MODULE"] = missing;

  Outcome r = run({PRIME_EXE, "trace", s.path().string(), "--screen", "64", "48"}, env);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err,
              HasSubstr("prime: running headless (cannot load the window module " + missing +
                        " (PRIME_WINDOW_MODULE): " + missing + ": cannot open shared object file"));
  EXPECT_THAT(r.out, HasSubstr("traced "));
  EXPECT_TRUE(s.exists("graph_scr"));

  r = run({PRIME_EXE, "view", s.path("graph_scr").string()}, env);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("prime: running headless (cannot load the window module " + missing +
                               " (PRIME_WINDOW_MODULE): "));
  EXPECT_THAT(r.err, HasSubstr("nothing to show"));

  // A library that loads but is not the module.
  env["PRIME_WINDOW_MODULE"] = "libm.so.6";
  r = run({PRIME_EXE, "trace", s.path().string(), "--screen", "64", "48"}, env);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("prime: running headless (the window module libm.so.6 is not "
                               "PRIME's (no prime_window_sdl_open): "));
}

}  // namespace

// A DISPLAY that names no X server (everyday over ssh and in containers)
// made SDL fall back to a driver whose windows nobody sees (offscreen), and
// the render then waited for an Esc nobody could press. Only a visible
// window may wait: otherwise prime says why and runs headless.
TEST(WindowModule, AStaleDisplayNeverWaitsForAnInvisibleWindow) {
  prime::test::TempScene s;
  sphere(s);
  ASSERT_EQ(run({PRIME_EXE, "model", s.path().string()}, {}).status, 0);
  for (const std::string driver : {"offscreen", ""}) {  // named, and SDL's own fallback
    std::map<std::string, std::string> env{{"DISPLAY", ":65533"}, {"SDL_VIDEODRIVER", driver}};
    const Outcome r = run({PRIME_EXE, "trace", s.path().string(), "--screen", "64", "48"}, env);
    ASSERT_EQ(r.status, 0) << "driver '" << driver << "': " << r.err;  // -1: it hung
    EXPECT_THAT(r.err, HasSubstr("prime: running headless (")) << driver;
    EXPECT_THAT(r.err, Not(HasSubstr("drawing in window"))) << driver;
    EXPECT_THAT(r.out, HasSubstr("traced ")) << driver;
  }
}
