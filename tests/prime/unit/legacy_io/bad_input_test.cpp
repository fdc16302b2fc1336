// Every kind of bad input gets an error naming the file, the line (or byte
// offset), the field, what was expected and what was found — and a failed
// `prime model` leaves the previous databases exactly as they were.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "legacy_io/prime/graph_file.h"
#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/model_builder.h"
#include "legacy_io/prime/obj_file.h"
#include "legacy_io/prime/obj_list.h"
#include "legacy_io/prime/prim_file.h"
#include "tests/support/temp_scene.h"

namespace prime::io {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A valid one-object scene, which each test then breaks in one place.
void goodScene(const test::TempScene& s) {
  s.write("Model.txt", "AddObj d1.txt\nAddToObjList 1\nAddMap m.txt\n");
  s.write("obj/H1.txt", "0.1 0.2 0.3 0.4 0.5 0.999 2 2 1.5\n");
  s.write("obj/D1.txt", "3\n- 1 2\nB 1\nS 1\nNULL\n");
  s.write("prim/B1.txt", "B\n100 100 100\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  s.write("prim/S1.txt", "S\n60 60 60\n50 50 0\n0 0 0\n0 0 0\n1 1\n0\n");
  s.write("map/m.txt", "1\n2 1\n0.1 0.2\n0.3 0.4\n0.5 0.6\n");
}

// Runs the model and returns the error message (fails the test if none).
std::string modelError(const test::TempScene& s) {
  try {
    writeModel(SceneDir(s.path()), buildModel(SceneDir(s.path())));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

TEST(BadInput, GoodSceneModels) {
  test::TempScene s;
  goodScene(s);
  EXPECT_NO_THROW(writeModel(SceneDir(s.path()), buildModel(SceneDir(s.path()))));
  EXPECT_EQ(s.read("prim/PrimFile").size(), 2 * 291u);
}

TEST(BadInput, MissingFile) {
  test::TempScene s;
  goodScene(s);
  std::filesystem::remove(s.path("prim/S1.txt"));
  const std::string msg = modelError(s);
  EXPECT_THAT(msg, HasSubstr("prim/S1.txt"));
  EXPECT_THAT(msg, HasSubstr("does not exist"));
  EXPECT_THAT(msg, HasSubstr("D1.txt:4"));  // named by line 4 of the D file
}

TEST(BadInput, TooFewNumbers) {
  test::TempScene s;
  goodScene(s);
  s.write("prim/S1.txt", "S\n60 60 60\n50 50 0\n0 0 0\n0 0 0\n1\n");
  const std::string msg = modelError(s);
  EXPECT_THAT(msg, HasSubstr("prim/S1.txt:6"));
  EXPECT_THAT(msg, HasSubstr("surface 0 inside map"));
  EXPECT_THAT(msg, HasSubstr("found end of file (too few numbers)"));
}

// M35: the offending word with its NUL and control bytes escaped, numbers
// beyond double's range called out of range, a byte order mark skipped.
TEST(BadInput, MessagesNameTheRealProblem) {
  {
    test::TempScene s;
    goodScene(s);
    const char text[] = "0.1 0.2\n0.3 ab\0cd\x01 0.4 0.5 0.999 2 2 1.5\n";
    s.write("obj/H1.txt", std::string(text, sizeof text - 1));
    EXPECT_THAT(modelError(s),
                HasSubstr("obj/H1.txt:2: fDR[G]: expected a number, found \"ab\\x00cd\\x01\""));
  }
  for (const char* big : {"1e309", "1e-400", "-1e309"}) {
    test::TempScene s;
    goodScene(s);
    s.write("obj/H1.txt", std::string("0.1 0.2\n0.3 ") + big + " 0.4 0.5 0.999 2 2 1.5\n");
    const std::string msg = modelError(s);
    EXPECT_THAT(msg, HasSubstr("obj/H1.txt:2: fDR[G]: expected a number within double's range"));
    EXPECT_THAT(msg, HasSubstr(std::string("found \"") + big + "\" (out of range)"));
  }
  {
    test::TempScene s;
    goodScene(s);
    writeModel(SceneDir(s.path()), buildModel(SceneDir(s.path())));
    const auto plain = s.read("prim/PrimFile");
    // The type letter is the file's first byte (K36): after the BOM.
    s.write("prim/S1.txt", "\xEF\xBB\xBFS\n60 60 60\n50 50 0\n0 0 0\n0 0 0\n1 1\n0\n");
    writeModel(SceneDir(s.path()), buildModel(SceneDir(s.path())));
    EXPECT_EQ(s.read("prim/PrimFile"), plain);  // the BOM changes nothing
  }
}

TEST(BadInput, NonNumericText) {
  test::TempScene s;
  goodScene(s);
  s.write("obj/H1.txt", "0.1 0.2\n0.3 zero 0.4 0.5 0.999 2 2 1.5\n");
  const std::string msg = modelError(s);
  EXPECT_THAT(msg, HasSubstr("obj/H1.txt:2: fDR[G]: expected a number, found \"zero\""));
}

TEST(BadInput, NanAndInf) {
  test::TempScene s;
  goodScene(s);
  s.write("prim/B1.txt", "B\n100 nan 100\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  EXPECT_THAT(modelError(s),
              HasSubstr("prim/B1.txt:2: scale y: expected a finite number, found \"nan\""));
  s.write("prim/B1.txt", "B\n100 100 100\n0 0 -inf\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  EXPECT_THAT(modelError(s), HasSubstr("translate z: expected a finite number, found \"-inf\""));
}

TEST(BadInput, UnknownTypeLetter) {
  test::TempScene s;
  goodScene(s);
  s.write("prim/B1.txt", "Q\n100 100 100\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  const std::string msg = modelError(s);
  EXPECT_THAT(msg, HasSubstr("prim/B1.txt:1: type letter"));
  EXPECT_THAT(msg, HasSubstr("found 'Q'"));
}

TEST(BadInput, TypeLetterMustBeTheFirstByte) {
  test::TempScene s;
  goodScene(s);
  s.write("prim/B1.txt", " B\n100 100 100\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  EXPECT_THAT(modelError(s), HasSubstr("K36"));
}

TEST(BadInput, UnknownOpcode) {
  test::TempScene s;
  goodScene(s);
  s.write("obj/D1.txt", "3\n* 1 2\nB 1\nS 1\nNULL\n");
  EXPECT_THAT(
      modelError(s),
      HasSubstr("obj/D1.txt:2: entry 0 opcode: expected one of + - & C B S N T Y O, found \"*\""));
  s.write("obj/D1.txt", "3\n- 1 2\nB1\nS 1\nNULL\n");
  EXPECT_THAT(modelError(s), HasSubstr("write the letter and the number apart, e.g. \"B 1\""));
}

// Issue 37: a numEntries larger than the entries listed ran into the
// bounding volume's NULL and was told to write "N ULL" apart (K35's hint).
TEST(BadInput, NumEntriesLargerThanTheEntriesListed) {
  test::TempScene s;
  goodScene(s);
  s.write("obj/D1.txt", "4\n- 1 2\nB 1\nS 1\nNULL\n");
  const std::string m = modelError(s);
  EXPECT_THAT(m, HasSubstr("obj/D1.txt:5: entry 3 opcode: expected one of + - & C B S N T Y O, "
                           "found \"NULL\", the bounding volume's word (numEntries is 4 but the "
                           "file lists 3 entries)"));
  EXPECT_THAT(m, Not(HasSubstr("apart")));
  s.write("obj/D1.txt", "5\n- 1 2\nB 1\nS 1\n");
  EXPECT_THAT(modelError(s), HasSubstr("entry 3 opcode: expected one of + - & C B S N T Y O, found "
                                       "end of file (numEntries is 5 but the file lists 3 "
                                       "entries)"));
}

TEST(BadInput, ChildIndexOutOfRange) {
  test::TempScene s;
  goodScene(s);
  s.write("obj/D1.txt", "3\n- 1 3\nB 1\nS 1\nNULL\n");
  EXPECT_THAT(
      modelError(s),
      HasSubstr("obj/D1.txt:2: child index of '-': expected an entry number 0..2, found 3"));
}

TEST(BadInput, ChildIndexCycle) {
  test::TempScene s;
  goodScene(s);
  s.write("obj/D1.txt", "4\n- 1 2\n+ 0 3\nS 1\nB 1\nNULL\n");
  const std::string msg = modelError(s);
  EXPECT_THAT(msg, HasSubstr("obj/D1.txt:3"));
  EXPECT_THAT(msg, HasSubstr("cycle"));
}

TEST(BadInput, ObjectCopyOfMissingObject) {
  test::TempScene s;
  goodScene(s);
  s.write("obj/D1.txt", "2\n+ 1 1\nO 7 1\nNULL\n");
  const std::string msg = modelError(s);
  EXPECT_THAT(msg, HasSubstr("obj/D1.txt:3: O entry source object"));
  EXPECT_THAT(msg, HasSubstr("found object 7, which does not exist"));
}

TEST(BadInput, MapDimensions) {
  test::TempScene s;
  goodScene(s);
  s.write("map/m.txt", "1\n0 3\n");
  EXPECT_THAT(modelError(s),
              HasSubstr("map/m.txt:2: uScale vScale: expected two sizes > 0, found 0 3"));
  s.write("map/m.txt", "1\n200 200\n");
  EXPECT_THAT(modelError(s), HasSubstr("uScale*vScale <= 32767"));
  s.write("map/m.txt", "1\n2 1\n0.1 0.2\n0.3 0.4\n0.5\n");
  EXPECT_THAT(modelError(s),
              HasSubstr("B texel 1 (u 1, v 0): expected a number, found end of file"));
}

TEST(BadInput, TruncatedBinaryFiles) {
  // A graph file cut inside its header, and an object file cut inside its
  // header (4 + 5 doubles = 44 bytes in, the 6th hue double is tT): both name
  // the byte offset and the field being read.
  try {
    graphFileFromBytes(std::vector<std::uint8_t>{1, 0, 5}, "graph_scr");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()),
                HasSubstr("graph_scr (byte 2): numPixAcross: expected 2 more byte(s)"));
  }
  try {
    objFileFromBytes(std::vector<std::uint8_t>(50, 0), "O1");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("O1 (byte 44): hue.tT: expected 8 more byte(s)"));
  }
}

TEST(BadInput, SizesThatAreNotWholeRecords) {
  EXPECT_THROW(
      {
        try {
          primFileFromBytes(std::vector<std::uint8_t>(300, 0), "PrimFile");
        } catch (const InputError& e) {
          EXPECT_THAT(std::string(e.what()), HasSubstr("1 records and 9 extra bytes"));
          throw;
        }
      },
      InputError);
  EXPECT_THROW(objFileFromBytes(std::vector<std::uint8_t>(76 + 5, 0), "O1"), InputError);
  EXPECT_THROW(objListFromBytes(std::vector<std::uint8_t>(3, 0), "List"), InputError);
  std::vector<std::uint8_t> map = {1, 0, 2, 0};
  map.resize(4 + 8, 0);  // header says 1 x 2 = 2 doubles, file has 1
  EXPECT_THROW(mapFileFromBytes(map, "Map1_R.map"), InputError);
  std::vector<std::uint8_t> graph = {1, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0};  // 5 pixel bytes
  try {
    graphFileFromBytes(graph, "graph_scr");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()),
                HasSubstr("4 pixels (2 x 2, the listing's inclusive loops) or 1 pixels"));
  }
  std::vector<std::uint8_t> objHeader(76, 0);
  objHeader[0] = 2;  // numEntries 2, but no records follow
  EXPECT_THROW(objFileFromBytes(objHeader, "O1"), InputError);
}

TEST(BadInput, FailedModelLeavesPreviousDatabasesUntouched) {
  test::TempScene s;
  goodScene(s);
  writeModel(SceneDir(s.path()), buildModel(SceneDir(s.path())));
  const auto prims = s.read("prim/PrimFile"), obj = s.read("obj/O1"), list = s.read("obj/List");
  const auto map = s.read("map/Map1_R.map");
  // Change the scene so that it would produce different databases, but break
  // the last input read (the map).
  s.write("prim/B1.txt", "B\n7 7 7\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  s.write("map/m.txt", "1\n2 1\n0.1 oops\n");
  EXPECT_THAT(modelError(s), HasSubstr("map/m.txt:3"));
  EXPECT_EQ(s.read("prim/PrimFile"), prims);
  EXPECT_EQ(s.read("obj/O1"), obj);
  EXPECT_EQ(s.read("obj/List"), list);
  EXPECT_EQ(s.read("map/Map1_R.map"), map);
  for (const auto& e : std::filesystem::recursive_directory_iterator(s.path()))
    EXPECT_EQ(e.path().string().find("prime-tmp"), std::string::npos) << e.path();
}

TEST(BadInput, NamesCannotLeaveTheSceneDirectory) {
  test::TempScene s;
  goodScene(s);
  s.write("Model.txt", "AddMap ../../etc/passwd\n");
  EXPECT_THAT(modelError(s), HasSubstr("Model.txt:1: file name: expected a plain file name"));
  s.write("Model.txt", "AddObj /tmp/d1.txt\n");
  EXPECT_THAT(modelError(s), HasSubstr("found \"/tmp/d1.txt\""));
  s.write("Model.txt", "AddObj d1.txt\nCopyObj O1 ../O2 c.txt\n");
  EXPECT_THAT(modelError(s), HasSubstr("found \"../O2\""));
  s.write("Model.txt", "AddObj d1.txt\nAddMap link.txt\n");
  std::filesystem::create_symlink(s.path("map/m.txt"), s.path("map/link.txt"));
  EXPECT_THAT(modelError(s), HasSubstr("is a symbolic link"));
}

TEST(BadInput, ModelTxtItself) {
  test::TempScene s;
  goodScene(s);
  s.write("Model.txt", "AddObj d1.txt\nAddToObjList\n");
  EXPECT_THAT(modelError(s), HasSubstr("Model.txt:2: AddToObjList arguments: expected 1"));
  s.write("Model.txt", "AddObject d1.txt\n");
  EXPECT_THAT(modelError(s), HasSubstr("found \"AddObject\""));
  s.write("Model.txt", "AddObj d1.txt\nAddToObjList 2\n");
  EXPECT_THAT(modelError(s), HasSubstr("found 2 (no obj/O2)"));
}

TEST(BadInput, IntegerOutOfTurboCRange) {
  test::TempScene s;
  goodScene(s);
  s.write("prim/S1.txt", "S\n60 60 60\n50 50 0\n0 0 0\n0 0 0\n1 40000\n0\n");
  EXPECT_THAT(modelError(s), HasSubstr("16-bit int"));
}

TEST(BadInput, SingularTransform) {
  test::TempScene s;
  goodScene(s);
  s.write("prim/S1.txt", "S\n60 0 60\n50 50 0\n0 0 0\n0 0 0\n1 1\n0\n");
  EXPECT_THAT(modelError(s),
              HasSubstr("prim/S1.txt: transformation: expected an invertible matrix"));
  EXPECT_THAT(modelError(s), HasSubstr("a zero scale factor"));
}

// M12: a scale too large for a double overflows the matrix to infinity; the
// message says so instead of blaming a zero scale (issue 17). 1e200 * 1e200
// overflows in Scale's products; the text parser accepts each number.
TEST(BadInput, OverflowingTransformIsNotBlamedOnAZeroScale) {
  test::TempScene s;
  goodScene(s);
  s.write("prim/S1.txt", "S\n1e200 1e200 1e200\n1e300 50 0\n0 0 0\n1e200 1e200 1e200\n1 1\n0\n");
  const std::string msg = modelError(s);
  EXPECT_THAT(msg, HasSubstr("prim/S1.txt: transformation: expected a matrix of finite numbers"));
  EXPECT_THAT(msg, HasSubstr("overflowed to"));
  EXPECT_THAT(msg, Not(HasSubstr("zero scale")));
}

}  // namespace
}  // namespace prime::io
