// The five unit primitives for the modern profile: arithmetic done right.
//   - The whole line is intersected: the result is the parameter interval
//     [tIn, tOut] where the line is inside the solid, however it is placed
//     (an origin inside gives tIn < 0); the caller clips to its ray.
//   - Quadratics are solved without cancellation (q = -(b + sign(b) sqrt(D)),
//     roots q/a and c/q).
//   - Cube and pyramid are convex polyhedra clipped plane by plane; sphere,
//     cylinder and cone are quadrics clipped by their cap slabs.
//   - Normals are the solid's OUTWARD unit normals at entry and at exit, in
//     the primitive's local frame (transform them by the inverse transpose).
// Pure functions: no I/O, no globals, no heap.
#pragma once

#include "legacy_io/prime/records.h"
#include "src/geom/ray.h"
#include "src/prime/geom/prim_hit.h"

namespace prime {

// False when the line misses the solid (or only touches it: tIn == tOut is
// reported as a miss only if the direction is degenerate).
bool intersectModern(io::PrimType type, const Ray& local, PrimHit& out);
// intersectModern's answer and t's, bit for bit, without the normals (left
// unspecified): for the tests that need only where the line is inside.
bool intersectModernT(io::PrimType type, const Ray& local, PrimHit& out);

bool sphereModern(const Ray& local, PrimHit& out);
bool cylinderModern(const Ray& local, PrimHit& out);
bool coneModern(const Ray& local, PrimHit& out);
bool cubeModern(const Ray& local, PrimHit& out);
// cubeModern as the generic clip by six half-spaces computes it: the same
// bits (cubeModern writes each face's dot products out); kept for the test.
bool cubeModernByPlanes(const Ray& local, PrimHit& out);
bool pyramidModern(const Ray& local, PrimHit& out);

// The surfaces of the solid that pass within 16 times the error bound `err`
// (per axis, local units) of the local point p, for spawning secondary rays off
// edges and corners as well as faces. Writes the outward unit normal of each
// such surface (at most `max`) and returns their number; returns -1 when p
// is farther than that outside the solid (no surface of it is near). Every constraint of the solid
// is evaluated with a bound on its own rounding error, so "within err" is conservative.
int nearSurfacesModern(io::PrimType type, const Vec3& p, const Vec3& err, Vec3* out, int max);

// Both roots of a t^2 + 2 b t + c = 0 (the listing's half-b form), ordered,
// computed without cancellation. False when there are none (D < 0) or a = 0.
bool solveQuadratic(double a, double b, double c, double& t0, double& t1);

}  // namespace prime
