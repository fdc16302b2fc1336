// Bad scene data that only shows at render time is reported when the scene
// is loaded, naming the object, primitive and file.
#include "src/prime/scene/scene_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "legacy_io/common/error.h"
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

}  // namespace
}  // namespace prime
