// A bounding volume hierarchy over a scene's objects, so that a ray tests
// only the objects whose boxes it meets, nearest first. It returns exactly
// what the listing's linear search over obj/List returns: candidates are
// pruned only when their box starts strictly beyond the nearest hit so far,
// and the caller breaks ties between equal t by list order.
#pragma once
#include <span>
#include <vector>

#include "src/scene/aabb.h"

namespace prime {

class ObjectBvh {
 public:
  explicit ObjectBvh(const Scene& scene);

  // Calls visit(objectIndex, boxEntry) for every object whose box the ray
  // meets at boxEntry <= limit(), nearest box first. `limit` is re-read
  // after each visit, so the caller can shrink it as hits are found.
  template <class Visit, class Limit>
  void traverse(const Ray& ray, Visit&& visit, Limit&& limit) const {
    traverse(BoxRay(ray), visit, limit);
  }
  // The same with the ray prepared by the caller.
  template <class Visit, class Limit>
  void traverse(const BoxRay& ray, Visit&& visit, Limit&& limit) const;

  const Aabb& objectBox(int object) const { return objectBoxes_[object]; }
  std::span<const Aabb> objectBoxes() const { return objectBoxes_; }
  const Aabb& primBox(int prim) const { return primBoxes_[prim]; }

 private:
  struct Node {
    Aabb box;
    int left = -1, right = -1;  // children, or -1 for a leaf
    int first = 0, count = 0;   // leaf: range in order_
  };
  int build(int first, int count, int depth);
  std::vector<Aabb> objectBoxes_, primBoxes_;
  std::vector<int> order_;  // object indices, grouped by leaf
  std::vector<Node> nodes_;
};

template <class Visit, class Limit>
void ObjectBvh::traverse(const BoxRay& ray, Visit&& visit, Limit&& limit) const {
  if (nodes_.empty()) return;
  struct Item {
    int node;
    double t;
  };
  Item stack[64];
  int top = 0;
  const double t0 = nodes_[0].box.entry(ray);
  if (t0 <= limit()) stack[top++] = {0, t0};
  while (top > 0) {
    const Item it = stack[--top];
    if (it.t > limit()) continue;
    const Node& n = nodes_[it.node];
    if (n.left < 0) {
      for (int k = n.first; k < n.first + n.count; ++k) {
        const int obj = order_[k];
        const double t = objectBoxes_[obj].entry(ray);
        if (t <= limit()) visit(obj, t);
      }
      continue;
    }
    const double tl = nodes_[n.left].box.entry(ray), tr = nodes_[n.right].box.entry(ray);
    // Push the farther child first so the nearer is visited first.
    if (tl <= tr) {
      if (tr <= limit()) stack[top++] = {n.right, tr};
      if (tl <= limit()) stack[top++] = {n.left, tl};
    } else {
      if (tl <= limit()) stack[top++] = {n.left, tl};
      if (tr <= limit()) stack[top++] = {n.right, tr};
    }
  }
}

}  // namespace prime
