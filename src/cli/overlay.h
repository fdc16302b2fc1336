// `prime probe SCENE --pixel X Y --overlay OUT.png` for every system: the
// pixel's ray tree (palette/ray_overlay.h) over the system's picture, and
// the segments of the probe logs that record rays as events.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "palette/ray_overlay.h"
#include "src/render/probe_log.h"
#include "src/render/rgb_image.h"

namespace prime::cli {

// Draws and writes the overlay (all or nothing); returns the path.
std::string writeOverlay(const std::string& path, const Image8& picture,
                         std::span<const OverlaySegment> segments, const PictureProjection& camera,
                         int column, int row);

// How far a ray that hits nothing is drawn: far enough that its end
// projects to its vanishing point within a pixel for any scene of the
// shipped size (the picture clips it).
inline constexpr double kMissLength = 1e7;

}  // namespace prime::cli
