#include "src/prime/render/primary_mask.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace prime {

namespace {

constexpr double kPadPixels = 2.0;

struct Rect {
  int row0, row1, col0, col1;  // inclusive
};

// The direction of pixel (row, column) is toFirst + column*stepAcross +
// row*stepDown (LinearView: ListingCamera's window point windowLeft + ... minus
// the eye, K23 stepping down; or the free camera's). A point X in front of
// the eye E lies on the ray of the fractional pixel (q/s, p/s) where
// X - E = s*toFirst + p*A + q*D; s <= 0 means X is level with or behind the eye.
class Projector {
 public:
  explicit Projector(const LinearView& view) {
    c0_ = view.toFirst;
    c1_ = view.stepAcross;
    c2_ = view.stepDown;
    eye_ = view.eye;
    det_ = dot(c0_, cross(c1_, c2_));
    const double scale = norm(c0_) * norm(c1_) * norm(c2_);
    // A nearly singular basis would make the projection itself inexact.
    usable_ = std::isfinite(det_) && scale > 0.0 && std::abs(det_) > 1e-9 * scale;
  }
  bool usable() const { return usable_; }

  // (row, column) of X, or nothing when X is not strictly in front of the eye.
  std::optional<std::pair<double, double>> pixel(const Vec3& x) const {
    const Vec3 r{x[0] - eye_[0], x[1] - eye_[1], x[2] - eye_[2]};
    // Cramer's rule for [c0 c1 c2] (s, p, q) = r.
    const double s = dot(r, cross(c1_, c2_)) / det_;
    const double p = dot(c0_, cross(r, c2_)) / det_;
    const double q = dot(c0_, cross(c1_, r)) / det_;
    if (!(s > 1e-12) || !std::isfinite(p) || !std::isfinite(q)) return std::nullopt;
    return std::make_pair(q / s, p / s);
  }

 private:
  static double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
  Vec3 c0_{}, c1_{}, c2_{}, eye_{};
  double det_ = 0.0;
  bool usable_ = false;
};

// The pixels whose rays can meet `box`, or nothing when that may be any pixel.
std::optional<Rect> projectedRect(const Projector& proj, const Aabb& box, int rows, int columns) {
  double rowLo = INFINITY, rowHi = -INFINITY, colLo = INFINITY, colHi = -INFINITY;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner{c & 1 ? box.hi[0] : box.lo[0], c & 2 ? box.hi[1] : box.lo[1],
                      c & 4 ? box.hi[2] : box.lo[2]};
    const auto px = proj.pixel(corner);
    if (!px) return std::nullopt;
    rowLo = std::min(rowLo, px->first);
    rowHi = std::max(rowHi, px->first);
    colLo = std::min(colLo, px->second);
    colHi = std::max(colHi, px->second);
  }
  // Clamp in double first: the projection of a box near the eye plane can be
  // far outside int's range.
  auto clampTo = [](double v, int n) {
    return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(n)));
  };
  return Rect{clampTo(std::floor(rowLo - kPadPixels), rows),
              clampTo(std::ceil(rowHi + kPadPixels), rows),
              clampTo(std::floor(colLo - kPadPixels), columns),
              clampTo(std::ceil(colHi + kPadPixels), columns)};
}

}  // namespace

PrimaryRayMask::PrimaryRayMask(const ListingCamera& camera, std::span<const Aabb> boxes)
    : rows_(camera.rows()), columns_(camera.columns()) {
  build(camera.linearView(), boxes);
}

PrimaryRayMask::PrimaryRayMask(const PrimeCamera& camera, std::span<const Aabb> boxes)
    : rows_(camera.rows()), columns_(camera.columns()) {
  build(camera.linearView(), boxes);
}

void PrimaryRayMask::build(const LinearView& view, std::span<const Aabb> boxes) {
  const Projector proj(view);
  if (!proj.usable()) return;
  // A 2-D difference array: +1/-1 at the rectangles' corners, then prefix
  // sums, so the cost is one step per box plus one per pixel.
  const auto w = static_cast<std::size_t>(columns_) + 1;
  std::vector<std::int32_t> diff((static_cast<std::size_t>(rows_) + 1) * w, 0);
  for (const Aabb& box : boxes) {
    if (box.empty()) continue;  // an object with no primitive box is never tested
    const std::optional<Rect> r = projectedRect(proj, box, rows_, columns_);
    if (!r) return;  // this box may be seen anywhere: no mask
    const int r0 = std::max(r->row0, 0), r1 = std::min(r->row1, rows_ - 1);
    const int c0 = std::max(r->col0, 0), c1 = std::min(r->col1, columns_ - 1);
    if (r0 > r1 || c0 > c1) continue;  // entirely off the image
    const auto at = [&](int row, int col) -> std::int32_t& {
      return diff[static_cast<std::size_t>(row) * w + static_cast<std::size_t>(col)];
    };
    ++at(r0, c0);
    --at(r0, c1 + 1);
    --at(r1 + 1, c0);
    ++at(r1 + 1, c1 + 1);
  }
  covered_.assign(static_cast<std::size_t>(rows_) * columns_, 0);
  std::vector<std::int32_t> above(w, 0);  // column sums of the rows so far
  for (int i = 0; i < rows_; ++i) {
    std::int32_t run = 0;
    for (int j = 0; j < columns_; ++j) {
      above[j] += diff[static_cast<std::size_t>(i) * w + j];
      run += above[j];
      covered_[static_cast<std::size_t>(i) * columns_ + j] = run > 0 ? 1 : 0;
    }
  }
}

double PrimaryRayMask::coverage() const {
  if (covered_.empty()) return 1.0;
  return static_cast<double>(std::count(covered_.begin(), covered_.end(), 1)) /
         static_cast<double>(covered_.size());
}

}  // namespace prime
