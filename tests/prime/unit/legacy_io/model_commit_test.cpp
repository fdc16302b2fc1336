// `prime model` all or nothing (docs/prime/deviations.md M19-M22): the
// databases switch together through a journal, a failure at any step leaves
// exactly the old or (once the journal is written) exactly the new databases,
// a mixture is refused by verifyModel, two runs take a lock, and Model.txt is
// read the same with any line ending and refused when it builds nothing.
#include "legacy_io/prime/model_commit.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>

#include "legacy_io/common/run_inputs.h"
#include "legacy_io/prime/model_builder.h"
#include "tests/support/error_message.h"
#include "tests/support/temp_scene.h"

namespace prime::io {
namespace {

namespace fs = std::filesystem;

using Files = std::map<std::string, std::vector<std::uint8_t>>;

// The sphere scene of tests/prime/data (one object, one map).
void copySphere(const test::TempScene& s) {
  fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path(),
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

// Every database of the scene (the files of prim/, obj/ and map/ that are not
// text inputs), and whether a temporary is left anywhere.
Files databases(const test::TempScene& s, bool* temporaries = nullptr) {
  Files f;
  for (const char* sub : {"prim", "obj", "map"})
    for (const auto& e : fs::directory_iterator(s.path(sub))) {
      const std::string name = e.path().filename().string();
      if (name.find(".prime-tmp.") != std::string::npos) {
        if (temporaries) *temporaries = true;
        continue;
      }
      if (e.is_regular_file() && e.path().extension() != ".txt")
        f[std::string(sub) + "/" + name] = s.read(std::string(sub) + "/" + name);
    }
  return f;
}

using test::messageOf;

class ModelCommit : public ::testing::Test {
 protected:
  void SetUp() override {
    copySphere(s);
    oldModel = buildModel(SceneDir(s.path()));
    // The new run: the sphere at another scale (different PrimFile bytes) and
    // another map colour (different map bytes).
    s.write("prim/S1.txt", "S\n200 200 200\n500 500 500\n0 0 0\n0 0 0\n1 1\n0\n");
    s.write("map/m1.txt", "1\n1 1\n0.25\n0.5\n0.75\n");
    newModel = buildModel(SceneDir(s.path()));
    writeModel(SceneDir(s.path()), oldModel);
    oldFiles = databases(s);
    writeModel(SceneDir(s.path()), newModel);
    newFiles = databases(s);
    writeModel(SceneDir(s.path()), oldModel);
  }
  void TearDown() override { unsetenv(kModelFaultVariable); }

  test::TempScene s;
  Model oldModel, newModel;
  Files oldFiles, newFiles;
};

TEST_F(ModelCommit, TheTwoRunsDifferInEveryKindOfDatabase) {
  // Else "old or new" below could not tell them apart.
  ASSERT_EQ(oldFiles.size(), newFiles.size());
  EXPECT_NE(oldFiles["prim/PrimFile"], newFiles["prim/PrimFile"]);
  EXPECT_NE(oldFiles["map/Map1_R.map"], newFiles["map/Map1_R.map"]);
  EXPECT_TRUE(fs::exists(s.path(kModelStamp)));
  EXPECT_FALSE(fs::exists(s.path(kModelJournal)));
}

TEST_F(ModelCommit, TheStampsDigestsAreEachDatabasesSha256) {
  // Checked against an independent SHA-256: coreutils' sha256sum. Stamps
  // written by any version must keep verifying, whatever library hashes.
  std::ifstream in(s.path(kModelStamp));
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, "prime-model 1");
  int checked = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string digest, size, path;
    fields >> digest >> size >> path;
    const std::string command = "sha256sum '" + s.path(path).string() + "'";
    FILE* p = popen(command.c_str(), "r");
    ASSERT_NE(p, nullptr);
    char out[65] = {};
    ASSERT_EQ(std::fread(out, 1, 64, p), 64u);
    EXPECT_EQ(pclose(p), 0);
    EXPECT_EQ(digest, std::string(out)) << path;
    EXPECT_EQ(std::stoul(size), oldFiles[path].size()) << path;
    ++checked;
  }
  EXPECT_EQ(checked, 6);  // PrimFile, List, O1 and three maps
}

TEST_F(ModelCommit, AFailureAtEveryStepLeavesExactlyTheOldOrTheNewDatabases) {
  const SceneDir scene(s.path());
  int old = 0, fresh = 0, step = 1;
  for (;; ++step) {
    ASSERT_LT(step, 100) << "the switch never completed";
    setenv(kModelFaultVariable, ("fail:" + std::to_string(step)).c_str(), 1);
    const std::string m = messageOf([&] { writeModel(scene, newModel); });
    unsetenv(kModelFaultVariable);
    if (m == "(no error)") break;  // past the last step
    EXPECT_NE(m.find("injected failure"), std::string::npos) << m;
    // What a later trace or prime model does first: finish a pending journal.
    settleModel(scene);
    EXPECT_NO_THROW(verifyModel(scene)) << "step " << step;
    bool temporaries = false;
    const Files now = databases(s, &temporaries);
    EXPECT_FALSE(temporaries) << "step " << step;
    if (now == oldFiles)
      ++old;
    else if (now == newFiles)
      ++fresh;
    else
      ADD_FAILURE() << "step " << step << ": a mixture of the two runs";
    writeModel(scene, oldModel);
    ASSERT_EQ(databases(s), oldFiles);
  }
  // 5 databases (PrimFile, List, O1, 3 maps: 6 files): 6 temporaries and the
  // journal fail before the commit point; 6 renames and the stamp after it.
  EXPECT_EQ(old, 7);
  EXPECT_EQ(fresh, 7);
  EXPECT_EQ(databases(s), newFiles);
}

TEST_F(ModelCommit, AMixtureIsRefusedNamingTheFile) {
  const SceneDir scene(s.path());
  EXPECT_NO_THROW(verifyModel(scene));
  s.writeBytes("prim/PrimFile", newFiles["prim/PrimFile"]);  // one file of the other run
  const std::string m = messageOf([&] { verifyModel(scene); });
  EXPECT_NE(m.find("prim/PrimFile"), std::string::npos) << m;
  EXPECT_NE(m.find("the databases are a mixture of two `prime model` runs"), std::string::npos)
      << m;
  EXPECT_NE(m.find("run prime model"), std::string::npos) << m;
  // A scene built before stamps (or by the original) is read as before.
  fs::remove(s.path(kModelStamp));
  EXPECT_NO_THROW(verifyModel(scene));
}

TEST_F(ModelCommit, ASecondRunIsBusyWhileTheFirstHoldsTheLock) {
  const SceneDir scene(s.path());
  const auto first = lockForModel(scene, false);
  const std::string m = messageOf([&] { writeModel(scene, newModel); });
  EXPECT_NE(m.find("busy: another prime model (pid "), std::string::npos) << m;
  EXPECT_EQ(databases(s), oldFiles);
}

TEST_F(ModelCommit, AModelInputNamedLikeAnOutputIsNotReplaced) {
  // AddMap reads map/Map1_R.map as text; the map it makes is map/Map1_R.map.
  const std::string text = "1\n1 1\n0.5\n0.5\n0.5\n";
  s.write("map/Map1_R.map", text);
  s.write("Model.txt", "AddObj d1.txt\nAddToObjList 1\nAddMap Map1_R.map\n");
  const RunInputs run;
  const SceneDir scene(s.path());
  const std::string m = messageOf([&] { writeModel(scene, buildModel(scene)); });
  EXPECT_NE(m.find("is the input"), std::string::npos) << m;
  const auto after = s.read("map/Map1_R.map");
  EXPECT_EQ(std::string(after.begin(), after.end()), text);
}

TEST(ModelText, AnyLineEndingGivesTheSameCalls) {
  const std::string lf = "# comment\nAddObj d1.txt\nAddToObjList 1\n\nAddMap m1.txt # the map\n";
  std::string crlf, cr;
  for (char c : lf) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    cr += c == '\n' ? '\r' : c;
  }
  const auto want = parseModelText(lf, "Model.txt");
  ASSERT_EQ(want.size(), 3u);
  for (const std::string& text : {crlf, cr}) {
    const auto got = parseModelText(text, "Model.txt");
    ASSERT_EQ(got.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(got[i].name, want[i].name);
      EXPECT_EQ(got[i].args, want[i].args);
      EXPECT_EQ(got[i].line, want[i].line);  // lines 2, 3, 5
    }
  }
}

TEST(ModelText, ACrOnlySceneModelsTheSameDatabasesAsLf) {
  test::TempScene lf, cr;
  copySphere(lf);
  copySphere(cr);
  for (const char* f : {"Model.txt", "obj/D1.txt", "obj/H1.txt", "prim/S1.txt", "map/m1.txt"}) {
    auto bytes = cr.read(f);
    for (auto& b : bytes)
      if (b == '\n') b = '\r';
    cr.writeBytes(f, bytes);
  }
  writeModel(SceneDir(lf.path()), buildModel(SceneDir(lf.path())));
  writeModel(SceneDir(cr.path()), buildModel(SceneDir(cr.path())));
  EXPECT_EQ(databases(cr), databases(lf));
  EXPECT_EQ(databases(cr).size(), 6u);
}

TEST(ModelText, AModelWithNoObjectIsRefusedUnlessAllowed) {
  test::TempScene s;
  copySphere(s);
  for (const std::string& text : {std::string(), std::string("# AddObj d1.txt\n# nothing\n"),
                                  std::string("AddMap m1.txt\n")}) {
    s.write("Model.txt", text);
    const std::string m = messageOf([&] { buildModel(SceneDir(s.path())); });
    EXPECT_NE(m.find("Model.txt: objects: expected at least one AddObj or CopyObj"),
              std::string::npos)
        << m;
    ModelOptions allow;
    allow.allowEmpty = true;
    EXPECT_NO_THROW(buildModel(SceneDir(s.path()), allow));
  }
}

TEST(ModelText, AModelTxtThatIsADirectoryIsRefusedAsOne) {
  test::TempScene s;
  copySphere(s);
  fs::remove(s.path("Model.txt"));
  fs::create_directories(s.path("Model.txt"));
  const std::string m = messageOf([&] { buildModel(SceneDir(s.path())); });
  EXPECT_NE(m.find("Model.txt"), std::string::npos) << m;
  EXPECT_NE(m.find("is a directory"), std::string::npos) << m;
}

}  // namespace
}  // namespace prime::io
