// What fuzzing the readers found (tests/fuzz), one test per finding, each
// feeding the input that broke a reader. Each input was run through the fuzz
// target named and failed it there (crash, sanitizer report, timeout or an
// exception other than InputError); most were written by hand while reading
// the reader for its fuzz target, as libFuzzer's inputs stay far smaller.
// Every reader must return, or throw an InputError that names the place.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "legacy_io/prime/dump.h"
#include "legacy_io/prime/graph_file.h"
#include "legacy_io/prime/model_builder.h"
#include "legacy_io/prime/text_inputs.h"
#include "tests/support/temp_scene.h"

namespace prime::io {
namespace {

using ::testing::HasSubstr;

std::vector<std::uint8_t> objFileBytes(const std::vector<ObjRecord>& entries) {
  ObjFile f;
  f.header.numEntries = static_cast<std::int16_t>(entries.size());
  f.entries = entries;
  return toBytes(f);
}

ObjRecord entry(char op, int l, int r) {
  ObjRecord o;
  o.opCode = {op, 0, 0, 0};
  o.l = static_cast<std::int16_t>(l);
  o.r = static_cast<std::int16_t>(r);
  return o;
}

// A D file whose tree is a chain as deep as the format allows: entry i is
// "+ i+1 last" and the last entry is a leaf, 32767 entries in all.
std::string deepChainDFile(int last) {
  std::string text = std::to_string(last + 1) + "\n";
  for (int i = 0; i < last; ++i)
    text += "+ " + std::to_string(i + 1) + " " + std::to_string(last) + "\n";
  return text + "S 1\nNULL\n";
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

// Found (text_inputs_fuzz, ASan stack-overflow): parseObjText's cycle check recursed once per
// level (std::function frames), so a legal 32767-entry chain overflowed the stack under ASan.
// Fixed: the check walks the tree with an explicit stack.
TEST(FuzzRegressions, ObjTextDeepChainDoesNotOverflowTheStack) {
  TextReader in(deepChainDFile(32766), "obj/D1.txt");
  const ObjText o = parseObjText(in);
  EXPECT_EQ(o.entries.size(), 32767u);

  // The same chain closed into a cycle at the bottom is still found, with the
  // line of the entry that leads back.
  std::string cyclic = deepChainDFile(32766);
  const std::string lastOp = "+ 32766 32766\n";
  cyclic.replace(cyclic.find(lastOp), lastOp.size(), "+ 0 32766\n");
  TextReader bad(cyclic, "obj/D1.txt");
  EXPECT_EQ(
      errorOf([&] { parseObjText(bad); }),
      "obj/D1.txt:32767: child index: expected a tree (no entry may contain itself), found entry "
      "32765 leads back to entry 0 (a cycle)");
}

// Found (dump_fuzz, timeout): `prime dump` of an O file whose entries share subtrees (entry i is
// "+ i+1 i+1") printed every path, 2^40 lines for this 405-byte file (a timeout). Fixed: a shared
// operator is printed once, then named.
TEST(FuzzRegressions, DumpOfSharedSubtreesIsLinear) {
  std::vector<ObjRecord> entries;
  for (int i = 0; i < 40; ++i) entries.push_back(entry('+', i + 1, i + 1));
  entries.push_back(entry('P', 0, 0));
  test::TempScene s;
  s.writeBytes("obj/O1", objFileBytes(entries));
  const auto start = std::chrono::steady_clock::now();
  const std::string text = dumpDatabase(s.path("obj/O1").string(), DatabaseKind::ObjFile);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_LT(text.size(), 20000u);
  EXPECT_THAT(text, HasSubstr("CSG tree:\n  union (+)\n    union (+)\n"));
  EXPECT_THAT(text, HasSubstr("    union (+): entry 1, shown above\n"));
}

// Found (dump_fuzz, ASan stack-overflow): the same recursion overflowed the stack on a 32767-deep
// chain (262 KB); and the indentation alone made the output quadratic. Fixed: an explicit stack,
// and past 32 levels the depth is written as a number.
TEST(FuzzRegressions, DumpOfDeepChain) {
  std::vector<ObjRecord> entries;
  const int last = 32766;
  for (int i = 0; i < last; ++i) entries.push_back(entry('+', i + 1, last));
  entries.push_back(entry('P', 0, 0));
  test::TempScene s;
  s.writeBytes("obj/O1", objFileBytes(entries));
  const std::string text = dumpDatabase(s.path("obj/O1").string(), DatabaseKind::ObjFile);
  EXPECT_LT(text.size(), 12'000'000u);
  EXPECT_THAT(text, HasSubstr("(depth 32766) prim 0\n"));
}

// A valid scene to break in one place (as in bad_input_test.cpp).
void goodCopyScene(const test::TempScene& s) {
  s.write("obj/H1.txt", "0.1 0.2 0.3 0.4 0.5 0.999 2 2 1.5\n");
  s.write("obj/D1.txt", "3\n- 1 2\nB 1\nS 1\nNULL\n");
  s.write("prim/B1.txt", "B\n100 100 100\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n");
  s.write("prim/S1.txt", "S\n60 60 60\n50 50 0\n0 0 0\n0 0 0\n1 1\n0\n");
  s.write("obj/Copy/c.txt", "1 1 1\n0 0 0\n0 0 0\n0 0 0\n");
}

// Found (model_builder_fuzz, uncaught filesystem_error): "CopyObj O1 Copy c.txt" made writeModel
// rename a file onto the obj/Copy/ folder (std::filesystem_error, not an InputError, after some
// databases were already replaced); "CopyObj O1 List c.txt" wrote the object over obj/List
// (filesystem_error again); and "CopyObj O1 D1.txt c.txt" silently replaced the text input
// obj/D1.txt with binary data. Fixed: the destination must not name one of the other files of
// obj/.
TEST(FuzzRegressions, CopyObjDestinationMustNotReplaceOtherFiles) {
  for (const std::string dest : {"Copy", "List", "D1.txt", "H1.TXT"}) {
    test::TempScene s;
    goodCopyScene(s);
    s.write("Model.txt", "AddObj d1.txt\nAddToObjList 1\nCopyObj O1 " + dest + " c.txt\n");
    const std::string msg =
        errorOf([&] { writeModel(SceneDir(s.path()), buildModel(SceneDir(s.path()))); });
    EXPECT_THAT(
        msg, HasSubstr("Model.txt:3: CopyObj destination object: expected a name for a new object "
                       "file in obj/ like O4 (not List, Copy or a .txt input), found \"" +
                       dest + "\""));
    EXPECT_FALSE(s.exists("obj/List"));
    const auto d1 = s.read("obj/D1.txt");
    EXPECT_EQ(std::string(d1.begin(), d1.end()), "3\n- 1 2\nB 1\nS 1\nNULL\n");
  }
}

// Found (model_builder_fuzz, out-of-memory with 'L', --no-16bit-limit): an object of many O
// entries, each copying a big object (here 20000 entries that share one leaf), grew past the
// 32767-entry limit before the limit was checked; 32767 such entries allocate gigabytes. Fixed:
// the limit is checked before each copy, at the O entry's line.
TEST(FuzzRegressions, ObjectCopiesCheckTheEntryLimitBeforeCopying) {
  test::TempScene s;
  goodCopyScene(s);
  std::string d1 = "20000\n";
  for (int i = 0; i < 19999; ++i)
    d1 += "+ " + std::to_string(i + 1) + " " + std::to_string(i + 1) + "\n";
  s.write("obj/D1.txt", d1 + "S 1\nNULL\n");
  s.write("obj/H2.txt", "0.1 0.2 0.3 0.4 0.5 0.999 2 2 1.5\n");
  s.write("obj/D2.txt", "3\n+ 1 2\nO 1 1\nO 1 1\nNULL\n");
  s.write("prim/A1.txt", "1 1 1\n0 0 0\n0 0 0\n0 0 0\n");
  s.write("Model.txt", "AddObj d1.txt\nAddObj d2.txt\n");
  ModelOptions options;
  options.limitPrimFileTo16Bits = false;
  EXPECT_THAT(
      errorOf([&] { buildModel(SceneDir(s.path()), options); }),
      HasSubstr("obj/D2.txt:4: numEntries: expected at most 32767 entries after copying objects, "
                "found 40001 once this O entry copies the 20000 entries of object 1"));
}

// Found (model_builder_fuzz, uncaught filesystem_error): a file name longer than the file system
// allows ("AddMap aaa...a.txt", 300 bytes) made std::filesystem throw its own filesystem_error
// ("File name too long") instead of an InputError. Fixed: SceneDir refuses names longer than 255
// bytes.
TEST(FuzzRegressions, OverlongFileNameIsAnInputError) {
  test::TempScene s;
  goodCopyScene(s);
  s.write("Model.txt", "AddMap " + std::string(300, 'a') + ".txt\n");
  EXPECT_THAT(
      errorOf([&] { buildModel(SceneDir(s.path())); }),
      HasSubstr("Model.txt:1: file name: expected at most 255 bytes (the file system's NAME_MAX), "
                "found 304 bytes (\"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...\")"));
  s.write("Model.txt", "AddObj d" + std::string(300, '1') + ".txt\n");
  EXPECT_THAT(errorOf([&] { buildModel(SceneDir(s.path())); }),
              HasSubstr("Model.txt:1: file name: expected at most 255 bytes"));
}

// Found while writing text_inputs_fuzz (no crash: a wrong value): "+-5" read as -5 (the '+' was
// skipped and from_chars took the '-'); fscanf's %lf and %d stop there. One sign only.
TEST(FuzzRegressions, NumbersTakeOneSignOnly) {
  TextReader in("+-5 +-2.5 +5 -5", "light/light.txt");
  EXPECT_EQ(errorOf([&] { in.int16("number of lights"); }),
            "light/light.txt:1: number of lights: expected an integer, found \"+-5\"");
  EXPECT_EQ(errorOf([&] { in.number("ambient x"); }),
            "light/light.txt:1: ambient x: expected a number, found \"+-5\"");
  (void)in.token("skip");
  EXPECT_EQ(errorOf([&] { in.number("ambient y"); }),
            "light/light.txt:1: ambient y: expected a number, found \"+-2.5\"");
  (void)in.token("skip");
  EXPECT_EQ(in.int16("a"), 5);
  EXPECT_EQ(in.number("b"), -5.0);
}

}  // namespace
}  // namespace prime::io

namespace prime::io {
namespace {

TEST(FuzzRegressions, PartialGraphFileHeaderCannotAskForGigabytes) {
  // A 6-byte "partial" file whose header claims 32767 x 32767 pixels.
  const std::vector<std::uint8_t> bytes = {1, 0, 0xFF, 0x7F, 0xFF, 0x7F};
  try {
    graphFilePrefixFromBytes(bytes, "x.partial");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("at most 8192 x 8192 pixels"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace prime::io
