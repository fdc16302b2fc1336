// SceneDir finds a scene's files without regard to case (M40): a scene copied
// from a DOS disk (PRIM/PRIMFILE, OBJ/LIST, MAP/MAP1_R.MAP) reads on a
// case-sensitive file system; two names that differ only by case are refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "legacy_io/common/error.h"
#include "legacy_io/prime/scene_dir.h"
#include "tests/support/temp_scene.h"

namespace {

namespace fs = std::filesystem;
using prime::io::InputError;
using prime::io::SceneDir;
using ::testing::HasSubstr;

TEST(SceneDirCase, FindsUpperCaseNamesAndKeepsTheirSpelling) {
  prime::test::TempScene s;  // its own prim/, obj/ ...: the DOS scene goes in DOS/
  s.write("DOS/OBJ/LIST", "x");
  s.write("DOS/prim/PRIMFILE", "x");
  s.write("DOS/MODEL.TXT", "x");
  const SceneDir dir(s.path("DOS"));
  EXPECT_EQ(dir.find("obj", "List"), s.path("DOS/OBJ/LIST"));
  EXPECT_EQ(dir.find("prim", "PrimFile"), s.path("DOS/prim/PRIMFILE"));
  EXPECT_EQ(dir.find(".", "Model.txt"), s.path("DOS/MODEL.TXT"));
  EXPECT_EQ(dir.existingInput("obj", "List", "test"), s.path("DOS/OBJ/LIST"));
}

TEST(SceneDirCase, TheExactNameIsFoundAndAMissingOneIsCanonical) {
  prime::test::TempScene s;
  s.write("obj/List", "x");
  const SceneDir dir(s.path());
  EXPECT_EQ(dir.find("obj", "List"), s.path("obj/List"));
  EXPECT_EQ(dir.find("obj", "O7"), s.path("obj/O7"));  // not there: the canonical path
  EXPECT_EQ(dir.find("nowhere/deeper", "X"), s.path("nowhere/deeper/X"));
  EXPECT_THROW(dir.existingInput("obj", "O7", "test"), InputError);
}

TEST(SceneDirCase, AFileWrittenAfterTheFirstLookupIsFound) {
  prime::test::TempScene s;
  s.write("obj/List", "x");
  const SceneDir dir(s.path());
  EXPECT_EQ(dir.find("obj", "O1"), s.path("obj/O1"));  // lists obj/ without O1
  s.write("obj/O1", "x");
  EXPECT_EQ(dir.existingInput("obj", "O1", "test"), s.path("obj/O1"));
}

TEST(SceneDirCase, TwoNamesThatDifferOnlyByCaseAreRefusedNamingBoth) {
  prime::test::TempScene s;
  s.write("obj/List", "x");
  s.write("obj/LIST", "y");
  const SceneDir dir(s.path());
  try {
    dir.find("obj", "List");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("obj: two entries differ only by case, LIST and List"));
    EXPECT_THAT(e.what(), HasSubstr("M40"));
  }
  // A clash of directories too.
  prime::test::TempScene t;
  fs::create_directories(t.path("MAP"));  // beside TempScene's map/
  EXPECT_THROW(SceneDir(t.path()).find("map", "Map1_R.map"), InputError);
}

TEST(SceneDirCase, UnsafeNamesAreStillRefused) {
  prime::test::TempScene s;
  const SceneDir dir(s.path());
  EXPECT_THROW(dir.existingInput("obj", "../secret", "test"), InputError);
}

}  // namespace
