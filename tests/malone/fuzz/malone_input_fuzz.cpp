// Malone's reader (legacy_io/malone/input.h) and scene builder
// (src/malone/scene.h) on any bytes: they return, or throw
// prime::io::InputError naming the file and a line (and column and token).
// What they return keeps its promises: every primitive has a surface, every
// number is finite, the viewer's resolution is in range; one pixel of a small
// scene traces to a colour without trapping.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "legacy_io/common/error.h"
#include "legacy_io/malone/input.h"
#include "src/malone/scene.h"
#include "src/malone/tracer.h"

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
  if (size > 200000) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  malone::ReadOptions options;
  options.comments = size % 2 == 0;  // both readings
  options.maxResolution = 64;        // keep the pixel below cheap
  try {
    const malone::SceneFile file = malone::readScene(text, "fuzz.mal", options);
    check(file.viewers >= 1, "a scene without a viewer was accepted");
    for (const auto& p : file.primitives) {
      check(p.surface >= 0 && p.surface < static_cast<int>(file.surfaces.size()),
            "a primitive without a surface");
      for (double v : p.numbers) check(std::isfinite(v), "a non-finite number");
    }
    const malone::Scene scene = malone::buildScene(file, "fuzz.mal");
    check(scene.viewer.xRes >= 1 && scene.viewer.xRes <= 64, "resolution out of range");
    for (const auto& l : scene.lights) check(finite(l.position), "a non-finite light");
    if (scene.primitives.size() * (scene.lights.size() + 1) < 2000) {
      malone::TraceSettings settings;
      settings.maxDepth = 4;
      const malone::Tracer tracer(scene, settings);
      malone::TraceStats stats;
      (void)tracer.pixel(scene.viewer.xRes / 2, scene.viewer.yRes / 2, stats);
    }
  } catch (const io::InputError& e) {
    check(!e.where().file.empty(), "an error without a file");
    check(e.where().line.has_value(), "an error without a line");
  }
  return 0;
}
