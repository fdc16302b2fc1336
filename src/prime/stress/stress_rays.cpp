// The stress suite's random rays (stress_rays.h).
#include "src/prime/stress/stress_rays.h"

namespace prime::stress {

std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
  Rng r(a * 0x2545F4914F6CDD1Dull + b);
  return r.next();
}

Vec3 unitV(const Vec3& v) {
  const double l = std::sqrt(dot(v, v));
  return l > 0 ? v * (1 / l) : v;
}

namespace {

Vec3 perpendicular(const Vec3& n, Rng& rng) {  // a random unit vector perpendicular to n
  for (;;) {
    const Vec3 c = cross(n, rng.unitVector());
    if (dot(c, c) > 1e-6) return unitV(c);
  }
}

struct SurfacePoint {
  Vec3 p, n;    // point and outward unit normal (local)
  bool curved;  // on a curved surface (sphere, cylinder/cone body)
};

SurfacePoint surfacePoint(char type, Rng& rng) {
  switch (type) {
    case 'S': {
      const Vec3 n = rng.unitVector();
      return {n, n, true};
    }
    case 'B': {
      const int k = rng.below(3), side = rng.below(2);
      Vec3 p{rng.uniform(), rng.uniform(), rng.uniform()}, n{0, 0, 0};
      p[k] = side, n[k] = side ? 1 : -1;
      return {p, n, false};
    }
    case 'C': {
      const double f = rng.uniform(0, 2 * kPi);
      if (rng.below(10) < 7)
        return {{std::cos(f), std::sin(f), rng.uniform()}, {std::cos(f), std::sin(f), 0}, true};
      const double r = std::sqrt(rng.uniform());
      const bool top = rng.coin();
      return {{r * std::cos(f), r * std::sin(f), top ? 1.0 : 0.0}, {0, 0, top ? 1.0 : -1.0}, false};
    }
    case 'N': {
      const double f = rng.uniform(0, 2 * kPi);
      if (rng.below(10) < 7) {
        const double z = std::sqrt(rng.uniform());
        return {{z * std::cos(f), z * std::sin(f), z}, unitV({std::cos(f), std::sin(f), -1}), true};
      }
      const double r = std::sqrt(rng.uniform());
      return {{r * std::cos(f), r * std::sin(f), 1.0}, {0, 0, 1}, false};
    }
    default: {  // 'Y'
      const int face = rng.below(5);
      if (face == 4) return {{rng.uniform(), 0, rng.uniform()}, {0, -1, 0}, false};
      static const Vec3 base[4][2] = {{{0, 0, 0}, {1, 0, 0}},
                                      {{1, 0, 0}, {1, 0, 1}},
                                      {{1, 0, 1}, {0, 0, 1}},
                                      {{0, 0, 1}, {0, 0, 0}}};
      static const Vec3 normal[4] = {{0, 0.5, -1}, {1, 0.5, 0}, {0, 0.5, 1}, {-1, 0.5, 0}};
      double a = rng.uniform(), b = rng.uniform();
      if (a + b > 1) a = 1 - a, b = 1 - b;
      const Vec3 apex{0.5, 1, 0.5};
      const Vec3 p =
          base[face][0] + (base[face][1] - base[face][0]) * a + (apex - base[face][0]) * b;
      return {p, unitV(normal[face]), false};
    }
  }
}

struct EdgePoint {
  Vec3 p, e, n1, n2;  // point, edge direction, the two faces' outward normals
};

EdgePoint edgePoint(char type, Rng& rng) {
  switch (type) {
    case 'B': {
      const int k = rng.below(3), a = (k + 1) % 3, b = (k + 2) % 3;
      const int sa = rng.below(2), sb = rng.below(2);
      Vec3 p{}, e{0, 0, 0}, n1{0, 0, 0}, n2{0, 0, 0};
      p[k] = rng.uniform(), p[a] = sa, p[b] = sb;
      e[k] = 1, n1[a] = sa ? 1 : -1, n2[b] = sb ? 1 : -1;
      return {p, e, n1, n2};
    }
    case 'Y': {
      const Vec3 apex{0.5, 1, 0.5};
      static const Vec3 corner[4] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
      static const Vec3 normal[4] = {{0, 0.5, -1}, {1, 0.5, 0}, {0, 0.5, 1}, {-1, 0.5, 0}};
      const int i = rng.below(4);
      const double s = rng.uniform();
      if (rng.coin()) {  // a base edge: base and side face i
        const Vec3 a = corner[i], b = corner[(i + 1) % 4];
        return {a + (b - a) * s, unitV(b - a), {0, -1, 0}, unitV(normal[i])};
      }
      // a lateral edge from corner i to the apex: side faces i-1 and i
      const Vec3 a = corner[i];
      return {a + (apex - a) * s, unitV(apex - a), unitV(normal[(i + 3) % 4]), unitV(normal[i])};
    }
    case 'C': {
      const double f = rng.uniform(0, 2 * kPi);
      const bool top = rng.coin();
      return {{std::cos(f), std::sin(f), top ? 1.0 : 0.0},
              {-std::sin(f), std::cos(f), 0},
              {std::cos(f), std::sin(f), 0},
              {0, 0, top ? 1.0 : -1.0}};
    }
    case 'N': {
      const double f = rng.uniform(0, 2 * kPi);
      return {{std::cos(f), std::sin(f), 1},
              {-std::sin(f), std::cos(f), 0},
              unitV({std::cos(f), std::sin(f), -1}),
              {0, 0, 1}};
    }
    default: {  // the sphere has no edge: a tangent point stands in
      const Vec3 n = rng.unitVector();
      return {n, perpendicular(n, rng), n, n};
    }
  }
}

Vec3 vertexPoint(char type, Rng& rng) {
  switch (type) {
    case 'B':
      return {double(rng.below(2)), double(rng.below(2)), double(rng.below(2))};
    case 'Y': {
      static const Vec3 v[5] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0.5, 1, 0.5}};
      return v[rng.below(5)];
    }
    case 'N': {
      if (rng.coin()) return {0, 0, 0};  // the apex
      static const Vec3 v[4] = {{1, 0, 1}, {0, 1, 1}, {-1, 0, 1}, {0, -1, 1}};
      return v[rng.below(4)];
    }
    case 'C': {
      static const Vec3 v[8] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0},
                                {1, 0, 1}, {0, 1, 1}, {-1, 0, 1}, {0, -1, 1}};
      return v[rng.below(8)];
    }
    default: {  // the poles and axis points of the sphere's (u, v) mapping
      static const Vec3 v[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
      return v[rng.below(6)];
    }
  }
}

}  // namespace

Vec3 centreOf(char type) {
  switch (type) {
    case 'S':
      return {0, 0, 0};
    case 'C':
      return {0, 0, 0.5};
    case 'N':
      return {0, 0, 0.6};
    case 'Y':
      return {0.5, 0.3, 0.5};
    default:
      return {0.5, 0.5, 0.5};
  }
}
Vec3 interiorPoint(char type, Rng& rng) {
  const Vec3 c = centreOf(type);
  const double r = type == 'N' || type == 'Y' ? 0.15 : 0.3;
  return c + rng.unitVector() * (r * rng.uniform());
}

LocalRay uniformRay(char type, Rng& rng) {
  const Vec3 c = centreOf(type);
  const Vec3 o = c + rng.unitVector() * rng.uniform(1.8, 4.0);
  const Vec3 target =
      c + Vec3{rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9)};
  return {o, target - o};
}

LocalRay grazingRay(char type, Rng& rng) {
  const SurfacePoint s = surfacePoint(type, rng);
  const Vec3 t = perpendicular(s.n, rng);
  const double eps = (rng.coin() ? 1 : -1) * std::pow(10.0, -rng.uniform(2, 14));
  const Vec3 d = unitV(t + s.n * eps);
  return {s.p - d * rng.uniform(1, 3), d};
}

LocalRay tangentRay(char type, Rng& rng) {
  const SurfacePoint s = surfacePoint(type, rng);
  if (s.curved) {
    Vec3 t = perpendicular(s.n, rng);
    if (type == 'N' || type == 'C') {  // along the circle of the body: touches one point only
      t = unitV(Vec3{-s.n[1], s.n[0], 0});
    }
    return {s.p - t * rng.uniform(1, 3), t};
  }
  // A polyhedron (or a cap): a supporting line at an edge, touching only it.
  const EdgePoint e = edgePoint(type, rng);
  const Vec3 m = unitV(e.n1 + e.n2);
  Vec3 d = unitV(cross(m, e.e));
  d = unitV(d + e.e * rng.uniform(-1, 1));
  return {e.p - d * rng.uniform(1, 3), d};
}

LocalRay faceRay(char type, Rng& rng) {
  const SurfacePoint s = surfacePoint(type, rng);
  if (s.curved) {
    if (type == 'C') return {s.p - Vec3{0, 0, 2}, {0, 0, 1}};  // a generator line of the body
    if (type == 'N') {
      const Vec3 g = unitV(s.p);  // through the apex
      return {s.p - g * 2.0, g};
    }
    const Vec3 t = perpendicular(s.n, rng);
    return {s.p - t * 2.0, t};
  }
  const Vec3 t = perpendicular(s.n, rng);
  return {s.p - t * rng.uniform(1, 2), t};
}

LocalRay edgeRay(char type, Rng& rng) {
  const EdgePoint e = edgePoint(type, rng);
  if (rng.coin()) return {e.p - e.e * rng.uniform(0.5, 2), e.e};  // along the edge
  Vec3 d = rng.unitVector();
  if (dot(d, e.n1 + e.n2) > 0) d = -d;  // arriving from outside
  return {e.p - d * rng.uniform(1, 3), d};
}

LocalRay vertexRay(char type, Rng& rng) {
  const Vec3 v = vertexPoint(type, rng);
  Vec3 d = rng.unitVector();
  if (dot(d, v - centreOf(type)) > 0) d = -d;
  return {v - d * rng.uniform(1, 3), d};
}

LocalRay onSurfaceRay(char type, Rng& rng) {
  const SurfacePoint s = surfacePoint(type, rng);
  return {s.p, rng.unitVector()};
}

}  // namespace prime::stress
