#include "src/geom/bvh.h"

#include <algorithm>
#include <utility>

namespace prime {

Bvh::Bvh(std::vector<Aabb> boxes) : boxes_(std::move(boxes)) {
  for (int i = 0; i < static_cast<int>(boxes_.size()); ++i)
    if (!boxes_[i].empty()) order_.push_back(i);
  centres_.reserve(boxes_.size());
  for (const Aabb& b : boxes_) centres_.push_back(b.centre());
  if (!order_.empty()) build(0, static_cast<int>(order_.size()), 0);
  centres_ = {};  // only the build needs them
}

// Median split on the longest axis of the box centres; leaves of <= 4.
int Bvh::build(int first, int count, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Aabb box, centres;
  for (int k = first; k < first + count; ++k) {
    box.add(boxes_[order_[k]]);
    centres.add(centres_[order_[k]]);
  }
  nodes_[index].box = box;
  if (count <= 4 || depth >= 60) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    const Aabb& only = boxes_[order_[first]];
    nodes_[index].oneBox = count == 1 && box.lo == only.lo && box.hi == only.hi;
    return index;
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (centres.hi[i] - centres.lo[i] > centres.hi[axis] - centres.lo[axis]) axis = i;
  const int mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](int a, int b) { return centres_[a][axis] < centres_[b][axis]; });
  const int left = build(first, mid - first, depth + 1);
  const int right = build(mid, first + count - mid, depth + 1);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

}  // namespace prime
