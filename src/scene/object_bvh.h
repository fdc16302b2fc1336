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
  // The node in hand is kept in registers, not pushed and popped: most rays
  // meet one or two nodes, and a push followed at once by its pop stalls on
  // store-to-load forwarding.
  Item stack[64];
  int top = 0;
  int node = 0;
  if (!(nodes_[0].box.entry(ray) <= limit())) return;
  for (;;) {
    const Node& n = nodes_[node];
    bool descend = false;
    if (n.left < 0) {
      for (int k = n.first; k < n.first + n.count; ++k) {
        const int obj = order_[k];
        const double t = objectBoxes_[obj].entry(ray);
        if (t <= limit()) visit(obj, t);
      }
    } else {
      // The nearer child next, the farther one onto the stack.
      const double tl = nodes_[n.left].box.entry(ray), tr = nodes_[n.right].box.entry(ray);
      const bool leftFirst = tl <= tr;
      const int nearNode = leftFirst ? n.left : n.right, farNode = leftFirst ? n.right : n.left;
      const double tNear = leftFirst ? tl : tr, tFar = leftFirst ? tr : tl;
      if (tFar <= limit()) stack[top++] = {farNode, tFar};
      if (tNear <= limit()) {
        node = nearNode;
        descend = true;
      }
    }
    if (descend) continue;
    for (;;) {  // the nearest waiting node that can still hold a nearer hit
      if (top == 0) return;
      const Item it = stack[--top];
      if (it.t <= limit()) {
        node = it.node;
        break;
      }
    }
  }
}

}  // namespace prime
