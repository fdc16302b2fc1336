// Replaying history: every scene under scenes/ is modelled and rendered by the
// real `prime` executable, and what it writes is compared byte for byte with
// the golden files under tests/prime/golden/<scene>/:
//
//   db/...      every database `prime model` writes (prim/PrimFile, obj/O<n>,
//               obj/List, map/Map<n>_R|G|B.map), and no others
//   graph_scr   the graph file of the render
//   command.txt the render command, without the scene and the output file,
//               e.g. "trace --screen 512 384 --palette plate3" or
//               "plate1 --screen 512 384" (reduced so that CI, which runs the
//               suite twice, once under ASan, stays fast)
//
// A scene without a golden directory fails. A golden is committed only after
// its PNG was looked at and pixels were checked by hand: tests/prime/golden/README.md.
// To rewrite the goldens after an intended change, see tests/prime/golden/README.md
// (PRIME_UPDATE_GOLDEN=1).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "legacy_io/prime/graph_file.h"
#include "tests/support/run_prime.h"

namespace {

namespace fs = std::filesystem;

const fs::path kScenes = PRIME_SCENES;
const fs::path kGolden = fs::path(PRIME_GOLDEN);

bool updating() {
  const char* v = std::getenv("PRIME_UPDATE_GOLDEN");
  return v != nullptr && std::string(v) == "1";
}

std::vector<std::string> sceneNames() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kScenes))
    if (e.is_directory()) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::uint8_t> readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

using prime::test::CommandResult;
using prime::test::runPrime;

// A private copy of the scene's text inputs (tests run in parallel, and the
// scene directory may hold databases from a user's own runs).
class SceneCopy {
 public:
  explicit SceneCopy(const std::string& scene, const std::string& tag) {
    root_ = fs::temp_directory_path() /
            ("prime-replay-" + scene + "-" + tag + "-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    for (const auto& e : fs::recursive_directory_iterator(kScenes / scene)) {
      const fs::path rel = fs::relative(e.path(), kScenes / scene);
      if (e.is_directory()) {
        fs::create_directories(root_ / rel);
      } else if (e.path().extension() == ".txt") {
        fs::create_directories((root_ / rel).parent_path());
        fs::copy_file(e.path(), root_ / rel);
      }
    }
    for (const char* sub : {"prim", "bound", "obj/Copy", "map", "light"})
      fs::create_directories(root_ / sub);
  }
  ~SceneCopy() {
    if (!keep_) {
      std::error_code ec;
      fs::remove_all(root_, ec);
    }
  }
  SceneCopy(const SceneCopy&) = delete;
  SceneCopy& operator=(const SceneCopy&) = delete;
  const fs::path& path() const { return root_; }
  void keep() { keep_ = true; }

 private:
  fs::path root_;
  bool keep_ = false;
};

// The databases `prime model` wrote, relative to the scene: PrimFile, O<n>,
// List and the map channels.
std::vector<std::string> databases(const fs::path& root) {
  static const std::regex kDb(R"((prim/PrimFile|obj/List|obj/O[0-9]+|map/Map[0-9]+_[RGB]\.map))");
  std::vector<std::string> out;
  for (const char* sub : {"prim", "obj", "map"}) {
    if (!fs::exists(root / sub)) continue;
    for (const auto& e : fs::directory_iterator(root / sub)) {
      const std::string rel = std::string(sub) + "/" + e.path().filename().string();
      if (e.is_regular_file() && std::regex_match(rel, kDb)) out.push_back(rel);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string command(const std::string& scene) {
  std::string c = readText(kGolden / scene / "command.txt");
  while (!c.empty() && (c.back() == '\n' || c.back() == '\r' || c.back() == ' ')) c.pop_back();
  return c;
}

// What changed between two graph files, for the failure message.
std::string describeGraphDiff(const fs::path& golden, const fs::path& actual) {
  std::ostringstream os;
  const auto a = prime::io::readGraphFile(golden.string());
  const auto b = prime::io::readGraphFile(actual.string());
  if (a.graphType != b.graphType || a.width() != b.width() || a.height() != b.height()) {
    os << "header differs: golden graphType " << a.graphType << ", " << a.width() << " x "
       << a.height() << " pixels; now graphType " << b.graphType << ", " << b.width() << " x "
       << b.height() << "\n";
    return os.str();
  }
  std::size_t differing = 0;
  std::vector<std::string> first;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (a.at(x, y) != b.at(x, y)) {
        ++differing;
        if (first.size() < 10)
          first.push_back("(" + std::to_string(x) + "," + std::to_string(y) + ") " +
                          std::to_string(a.at(x, y)) + " -> " + std::to_string(b.at(x, y)));
      }
  os << differing << " of " << a.pixels.size()
     << " pixels differ (column,row golden -> now); first:";
  for (const auto& f : first) os << " " << f;
  os << "\n";
  return os.str();
}

class ReplayScene : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    // No window, ever: `prime trace` opens one when there is a display.
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
  }
  // HasAGolden fails for a scene without one; the other tests then skip.
  bool hasGolden() const { return fs::exists(kGolden / GetParam() / "command.txt"); }
};

TEST_P(ReplayScene, HasAGolden) {
  const std::string scene = GetParam();
  EXPECT_TRUE(fs::exists(kGolden / scene / "command.txt"))
      << "scenes/" << scene
      << " has no golden files: render it, look at the PNG, check pixels by hand, then "
      << "add tests/prime/golden/" << scene << "/ (tests/prime/golden/README.md)";
}

TEST_P(ReplayScene, ModelWritesTheGoldenDatabases) {
  const std::string scene = GetParam();
  if (!hasGolden()) GTEST_SKIP() << "no tests/prime/golden/" << scene << "/command.txt";
  SceneCopy copy(scene, "db");
  if (command(scene).rfind("plate1", 0) == 0)
    GTEST_SKIP() << "plate1 has no databases: it is not ray traced";
  const CommandResult m = runPrime("model " + copy.path().string());
  ASSERT_EQ(m.status, 0) << m.output;
  const fs::path golden = kGolden / scene / "db";
  const auto now = databases(copy.path());
  if (updating()) {
    fs::remove_all(golden);
    for (const auto& rel : now) {
      fs::create_directories((golden / rel).parent_path());
      fs::copy_file(copy.path() / rel, golden / rel);
    }
    std::printf("updated %s (%zu databases)\n", golden.c_str(), now.size());
    return;
  }
  const auto want = databases(golden);
  EXPECT_EQ(now, want) << "`prime model scenes/" << scene
                       << "` writes a different set of databases";
  for (const auto& rel : want) {
    if (!fs::exists(copy.path() / rel)) continue;
    const auto a = readBytes(golden / rel), b = readBytes(copy.path() / rel);
    if (a == b) continue;
    std::size_t at = 0;
    while (at < a.size() && at < b.size() && a[at] == b[at]) ++at;
    copy.keep();
    ADD_FAILURE() << rel << " differs from tests/prime/golden/" << scene << "/db/" << rel << ": "
                  << a.size() << " bytes golden, " << b.size() << " now, first difference at byte "
                  << at << "\n  compare: prime dump " << (golden / rel).string()
                  << " vs prime dump " << (copy.path() / rel).string();
  }
}

TEST_P(ReplayScene, RenderWritesTheGoldenGraphFile) {
  const std::string scene = GetParam();
  if (!hasGolden()) GTEST_SKIP() << "no tests/prime/golden/" << scene << "/command.txt";
  SceneCopy copy(scene, "graph");
  const std::string cmd = command(scene);
  const fs::path out = copy.path() / "graph_scr";
  // "trace --screen 512 384" -> "trace DIR --screen 512 384 ..." (the scene
  // first: a vector option would otherwise swallow it).
  const std::size_t space = cmd.find(' ');
  const std::string verb = cmd.substr(0, space),
                    flags = space == std::string::npos ? "" : cmd.substr(space);
  CommandResult r;
  if (verb == "plate1") {
    r = runPrime(verb + " " + copy.path().string() + flags + " -q --out " + out.string());
  } else {
    r = runPrime("model " + copy.path().string());
    ASSERT_EQ(r.status, 0) << r.output;
    r = runPrime(verb + " " + copy.path().string() + flags + " -q --threads 2 --out " +
                 out.string());
  }
  ASSERT_EQ(r.status, 0) << r.output;
  const fs::path golden = kGolden / scene / "graph_scr";
  if (updating()) {
    fs::copy_file(out, golden, fs::copy_options::overwrite_existing);
    std::printf("updated %s\n", golden.c_str());
    return;
  }
  if (readBytes(golden) == readBytes(out)) return;
  const fs::path kept = fs::temp_directory_path() / ("prime-replay-" + scene + ".graph_scr");
  fs::copy_file(out, kept, fs::copy_options::overwrite_existing);
  ADD_FAILURE() << "`prime " << cmd << " scenes/" << scene
                << "` no longer writes tests/prime/golden/" << scene << "/graph_scr:\n  "
                << describeGraphDiff(golden, out) << "  the new file is " << kept.string()
                << "\n  see what changed: prime diff " << golden.string() << " " << kept.string()
                << " --image diff.png";
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReplayScene, ::testing::ValuesIn(sceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
