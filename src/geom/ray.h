// Ray.h of the listing: an origin and a direction. Directions are NOT
// normalised after transformation into primitive space (errata E55), so a
// parameter t means the same point in world and primitive space.
#pragma once
#include "src/math/matrix.h"
#include "src/math/vec.h"

namespace prime {

struct Ray {
  Vec3 o{};  // xO
  Vec3 d{};  // xD
};

// TransformRay (Transfrm module, E55): origin by the full inverse matrix,
// direction by its 3x3 part.
inline Ray transformRay(const Ray& world, const Matrix4& inverse) {
  return {pointMatrixMul(world.o, inverse), vectorMatrixMul(world.d, inverse)};
}

}  // namespace prime
