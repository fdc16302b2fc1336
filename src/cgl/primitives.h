// The Waterloo CGL package's object nodes (M. A. J. Sweeney, "The Waterloo
// CGL Ray Tracing Package", University of Waterloo CS-85-35, 1985, sections
// 2-4 and 7): what the preprocessor makes of a sphere, an open cylinder, a
// triangle or rectangle, or a super box, and each one's intersection routine
// and texture indices, exactly as the document prints them (its quirks kept
// and named in docs/cgl/deviations.md).
//
// Every routine takes the ray R(t) = O + tD and reports the smallest t > tMin
// it accepts (tMin = 0 is the document's t <= 0 rejection; the tracer passes
// its self-intersection guard, CGL-Q44). Nothing here allocates.
#pragma once
#include <array>
#include <cstdint>

#include "src/geom/aabb.h"
#include "src/geom/ray.h"
#include "src/math/vec.h"

namespace prime::cgl {

enum class ObjectKind : std::uint8_t { Sphere, Cylinder, Polygon, Box, Fractal };
// The length of the statistics arrays indexed by ObjectKind (TraceStats::
// tests, hits); the Box entry stays 0, boxes are counted apart.
inline constexpr int kPrimitiveKinds = 5;

const char* kindName(ObjectKind kind);

// One object node (sections 2.1, 3.1, 4.1, 7.1). Fields by kind:
//  Sphere: c (the transformed centre), r, r2 = r^2 (the radius is never
//    scaled), a1, a2 (the texture axes named in the file, untransformed).
//  Cylinder: a (anchor, the first end point), p (path: second - first), pp =
//    P.P, r, r2, a1 (texture axis: P x (0,0,1), or P x (0,1,0) when P is
//    parallel to z; normalised, CGL-Q47).
//  Polygon: n (plane normal N_E1 x N_E2), v0 (plane point), edges (3 or 4)
//    edge normals en[k] and d[k], e1 and ne1 (the texture frame), u/v min
//    and max over the vertices.
//  Box: the union of its contents' boxes; its contents are the objects that
//    follow it in the list up to (not including) index `skip`.
//  Fractal (section 5.4): `fractal`, the index of its tree and facets in
//    Scene::fractals; v0, e1, ne1 and the u/v min and max, the texture frame
//    of section 5.3; box, the tree's root box.
struct Object {
  ObjectKind kind = ObjectKind::Sphere;
  bool opaque = true;  // the surface's transparency k_t is 0.0 (section 9.3)
  int surface = 0;     // 0-based index into Scene::surfaces (-1 for a box)
  int node = 0;        // the scene node it came from (1-based), for messages and the probe
  Aabb box;            // minimal bounding box (padded a little, see scene.cpp)
  Vec3 c{}, a1{}, a2{};
  double r = 0, r2 = 0;
  Vec3 a{}, p{};
  double pp = 0;
  Vec3 n{}, v0{}, e1{}, ne1{};
  std::array<Vec3, 4> en{};
  std::array<double, 4> d{};
  int edges = 0;
  double umin = 0, umax = 0, vmin = 0, vmax = 0;
  int skip = 0;      // Box: index of the first object after its contents
  int fractal = -1;  // Fractal: index into Scene::fractals
};

// Intersections. On a hit within (tMin, tMax) return true and set t (and for
// the cylinder the axial parameter u_i of the chosen root, used for its
// normal and texture).
// Section 2.2: a = D.D, b = 2 D.L, c = L.L - r^2 (L = O - C); the smaller
// root, else the larger; t <= tMin is a miss.
bool hitSphere(const Object& s, const Ray& ray, double tMin, double tMax, double& t);
// Section 3.2 (CGL-E40: c = L.L - r^2; CGL-Q46: only the chosen root's u_i is
// range-checked, so a ray whose near root lies beyond an end misses even when
// its far root is on the cylinder).
bool hitCylinder(const Object& cyl, const Ray& ray, double tMin, double tMax, double& t,
                 double& axial);
// Section 4.2: t from the plane, then I.N_Ek - d_k >= 0 for every edge.
bool hitPolygon(const Object& poly, const Ray& ray, double tMin, double tMax, double& t);
// The ray/box test (section 7 and ICube, Appendix 4): the entry parameter
// of the ray into the box for t >= 0 (0 when it starts inside), or +infinity
// when it misses it ahead (CGL-Q48).
double boxEntry(const Object& box, const BoxRay& ray);

// The geometric normal at the hit point, before any facing: sphere
// (I - C)/|I - C|; cylinder (I - (A + u_i P)) normalised; polygon N. A
// fractal's is its facet's (facetNormal, src/cgl/fractal.h): the tracer asks
// the surface, and this returns 0 for it.
Vec3 normalAt(const Object& o, const Vec3& point, double axial);

// Texture coordinates in [0, 1] (sections 2.3, 3.3, 4.3): sphere
// ((N.A1)+1)/2, ((N.A2)+1)/2; cylinder u = u_i, v = ((N.A1)+1)/2; polygon
// I = V0 + u E1 + v N_E1 solved, then normalised by the min/max over the
// vertices; fractal (section 5.7) the x and z equations of the same frame
// solved, normalised by the min/max over the facet vertices. `normal` is the
// geometric normal (not faced).
void textureUv(const Object& o, const Vec3& point, const Vec3& normal, double axial, double& u,
               double& v);

// Section 10: u_i = int(512 u umod) mod 512 (likewise v), as C coerces (the
// integer part, towards zero), then folded into 0..511 (CGL-Q50).
int textureIndex(double u, double mod);

}  // namespace prime::cgl
