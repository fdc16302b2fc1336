#include "src/cli/malone/options.h"

#include <chrono>

#include "legacy_io/common/error.h"
#include "legacy_io/malone/input.h"

namespace prime::cli::malone {

void addMaloneOptions(CLI::App* cmd, MaloneOptions& o) {
  cmd->add_option("SCENE", o.file, "Malone scene file (a stream of numbers)")->required();
  cmd->add_flag("--comments", o.comments,
                "Extension, not the original: '#' starts a comment to the end of the line");
  cmd->add_option("--max-depth", o.trace.maxDepth,
                  "Deepest ray traced; the primary ray has depth 1 (default 7)")
      ->check(CLI::Range(1, 64));
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

}  // namespace prime::cli::malone
