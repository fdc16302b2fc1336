// World-space boxes around PRIME's primitives, used only to skip work: a ray
// that misses a primitive's box cannot hit the primitive, and every t in an
// object's Roth list is a point on one of its primitives. Boxes are padded so
// that rounding in the primitive tests can never put a reported hit outside
// its box.
#pragma once
#include <array>
#include <vector>

#include "src/geom/aabb.h"
#include "src/prime/scene/scene.h"

namespace prime {

// The unit primitive's box (S, C, N about the z axis; B and Y in the unit
// cube) mapped by the primitive's transform, padded.
Aabb primitiveBox(const ScenePrim& p);
// The same box's eight corners mapped by the transform, unpadded: the
// primitive lies in their convex hull (a parallelepiped, often much smaller
// than its axis-aligned box).
std::array<Vec3, 8> primitiveCorners(const ScenePrim& p);
// Points whose convex hull holds the primitive, mapped by its transform: the
// vertices of the cube and the pyramid, and for the round primitives the
// vertices of a circumscribed polyhedron: the cylinder in a regular
// 16-gon prism, the cone in a 16-gon pyramid, the sphere in the body a
// circumscribed octagon sweeps about the z axis, itself in 16-gon frusta.
// Much closer to a round primitive than its box's corners.
std::vector<Vec3> primitiveHullPoints(const ScenePrim& p);

}  // namespace prime
