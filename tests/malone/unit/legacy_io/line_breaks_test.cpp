// M21: a scene file reads the same with LF, CR LF or CR-only line breaks, and
// an error names the same line in all three.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "legacy_io/common/error.h"
#include "legacy_io/malone/input.h"

namespace prime::malone {
namespace {

std::string withBreaks(const std::string& lf, const std::string& nl) {
  std::string out;
  for (char c : lf) out += c == '\n' ? nl : std::string(1, c);
  return out;
}

TEST(MaloneLineBreaks, EveryDocumentSceneReadsTheSameWithCrLfAndCr) {
  std::ifstream in(std::string(MALONE_SCENES) + "/doc-annulus.mal", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const SceneFile lf = readScene(ss.str(), "a.mal");
  ASSERT_FALSE(lf.primitives.empty());
  for (const char* nl : {"\r\n", "\r"}) {
    const SceneFile other = readScene(withBreaks(ss.str(), nl), "a.mal");
    EXPECT_EQ(other.primitives.size(), lf.primitives.size());
    EXPECT_EQ(other.surfaces.size(), lf.surfaces.size());
    EXPECT_EQ(other.lights.size(), lf.lights.size());
  }
}

TEST(MaloneLineBreaks, AnErrorNamesTheSameLine) {
  // Line 3 holds a word where a number must be, in every spelling.
  std::string where[3];
  int k = 0;
  for (const char* nl : {"\n", "\r\n", "\r"}) {
    try {
      readScene(withBreaks("1\n0 0 0 1\nx\n", nl), "b.mal");
    } catch (const io::InputError& e) {
      where[k] = e.what();
    }
    ++k;
  }
  EXPECT_NE(where[0].find("b.mal:3"), std::string::npos) << where[0];
  EXPECT_EQ(where[1], where[0]);
  EXPECT_EQ(where[2], where[0]);
}

}  // namespace
}  // namespace prime::malone
