// Bad scene data that only shows at render time is reported when the scene
// is loaded, naming the object, primitive and file.
#include "src/prime/scene/scene_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "legacy_io/common/error.h"
#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/model_builder.h"
#include "legacy_io/prime/obj_file.h"
#include "legacy_io/prime/prim_file.h"
#include "tests/support/temp_scene.h"

namespace prime {
namespace {

using ::testing::HasSubstr;

void sphereScene(const test::TempScene& s, const std::string& maps = "1 1") {
  s.write("Model.txt", "AddObj d1.txt\nAddToObjList 1\nAddMap m.txt\n");
  s.write("obj/H1.txt", "0.5 0 0.8 0.4 0.2 0.999 2 2 1.5\n");
  s.write("obj/D1.txt", "1\nS 1\nNULL\n");
  s.write("prim/S1.txt", "S\n100 100 100\n500 500 500\n0 0 0\n0 0 0\n" + maps + "\n0\n");
  s.write("map/m.txt", "1\n1 1\n0.5 0.5 0.5\n");
  s.write("light/light.txt", "1 1 1\n0\n");
  const io::SceneDir dir(s.path());
  io::writeModel(dir, io::buildModel(dir));
}

std::string loadError(const test::TempScene& s) {
  try {
    loadScene(io::SceneDir(s.path()));
  } catch (const std::exception& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error";
  return {};
}

TEST(SceneLoader, LoadsAModelledScene) {
  test::TempScene s;
  sphereScene(s);
  const Scene scene = loadScene(io::SceneDir(s.path()));
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].entries.size(), 1u);
  EXPECT_EQ(scene.prims.size(), 1u);
  ASSERT_NE(scene.map(1), nullptr);
  EXPECT_TRUE(scene.map(1)->constant);
  EXPECT_EQ(scene.ambient, (Vec3{1, 1, 1}));
}

TEST(SceneLoader, MissingMapIsNamedWithObjectAndPrimitive) {
  test::TempScene s;
  sphereScene(s, "1 7");
  const std::string msg = loadError(s);
  EXPECT_THAT(msg, HasSubstr("obj/O1"));
  EXPECT_THAT(msg, HasSubstr("primitive 0 (sphere) surface 0 inside map"));
  EXPECT_THAT(msg, HasSubstr("found map 7, which does not exist"));
}

TEST(SceneLoader, BoundThatIsNotAPrimitiveType) {
  test::TempScene s;
  sphereScene(s);
  // Point the object's bound at a record whose type byte is not a letter.
  auto prims = io::readPrimFile(s.path("prim/PrimFile").string());
  prims.prims.push_back(prims.prims[0]);
  prims.prims[1].type = 'Q';
  io::writePrimFile(s.path("prim/PrimFile").string(), prims);
  auto obj = io::readObjFile(s.path("obj/O1").string());
  obj.header.boundVol = 1;
  io::writeObjFile(s.path("obj/O1").string(), obj);
  const std::string msg = loadError(s);
  EXPECT_THAT(msg, HasSubstr("obj/O1"));
  EXPECT_THAT(msg, HasSubstr("bounding volume (primitive 1)"));
}

TEST(SceneLoader, PrimitiveNumberOutOfRange) {
  test::TempScene s;
  sphereScene(s);
  auto obj = io::readObjFile(s.path("obj/O1").string());
  obj.entries[0].l = 5;
  io::writeObjFile(s.path("obj/O1").string(), obj);
  const std::string msg = loadError(s);
  EXPECT_THAT(msg,
              HasSubstr("obj/O1 (byte 76): entry 0 primitive: expected a primitive number 0..0"));
}

TEST(SceneLoader, CycleInABinaryObjectFile) {
  test::TempScene s;
  sphereScene(s);
  io::ObjFile obj = io::readObjFile(s.path("obj/O1").string());
  io::ObjRecord u;
  u.opCode = {'+', 0, 0, 0};
  u.l = 1;
  u.r = 0;  // the root contains itself
  obj.entries = {u, obj.entries[0]};
  obj.header.numEntries = 2;
  io::writeObjFile(s.path("obj/O1").string(), obj);
  EXPECT_THAT(loadError(s), HasSubstr("cycle"));
}

TEST(SceneLoader, StaleDatabasesAreReported) {
  test::TempScene s;
  sphereScene(s);
  EXPECT_TRUE(staleDatabases(io::SceneDir(s.path())).empty());
  const auto later =
      std::filesystem::last_write_time(s.path("prim/PrimFile")) + std::chrono::seconds(5);
  std::filesystem::last_write_time(s.path("prim/S1.txt"), later);
  const auto stale = staleDatabases(io::SceneDir(s.path()));
  ASSERT_EQ(stale.size(), 1u);
  EXPECT_THAT(stale[0], HasSubstr("prim/S1.txt is newer than the databases"));
  std::filesystem::remove(s.path("obj/List"));
  EXPECT_THAT(staleDatabases(io::SceneDir(s.path()))[0], HasSubstr("obj/List does not exist"));
}

// M33: NaN and infinities in a binary database are refused, naming the
// record, the field and its byte. Offsets by hand (records.h): a packed Prim
// is the type byte, then the transform's 16 doubles, then the inverse's, so
// transform[1][2] of record 0 is at 1 + 8 * (4 + 2) = 49 and inverse[3][3]
// at 1 + 128 + 8 * 15 = 249; an ObjHeader's hue starts at byte 4 (after
// numEntries and boundVol), fDR[2] 8 * 4 = 32 bytes in: byte 36; texel 0 of
// a map follows its 4-byte header.
TEST(SceneLoader, NonFiniteNumbersInTheDatabasesAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  {
    test::TempScene s;
    sphereScene(s);
    auto prims = io::readPrimFile(s.path("prim/PrimFile").string());
    prims.prims[0].transform[1][2] = nan;
    io::writePrimFile(s.path("prim/PrimFile").string(), prims);
    const std::string msg = loadError(s);
    EXPECT_THAT(msg, HasSubstr("PrimFile (byte 49): PrimFile record 0 transform[1][2]"));
    EXPECT_THAT(msg, HasSubstr("found NaN"));
  }
  {
    test::TempScene s;
    sphereScene(s);
    auto prims = io::readPrimFile(s.path("prim/PrimFile").string());
    prims.prims[0].inverse[3][3] = -inf;
    io::writePrimFile(s.path("prim/PrimFile").string(), prims);
    EXPECT_THAT(
        loadError(s),
        HasSubstr("PrimFile (byte 249): PrimFile record 0 inverse[3][3]: expected a finite"));
  }
  {
    test::TempScene s;
    sphereScene(s);
    auto obj = io::readObjFile(s.path("obj/O1").string());
    obj.header.hue.fDR[2] = inf;
    io::writeObjFile(s.path("obj/O1").string(), obj);
    const std::string msg = loadError(s);
    EXPECT_THAT(msg, HasSubstr("obj/O1 (byte 36): ObjHeader hue fDR[2]"));
    EXPECT_THAT(msg, HasSubstr("found +infinity"));
  }
  {
    test::TempScene s;
    sphereScene(s);
    for (const char* c : {"R", "G", "B"}) {
      const std::string name = std::string("map/Map1_") + c + ".map";
      auto m = io::readMapFile(s.path(name).string());
      if (*c == 'G') m.texels[0] = nan;
      io::writeMapFile(s.path(name).string(), m);
    }
    EXPECT_THAT(loadError(s), HasSubstr("Map1_G.map (byte 4): texel 0 (u 0, v 0)"));
  }
}

// M34: 20 nested doublings (2^21 - 1 visits per ray when walked per
// reference) get a warning naming the object; a plain tree gets none.
TEST(SceneLoader, LargeSharedSubtreesAreWarnedAbout) {
  Scene scene;
  SceneObject o;
  o.number = 3;
  for (int i = 0; i < 20; ++i) o.entries.push_back({'+', i + 1, i + 1});
  o.entries.push_back({'P', 0, 0});
  scene.objects.push_back(o);
  SceneObject plain;
  plain.number = 4;
  plain.entries = {{'+', 1, 2}, {'P', 0, 0}, {'P', 0, 0}};
  scene.objects.push_back(plain);
  const auto warnings = sharedSubtreeWarnings(scene);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("object 3 (obj/O3): its 21 CSG entries share subtrees"));
  EXPECT_THAT(warnings[0], HasSubstr("2097151 entry visits per ray"));
  EXPECT_THAT(warnings[0], HasSubstr("stops the render with an error (more than 1048576 visits)"));
}

}  // namespace
}  // namespace prime
