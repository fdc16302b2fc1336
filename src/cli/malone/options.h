// The options every Malone command shares: how the scene is read and traced.
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
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

// What a whole picture may take (trace and bench hold all of it; probe one
// pixel, walk the window's): a viewer of 16384 x 16384 asked for 6.2 GB
// before the first row. Throws io::InputError naming the viewer (or --size).
inline constexpr std::uint64_t kPictureBytesPerPixel = 31;
inline constexpr std::uint64_t kMaxPictureBytes = std::uint64_t{4} << 30;
void checkPictureMemory(const prime::malone::Scene& scene, const MaloneOptions& o);

}  // namespace prime::cli::malone
