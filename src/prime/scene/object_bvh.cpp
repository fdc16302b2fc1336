#include "src/prime/scene/object_bvh.h"

#include <cmath>
#include <cstddef>

namespace prime {

namespace {

Aabb unionOfLeaves(const SceneObject& obj, const std::vector<Aabb>& primBoxes) {
  Aabb box;
  for (const auto& e : obj.entries)
    if (e.op == 'P') box.add(primBoxes[e.l]);
  return box;
}

void addBox(Aabb& to, const Aabb& b) {
  if (!b.empty()) to.add(b);  // (adding an empty box's corners would fill space)
}

// The box of the object's solid by the set operations, from the root (entry
// 0): a leaf's is its primitive's, a union's both operands', a difference's
// its left operand's (the solid lies inside it), an intersection's the
// common part of both. Each entry once (shared subtrees), without recursion
// (chains of thousands of entries, M31). An entry the compiler would refuse
// (an index out of range, a cycle, an unknown operator) gives the union of
// the leaves, as kLeaves.
Aabb solidBox(const SceneObject& obj, const std::vector<Aabb>& primBoxes) {
  const std::size_t n = obj.entries.size();
  if (n == 0) return {};
  std::vector<Aabb> box(n);
  std::vector<char> state(n, 0);  // 0 not seen, 1 children pending, 2 done
  std::vector<std::size_t> stack{0};
  auto valid = [&](int i) { return i >= 0 && static_cast<std::size_t>(i) < n; };
  while (!stack.empty()) {
    const std::size_t k = stack.back();
    const CsgEntry& e = obj.entries[k];
    if (state[k] == 2) {
      stack.pop_back();
      continue;
    }
    if (e.op == 'P') {
      if (e.l < 0 || static_cast<std::size_t>(e.l) >= primBoxes.size())
        return unionOfLeaves(obj, primBoxes);
      box[k] = primBoxes[static_cast<std::size_t>(e.l)];
      state[k] = 2;
      stack.pop_back();
      continue;
    }
    if ((e.op != '+' && e.op != '-' && e.op != '&') || !valid(e.l) || !valid(e.r))
      return unionOfLeaves(obj, primBoxes);
    const std::size_t l = static_cast<std::size_t>(e.l), r = static_cast<std::size_t>(e.r);
    if (state[k] == 0) {
      state[k] = 1;
      for (const std::size_t c : {l, r}) {
        if (state[c] == 1) return unionOfLeaves(obj, primBoxes);  // a cycle
        if (state[c] == 0) stack.push_back(c);
      }
      continue;
    }
    // state 1: both operands are done
    if (e.op == '+') {
      addBox(box[k], box[l]);
      addBox(box[k], box[r]);
    } else if (e.op == '-') {
      box[k] = box[l];
    } else {
      box[k] = box[l].intersected(box[r]);
    }
    state[k] = 2;
    stack.pop_back();
  }
  return box[0];
}

std::vector<Aabb> boxesOfObjects(const Scene& scene, const std::vector<Aabb>& primBoxes,
                                 ObjectBvh::ObjectBoxes mode) {
  std::vector<Aabb> boxes;
  for (const auto& obj : scene.objects) {
    Aabb box = mode == ObjectBvh::ObjectBoxes::kSolid ? solidBox(obj, primBoxes)
                                                      : unionOfLeaves(obj, primBoxes);
    // Not intersected with the bounding volume's box: the listing's bound
    // test only asks whether the ray meets the bound somewhere ahead, not
    // where, so the object can be hit outside its bound (the exact bound
    // test still runs for every candidate).
    boxes.push_back(box);
  }
  return boxes;
}
}  // namespace

template <class Visit>
void ObjectBvh::forEachLeafInObjects(const Scene& scene, Visit&& visit) const {
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const Aabb& object = objectBox(static_cast<int>(k));
    if (object.empty()) continue;
    for (const CsgEntry& e : scene.objects[k].entries)
      if (e.op == 'P') {
        // (Within a union of leaves' box a leaf's box is itself, bit for bit.)
        const Aabb b = primBox(e.l).intersected(object);
        if (!b.empty()) visit(e.l, b);
      }
  }
}

std::vector<Aabb> ObjectBvh::primitiveBoxesOfObjects(const Scene& scene) const {
  std::vector<Aabb> boxes;
  forEachLeafInObjects(scene, [&](int, const Aabb& box) { boxes.push_back(box); });
  return boxes;
}

std::vector<std::vector<Vec3>> ObjectBvh::primitiveHullsOfObjects(const Scene& scene) const {
  std::vector<std::vector<Vec3>> hulls;
  forEachLeafInObjects(scene, [&](int prim, const Aabb&) {
    hulls.push_back(primitiveHullPoints(scene.prims[static_cast<std::size_t>(prim)]));
  });
  return hulls;
}

ObjectBvh::ObjectBvh(const Scene& scene, ObjectBoxes objectBoxes) {
  for (const auto& p : scene.prims) primBoxes_.push_back(primitiveBox(p));
  bvh_ = Bvh(boxesOfObjects(scene, primBoxes_, objectBoxes));
}

Aabb ObjectBvh::objectsBox() const {
  Aabb all;
  for (const Aabb& b : bvh_.boxes()) {
    if (b.empty()) continue;
    bool finite = true;
    for (int i = 0; i < 3; ++i) finite = finite && std::isfinite(b.lo[i]) && std::isfinite(b.hi[i]);
    if (finite) all.add(b);
  }
  return all;
}

}  // namespace prime
