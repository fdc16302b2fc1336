// The `prime` commands as a user runs them: exit codes and messages.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "tests/support/run_prime.h"
#include "tests/support/temp_scene.h"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using prime::test::CommandResult;
using prime::test::runPrime;

using prime::test::sphere;

TEST(PrimeCommand, TraceRefusesStaleDatabasesAndModelFixesIt) {
  prime::test::TempScene s;
  sphere(s);
  CommandResult r = runPrime("trace " + s.path().string());
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.output, HasSubstr("prim/PrimFile does not exist"));
  EXPECT_THAT(r.output, HasSubstr("add --model"));
  r = runPrime("trace --model " + s.path().string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("traced 350 x 769 pixels (graph file header 349 x 768)"));
  EXPECT_THAT(r.output,
              HasSubstr("rays: 356330 (primary 269150, reflected 43590, transmitted 43590)"));
  EXPECT_TRUE(s.exists("graph_scr"));
}

// A band (--rows) says the rows it traced of how many, and why it ran
// headless; one bench table is one system's, and a scene of another is said
// to be one (it was misread as this system's).
TEST(PrimeCommand, ABandSaysItsRowsAndABenchOneSystem) {
  prime::test::TempScene s;
  sphere(s);
  CommandResult r = runPrime("trace --model " + s.path().string() + " --rows 0-40 --out " +
                             s.path("band.gr").string() + " --threads 1");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("traced 41 of 769 rows (a band) of 350 x 769 pixels"));
  EXPECT_THAT(r.output, HasSubstr("running headless (--rows: a band renders headless)"));
  const std::string scenes = std::string(PRIME_SCENES) + "/..";
  r = runPrime("bench " + scenes + "/cgl/ball.cgl " + scenes + "/malone/glass.mal --runs 1");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("/malone/glass.mal is a scene of Malone's ray tracer (1995), "
                                  "and this bench times scenes of the Waterloo CGL package "
                                  "(1985): one table is one system's"));
}

// Standard output that cannot be written is an error, not a success; the
// palette on another monitor is printed as it shows there; dump knows the
// graph files the docs name with --out.
TEST(PrimeCommand, OutputThatCannotBeWrittenAndPaletteOnAMonitor) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  prime::test::TempScene s;
  const int status = std::system(
      (std::string(PRIME_EXE) + " palette listing > /dev/full 2> " + s.path("err.txt").string())
          .c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
  const std::vector<std::uint8_t> err = s.read("err.txt");
  EXPECT_THAT(std::string(err.begin(), err.end()),
              HasSubstr("prime: cannot write standard output"));
  CommandResult r = runPrime("palette listing --monitor 8503");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("name listing (8503)"));
  EXPECT_THAT(r.output, HasSubstr("\n  1 44 44 44"));  // the green level 44 of 20 44 15, as grey
  sphere(s);
  ASSERT_EQ(runPrime("trace --model -q " + s.path().string() + " --out " +
                     s.path("picture.graph").string())
                .status,
            0);
  r = runPrime("dump " + s.path("picture.graph").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("graph file, graphType"));
  // A palette file that keeps the built-in's name (as `prime palette listing`
  // writes it) but not its colours is the file's, not "listing".
  const std::string pal = s.path("my.pal").string();
  ASSERT_EQ(runPrime("palette listing > " + pal).status, 0);
  const std::vector<std::uint8_t> bytes = s.read("my.pal");
  std::string text(bytes.begin(), bytes.end());
  const std::size_t one = text.find("\n  1 ");
  ASSERT_NE(one, std::string::npos);
  text.replace(one, text.find('\n', one + 1) - one, "\n  1 0 0 0");
  s.write("my.pal", text);
  r = runPrime("export " + s.path("picture.graph").string() + " " + s.path("p.png").string() +
               " --palette " + pal);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("palette user palette " + pal + ", DAC round"));
}

// M34: an object whose entries share subtrees (each of 20 unions takes the
// next entry twice: 2^21 - 1 visits walked per reference) is warned about
// when it is modelled, not only when it is traced; the model still succeeds.
TEST(PrimeCommand, ModelWarnsAboutLargeSharedSubtrees) {
  prime::test::TempScene s;
  sphere(s);
  std::string d = "21\n";
  for (int i = 0; i < 20; ++i)
    d += "+ " + std::to_string(i + 1) + " " + std::to_string(i + 1) + "\n";
  s.write("obj/D1.txt", d + "S 1\nNULL\n");
  const CommandResult r = runPrime("model " + s.path().string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("warning: object 1 (obj/O1): its 21 CSG entries share subtrees"));
  EXPECT_THAT(r.output, HasSubstr("2097151 entry visits per ray"));
}

TEST(PrimeCommand, ModelErrorExitsNonZeroNamingFileLineAndField) {
  prime::test::TempScene s;
  sphere(s);
  s.write("obj/H1.txt", "0.5 0.0\n0.8 x 0.2\n0.999\n2 2\n1.5\n");
  const CommandResult r = runPrime("model " + s.path().string());
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.output, HasSubstr("obj/H1.txt:2: fDR[G]: expected a number, found \"x\""));
}

// R10: a window of no size and a ray of no direction are refused (a usage
// error: exit 2) instead of rendering one flat colour with exit 0.
TEST(PrimeCommand, ZeroWindowsAndRaysAreRefused) {
  prime::test::TempScene s;
  sphere(s);
  ASSERT_EQ(runPrime("model " + s.path().string()).status, 0);
  CommandResult r = runPrime("trace " + s.path().string() +
                             " --no-window --window-left 1 2 3 --window-right 1 2 3");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("the window has zero width"));
  r = runPrime("trace " + s.path().string() + " --no-window --window-left 0 0 0");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("the window has zero height"));
  r = runPrime("probe " + s.path().string() + " --ray 500 500 -1500 0 0 0");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("the direction is 0 0 0"));
  EXPECT_FALSE(s.exists("graph_scr"));
}

TEST(PrimeCommand, ProbeExplainsTheCentrePixel) {
  prime::test::TempScene s;
  sphere(s);
  ASSERT_EQ(runPrime("model " + s.path().string()).status, 0);
  CommandResult r = runPrime("probe " + s.path().string() + " --pixel 174 384");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("primary ray, depth 0"));
  EXPECT_THAT(r.output, HasSubstr("nearest: object 1 prim 0 (sphere)"));
  EXPECT_THAT(r.output, HasSubstr("palette index 68"));
  r = runPrime("probe " + s.path().string() + " --pixel 0 0 --json");
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("\"index\":1"));
  EXPECT_THAT(r.output, HasSubstr("\"event\":\"miss\""));
  r = runPrime("probe " + s.path().string() + " --pixel 350 0");
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("outside the image (350 x 769)"));
}

TEST(PrimeCommand, VectorOptionsMayComeBeforeTheDirectory) {
  // --viewport takes exactly four numbers; the scene directory after it is
  // the positional argument, not a fifth number.
  prime::test::TempScene s;
  sphere(s);
  const CommandResult r = runPrime(
      "trace --viewport 0.125 0 0.875 1 --screen 512 384 --model --no-window " + s.path().string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("traced 385 x 385 pixels"));
}

TEST(PrimeCommand, DumpNamesTheKindOrAsksForIt) {
  prime::test::TempScene s;
  sphere(s);
  ASSERT_EQ(runPrime("model " + s.path().string()).status, 0);
  CommandResult r = runPrime("dump " + s.path("obj/O1").string());
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("1 entry, bounding volume none"));
  EXPECT_THAT(r.output, HasSubstr("prim 0"));
  r = runPrime("dump " + s.path("Model.txt").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.output, HasSubstr("--as prim|obj|list|map|graph"));
}

// Usage errors: one line with the prime: prefix and exit status 2 (not
// CLI11's 105-114); a mistyped command gets a suggestion.
TEST(PrimeCommand, UsageErrorsExitTwoWithTheirPrefix) {
  CommandResult r = runPrime("tracee scenes");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("prime: unknown command 'tracee' - did you mean 'trace'?"));
  const std::string scene = std::string(PRIME_SCENES) + "/default";
  r = runPrime("trace --no-such-option " + scene);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("prime: unknown option '--no-such-option' (prime trace " + scene +
                                  " --help)"));
  // A misspelt option: the one meant, not CLI11's "not expected: modern --profil".
  r = runPrime("trace " + scene + " --profil modern");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("prime: unknown option '--profil' - did you mean '--profile'? "
                                  "(prime trace " +
                                  scene + " --help)"));
  // Another system's scene: its own help, which lists its options.
  const std::string cgl = std::string(PRIME_SCENES) + "/../cgl/glass.cgl";
  r = runPrime("trace " + cgl + " --fix K10");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output,
              HasSubstr("prime: unknown option '--fix' (prime trace " + cgl + " --help)"));
  r = runPrime("trace " + scene + " extra");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("prime: an argument the command does not take: 'extra'"));
  r = runPrime("");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("prime: A subcommand is required"));
}

TEST(PrimeCommand, VersionAndHelpCommand) {
  CommandResult r = runPrime("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("prime 0."));
  r = runPrime("help trace");
  EXPECT_EQ(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("Usage:"));
  EXPECT_THAT(r.output, HasSubstr("--profile"));
}

// A run that names a command registers that command alone (src/cli/main.cpp,
// commands()); `prime --help` registers every one and checks the table, so a
// command missing from it, or renamed, fails here.
TEST(PrimeCommand, HelpListsEveryCommandThroughTheTable) {
  const CommandResult r = runPrime("--help");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("internal error")));
  for (const char* c :
       {"model",   "dump",       "trace",   "probe",  "view",        "export",   "diff",
        "palette", "export-pov", "bench",   "plate1", "stress",      "quantize", "film",
        "check",   "new",        "compare", "walk",   "cgl-splines", "cook",     "tovector"})
    EXPECT_THAT(r.output, HasSubstr("\n  " + std::string(c) + " ")) << c;
}

// Errors found with the command alone are reported by the whole command line,
// so messages that name other commands are unchanged: a usage error of a
// routed command, and a scene argument that is another command's name.
TEST(PrimeCommand, OneCommandAloneParsesAsTheWholeCommandLine) {
  CommandResult r = runPrime("trace --no-such-option " + std::string(PRIME_SCENES) + "/default");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output,
              HasSubstr("(prime trace " + std::string(PRIME_SCENES) + "/default --help)"));
  r = runPrime("dump model");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("File does not exist: model (prime dump --help)"));
  r = runPrime("tovector 255 0 0");
  EXPECT_EQ(r.status, 0) << r.output;
  r = runPrime("tovector 255 0");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("(prime tovector --help)"));
}

}  // namespace
