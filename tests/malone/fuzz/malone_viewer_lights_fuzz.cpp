// Malone's viewer and light records (102, and 101, 103, 104, 105 of
// legacy_io/malone/input.h) as the scene builder turns them into a camera and
// light samples (src/malone/scene.h), on any bytes, with the options the
// command line uses (X_RES and Y_RES up to 16384, sampled lights up to 100000
// samples each): readScene and buildScene return, or throw
// prime::io::InputError naming the file and a line. malone_input fuzzes the
// whole language at small resolutions and traces a pixel; this target's seeds
// and dictionary dwell on the records that size what a render allocates.
// What the builder returns keeps its promises: one light sample per point
// light and `samples` per sampled light, each finite and carrying rgb /
// samples; a finite viewer whose look-at is not its eye, its resolution as
// read and in range.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "legacy_io/common/error.h"
#include "legacy_io/malone/input.h"
#include "src/malone/scene.h"

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}
void check(bool ok, const char* what) {
  if (!ok) fail(what);
}
bool finite(const prime::Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace prime;
  using malone::ObjectId;
  if (size > 200000) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  malone::ReadOptions options;  // the command line's: maxResolution 16384
  options.comments = size % 2 == 1;
  try {
    const malone::SceneFile file = malone::readScene(text, "fuzz.mal", options);
    const malone::Scene scene = malone::buildScene(file, "fuzz.mal");
    const auto& v = scene.viewer;
    check(v.xRes == file.viewer.xRes && v.yRes == file.viewer.yRes, "resolution not as read");
    check(v.xRes >= 1 && v.xRes <= options.maxResolution && v.yRes >= 1 &&
              v.yRes <= options.maxResolution,
          "resolution out of range");
    check(finite(v.eye) && finite(v.lookAt) && finite(v.x) && finite(v.y), "a non-finite viewer");
    check(!(v.eye == v.lookAt), "a viewer looking at its own eye");
    check(scene.lightCount == static_cast<int>(file.lights.size()), "light count");
    std::size_t expected = 0, at = 0;
    for (const auto& l : file.lights) {
      const int n = l.id == ObjectId::SampledLight ? l.samples : 1;
      check(n >= 1 && n <= 100000, "samples out of range");
      expected += static_cast<std::size_t>(n);
      check(expected <= scene.lights.size(), "fewer light samples than the file asks for");
      for (int k = 0; k < n; ++k, ++at) {
        const auto& s = scene.lights[at];
        check(finite(s.position), "a non-finite light sample");
        check(s.inverseSquare == (l.id != ObjectId::PointLightNoFalloff), "r^-2 law not as read");
        for (int c = 0; c < 3; ++c)
          check(s.rgb[c] == l.rgb[c] / n, "a light sample's rgb is not rgb / samples");
      }
    }
    check(expected == scene.lights.size(), "more light samples than the file asks for");
  } catch (const io::InputError& e) {
    check(e.where().file == "fuzz.mal", "an error without the file");
    check(e.where().line.has_value(), "an error without a line");
    check(std::string(e.what()).rfind("fuzz.mal:", 0) == 0, "a message without file:line");
  }
  return 0;
}
