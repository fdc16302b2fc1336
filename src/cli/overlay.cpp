#include "src/cli/overlay.h"

namespace prime::cli {

std::string writeOverlay(const std::string& path, const Image8& picture,
                         std::span<const OverlaySegment> segments, const PictureProjection& camera,
                         int column, int row) {
  writePng(path, drawRayOverlay(picture, segments, camera, column, row));
  return path;
}

}  // namespace prime::cli
