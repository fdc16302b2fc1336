// Supersampling and adaptive tree-depth control are off in the 1991 profile
// and, when on, behave as specified.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "legacy_io/prime/graph_file.h"
#include "tests/support/temp_scene.h"

namespace {

namespace fs = std::filesystem;

struct Scene {
  prime::test::TempScene s;
  Scene() {
    fs::copy(fs::path(PRIME_TEST_DATA) / "sphere", s.path(),
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    EXPECT_EQ(std::system((std::string(PRIME_EXE) + " model -q " + s.path().string()).c_str()), 0);
  }
  prime::io::GraphFile trace(const std::string& flags, const std::string& name) {
    const std::string out = (s.path() / name).string();
    EXPECT_EQ(std::system((std::string(PRIME_EXE) + " trace -q " + s.path().string() + " --out " +
                           out + " " + flags)
                              .c_str()),
              0);
    return prime::io::readGraphFile(out);
  }
};

TEST(Sampling, OneSampleAndZeroWeightAreTheListing) {
  Scene sc;
  const auto base = sc.trace("", "base");
  EXPECT_EQ(sc.trace("--samples 1", "one").pixels, base.pixels);
  EXPECT_EQ(sc.trace("--min-weight 0", "w0").pixels, base.pixels);
}

TEST(Sampling, SupersamplingOnlyChangesPixelsOnTheSilhouette) {
  // The lone sphere is one flat colour (index 68, see replay_sphere_test):
  // averaging 3x3 rays can only change pixels whose footprint straddles its
  // edge, where colours mix, and the centre stays 68.
  Scene sc;
  const auto base = sc.trace("", "base");
  for (const char* flags : {"--samples 3", "--adaptive 0.01"}) {
    const auto g = sc.trace(flags, "ss");
    long changed = 0;
    for (std::size_t i = 0; i < g.pixels.size(); ++i) changed += g.pixels[i] != base.pixels[i];
    EXPECT_GT(changed, 50) << flags;    // the edge is anti-aliased
    EXPECT_LT(changed, 2500) << flags;  // a perimeter of ~1,400 pixels, nothing more
    EXPECT_EQ(g.at(174, 384), 68) << flags;
    EXPECT_EQ(g.at(0, 0), 1) << flags;
  }
}

}  // namespace
