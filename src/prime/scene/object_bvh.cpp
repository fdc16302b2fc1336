#include "src/prime/scene/object_bvh.h"

namespace prime {

namespace {
std::vector<Aabb> boxesOfObjects(const Scene& scene, const std::vector<Aabb>& primBoxes) {
  std::vector<Aabb> boxes;
  for (const auto& obj : scene.objects) {
    Aabb box;
    for (const auto& e : obj.entries)
      if (e.op == 'P') box.add(primBoxes[e.l]);
    // Not intersected with the bounding volume's box: the listing's bound
    // test only asks whether the ray meets the bound somewhere ahead, not
    // where, so the object can be hit outside its bound (the exact bound
    // test still runs for every candidate).
    boxes.push_back(box);
  }
  return boxes;
}
}  // namespace

std::vector<Aabb> ObjectBvh::primitiveBoxesOfObjects(const Scene& scene) const {
  std::vector<Aabb> boxes;
  for (std::size_t k = 0; k < scene.objects.size(); ++k)
    for (const CsgEntry& e : scene.objects[k].entries)
      if (e.op == 'P' && !objectBox(static_cast<int>(k)).empty()) boxes.push_back(primBox(e.l));
  return boxes;
}

ObjectBvh::ObjectBvh(const Scene& scene) {
  for (const auto& p : scene.prims) primBoxes_.push_back(primitiveBox(p));
  bvh_ = Bvh(boxesOfObjects(scene, primBoxes_));
}

}  // namespace prime
