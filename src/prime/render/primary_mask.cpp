#include "src/prime/render/primary_mask.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace prime {

namespace {

constexpr double kPadPixels = 2.0;

struct Rect {
  int row0, row1, col0, col1;  // inclusive
  // Per row from row0, the columns kept within col0..col1 (c0 > c1: none),
  // when the box's hull narrows it; empty otherwise.
  std::vector<std::pair<int, int>> rowColumns;
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
              clampTo(std::ceil(colHi + kPadPixels), columns),
              {}};
}

// The convex hull of 2-D points (Andrew's monotone chain), counter-clockwise,
// no repeated point; fewer than three points when they are all on one line.
std::vector<std::pair<double, double>> convexHull(std::vector<std::pair<double, double>> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  auto cross = [](const std::pair<double, double>& o, const std::pair<double, double>& a,
                  const std::pair<double, double>& b) {
    return (a.first - o.first) * (b.second - o.second) -
           (a.second - o.second) * (b.first - o.first);
  };
  std::vector<std::pair<double, double>> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);  // the last point is the first
  return h;
}

// Narrows `rect` row by row to the columns within kPadPixels of the convex
// hull of `points` (their projections): for row i, the hull's part between
// rows i - kPadPixels and i + kPadPixels, widened by kPadPixels, the margin
// the rectangle has. That part's column range is reached at a hull vertex
// inside the band or where a hull edge crosses one of the band's edges.
// (Rounding in the hull's construction moves a vertex by far less than the
// margin: a point it drops as inside lies within a rounding error of the
// hull.) Nothing is narrowed when a point is not in front of the eye.
void narrowToHull(const Projector& proj, std::span<const Vec3> points, Rect& rect) {
  std::vector<std::pair<double, double>> px;
  px.reserve(points.size());
  for (const Vec3& point : points) {
    const auto p = proj.pixel(point);
    if (!p) return;
    px.push_back(*p);
  }
  const std::vector<std::pair<double, double>> hull = convexHull(std::move(px));
  if (hull.empty()) return;
  auto clampTo = [](double v, int lo, int hi) {
    return static_cast<int>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
  };
  rect.rowColumns.reserve(static_cast<std::size_t>(rect.row1 - rect.row0 + 1));
  const std::size_t n = hull.size();
  for (int i = rect.row0; i <= rect.row1; ++i) {
    const double a = i - kPadPixels, b = i + kPadPixels;
    double lo = INFINITY, hi = -INFINITY;
    auto take = [&](double c) {
      lo = std::min(lo, c);
      hi = std::max(hi, c);
    };
    for (std::size_t k = 0; k < n; ++k) {
      const auto [rk, ck] = hull[k];
      if (rk >= a && rk <= b) take(ck);
      if (n < 2) continue;
      const auto [rm, cm] = hull[(k + 1) % n];
      if (rk == rm) continue;  // an edge along a row: its ends are counted
      for (const double edge : {a, b})
        if ((rk - edge) * (rm - edge) <= 0.0) take(ck + (edge - rk) * (cm - ck) / (rm - rk));
    }
    if (!(lo <= hi)) {
      rect.rowColumns.emplace_back(1, 0);  // the hull does not come near this row
      continue;
    }
    rect.rowColumns.emplace_back(
        std::max(rect.col0, clampTo(std::floor(lo - kPadPixels), rect.col0 - 1, rect.col1 + 1)),
        std::min(rect.col1, clampTo(std::ceil(hi + kPadPixels), rect.col0 - 1, rect.col1 + 1)));
  }
}

}  // namespace

PrimaryRayMask::PrimaryRayMask(const ListingCamera& camera, std::span<const Aabb> boxes)
    : rows_(camera.rows()), columns_(camera.columns()) {
  build(camera.linearView(), boxes, {});
}

PrimaryRayMask::PrimaryRayMask(const PrimeCamera& camera, std::span<const Aabb> boxes,
                               std::span<const std::vector<Vec3>> hulls)
    : rows_(camera.rows()), columns_(camera.columns()) {
  build(camera.linearView(), boxes, hulls.size() == boxes.size() ? hulls : decltype(hulls){});
}

void PrimaryRayMask::build(const LinearView& view, std::span<const Aabb> boxes,
                           std::span<const std::vector<Vec3>> hulls) {
  const Projector proj(view);
  if (!proj.usable()) return;
  // Each box's rectangle on the image, then per row the union of the
  // rectangles that cross it as sorted, disjoint column runs, built by one
  // sweep down the rows (a row whose set of rectangles is the previous
  // row's shares its runs): memory and time grow with the boxes and the
  // rows, not with the pixels, and nothing is left for the render threads
  // to wait on.
  std::vector<Rect> rects;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const Aabb& box = boxes[k];
    if (box.empty()) continue;  // an object with no primitive box is never tested
    const std::optional<Rect> r = projectedRect(proj, box, rows_, columns_);
    if (!r) return;  // this box may be seen anywhere: no mask
    const int r0 = std::max(r->row0, 0), r1 = std::min(r->row1, rows_ - 1);
    const int c0 = std::max(r->col0, 0), c1 = std::min(r->col1, columns_ - 1);
    if (r0 > r1 || c0 > c1) continue;  // entirely off the image
    rects.push_back({r0, r1, c0, c1, {}});
    if (!hulls.empty()) narrowToHull(proj, hulls[k], rects.back());
  }
  masked_ = true;
  std::sort(rects.begin(), rects.end(),
            [](const Rect& a, const Rect& b) { return a.row0 < b.row0; });
  rowRuns_.assign(static_cast<std::size_t>(rows_), {0, 0});
  std::vector<const Rect*> active;
  std::vector<std::pair<int, int>> spans;  // this row's column ranges
  std::size_t next = 0;
  for (int i = 0; i < rows_; ++i) {
    bool changed = false;
    const auto ended =
        std::remove_if(active.begin(), active.end(), [i](const Rect* r) { return r->row1 < i; });
    changed = ended != active.end();
    active.erase(ended, active.end());
    for (; next < rects.size() && rects[next].row0 <= i; ++next) {
      active.push_back(&rects[next]);
      changed = true;
    }
    // A row crossed by the same rectangles as the previous one, none of them
    // narrowed row by row, shares its runs.
    const bool narrowed = std::any_of(active.begin(), active.end(),
                                      [](const Rect* r) { return !r->rowColumns.empty(); });
    if (!changed && !narrowed && i > 0) {
      rowRuns_[static_cast<std::size_t>(i)] = rowRuns_[static_cast<std::size_t>(i) - 1];
      continue;
    }
    spans.clear();
    for (const Rect* r : active) {
      if (r->rowColumns.empty()) {
        spans.emplace_back(r->col0, r->col1);
      } else {
        const auto [c0, c1] = r->rowColumns[static_cast<std::size_t>(i - r->row0)];
        if (c0 <= c1) spans.emplace_back(c0, c1);
      }
    }
    std::sort(spans.begin(), spans.end());
    const auto first = static_cast<std::uint32_t>(runs_.size());
    for (const auto& [c0, c1] : spans) {
      if (runs_.size() > first && c0 <= runs_.back().c1 + 1)
        runs_.back().c1 = std::max(runs_.back().c1, c1);
      else
        runs_.push_back({c0, c1});
    }
    rowRuns_[static_cast<std::size_t>(i)] = {first, static_cast<std::uint32_t>(runs_.size())};
  }
}

bool PrimaryRayMask::mayHit(int row, int column) const {
  if (!masked_) return true;
  const auto [first, last] = rowRuns_[static_cast<std::size_t>(row)];
  for (std::uint32_t k = first; k < last; ++k) {
    if (column < runs_[k].c0) return false;  // runs are sorted
    if (column <= runs_[k].c1) return true;
  }
  return false;
}

double PrimaryRayMask::coverage() const {
  if (!masked_) return 1.0;
  double covered = 0;
  for (const auto& [first, last] : rowRuns_)
    for (std::uint32_t k = first; k < last; ++k) covered += runs_[k].c1 - runs_[k].c0 + 1;
  return covered / (static_cast<double>(rows_) * columns_);
}

}  // namespace prime
