// The options every Malone command shares: how the scene is read and traced.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "src/cli/camera_flags.h"
#include "src/malone/render.h"
#include "src/malone/scene.h"

namespace prime::cli::malone {

struct MaloneOptions {
  std::string file;
  bool comments = false;
  std::string debug;             // depth | colour | normal
  std::vector<std::string> off;  // --no ambient,diffuse,...
  prime::malone::TraceSettings trace;
  int threads = 0;     // trace's shared --threads
  CameraFlags camera;  // --eye --look-at --up --fov --size --camera: replace the viewer's
  std::optional<FreeCameraSettings> applied;  // the camera they made (loadMalone)
};

void addMaloneOptions(CLI::App* cmd, MaloneOptions& o);
// Reads and builds the scene, applies --debug and --no to the settings and
// the camera flags to the viewer.
// With `timings`, the seconds spent reading the file and building the scene.
struct LoadTimings {
  double read = 0, build = 0;
};
prime::malone::Scene loadMalone(MaloneOptions& o, LoadTimings* timings = nullptr);

}  // namespace prime::cli::malone
