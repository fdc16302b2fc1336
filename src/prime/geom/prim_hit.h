// What intersecting one primitive gives: the parameters where the ray enters
// and leaves it and the normals there, in the primitive's local frame. The one
// result type of both profiles' primitive tests, the CSG walks' leaves and the
// stress suite's reference leaves.
//   1991 (primitives_1991.h, IntersectPrim 4565-4568 hands it to AddToTList):
//     both t > 0 (K7); the raw face normals as Swap() hands them out (K6),
//     not unit for the cone and pyramid (K5).
//   modern (primitives_modern.h): the whole line's interval (tIn < 0 for an
//     origin inside); outward unit normals at both ends.
#pragma once

#include "src/math/vec.h"

namespace prime {

struct PrimHit {
  double tIn = 0.0;
  double tOut = 0.0;
  Vec3 nIn{};
  Vec3 nOut{};
};

}  // namespace prime
