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
  // The panel under the rays: a ray crossing the text hides a few of its
  // pixels, the text never hides a ray.
  Image8 img = picture;
  for (std::uint8_t& v : img.rgb) v = static_cast<std::uint8_t>(v / 2);
  drawTextPanel(img, probed.text, probed.row);
  drawRays(img, probed.segments, probed.camera, probed.column, probed.row);
  return img;
}

std::string writeOverlay(const std::string& path, const Image8& picture,
                         const ProbedPixel& probed) {
  writePng(path, drawProbedPixel(picture, probed));
  return path;
}

}  // namespace prime::cli
