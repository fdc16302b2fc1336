#include "src/prime/scene/prim_boxes.h"

#include <cmath>

namespace prime {

std::array<Vec3, 8> primitiveCorners(const ScenePrim& p) {
  Vec3 lo{}, hi{};
  switch (p.type) {
    case io::PrimType::Sphere:
      lo = {-1, -1, -1};
      hi = {1, 1, 1};
      break;
    case io::PrimType::Cylinder:
    case io::PrimType::Cone:
      lo = {-1, -1, 0};
      hi = {1, 1, 1};
      break;
    case io::PrimType::Cube:
    case io::PrimType::Pyramid:
      lo = {0, 0, 0};
      hi = {1, 1, 1};
      break;
  }
  std::array<Vec3, 8> corners;
  for (int c = 0; c < 8; ++c)
    corners[static_cast<std::size_t>(c)] = pointMatrixMul(
        {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]}, p.transform);
  return corners;
}

Aabb primitiveBox(const ScenePrim& p) {
  Aabb box;
  for (const Vec3& corner : primitiveCorners(p)) box.add(corner);
  // Pad by a relative margin far above the rounding of any primitive test
  // (a few ulps of the coordinates) so that the box is conservative.
  double size = 0.0;
  for (int i = 0; i < 3; ++i)
    size = std::max({size, std::abs(box.lo[i]), std::abs(box.hi[i]), box.hi[i] - box.lo[i]});
  const double pad = 1e-7 * size + 1e-9;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] -= pad;
    box.hi[i] += pad;
  }
  return box;
}

}  // namespace prime
