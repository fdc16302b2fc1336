// M21: a CGL scene file reads the same with LF, CR LF or CR-only line breaks.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "legacy_io/cgl/scene_file.h"

namespace prime::cgl {
namespace {

TEST(CglLineBreaks, ASceneReadsTheSameWithCrLfAndCr) {
  std::ifstream in(std::string(CGL_SCENES) + "/ball.cgl", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const SceneFile lf = readScene(ss.str(), "f.cgl");
  ASSERT_FALSE(lf.nodes.empty());
  for (const char* nl : {"\r\n", "\r"}) {
    std::string text;
    for (char c : ss.str()) text += c == '\n' ? nl : std::string(1, c);
    const SceneFile other = readScene(text, "f.cgl");
    EXPECT_EQ(other.nodes.size(), lf.nodes.size());
    EXPECT_EQ(other.vertices.size(), lf.vertices.size());
    EXPECT_EQ(other.surfaces.size(), lf.surfaces.size());
    EXPECT_EQ(other.lights.size(), lf.lights.size());
  }
}

}  // namespace
}  // namespace prime::cgl
