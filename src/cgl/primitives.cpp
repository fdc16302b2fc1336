#include "src/cgl/primitives.h"

#include <cmath>

#include "src/cgl/fractal.h"

namespace prime::cgl {

const char* kindName(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::Sphere:
      return "sphere";
    case ObjectKind::Cylinder:
      return "cylinder";
    case ObjectKind::Polygon:
      return "polygon";
    case ObjectKind::Box:
      return "box";
    case ObjectKind::Fractal:
      return "fractal";
  }
  return "?";
}

bool hitSphere(const Object& s, const Ray& ray, double tMin, double tMax, double& t) {
  const Vec3 lambda = ray.o - s.c;
  const double a = dot(ray.d, ray.d);
  const double b = 2.0 * dot(ray.d, lambda);
  const double c = dot(lambda, lambda) - s.r2;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0 || a == 0.0) return false;
  const double root = std::sqrt(disc);
  double ti = (-b - root) / (2.0 * a);
  if (ti <= tMin) ti = (-b + root) / (2.0 * a);
  if (ti <= tMin || !(ti < tMax)) return false;
  t = ti;
  return true;
}

bool hitCylinder(const Object& cyl, const Ray& ray, double tMin, double tMax, double& t,
                 double& axial) {
  const double alpha = dot(ray.d, cyl.p) / cyl.pp;
  const Vec3 oa = ray.o - cyl.a;
  const double beta = dot(oa, cyl.p) / cyl.pp;
  const Vec3 lambda = oa - cyl.p * beta;
  const Vec3 omega = ray.d - cyl.p * alpha;
  const double a = dot(omega, omega);
  const double b = 2.0 * dot(omega, lambda);
  const double c = dot(lambda, lambda) - cyl.r2;  // printed "+ r^2": CGL-E40
  const double disc = b * b - 4.0 * a * c;
  // a = 0: the ray runs parallel to the axis and never crosses the open side.
  if (disc < 0.0 || a == 0.0) return false;
  const double root = std::sqrt(disc);
  double ti = (-b - root) / (2.0 * a);
  if (ti <= tMin) ti = (-b + root) / (2.0 * a);
  if (ti <= tMin || !(ti < tMax)) return false;
  // CGL-Q46: only the chosen root's u_i is checked, as printed.
  const double ui = alpha * ti + beta;
  if (ui < 0.0 || ui > 1.0) return false;
  t = ti;
  axial = ui;
  return true;
}

bool hitPolygon(const Object& poly, const Ray& ray, double tMin, double tMax, double& t) {
  const double denom = dot(ray.d, poly.n);
  if (denom == 0.0) return false;  // the ray runs in the plane's direction
  const double ti = dot(poly.v0 - ray.o, poly.n) / denom;
  if (ti <= tMin || !(ti < tMax)) return false;
  const Vec3 i = ray.o + ray.d * ti;
  for (int k = 0; k < poly.edges; ++k)
    if (dot(i, poly.en[k]) - poly.d[k] < 0.0) return false;
  t = ti;
  return true;
}

double boxEntry(const Object& box, const BoxRay& ray) {
  return box.box.entry(ray);
}

Vec3 normalAt(const Object& o, const Vec3& point, double axial) {
  switch (o.kind) {
    case ObjectKind::Sphere:
      return normalized(point - o.c);
    case ObjectKind::Cylinder:
      return normalized(point - (o.a + o.p * axial));
    case ObjectKind::Polygon:
      return o.n;
    case ObjectKind::Box:
    case ObjectKind::Fractal:  // the facet's: facetNormal (src/cgl/fractal.h)
      break;
  }
  return {0.0, 0.0, 0.0};
}

void textureUv(const Object& o, const Vec3& point, const Vec3& normal, double axial, double& u,
               double& v) {
  switch (o.kind) {
    case ObjectKind::Sphere:
      u = (dot(normal, o.a1) + 1.0) / 2.0;
      v = (dot(normal, o.a2) + 1.0) / 2.0;
      return;
    case ObjectKind::Cylinder:
      u = axial;
      v = (dot(normal, o.a1) + 1.0) / 2.0;
      return;
    case ObjectKind::Polygon: {
      const Vec3 q = point - o.v0;
      const double uu = dot(q, o.e1) / dot(o.e1, o.e1);
      const double vv = dot(q, o.ne1) / dot(o.ne1, o.ne1);
      u = (uu - o.umin) / (o.umax - o.umin);
      v = (vv - o.vmin) / (o.vmax - o.vmin);
      return;
    }
    case ObjectKind::Fractal:
      fractalTextureUv(o.v0, o.e1, o.ne1, o.umin, o.umax, o.vmin, o.vmax, point, u, v);
      return;
    case ObjectKind::Box:
      break;
  }
  u = v = 0.0;
}

int textureIndex(double u, double mod) {
  const double x = 512.0 * u * mod;
  if (!std::isfinite(x)) return 0;
  // int() of C: towards zero; then C's %, which keeps the sign, folded.
  const double whole = std::trunc(std::fmod(x, 512.0));
  int i = static_cast<int>(whole);
  if (i < 0) i += 512;
  return i % 512;
}

}  // namespace prime::cgl
