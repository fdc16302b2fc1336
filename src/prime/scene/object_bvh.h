// The shared BVH (src/geom/bvh.h) over a scene's objects, so that a ray
// tests only the objects whose boxes it meets, nearest first. It returns
// exactly what the listing's linear search over obj/List returns: candidates
// are pruned only when their box starts strictly beyond the nearest hit so
// far, and the caller breaks ties between equal t by list order.
#pragma once
#include <span>
#include <vector>

#include "src/geom/bvh.h"
#include "src/prime/scene/prim_boxes.h"

namespace prime {

class ObjectBvh {
 public:
  // An object's box: the union of its primitives' boxes (kLeaves: the 1991
  // profile, whose operators are the listing's and may keep nodes the set
  // operations drop), or the box of its solid by the set operations
  // (kSolid: a difference's is its left operand's, an intersection's the
  // common part of its operands'; the modern and thesis profiles, N18).
  enum class ObjectBoxes { kLeaves, kSolid };
  explicit ObjectBvh(const Scene& scene, ObjectBoxes objectBoxes = ObjectBoxes::kLeaves);

  // Calls visit(objectIndex, boxEntry) for every object whose box the ray
  // meets at boxEntry <= limit(), nearest box first. `limit` is re-read
  // after each visit, so the caller can shrink it as hits are found.
  template <class Visit, class Limit>
  void traverse(const Ray& ray, Visit&& visit, Limit&& limit) const {
    bvh_.traverse(BoxRay(ray), visit, limit);
  }
  // The same with the ray prepared by the caller.
  template <class Visit, class Limit>
  void traverse(const BoxRay& ray, Visit&& visit, Limit&& limit) const {
    bvh_.traverse(ray, visit, limit);
  }

  const Aabb& objectBox(int object) const { return bvh_.box(object); }
  std::span<const Aabb> objectBoxes() const { return bvh_.boxes(); }
  const Aabb& primBox(int prim) const { return primBoxes_[prim]; }
  // The union of the objects' finite boxes (empty when no object is bounded):
  // what `prime walk` turns about by default is its centre.
  Aabb objectsBox() const;
  // The box of every primitive of every object's CSG tree (not the bounds),
  // each within its object's box: a ray that meets none of them meets no
  // object. Tighter than the object boxes, for the primary-ray mask.
  std::vector<Aabb> primitiveBoxesOfObjects(const Scene& scene) const;
  // Points (primitiveHullPoints) around the primitive of each of those
  // boxes, in the same order: the primitive lies in their convex hull too.
  std::vector<std::vector<Vec3>> primitiveHullsOfObjects(const Scene& scene) const;

 private:
  // visit(prim, box) for each leaf of each object whose box (its
  // primitive's within its object's) is not empty: the order and the
  // choice both lists above follow.
  template <class Visit>
  void forEachLeafInObjects(const Scene& scene, Visit&& visit) const;
  std::vector<Aabb> primBoxes_;
  Bvh bvh_;
};

}  // namespace prime
