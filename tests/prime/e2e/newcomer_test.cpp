// A newcomer's first hour (issue 16): scene directories copied from DOS disks
// (upper-case 8.3 names, M40), a directory of databases only, `prime check`
// and the warnings of `prime model`, `prime new`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "legacy_io/prime/graph_file.h"
#include "tests/support/run_prime.h"
#include "tests/support/temp_scene.h"

namespace {

namespace fs = std::filesystem;
using prime::test::runPrime;
using prime::test::TempScene;
using ::testing::HasSubstr;
using ::testing::Not;

std::string q(const fs::path& p) {
  return "'" + p.string() + "'";
}

// The sphere scene of tests/data, modelled and traced in s/canon; its
// databases copied to s/DOS under the names a DOS disk gives them (and no
// text inputs: a disk of databases).
fs::path dosCopy(const TempScene& s) {
  const fs::path canon = s.path("canon"), dos = s.path("DOS");
  fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", canon, fs::copy_options::recursive);
  const auto r = runPrime("trace " + q(canon) + " --model -q");
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* d : {"PRIM", "OBJ", "MAP", "LIGHT"}) fs::create_directories(dos / d);
  fs::copy_file(canon / "prim/PrimFile", dos / "PRIM/PRIMFILE");
  fs::copy_file(canon / "obj/List", dos / "OBJ/LIST");
  fs::copy_file(canon / "obj/O1", dos / "OBJ/O1");
  for (const char* c : {"R", "G", "B"})
    fs::copy_file(canon / "map" / ("Map1_" + std::string(c) + ".map"),
                  dos / "MAP" / ("MAP1_" + std::string(c) + ".MAP"));
  fs::copy_file(canon / "light/light.txt", dos / "LIGHT/LIGHT.TXT");
  return dos;
}

TEST(DosNames, UpperCaseDatabasesAreFoundAndRenderTheSameBytes) {
  TempScene s;
  const fs::path dos = dosCopy(s);
  const auto r = runPrime("trace " + q(dos) + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  // Writing keeps the canonical name (M40).
  ASSERT_TRUE(fs::exists(dos / "graph_scr"));
  EXPECT_EQ(s.read("DOS/graph_scr"), s.read("canon/graph_scr"));
}

TEST(DosNames, TwoNamesThatDifferOnlyByCaseAreRefusedNamingBoth) {
  TempScene s;
  const fs::path dos = dosCopy(s);
  fs::copy_file(dos / "OBJ/LIST", dos / "OBJ/List");
  const auto r = runPrime("trace " + q(dos) + " -q");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("OBJ: two entries differ only by case, LIST and List"));
  EXPECT_THAT(r.output, HasSubstr("M40"));
}

TEST(DosNames, ADirectoryOfDatabasesOnlyIsNotToldToRunModel) {
  TempScene s;
  const fs::path dos = dosCopy(s);
  fs::remove(dos / "OBJ/LIST");
  const auto r = runPrime("trace " + q(dos) + " -q");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("/List does not exist"));
  EXPECT_THAT(r.output, Not(HasSubstr("prime model")));
  EXPECT_THAT(r.output, HasSubstr("no Model.txt"));
}

TEST(DosNames, UpperCaseTextInputsModel) {
  TempScene s;
  const fs::path dir = s.path("UP");
  fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path("canon"), fs::copy_options::recursive);
  for (const char* d : {"PRIM", "OBJ", "MAP", "LIGHT"}) fs::create_directories(dir / d);
  fs::copy_file(s.path("canon/Model.txt"), dir / "MODEL.TXT");
  fs::copy_file(s.path("canon/prim/S1.txt"), dir / "PRIM/S1.TXT");
  fs::copy_file(s.path("canon/obj/D1.txt"), dir / "OBJ/D1.TXT");
  fs::copy_file(s.path("canon/obj/H1.txt"), dir / "OBJ/H1.TXT");
  fs::copy_file(s.path("canon/map/m1.txt"), dir / "MAP/M1.TXT");
  fs::copy_file(s.path("canon/light/light.txt"), dir / "LIGHT/LIGHT.TXT");
  const auto r = runPrime("model " + q(dir));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("1 object file(s)"));
}

// A hue with every problem of the check: kRH 0.5 (K10), indx 1 with kDT 0.5
// (K13), tT 1 (K14), and 1 - fDR = (0, 0, 1), "blue", which ColorNum sends to
// index floor(0*7)*32 + floor(0*7)*4 + floor(1*3) = 3, a fixed entry (K16,
// K17) that InitPalette makes (150, 239, 130).
constexpr const char* kBadHue = "0.0 0.5\n1 1 0\n1.0\n0.5 2\n1\n";

TEST(Check, ACleanSceneExitsZero) {
  TempScene s;
  fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path(),
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  const auto r = runPrime("check " + q(s.path()));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("no problems found"));
}

TEST(Check, EachProblemIsNamedByFileLineFieldAndId) {
  TempScene s;
  fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path(),
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  s.write("obj/H1.txt", kBadHue);
  const auto r = runPrime("check " + q(s.path()));
  EXPECT_EQ(r.status, 1) << r.output;
  const std::string h = (s.path() / "obj/H1.txt").string();
  EXPECT_THAT(r.output, HasSubstr(h + ":4: kRH"));
  EXPECT_THAT(r.output, HasSubstr("K10"));
  EXPECT_THAT(r.output, Not(HasSubstr(h + ":4: kTH")));  // 2 is an integer
  EXPECT_THAT(r.output, HasSubstr(h + ":5: indx"));
  EXPECT_THAT(r.output, HasSubstr("K13"));
  EXPECT_THAT(r.output, HasSubstr(h + ":3: tT"));
  EXPECT_THAT(r.output, HasSubstr("K14"));
  EXPECT_THAT(r.output, HasSubstr(h + ":2: fDR[R]"));
  EXPECT_THAT(r.output, HasSubstr("palette index 3, which the 8514/A shows as (150, 239, 130)"));
  EXPECT_THAT(r.output, HasSubstr("4 problem(s)"));
}

TEST(Check, IndxOneIsHarmlessWithoutTransmission) {
  TempScene s;
  fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path(),
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  s.write("obj/H1.txt", "0.5 1.0\n0.2 0.6 0.8\n0.999\n2 2\n1\n");  // kDT 1: kST = 0
  const auto r = runPrime("check " + q(s.path()));
  EXPECT_EQ(r.status, 0) << r.output;
}

// Warnings reach the user with or without -q: -q drops the summary only, as
// its help says.
TEST(Check, ModelWarnsButBuilds) {
  for (const std::string quiet : {"", "-q "}) {
    TempScene s;
    fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path(),
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    s.write("obj/H1.txt", kBadHue);
    const auto r = runPrime("model " + quiet + q(s.path()));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_THAT(r.output,
                HasSubstr("prime: warning: " + (s.path() / "obj/H1.txt").string() + ":4: kRH"));
    EXPECT_EQ(r.output.find("modelled ") != std::string::npos, quiet.empty()) << r.output;
    EXPECT_TRUE(s.exists("obj/O1"));
  }
  EXPECT_THAT(runPrime("model --help").output,
              HasSubstr("warnings about the scene still go to standard error"));
}

TEST(New, WritesASceneThatModelsChecksCleanAndRenders) {
  TempScene s;
  const fs::path dir = s.path("first");
  auto r = runPrime("new " + q(dir));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("wrote " + dir.string()));
  r = runPrime("check " + q(dir));
  EXPECT_EQ(r.status, 0) << r.output;
  r = runPrime("model " + q(dir));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, Not(HasSubstr("warning")));
  r = runPrime("trace " + q(dir) + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  // Something is drawn: the sphere's orange and the cube's greys and checker
  // give many palette indices besides the background's 1.
  const auto g = prime::io::readGraphFile((dir / "graph_scr").string());
  std::set<int> colours;
  for (auto v : g.pixels) colours.insert(v);
  EXPECT_GT(colours.size(), 10u);
}

TEST(New, RefusesANonEmptyDirectory) {
  TempScene s;  // holds prim/, obj/ ...
  const auto r = runPrime("new " + q(s.path()));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("non-empty directory"));
  EXPECT_FALSE(s.exists("Model.txt"));
}

TEST(New, RefusesAnEmptyNameAndWritesNothingHere) {
  TempScene s;
  const fs::path here = s.path("here");
  fs::create_directories(here);
  const auto r = runPrime("new ''", here.string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("DIR: expected the name of a new or empty directory"));
  EXPECT_TRUE(fs::is_empty(here));
}

TEST(New, FillsAnEmptyDirectoryWholeAndLeavesNoTemporary) {
  TempScene s;
  const fs::path dir = s.path("empty");
  fs::create_directories(dir);
  const auto r = runPrime("new " + q(dir) + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "Model.txt"));
  EXPECT_TRUE(fs::exists(dir / "light" / "light.txt"));
  for (const auto& e : fs::directory_iterator(s.path()))
    EXPECT_THAT(e.path().filename().string(), Not(HasSubstr(".prime-new."))) << "a temporary left";
}

TEST(Check, ADirectoryWithNothingOfASceneIsNotClean) {
  TempScene s;
  const fs::path dir = s.path("nothing");
  fs::create_directories(dir);
  const auto r = runPrime("check " + q(dir));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("expected a PRIME scene directory"));
  EXPECT_THAT(r.output, Not(HasSubstr("no problems found")));
}

// Every command that writes a file names it on a line "wrote PATH" (not with
// -q): PRIME's trace and plate1, Malone's and CGL's trace.
TEST(WroteLines, EveryWrittenFileIsNamedOnceUnlessQuiet) {
  TempScene s;
  fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path("sphere"), fs::copy_options::recursive);
  const fs::path scenes = fs::path(PRIME_SCENES).parent_path();
  const std::string g = s.path("g.scr").string(), png = s.path("a.png").string(),
                    t = s.path("t.png").string(), ppm = s.path("m.ppm").string(),
                    rle = s.path("c.rle").string();
  struct Case {
    std::string args;
    std::vector<std::string> files;
  };
  const std::vector<Case> cases = {
      {"trace " + q(s.path("sphere")) + " --model --out " + g + " --png " + png +
           " --true-color-png " + t,
       {g, png, t}},
      {"plate1 " + q(scenes / "prime/plate1") + " --out " + g + " --png " + png, {g, png}},
      {"trace " + q(scenes / "malone/glass.mal") + " --ppm " + ppm + " --png " + png, {ppm, png}},
      {"trace " + q(scenes / "cgl/checkerboard.cgl") + " --rle " + rle + " --png " + png,
       {rle, png}},
  };
  for (const Case& c : cases) {
    auto r = runPrime(c.args);
    ASSERT_EQ(r.status, 0) << c.args << "\n" << r.output;
    for (const std::string& f : c.files) {
      const std::string line = "\nwrote " + f + "\n";
      const auto at = r.output.find(line);
      EXPECT_NE(at, std::string::npos) << c.args << "\n" << r.output;
      EXPECT_EQ(r.output.find(line, at + 1), std::string::npos) << "twice: " << line;
    }
    r = runPrime(c.args + " -q");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_THAT(r.output, Not(HasSubstr("wrote "))) << c.args;
  }
}

}  // namespace
