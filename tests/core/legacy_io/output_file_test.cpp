// Every output is written through a fresh temporary and renamed into place
// (legacy_io/common/output_file.h). The class of defects this guards against
// (issue 17, "Writing files"): temporaries at predictable names followed
// planted symbolic links (write-anywhere in a downloaded scene directory),
// and outputs that were device nodes or FIFOs were replaced by regular files.
#include "legacy_io/common/output_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "legacy_io/common/bytes.h"
#include "legacy_io/common/error.h"
#include "tests/support/temp_dir.h"

namespace prime::io {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(OutputFile, PlantedLinksAtTheOldTemporaryNamesAreNeverFollowed) {
  TempDir dir;
  const fs::path victim = dir / "victim.txt", target = dir / "out.bin";
  std::ofstream(victim) << "precious";
  // The names the writers used before: <out>.prime-tmp, <out>.tmp.<pid>, <out>.tmp.
  for (const std::string& suffix : std::vector<std::string>{
           ".prime-tmp", ".tmp." + std::to_string(::getpid()), ".tmp", ".prime-tmp.XXXXXX"})
    fs::create_symlink(victim, target.string() + suffix);
  const std::vector<std::uint8_t> bytes{1, 2, 3, 4};
  writeFileAtomically(target.string(), bytes);
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_EQ(contents(target), std::string("\x01\x02\x03\x04"));
  EXPECT_EQ(entries(dir.path()), 1 + 1 + 4);  // victim, out.bin, the four links: no temporary left
}

TEST(OutputFile, EachTemporaryHasAFreshName) {
  TempDir dir;
  OutputFile a((dir / "x").string()), b((dir / "x").string());
  EXPECT_NE(a.temporary(), b.temporary());
  EXPECT_EQ(a.temporary().rfind((dir / "x").string() + ".prime-tmp.", 0), 0u);
}

TEST(OutputFile, AFifoIsRefusedNotOpenedNorReplaced) {
  TempDir dir;
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    writeFileAtomically(fifo.string(), std::vector<std::uint8_t>{1});
    FAIL() << "a FIFO was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("it is a FIFO"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(fifo.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(entries(dir.path()), 1);
}

TEST(OutputFile, ADeviceNodeIsNeverReplaced) {
  // /dev/null itself cannot be used (its directory is not ours to write in);
  // the check is the same for any character device.
  try {
    checkOutputPath("/dev/null");
    FAIL() << "/dev/null accepted as an output";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a character device"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputFile, ADirectoryOrAMissingDirectoryIsNamed) {
  TempDir dir;
  fs::create_directories(dir / "sub");
  try {
    writeFileAtomically((dir / "sub").string(), std::vector<std::uint8_t>{1});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("it is a directory"), std::string::npos) << e.what();
  }
  try {
    writeFileAtomically((dir / "no" / "x.bin").string(), std::vector<std::uint8_t>{1});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("the directory " + (dir / "no").string() + " does not exist"),
        std::string::npos)
        << e.what();
  }
}

TEST(OutputFile, AnUncommittedTemporaryIsRemovedAndTheOldFileKept) {
  TempDir dir;
  const fs::path target = dir / "graph";
  std::ofstream(target) << "old";
  {
    OutputFile out(target.string());
    out.write(std::string_view("new, but never committed"));
    EXPECT_TRUE(fs::exists(out.temporary()));
  }  // an exception or an abort would leave here the same way
  EXPECT_EQ(contents(target), "old");
  EXPECT_EQ(entries(dir.path()), 1);
}

// Issue 37: export-pov wrote its texture PNGs one by one, then the scene: a
// failure at the scene (a full disk, an unwritable name) left the textures.
TEST(OutputSet, AFailureAtAnyFileLeavesNoneOfThem) {
  TempDir dir;
  {
    OutputSet files;
    files.add((dir / "scene-texture1.png").string()).write(std::string_view("texels"));
    EXPECT_THROW(files.add((dir / "no such dir" / "scene.pov").string()), InputError);
  }  // the exception left the set uncommitted
  EXPECT_EQ(entries(dir.path()), 0);
  OutputSet files;
  files.add((dir / "a").string()).write(std::string_view("A"));
  files.add((dir / "b").string()).write(std::string_view("B"));
  EXPECT_EQ(entries(dir.path()), 2);  // the two temporaries
  files.commit();
  EXPECT_EQ(contents(dir / "a"), "A");
  EXPECT_EQ(contents(dir / "b"), "B");
  EXPECT_EQ(entries(dir.path()), 2);
}

TEST(OutputFile, ALinkAtTheTargetIsReplacedNotWrittenThrough) {
  TempDir dir;
  const fs::path victim = dir / "victim.txt", target = dir / "out.png";
  std::ofstream(victim) << "precious";
  fs::create_symlink(victim, target);
  writeFileAtomically(target.string(), std::vector<std::uint8_t>{'n', 'e', 'w'});
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(target));
  EXPECT_EQ(contents(target), "new");
}

TEST(OutputFile, MegabytesWrittenBehindArriveWholeAndOnlyAtCommit) {
  // Past every whole MiB the written bytes are handed to the disk early
  // (write-behind); the file is still the temporary until commit, and its
  // bytes are exactly those written, in order, across the MiB boundaries.
  TempDir dir;
  const fs::path target = dir / "big";
  std::string expected;
  {
    OutputFile out(target.string());
    for (int piece = 0; expected.size() < 3u * 1024 * 1024 + 12345; ++piece) {
      std::string s(static_cast<std::size_t>(1000 + piece * 37 % 70000), '\0');
      for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<char>('a' + (piece + i) % 26);
      out.write(std::string_view(s));
      expected += s;
    }
    EXPECT_FALSE(fs::exists(target));
    EXPECT_GE(fs::file_size(out.temporary()), 3u * 1024 * 1024);  // handed over, not yet renamed
    out.commit();
  }
  EXPECT_EQ(contents(target), expected);
  EXPECT_EQ(entries(dir.path()), 1);
}

TEST(OutputFile, AnOutputKeepsTheUsualPermissions) {
  TempDir dir;
  const mode_t mask = ::umask(022);
  writeFileAtomically((dir / "f").string(), std::vector<std::uint8_t>{1});
  ::umask(mask);
  struct stat st {};
  ASSERT_EQ(::stat((dir / "f").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

}  // namespace
}  // namespace prime::io
