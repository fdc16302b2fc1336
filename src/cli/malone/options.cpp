#include "src/cli/malone/options.h"

#include <chrono>
#include <cstdint>
#include <string>

#include "legacy_io/common/error.h"
#include "legacy_io/malone/input.h"

namespace prime::cli::malone {

void addMaloneOptions(CLI::App* cmd, MaloneOptions& o) {
  cmd->add_option("SCENE", o.file, "Malone scene file (a stream of numbers)")->required();
  cmd->add_flag("--comments", o.comments,
                "Extension, not the original: '#' starts a comment to the end of the line");
  // Up to 10,000: the recursion takes about 490 bytes a level of a thread's
  // 8 MiB stack (17,000 levels overflow it), and MIN_WEIGHT cuts every path
  // sooner unless a surface reflects 99.9 % or more (MAL-D8).
  cmd->add_option("--max-depth", o.trace.maxDepth,
                  "Deepest ray traced, 1..10000; the primary ray has depth 1 (default 7; "
                  "--min-weight also ends paths)")
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--min-weight", o.trace.minWeight,
                  "MIN_WEIGHT: rays weighing less are not spawned (default 0.01/256)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--eps", o.trace.eps,
                  "Hits are accepted for eps < t < length (the trapped-ray rule; default 1e-6)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--debug", o.debug,
                  "A debug render of section 3.3.1: depth (grey 1/r), colour (K_d), normal (|n.i|)")
      ->check(CLI::IsMember({"depth", "colour", "color", "normal"}));
  cmd->add_option("--no", o.off,
                  "Turn off parts of the model: ambient,diffuse,specular,shadows,reflection,"
                  "refraction")
      ->delimiter(',')
      ->check(
          CLI::IsMember({"ambient", "diffuse", "specular", "shadows", "reflection", "refraction"}));
  cmd->add_flag("--linear-search", o.trace.linearSearch,
                "Test every primitive for every ray, as the original did (same pixels, slower)");
  addCameraFlags(cmd, o.camera, "the scene's viewer, 102");
}

prime::malone::Scene loadMalone(MaloneOptions& o, LoadTimings* timings) {
  using prime::malone::TraceSettings;
  for (const auto& part : o.off) {
    if (part == "ambient") o.trace.ambient = false;
    if (part == "diffuse") o.trace.diffuse = false;
    if (part == "specular") o.trace.specular = false;
    if (part == "shadows") o.trace.shadows = false;
    if (part == "reflection") o.trace.reflection = false;
    if (part == "refraction") o.trace.refraction = false;
  }
  if (o.debug == "depth") o.trace.debug = TraceSettings::Debug::Depth;
  if (o.debug == "colour" || o.debug == "color") o.trace.debug = TraceSettings::Debug::Colour;
  if (o.debug == "normal") o.trace.debug = TraceSettings::Debug::Normal;
  prime::malone::ReadOptions read;
  read.comments = o.comments;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto file = prime::malone::readSceneFile(o.file, read);
  const auto readDone = Clock::now();
  auto scene = prime::malone::buildScene(file, o.file);
  if (o.camera.given()) {
    o.applied = applyCameraFlags(withCameraFile(o.camera), prime::malone::freeCamera(scene.viewer));
    scene.viewer = prime::malone::viewerOf(*o.applied);
  }
  if (timings) {
    timings->read = std::chrono::duration<double>(readDone - start).count();
    timings->build = std::chrono::duration<double>(Clock::now() - readDone).count();
  }
  return scene;
}

void checkPictureMemory(const prime::malone::Scene& scene, const MaloneOptions& o) {
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(scene.viewer.xRes) * static_cast<std::uint64_t>(scene.viewer.yRes);
  if (pixels * kPictureBytesPerPixel <= kMaxPictureBytes) return;
  throw io::InputError(
      {o.file, std::nullopt, std::nullopt},
      o.applied ? "--size (the camera flags)" : "viewer, xres and yres",
      "a picture that fits in " + std::to_string(kMaxPictureBytes >> 30) + " GiB (" +
          std::to_string(kPictureBytesPerPixel) +
          " bytes a pixel: the render's three doubles, the window's and the PNG's bytes; at most " +
          std::to_string(kMaxPictureBytes / kPictureBytesPerPixel) + " pixels)",
      std::to_string(scene.viewer.xRes) + " x " + std::to_string(scene.viewer.yRes) + " = " +
          std::to_string(pixels) + " pixels, " +
          std::to_string(pixels * kPictureBytesPerPixel >> 20) + " MiB");
}

}  // namespace prime::cli::malone
