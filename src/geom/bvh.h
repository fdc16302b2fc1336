// A bounding volume hierarchy over any set of boxes (a system's objects,
// primitives or triangles), so that a ray visits only the boxes it meets,
// nearest first. It prunes a box only when the box starts strictly beyond
// the caller's limit, so a caller that keeps the nearest hit (and breaks ties
// by its own order) gets exactly what a linear search over all boxes gives.
#pragma once
#include <limits>
#include <span>
#include <vector>

#include "src/geom/aabb.h"

namespace prime {

class Bvh {
 public:
  Bvh() = default;
  // Boxes keep their index; empty boxes are never visited.
  explicit Bvh(std::vector<Aabb> boxes);

  // Calls visit(index, boxEntry) for every box the ray meets at
  // boxEntry <= limit(), nearest box first. `limit` is re-read after each
  // visit, so the caller can shrink it as hits are found.
  template <class Visit, class Limit>
  void traverse(const BoxRay& ray, Visit&& visit, Limit&& limit) const;

  const Aabb& box(int index) const { return boxes_[index]; }
  std::span<const Aabb> boxes() const { return boxes_; }

 private:
  struct Node {
    Aabb box;
    int left = -1, right = -1;  // children, or -1 for a leaf
    int first = 0, count = 0;   // leaf: range in order_
    // A leaf of one box, whose own box is that box (the union of one box):
    // the ray's entry into the node is the box's, not computed again.
    bool oneBox = false;
  };
  int build(int first, int count, int depth);
  std::vector<Aabb> boxes_;
  std::vector<Vec3> centres_;  // the boxes' centres, during the build
  std::vector<int> order_;     // box indices, grouped by leaf
  std::vector<Node> nodes_;
};

template <class Visit, class Limit>
void Bvh::traverse(const BoxRay& ray, Visit&& visit, Limit&& limit) const {
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
  // Aabb::entry is +infinity for a box the ray misses: such a box is never
  // met, even when limit() is +infinity (nothing found yet).
  constexpr double kMiss = std::numeric_limits<double>::infinity();
  auto within = [&](double t) { return t != kMiss && t <= limit(); };
  double nodeT = nodes_[0].box.entry(ray);  // the ray's entry into the node in hand
  if (!within(nodeT)) return;
  for (;;) {
    const Node& n = nodes_[node];
    bool descend = false;
    if (n.oneBox) {
      // within(nodeT) held when the node was taken; limit() has not changed since.
      visit(order_[n.first], nodeT);
    } else if (n.left < 0) {
      for (int k = n.first; k < n.first + n.count; ++k) {
        const int index = order_[k];
        const double t = boxes_[index].entry(ray);
        if (within(t)) visit(index, t);
      }
    } else {
      // The nearer child next, the farther one onto the stack.
      const double tl = nodes_[n.left].box.entry(ray), tr = nodes_[n.right].box.entry(ray);
      const bool leftFirst = tl <= tr;
      const int nearNode = leftFirst ? n.left : n.right, farNode = leftFirst ? n.right : n.left;
      const double tNear = leftFirst ? tl : tr, tFar = leftFirst ? tr : tl;
      if (within(tFar)) stack[top++] = {farNode, tFar};
      if (within(tNear)) {
        node = nearNode;
        nodeT = tNear;
        descend = true;
      }
    }
    if (descend) continue;
    for (;;) {  // the nearest waiting node that can still hold a nearer hit
      if (top == 0) return;
      const Item it = stack[--top];
      if (it.t <= limit()) {
        node = it.node;
        nodeT = it.t;
        break;
      }
    }
  }
}

}  // namespace prime
