// The work-skipping of the 1991 profile (TraceOptions::skipUnneededWork)
// must not change a single byte: render a scene whose objects have kSR = 0
// (kDR = 1) and kST = 0 (kDT = 1) with and without skipping and compare.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "legacy_io/prime/turbo_c.h"
#include "tests/support/temp_scene.h"

namespace {

namespace fs = std::filesystem;

TEST(Skips, SameBytesWithAndWithoutSkipping) {
  prime::test::TempScene s;
  fs::copy(fs::path(PRIME_SCENES) / "default", s.path(),
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  s.write("obj/H1.txt", "1.0 1.0\n0.6 0.3 0.2\n0.999\n3 3\n1.0001\n");  // kSR = kST = 0
  s.write("obj/H2.txt", "0.3 1.0\n0.2 0.3 0.6\n0.999\n3 3\n1.5\n");     // kST = 0
  const std::string exe = PRIME_EXE, dir = s.path().string();
  ASSERT_EQ(std::system((exe + " model -q " + dir).c_str()), 0);
  ASSERT_EQ(std::system((exe + " trace -q --threads 2 " + dir + " --out " + dir + "/skip").c_str()),
            0);
  ASSERT_EQ(
      std::system(
          (exe + " trace -q --threads 2 --no-skip " + dir + " --out " + dir + "/all").c_str()),
      0);
  const auto a = prime::io::readFileBytes(dir + "/skip"),
             b = prime::io::readFileBytes(dir + "/all");
  ASSERT_EQ(a.size(), 6u + 350u * 769u * 2u);
  EXPECT_TRUE(a == b) << "skipping changed the image";
}

}  // namespace
