#include "src/scene/object_bvh.h"

#include <algorithm>

namespace prime {

ObjectBvh::ObjectBvh(const Scene& scene) {
  for (const auto& p : scene.prims) primBoxes_.push_back(primitiveBox(p));
  for (const auto& obj : scene.objects) {
    Aabb box;
    for (const auto& e : obj.entries)
      if (e.op == 'P') box.add(primBoxes_[e.l]);
    // Not intersected with the bounding volume's box: the listing's bound
    // test only asks whether the ray meets the bound somewhere ahead, not
    // where, so the object can be hit outside its bound (the exact bound
    // test still runs for every candidate).
    objectBoxes_.push_back(box);
  }
  for (int i = 0; i < static_cast<int>(objectBoxes_.size()); ++i)
    if (!objectBoxes_[i].empty()) order_.push_back(i);
  if (!order_.empty()) build(0, static_cast<int>(order_.size()), 0);
}

// Median split on the longest axis of the box centres; leaves of <= 4.
int ObjectBvh::build(int first, int count, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Aabb box, centres;
  for (int k = first; k < first + count; ++k) {
    box.add(objectBoxes_[order_[k]]);
    centres.add(objectBoxes_[order_[k]].centre());
  }
  nodes_[index].box = box;
  if (count <= 4 || depth >= 60) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (centres.hi[i] - centres.lo[i] > centres.hi[axis] - centres.lo[axis]) axis = i;
  const int mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](int a, int b) { return objectBoxes_[a].centre()[axis] < objectBoxes_[b].centre()[axis]; });
  const int left = build(first, mid - first, depth + 1);
  const int right = build(mid, first + count - mid, depth + 1);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

}  // namespace prime
