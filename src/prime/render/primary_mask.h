// Which pixels' primary rays can meet any object at all. Every primary ray
// starts at the eye, so an object's box is seen through a fixed region of the
// image: the central projection of the box onto the window, which is the
// convex hull of its eight corners' projections when the whole box lies in
// front of the eye. Pixels outside every object's projected rectangle (widened
// by two pixels for rounding and for supersampling offsets of up to half a
// pixel) get the background without a ray: the box tests they would run
// cannot accept the ray, so the pixel is the one the tracer would return.
// A box that reaches behind the eye, or a degenerate camera, covers every
// pixel (the mask is then simply not used). Given points around each
// primitive (its own turned box's corners, or a polyhedron closer to a round
// one), each rectangle is narrowed row by row to the convex hull of their
// projections, widened by the same margin.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "src/geom/aabb.h"
#include "src/prime/render/camera.h"

namespace prime {

class PrimaryRayMask {
 public:
  // `boxes`: every object's box as the tracer's box tests see it (empty
  // boxes are objects that cannot be hit).
  PrimaryRayMask(const ListingCamera& camera, std::span<const Aabb> boxes);
  // The same for the camera a render uses (the listing's or the free one).
  // `hulls`, if given, one set of points per box: what can be hit in that
  // box lies in the convex hull of those points as well, and each row keeps
  // only the columns near the hull's projection (within the same margin).
  PrimaryRayMask(const PrimeCamera& camera, std::span<const Aabb> boxes,
                 std::span<const std::vector<Vec3>> hulls = {});

  // False only when no primary ray through (row, column)'s footprint can meet a box.
  bool mayHit(int row, int column) const;
  struct Run {
    int c0, c1;  // columns c0..c1 (inclusive) may hit
  };
  // Whether the mask rules out any pixel; when it does, runs(row) are the
  // columns of `row` that may hit: sorted, disjoint, within the picture
  // (mayHit(row, c) is true exactly for the columns of these runs).
  bool masks() const { return masked_; }
  std::span<const Run> runs(int row) const {
    const auto [first, last] = rowRuns_[static_cast<std::size_t>(row)];
    return {runs_.data() + first, runs_.data() + last};
  }
  // The share of pixels that need a ray (1 when the mask covers everything).
  double coverage() const;

 private:
  void build(const LinearView& view, std::span<const Aabb> boxes,
             std::span<const std::vector<Vec3>> hulls);
  int rows_ = 0, columns_ = 0;
  bool masked_ = false;  // false: every pixel may hit
  std::vector<Run> runs_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>>
      rowRuns_;  // per row: its runs_ [first, last)
};

}  // namespace prime
