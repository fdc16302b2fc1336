#include "src/cli/overlay.h"

#include "palette/text/text_panel.h"

namespace prime::cli {

ProbedPixel ProbedPixel::placedAt(int dx, int dy) const {
  ProbedPixel out = *this;
  out.camera.offsetX += dx;
  out.camera.offsetY += dy;
  out.column += dx;
  out.row += dy;
  return out;
}

Image8 drawProbedPixel(const Image8& picture, const ProbedPixel& probed) {
  return drawRayOverlay(picture, probed.segments, probed.camera, probed.column, probed.row,
                        [&](Image8& img) { drawTextPanel(img, probed.text, probed.row); });
}

std::string writeOverlay(const std::string& path, const Image8& picture,
                         const ProbedPixel& probed) {
  writePng(path, drawProbedPixel(picture, probed));
  return path;
}

}  // namespace prime::cli
