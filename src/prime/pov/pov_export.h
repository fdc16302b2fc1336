// A PRIME scene as POV-Ray 3.7 scene language (`prime export-pov`): the unit
// primitives with their row-vector matrices, the CSG trees, the texture maps
// as image files, the lights, and a perspective camera that puts the listing's
// world window on the same pixels. Useful for a modern re-render of a 1991
// scene, and for timing PRIME against POV-Ray on the same geometry
// (bench/prime/pov_compare.sh).
//
// What is exact and what is approximate (docs/prime/pov-export.md):
//   exact   geometry (the five unit primitives, their matrices, CSG), the
//           camera rays through the pixel centres, lights, ambient, and the
//           recursion limit (max_trace_level = MaxDepth + 1);
//   close   texture lookup on spheres, cylinder and cone bodies, and the
//           front (z = 0) face of boxes; pyramids and the other box faces
//           use a planar projection;
//   loose   Hall's shading model has no POV-Ray equivalent, so the finish is
//           a documented approximation of it.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "legacy_io/common/pov_text.h"
#include "palette/png_image.h"
#include "src/math/matrix.h"
#include "src/prime/render/camera.h"
#include "src/prime/scene/scene.h"
#include "src/render/rgb_image.h"

namespace prime {

struct PovExportOptions {
  CameraSettings camera;  // the listing's camera and window (prime trace's flags)
  int maxDepth = 5;       // PRIME's MaxDepth; POV-Ray's max_trace_level counts the primary ray too
  std::string imageStem = "prime";  // texture files are <imageStem>_map<n>.png
  // The thesis profile's lights (docs/prime/thesis-profile.md): lights cast
  // shadows (T2) and, with a radius > 0, are circular area lights facing the
  // point lit (T10). Off: shadowless point lights, as the listing (K9).
  bool shadows = false;
  double lightRadius = 0.0;
};

// A texture map written next to the .pov file, named relative to it.
struct PovImage {
  std::string fileName;
  Image8 image;
};

struct PovExport {
  std::string pov;               // the scene file's text
  std::vector<PovImage> images;  // every image the text names
  int width = 0, height = 0;     // the image size to render at (+W +H): the listing's rays
};

// The camera POV-Ray needs for ray (row, column) of the listing to pass
// through the centre of pixel (row, column) of a width x height image.
struct PovCamera {
  Vec3 location{}, direction{}, right{}, up{};
  int width = 0, height = 0;
};
PovCamera povCamera(const CameraSettings& settings);

// `matrix <...>` takes the first three columns of a row-vector 4x4 matrix,
// row by row: exactly PRIME's p_world = p_local * M.
std::array<double, 12> povMatrix(const Matrix4& m);

// Shortest decimal that reads back as the same double (POV-Ray parses it).

PovExport exportPov(const Scene& scene, const PovExportOptions& options = {});

// Writes the .pov file and its images (next to it), each through a temporary
// file renamed into place. Throws std::runtime_error naming the file on failure.
void writePovExport(const PovExport& exported, const std::filesystem::path& povFile);

}  // namespace prime
