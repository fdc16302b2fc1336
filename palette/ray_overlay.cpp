#include "palette/ray_overlay.h"

#include <algorithm>
#include <cmath>

namespace prime {

namespace {

double det3(const Vec3& a, const Vec3& b, const Vec3& c) {
  return dot(a, cross(b, c));
}

void put(Image8& img, int x, int y, std::array<std::uint8_t, 3> c) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
  const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 3;
  img.rgb[i] = c[0];
  img.rgb[i + 1] = c[1];
  img.rgb[i + 2] = c[2];
}

// Liang-Barsky: the part of (x0,y0)-(x1,y1) inside [lo, hi] on both axes.
bool clip2d(double& x0, double& y0, double& x1, double& y1, double lo, double hiX, double hiY) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = x1 - x0, dy = y1 - y0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x0 - lo, hiX - x0, y0 - lo, hiY - y0};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0.0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  const double ax = x0 + t0 * dx, ay = y0 + t0 * dy;
  x1 = x0 + t1 * dx;
  y1 = y0 + t1 * dy;
  x0 = ax;
  y0 = ay;
  return true;
}

// A line between picture points (pixel (c, r) covers [c, c+1) x [r, r+1)).
void line(Image8& img, double x0, double y0, double x1, double y1, std::array<std::uint8_t, 3> c) {
  if (!clip2d(x0, y0, x1, y1, -1.0, img.width + 1.0, img.height + 1.0)) return;
  const double n = std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)));
  const int steps = static_cast<int>(std::max(n, 1.0));
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    put(img, static_cast<int>(std::floor(x0 + t * (x1 - x0))),
        static_cast<int>(std::floor(y0 + t * (y1 - y0))), c);
  }
}

void square(Image8& img, int cx, int cy, int half, std::array<std::uint8_t, 3> c) {
  for (int d = -half; d <= half; ++d) {
    put(img, cx + d, cy - half, c);
    put(img, cx + d, cy + half, c);
    put(img, cx - half, cy + d, c);
    put(img, cx + half, cy + d, c);
  }
}

}  // namespace

std::optional<PictureProjection::Point> PictureProjection::project(const Vec3& p) const {
  // p - eye = s toFirst + (s a) across + (s b) down: Cramer's rule.
  const Vec3 r = p - eye;
  const double d = det3(toFirst, across, down);
  if (!(std::abs(d) > 0.0) || !std::isfinite(d)) return std::nullopt;
  const double s = det3(r, across, down) / d;
  const double sa = det3(toFirst, r, down) / d;
  const double sb = det3(toFirst, across, r) / d;
  Point out;
  out.s = s;
  if (s != 0.0) {
    out.x = sa / s + offsetX;
    out.y = sb / s + offsetY;
  }
  return out;
}

std::optional<OverlayKind> overlayKind(std::string_view name) {
  if (name == "primary") return OverlayKind::Primary;
  if (name == "reflected") return OverlayKind::Reflected;
  if (name == "transmitted" || name == "refracted") return OverlayKind::Transmitted;
  if (name == "shadow") return OverlayKind::Shadow;
  return std::nullopt;
}

std::array<std::uint8_t, 3> overlayColour(OverlayKind kind) {
  switch (kind) {
    case OverlayKind::Primary:
      return {255, 255, 255};
    case OverlayKind::Reflected:
      return {0, 220, 255};
    case OverlayKind::Transmitted:
      return {255, 160, 0};
    case OverlayKind::Shadow:
      return {170, 170, 170};
  }
  return {255, 255, 255};
}

std::optional<std::array<PictureProjection::Point, 2>> projectSegment(
    const PictureProjection& camera, const OverlaySegment& seg) {
  auto a = camera.project(seg.from), b = camera.project(seg.to);
  if (!a || !b) return std::nullopt;
  // Clip at a plane just in front of the eye (a tenth of a millionth of
  // the nearer end's depth), so that a ray passing behind the eye is drawn
  // up to where it leaves the view.
  const double near = 1e-7 * std::max(std::abs(a->s), std::abs(b->s));
  if (a->s <= near && b->s <= near) return std::nullopt;
  if (a->s <= near || b->s <= near) {
    const double t = (near - a->s) / (b->s - a->s);
    const Vec3 cut = seg.from + (seg.to - seg.from) * t;
    const auto c = camera.project(cut);
    if (!c) return std::nullopt;
    (a->s <= near ? a : b) = c;
  }
  return std::array<PictureProjection::Point, 2>{*a, *b};
}

Image8 drawRayOverlay(const Image8& picture, std::span<const OverlaySegment> segments,
                      const PictureProjection& camera, int column, int row,
                      const std::function<void(Image8&)>& under) {
  Image8 img = picture;
  for (std::uint8_t& v : img.rgb) v = static_cast<std::uint8_t>(v / 2);
  if (under) under(img);
  // Shadow rays first, so the tree's own rays stay on top.
  for (const bool shadows : {true, false})
    for (const OverlaySegment& seg : segments) {
      if ((seg.kind == OverlayKind::Shadow) != shadows) continue;
      const auto ends = projectSegment(camera, seg);
      if (!ends) continue;
      const auto c = overlayColour(seg.kind);
      line(img, (*ends)[0].x, (*ends)[0].y, (*ends)[1].x, (*ends)[1].y, c);
      if (seg.hit && (*ends)[1].s > 0.0)
        square(img, static_cast<int>(std::floor((*ends)[1].x)),
               static_cast<int>(std::floor((*ends)[1].y)), 2, c);
    }
  square(img, column, row, 3, {255, 0, 255});  // the probed pixel
  return img;
}

}  // namespace prime
