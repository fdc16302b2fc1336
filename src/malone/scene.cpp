#include "src/malone/scene.h"

#include <cmath>
#include <numbers>

namespace prime::malone {

namespace {

Vec3 at(const std::vector<double>& v, std::size_t i) {
  return {v[i], v[i + 1], v[i + 2]};
}

[[noreturn]] void refuse(const PrimitiveRecord& p, const std::string& field,
                         const std::string& expected, const std::string& found) {
  throw io::InputError(p.where, std::string(objectName(static_cast<int>(p.id))) + ", " + field,
                       expected, found);
}

std::string str(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
std::string str(const Vec3& v) {
  return "(" + str(v[0]) + ", " + str(v[1]) + ", " + str(v[2]) + ")";
}

Vec3 unitOrRefuse(const PrimitiveRecord& p, const std::string& field, const Vec3& v) {
  const double len = length(v);
  if (!(len > 0) || !std::isfinite(len)) refuse(p, field, "a non-zero vector", str(v));
  return v * (1.0 / len);
}

// The plane through `v0` spanned by a and b, as triangles and parallelograms
// precalculate it (section 2.5): the normal a x b, and the dot products of
// the barycentric test.
void spanned(Primitive& q, const PrimitiveRecord& p, const Vec3& v0, const Vec3& a, const Vec3& b) {
  q.c = v0;
  q.a = a;
  q.b = b;
  q.aa = dot(a, a);
  q.ab = dot(a, b);
  q.bb = dot(b, b);
  q.det = q.aa * q.bb - q.ab * q.ab;
  const Vec3 normal = cross(a, b);
  if (!(q.det > 1e-12 * q.aa * q.bb) || !(length(normal) > 0))
    refuse(p, "vertices", "three points that span a plane (not on one line)",
           "a degenerate shape: edges " + str(a) + " and " + str(b));
  q.n = normal * (1.0 / length(normal));
  q.D = dot(q.n, v0);
}

bool invert(const Mat3& m, Mat3& out) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  const double scale = length(m[0]) * length(m[1]) * length(m[2]);
  if (!(std::fabs(det) > 1e-12 * scale) || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  out[0] = {(m[1][1] * m[2][2] - m[1][2] * m[2][1]) * inv,
            (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv,
            (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv};
  out[1] = {(m[1][2] * m[2][0] - m[1][0] * m[2][2]) * inv,
            (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv,
            (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv};
  out[2] = {(m[1][0] * m[2][1] - m[1][1] * m[2][0]) * inv,
            (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv,
            (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv};
  return true;
}

Primitive build(const PrimitiveRecord& p, Scene& scene) {
  Primitive q;
  q.id = p.id;
  q.line = p.where.line.value_or(0);
  q.column = p.where.column.value_or(0);
  q.token = p.where.token.value_or(0);
  q.objectNumber = p.objectNumber;
  const auto& v = p.numbers;
  switch (p.id) {
    case ObjectId::Sphere:
      if (!(v[0] > 0)) refuse(p, "radius", "a radius > 0", str(v[0]));
      q.r = v[0];
      q.r2 = v[0] * v[0];
      q.c = at(v, 1);
      break;
    case ObjectId::Plane: {
      // n.x = D, normalised at read time (section 2.2).
      const Vec3 n = at(v, 1);
      const double len = length(n);
      q.n = unitOrRefuse(p, "normal", n);
      q.D = v[0] / len;
      break;
    }
    case ObjectId::Disk:
    case ObjectId::Annulus:
      q.c = at(v, 0);
      q.n = unitOrRefuse(p, "normal", at(v, 3));
      q.D = dot(q.n, q.c);
      if (!(v[6] > 0)) refuse(p, "radius", "a radius > 0", str(v[6]));
      q.r = v[6];
      q.r2 = v[6] * v[6];
      if (p.id == ObjectId::Annulus) {
        if (!(v[7] >= 0 && v[7] < v[6]))
          refuse(p, "r_in", "an inner radius from 0 to below the radius " + str(v[6]), str(v[7]));
        q.rIn2 = v[7] * v[7];
      }
      break;
    case ObjectId::Triangle:
      spanned(q, p, at(v, 0), at(v, 3) - at(v, 0), at(v, 6) - at(v, 0));
      break;
    case ObjectId::Parallelogram:
      spanned(q, p, at(v, 0), at(v, 3), at(v, 6));
      break;
    case ObjectId::Cone:
    case ObjectId::Cylinder: {
      const bool cone = p.id == ObjectId::Cone;
      if (cone) {
        if (!(v[0] > 0 && v[0] < 1))
          refuse(p, "alpha", "cos(theta) strictly between 0 and 1", str(v[0]));
        q.alpha = v[0];
        q.alpha2 = v[0] * v[0];
      } else {
        if (!(v[0] > 0)) refuse(p, "radius", "a radius > 0", str(v[0]));
        q.r = v[0];
        q.r2 = v[0] * v[0];
      }
      q.lo = std::min(v[1], v[2]);
      q.hi = std::max(v[1], v[2]);
      q.c = at(v, 3);
      q.axis = at(v, 6);
      q.u = unitOrRefuse(p, "axis", q.axis);
      q.axis2 = dot(q.axis, q.axis);
      break;
    }
    case ObjectId::Torus:
      if (!(v[1] > 0)) refuse(p, "r", "a tube radius > 0", str(v[1]));
      if (!(v[0] > 0)) refuse(p, "R", "a ring radius > 0", str(v[0]));
      q.R = v[0];
      q.r = v[1];
      q.c = at(v, 2);
      q.u = unitOrRefuse(p, "axis", at(v, 5));
      break;
    case ObjectId::Polygon: {
      const int n = static_cast<int>(v[0]);
      q.first = static_cast<int>(scene.polygonVertices.size());
      q.count = n;
      Vec3 newell{};
      for (int i = 0; i < n; ++i) {
        const Vec3 a = at(v, 1 + 3 * i), b = at(v, 1 + 3 * ((i + 1) % n));
        newell[0] += (a[1] - b[1]) * (a[2] + b[2]);
        newell[1] += (a[2] - b[2]) * (a[0] + b[0]);
        newell[2] += (a[0] - b[0]) * (a[1] + b[1]);
        scene.polygonVertices.push_back(a);
      }
      const double len = length(newell);
      double extent = 0;
      for (int i = 1; i < n; ++i) extent = std::max(extent, length(at(v, 1 + 3 * i) - at(v, 1)));
      if (!(len > 1e-12 * extent * extent))
        refuse(p, "vertices", "a polygon that encloses an area (not all on one line)",
               "a degenerate polygon of " + std::to_string(n) + " vertices");
      q.n = newell * (1.0 / len);
      q.D = dot(q.n, at(v, 1));
      int drop = 0;
      for (int k = 1; k < 3; ++k)
        if (std::fabs(q.n[k]) > std::fabs(q.n[drop])) drop = k;
      q.dropAxis = drop;
      break;
    }
    case ObjectId::Affine: {
      // M = (X Y Z)^-1, X, Y, Z the columns (section 2.6).
      q.c = at(v, 0);
      const Vec3 X = at(v, 3), Y = at(v, 6), Z = at(v, 9);
      const Mat3 cols = {Vec3{X[0], Y[0], Z[0]}, Vec3{X[1], Y[1], Z[1]}, Vec3{X[2], Y[2], Z[2]}};
      Affine affine;
      affine.mInv = cols;
      if (!invert(cols, affine.m))
        refuse(p, "X, Y, Z", "three independent axes (the matrix (X Y Z) is inverted)",
               "a singular matrix: X " + str(X) + ", Y " + str(Y) + ", Z " + str(Z));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) affine.mT[i][j] = affine.m[j][i];
      const Primitive inner = build(*p.inner, scene);
      scene.embedded.push_back(inner);
      affine.inner = static_cast<int>(scene.embedded.size()) - 1;
      scene.affines.push_back(affine);
      q.affine = static_cast<int>(scene.affines.size()) - 1;
      break;
    }
    default:
      refuse(p, "ID", "a primitive", std::to_string(static_cast<int>(p.id)));
  }
  return q;
}

}  // namespace

std::vector<Vec3> sphereSamples(const Vec3& centre, double radius, int count) {
  std::vector<Vec3> out;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = count == 1 ? 0.0 : 1.0 - 2.0 * (i + 0.5) / count;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * i;
    out.push_back(centre + Vec3{rho * std::cos(phi), rho * std::sin(phi), z} * radius);
  }
  if (count == 1) out[0] = centre;
  return out;
}

Scene buildScene(const SceneFile& file, const std::string& name) {
  Scene scene;
  scene.name = name;
  for (const auto& s : file.surfaces) {
    if (s.kt > 0 && !(s.index > 0))
      throw io::InputError(s.where, "surface, index",
                           "a refractive index > 0 on a transparent surface (k_t > 0)",
                           str(s.index));
    Surface t;
    t.colour = {s.colour[0], s.colour[1], s.colour[2]};
    for (int k = 0; k < 3; ++k) t.kd[k] = s.kd * s.colour[k];
    t.diffuse = s.kd;
    t.ks = s.ks;
    t.ke = s.ke;
    t.kt = s.kt;
    t.index = s.index;
    scene.surfaces.push_back(t);
  }
  scene.primitives.reserve(file.primitives.size());
  for (const auto& p : file.primitives) {
    Primitive q = build(p, scene);
    q.surface = p.surface;
    scene.primitives.push_back(q);
  }
  // Each sample of a sampled light is a light of its own (a shadow ray from
  // every shaded point): the scene's total is capped, as each light's count
  // is by the reader, before any is made.
  long samples = 0;
  for (const auto& l : file.lights) {
    if (l.id != ObjectId::SampledLight) continue;
    if (samples + l.samples > kMaxLightSamples)
      throw io::InputError(l.where, "sampled light, samples",
                           "at most " + std::to_string(kMaxLightSamples) +
                               " samples of sampled lights in the whole scene (" +
                               std::to_string(samples) + " before this light)",
                           std::to_string(l.samples) + " more");
    samples += l.samples;
  }
  scene.lights.reserve(static_cast<std::size_t>(samples) + file.lights.size());
  for (const auto& l : file.lights) {
    const Rgb rgb{l.rgb[0], l.rgb[1], l.rgb[2]};
    if (l.id == ObjectId::SampledLight) {
      if (!(l.radius >= 0))
        throw io::InputError(l.where, "sampled light, radius", "a radius >= 0", str(l.radius));
      const auto points = sphereSamples(l.position, l.radius, l.samples);
      for (const auto& pt : points)
        if (!(std::isfinite(pt[0]) && std::isfinite(pt[1]) && std::isfinite(pt[2])))
          throw io::InputError(l.where, "sampled light, radius",
                               "a sphere of finite points (centre and radius within the range "
                               "of a double)",
                               "centre " + str(l.position) + ", radius " + str(l.radius) +
                                   ", which puts a sample at " + str(pt));
      for (const auto& pt : points)
        scene.lights.push_back({pt,
                                {rgb[0] / l.samples, rgb[1] / l.samples, rgb[2] / l.samples},
                                true,
                                scene.lightCount});
    } else {
      scene.lights.push_back({l.position, rgb, l.id == ObjectId::PointLight, scene.lightCount});
    }
    ++scene.lightCount;
  }
  for (const auto& a : file.ambients) {
    for (int k = 0; k < 3; ++k) scene.ambient[k] += a[k];
    scene.hasAmbient = true;
  }
  const auto& v = file.viewer;
  if (!(length(v.lookAt - v.eye) > 0))
    throw io::InputError(v.where, "viewer, look-at", "a point other than the eye",
                         str(v.lookAt) + " (the eye itself)");
  scene.viewer = {v.eye, v.lookAt, v.x, v.y, v.xRes, v.yRes};
  return scene;
}

FreeCameraSettings freeCamera(const Viewer& v) {
  FreeCameraSettings c;
  c.eye = v.eye;
  c.lookAt = v.lookAt;
  c.up = v.y;
  c.fovY = 2.0 * std::atan(length(v.y)) * 180.0 / std::numbers::pi;
  c.width = v.xRes;
  c.height = v.yRes;
  return c;
}

Viewer viewerOf(const FreeCameraSettings& c) {
  const FreeCamera camera(c);  // the right and up a free camera has
  const double halfH = std::tan(0.5 * c.fovY * std::numbers::pi / 180.0);
  const double halfW = halfH * static_cast<double>(c.width) / static_cast<double>(c.height);
  Viewer v;
  v.eye = c.eye;
  v.lookAt = c.lookAt;
  v.x = camera.right() * halfW;
  v.y = camera.trueUp() * halfH;
  v.xRes = c.width;
  v.yRes = c.height;
  return v;
}

}  // namespace prime::malone
