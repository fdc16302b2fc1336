// readInputFile: the one way every system reads an input file. Anything that
// is not a regular file is refused by type (a FIFO would block forever, a
// device such as /dev/zero would never end), and a file over its format's cap
// is refused before it is read.
#include "legacy_io/common/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>

#include "legacy_io/common/bytes.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/text_reader.h"
#include "tests/support/error_message.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace prime::io {
namespace {

using test::TempDir;

using test::messageOf;

TEST(InputFile, ReadsARegularFileWhole) {
  TempDir dir;
  std::ofstream(dir / "a.txt") << "hello\nworld\n";
  EXPECT_EQ(readInputText(dir / "a.txt"), "hello\nworld\n");
  const auto bytes = readFileBytes(dir / "a.txt");
  EXPECT_EQ(bytes.size(), 12u);
  std::ofstream(dir / "empty");
  EXPECT_EQ(readInputText(dir / "empty"), "");
}

TEST(InputFile, AMissingFileIsNamed) {
  TempDir dir;
  InputFileOptions o;
  o.what = "a CGL scene file";
  const std::string m = messageOf([&] { readInputText(dir / "nope.cgl", o); });
  EXPECT_NE(m.find("nope.cgl"), std::string::npos) << m;
  EXPECT_NE(m.find("no such file (expected a CGL scene file)"), std::string::npos) << m;
}

TEST(InputFile, ADirectoryIsRefusedAsOne) {
  TempDir dir;
  fs::create_directories(dir / "sub");
  const std::string m = messageOf([&] { readFileBytes(dir / "sub"); });
  EXPECT_NE(m.find("is a directory, not an input file"), std::string::npos) << m;
}

// Before this reader a FIFO blocked `prime` forever (issue: nothing crashes).
TEST(InputFile, AFifoIsRefusedAtOnceInsteadOfBlocking) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const std::string m = messageOf([&] { readFileBytes(dir / "fifo"); });
  EXPECT_NE(m.find("is a FIFO (named pipe), not an input file"), std::string::npos) << m;
  const std::string t = messageOf([&] { TextReader::open(dir / "fifo", "scene/Model.txt"); });
  EXPECT_NE(t.find("scene/Model.txt: is a FIFO (named pipe), not a text input"), std::string::npos)
      << t;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

// Before this reader /dev/zero was read until memory ran out.
TEST(InputFile, ADeviceIsRefused) {
  if (!fs::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
  const std::string m = messageOf([&] { readFileBytes("/dev/zero"); });
  EXPECT_NE(m.find("/dev/zero: is a character device, not an input file"), std::string::npos) << m;
}

TEST(InputFile, AFileOverItsFormatsCapIsRefusedBeforeItIsRead) {
  TempDir dir;
  {
    std::ofstream f(dir / "big.rle", std::ios::binary);
    f << std::string(1000, 'x');
  }
  InputFileOptions o;
  o.maxBytes = 999;
  o.what = "a CGL RLE picture";
  const std::string m = messageOf([&] { readInputFile(dir / "big.rle", o); });
  EXPECT_NE(m.find("big.rle (byte 999): file size: expected at most 999 bytes for a CGL RLE "
                   "picture, found 1000 bytes"),
            std::string::npos)
      << m;
  o.maxBytes = 1000;
  EXPECT_EQ(readInputFile(dir / "big.rle", o).size(), 1000u);
  // A sparse file of 300 MiB: over the default cap, refused without reading it.
  ASSERT_EQ(::truncate((dir / "big.rle").c_str(), 300ll << 20), 0);
  const std::string d = messageOf([&] { readFileBytes(dir / "big.rle"); });
  EXPECT_NE(d.find("found 314572800 bytes"), std::string::npos) << d;
}

TEST(InputFile, TheDisplayNameIsUsedInMessages) {
  TempDir dir;
  InputFileOptions o;
  o.display = "scene/obj/O1";
  const std::string m = messageOf([&] { readInputFile(dir / "O1", o); });
  EXPECT_EQ(m.rfind("scene/obj/O1: no such file", 0), 0u) << m;
}

// A ^Z in the middle of a text (a binary COPY A+B): the text ends there, and
// an error that found its end says where the ^Z is and what it left unread.
// ^Z padding at the end (what the editors of the time wrote) says nothing.
TEST(InputFile, AnEndOfFileAtAMidTextCtrlZSaysWhy) {
  TempDir dir;
  const std::string cut = (dir / "cut.txt").string(), padded = (dir / "padded.txt").string();
  std::ofstream(cut, std::ios::binary) << "1 2\n\x1a"
                                       << "3 4\n";
  std::ofstream(padded, std::ios::binary) << "1 2\n\x1a\x1a\x1a";
  EXPECT_EQ(readInputText(cut), "1 2\n");
  EXPECT_EQ(readInputText(padded), "1 2\n");
  const auto atEnd = [](const std::string& file) {
    return InputError({file, 2, std::nullopt}, "z", "a number", "end of file");
  };
  EXPECT_EQ(dosEofNote(atEnd(cut)),
            "the text ends at the ^Z (0x1A) at byte 4, as DOS's text mode read it; 4 bytes after "
            "it are not read (M41)");
  EXPECT_EQ(dosEofNote(atEnd(padded)), "");
  EXPECT_EQ(dosEofNote(InputError({cut, 1, std::nullopt}, "x", "a number", "\"abc\"")), "");
}

}  // namespace
}  // namespace prime::io
