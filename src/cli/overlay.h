// One pixel explained and drawn, for every system: the pixel's ray tree
// (palette/ray_overlay.h) over the picture, with a panel of what `prime
// probe` prints for it (palette/text/text_panel.h). `prime probe SCENE
// --pixel X Y --overlay OUT.png` writes it; a click on a pixel of a `trace`,
// `walk` or `view --scene` window shows it (src/cli/pixel_inspector.h).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "palette/ray_overlay.h"
#include "src/render/probe_log.h"
#include "src/render/rgb_image.h"

namespace prime::cli {

// What a system's probe gives for one pixel: its text and JSON (as `prime
// probe` prints them), its rays as segments, and the camera that projects
// them onto the picture, in the coordinates of the picture drawn on (a
// window's frame may hold the picture at an offset: PRIME's 8514/A screen).
struct ProbedPixel {
  std::string text, json;
  std::vector<OverlaySegment> segments;
  PictureProjection camera;
  int column = 0, row = 0;  // the probed pixel, in the same coordinates
  // The same, moved by (dx, dy): the picture placed at (dx, dy) of a frame.
  ProbedPixel placedAt(int dx, int dy) const;
};

// The drawing: the picture dimmed, the probe's text on a panel at the edge
// away from the pixel, and the tree over both, the pixel outlined.
Image8 drawProbedPixel(const Image8& picture, const ProbedPixel& probed);

// Draws and writes it (all or nothing); returns the path.
std::string writeOverlay(const std::string& path, const Image8& picture, const ProbedPixel& probed);

// How far a ray that hits nothing is drawn: far enough that its end
// projects to its vanishing point within a pixel for any scene of the
// shipped size (the picture clips it).
inline constexpr double kMissLength = 1e7;

}  // namespace prime::cli
