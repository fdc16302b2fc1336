// The stress generator and the measurements (see stress.h and docs/prime/numerics.md).
#include "src/prime/stress/stress.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/primitives_1991.h"
#include "src/prime/geom/uv_mapping_1991.h"
#include "src/prime/render/tracer_1991.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/stress/reference.h"
#include "src/prime/math/listing_vec.h"
#include "src/prime/math/listing_matrix.h"

namespace prime::stress {

// ------------------------------------------------------------------ figures

void ErrorHistogram::add(double e) {
  ++count;
  if (!(e > 0)) {
    if (e == 0) ++zeros;
    return;
  }
  max = std::max(max, e);
  int bin = static_cast<int>(std::floor((std::log10(e) + 20.0) * 10.0));
  bins[static_cast<std::size_t>(std::clamp(bin, 0, kBins - 1))]++;
}

double ErrorHistogram::quantile(double q) const {
  if (count == 0) return 0;
  const auto want = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count)));
  std::uint64_t seen = zeros;
  if (seen >= want) return 0;
  for (int i = 0; i < kBins; ++i) {
    seen += bins[static_cast<std::size_t>(i)];
    if (seen >= want) return std::min(max, std::pow(10.0, (i + 1) / 10.0 - 20.0));
  }
  return max;
}

ErrorHistogram& ErrorHistogram::operator+=(const ErrorHistogram& o) {
  for (int i = 0; i < kBins; ++i)
    bins[static_cast<std::size_t>(i)] += o.bins[static_cast<std::size_t>(i)];
  count += o.count;
  zeros += o.zeros;
  max = std::max(max, o.max);
  return *this;
}

Figures& Figures::operator+=(const Figures& o) {
  rays += o.rays, refHits += o.refHits, compared += o.compared;
  wrongHitMiss += o.wrongHitMiss, ambiguousHitMiss += o.ambiguousHitMiss;
  wrongInOut += o.wrongInOut, ambiguousInOut += o.ambiguousInOut;
  wrongSurface += o.wrongSurface, ambiguousSurface += o.ambiguousSurface;
  nanInf += o.nanInf, uvNan += o.uvNan;
  secondary += o.secondary, selfHits += o.selfHits, wrongSide += o.wrongSide;
  semanticK7 += o.semanticK7, semanticCsg += o.semanticCsg, semanticK4 += o.semanticK4;
  listingErrors += o.listingErrors, uvFaceChanges += o.uvFaceChanges, refDisagree += o.refDisagree;
  chains += o.chains, chainSteps += o.chainSteps, chainsComplete += o.chainsComplete;
  tRel += o.tRel, normalAngle += o.normalAngle, uv += o.uv;
  return *this;
}

const std::vector<ClassInfo>& stressClasses() {
  static const std::vector<ClassInfo> classes{
      {"uniform", "baseline: random rays from outside at the solid, moderate transforms"},
      {"grazing", "rays meeting a surface at 1e-2..1e-14 rad off tangent"},
      {"tangent", "rays tangent to a curved surface, or touching a polyhedron at an edge only"},
      {"face", "rays lying in a face plane, along a cylinder/cone generator, in a cap plane"},
      {"edge", "rays along an edge, or through an edge point from outside"},
      {"vertex", "rays through a vertex (corners, apex, poles, rim points)"},
      {"on-surface", "origins on the surface (as secondary rays have), any direction"},
      {"scale", "uniform rays and grazing rays, the solid scaled by 1e-6 .. 1e6"},
      {"translate", "the solid translated by up to 1e6, rays from nearby"},
      {"near-singular", "axis scales in a ratio of 1e4 .. 1e9, then rotated"},
      {"rot90", "rotations by multiples of 90 degrees (K3: not snapped), face/edge/vertex rays"},
      {"coincident", "CSG operands with coincident faces (shared, touching, identical)"},
      {"tir-chain", "chains of 16 internal reflections inside the solid"},
      {"mirrors", "two parallel mirrors 1e-3 .. 1e3 apart, 16 bounces"},
  };
  return classes;
}

namespace {

using LD = long double;
constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr LD kPi = 3.141592653589793238462643383279502884L;

// ------------------------------------------------------------------ random

struct Rng {
  std::uint64_t s;
  explicit Rng(std::uint64_t seed) : s(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
  bool coin() { return (next() & 1) != 0; }
  Vec3 unitVector() {
    for (;;) {
      const Vec3 v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      const double l = dot(v, v);
      if (l > 1e-4 && l <= 1) return v * (1 / std::sqrt(l));
    }
  }
};

std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
  Rng r(a * 0x2545F4914F6CDD1Dull + b);
  return r.next();
}

Vec3 unitV(const Vec3& v) {
  const double l = std::sqrt(dot(v, v));
  return l > 0 ? v * (1 / l) : v;
}
Vec3 perpendicular(const Vec3& n, Rng& rng) {  // a random unit vector perpendicular to n
  for (;;) {
    const Vec3 c = cross(n, rng.unitVector());
    if (dot(c, c) > 1e-6) return unitV(c);
  }
}

// ------------------------------------------------------------------ local features

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

struct LocalRay {
  Vec3 o, d;
};

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

// ------------------------------------------------------------------ subjects

struct Subject {
  Scene scene;
  std::vector<RefPrim<LD>> refLd;
  std::vector<RefPrim<Quad>> refQ;
  double size = 1;  // world size of the solids (for the self-intersection distance)
};

Matrix4 listingTransform(const Vec3& s, const Vec3& t, const Vec3& r) {
  Matrix4 m = identity4();
  transform(m, s, t, {0, 0, 0}, r);
  return m;
}

// The same with EXACT quarter turns (r in multiples of 90 degrees).
Matrix4 exactQuarterTransform(const Vec3& s, const Vec3& t, const std::array<int, 3>& quarters) {
  Matrix4 m = identity4();
  scale(m, s);
  auto cs = [](int q, double& c, double& sn) {
    static const double C[4] = {1, 0, -1, 0}, S[4] = {0, 1, 0, -1};
    c = C[((q % 4) + 4) % 4], sn = S[((q % 4) + 4) % 4];
  };
  double c, sn;
  cs(quarters[0], c, sn);
  for (int i = 0; i < 4; ++i) {
    const double tmp = m[i][Y];
    m[i][Y] = tmp * c - m[i][Z] * sn;
    m[i][Z] = m[i][Z] * c + tmp * sn;
  }
  cs(quarters[1], c, sn);
  for (int i = 0; i < 4; ++i) {
    const double tmp = m[i][X];
    m[i][X] = tmp * c + m[i][Z] * sn;
    m[i][Z] = m[i][Z] * c - tmp * sn;
  }
  cs(quarters[2], c, sn);
  for (int i = 0; i < 4; ++i) {
    const double tmp = m[i][X];
    m[i][X] = tmp * c - m[i][Y] * sn;
    m[i][Y] = m[i][Y] * c + tmp * sn;
  }
  translate(m, t);
  return m;
}

Matrix4 mul(Matrix4 a, const Matrix4& b) {
  matrixMul(a, b);
  return a;
}

struct PrimSpec {
  char type;
  Matrix4 m;
};

Subject makeSubject(const std::vector<PrimSpec>& prims,
                    const std::vector<std::vector<CsgEntry>>& objects) {
  Subject s;
  s.scene.name = "stress";
  s.scene.maps.resize(2);
  s.scene.maps[1].uScale = s.scene.maps[1].vScale = 1;
  for (auto& c : s.scene.maps[1].channel) c = {0.5};
  s.scene.ambient = {0.2, 0.2, 0.2};
  s.size = 0;
  for (const PrimSpec& p : prims) {
    ScenePrim sp;
    sp.type = io::primType(p.type).value();  // the generator's letters are all valid
    sp.transform = p.m;
    if (!inverse(p.m, sp.inverse)) throw std::logic_error("stress: singular transform");
    for (auto& m : sp.map) m = {1, 1};
    s.scene.prims.push_back(sp);
    s.refLd.push_back(RefPrim<LD>::make(p.type, p.m));
    s.refQ.push_back(RefPrim<Quad>::make(p.type, p.m));
    double norm = 0;
    for (int i = 0; i < 3; ++i)
      norm = std::max(norm, std::abs(p.m[i][0]) + std::abs(p.m[i][1]) + std::abs(p.m[i][2]));
    s.size = std::max(s.size, norm);
  }
  int number = 1;
  for (const auto& entries : objects) {
    SceneObject o;
    o.number = number++;
    o.entries = entries;
    o.hue.kDR = 0.5, o.hue.kDT = 0.5, o.hue.fDR = {0.5, 0.5, 0.5}, o.hue.tT = 1, o.hue.indx = 1.5;
    s.scene.objects.push_back(o);
  }
  return s;
}

// ------------------------------------------------------------------ reference evaluation

struct RefResult {
  bool hit = false, exit = false;
  LD t = 0, a = 0, b = 0;  // the nearest boundary ahead, and its solid span [a, b]
  int obj = -1, prim = -1;
  V3<LD> n{};  // outward normal of the result solid there (local frame of prim)
};

template <class T>
RefList<T> refObject(const std::vector<CsgEntry>& e, int node,
                     const std::vector<std::optional<RefInterval<T>>>& iv, int depth = 0) {
  if (node < 0 || node >= static_cast<int>(e.size()) || depth > static_cast<int>(e.size()))
    return {};
  const CsgEntry& c = e[static_cast<std::size_t>(node)];
  if (c.op == 'P') {
    const auto& h = iv[static_cast<std::size_t>(c.l)];
    if (!h) return {};
    return {{{h->tIn, c.l, h->nIn}, {h->tOut, c.l, h->nOut}}};
  }
  RefList<T> a = refObject(e, c.l, iv, depth + 1);
  if (a.empty() && (c.op == '-' || c.op == '&')) return a;
  return refCombine(c.op, a, refObject(e, c.r, iv, depth + 1));
}

template <class T>
RefResult refNearest(const Subject& s, const std::vector<RefPrim<T>>& prims, const Ray& ray,
                     bool k7) {
  std::vector<std::optional<RefInterval<T>>> iv(prims.size());
  const RefRay<T> w{cast3<T>(ray.o), cast3<T>(ray.d)};
  for (std::size_t k = 0; k < prims.size(); ++k) {
    const RefRay<T> l{prims[k].toLocalPoint(w.o), prims[k].toLocalVector(w.d)};
    RefInterval<T> in;
    if (refIntersect(prims[k].type, l, in) && (!k7 || in.tIn > T(0))) iv[k] = in;
  }
  RefResult r;
  for (std::size_t o = 0; o < s.scene.objects.size(); ++o) {
    const RefList<T> list = refObject(s.scene.objects[o].entries, 0, iv);
    for (const auto& span : list) {
      const bool entry = span.in.t > T(0);
      if (!entry && !(span.out.t > T(0))) continue;
      const RefNode<T>& node = entry ? span.in : span.out;
      if (!r.hit || LD(node.t) < r.t) {
        r.hit = true, r.exit = !entry, r.t = LD(node.t), r.a = LD(span.in.t), r.b = LD(span.out.t);
        r.obj = static_cast<int>(o), r.prim = node.prim, r.n = cast3<LD>(node.n);
      }
      break;
    }
  }
  return r;
}

// ------------------------------------------------------------------ the profiles

struct ProfileHit {
  bool hit = false, exit = false, error = false;
  double t = 0;
  int obj = -1, prim = -1;
  Vec3 point{}, local{}, normal{}, pointError{};
  SurfaceHit surf;  // the modern profile's whole answer (spawnOrigin needs it)
};

ProfileHit modernHit(const TracerModern& tracer, const Ray& ray) {
  TraceStats stats;
  SurfaceHit h;
  ProfileHit p;
  if (!tracer.nearestHit(ray, h, stats)) return p;
  p.hit = true, p.exit = h.exitsObject, p.t = h.t, p.obj = h.obj, p.prim = h.prim;
  p.point = h.point, p.local = h.local, p.normal = h.normal, p.pointError = h.pointError;
  p.surf = h;
  return p;
}

// CastRay's nearest-object search of the 1991 profile (tracer_1991.cpp),
// over the object list in order, without bounds (the stress scenes have none).
ProfileHit listingHit(const Scene& scene, const Ray& rayIn) {
  Ray ray = rayIn;
  unitVector(ray.d, ray.d);  // E41
  ProfileHit p;
  double nearest = 1e100;
  for (int k = 0; k < static_cast<int>(scene.objects.size()); ++k) {
    auto leaf = [&](int primNum) -> std::optional<PrimHit> {
      const ScenePrim& sp = scene.prims[static_cast<std::size_t>(primNum)];
      PrimHit h;
      if (!intersectPrimitive1991(sp.type, transformRay(ray, sp.inverse), h)) return std::nullopt;
      return h;
    };
    TList list;
    try {
      list = csg1991(scene.objects[static_cast<std::size_t>(k)].entries, leaf, {});
    } catch (const CsgError&) {
      p.error = true;
      return p;
    }
    if (list.empty()) continue;
    const double t = list.front().t;  // K30
    if (t != 0.0 && t < nearest) {
      nearest = t;
      p.hit = true, p.t = t, p.obj = k, p.prim = list.front().prim,
      p.exit = list.front().surfType == kSurfIn;
      Vec3 n{};
      unitVector(list.front().norm, n);
      p.normal = n;
    }
  }
  if (!p.hit) return p;
  const ScenePrim& sp = scene.prims[static_cast<std::size_t>(p.prim)];
  const Ray local = transformRay(ray, sp.inverse);
  for (int i = 0; i < 3; ++i) {
    p.point[i] = ray.o[i] + p.t * ray.d[i];
    p.local[i] = local.o[i] + p.t * local.d[i];
  }
  Vec3 n = vectorMatrixMul(p.normal, sp.transform);  // K4
  unitVector(n, n);
  p.normal = n;
  return p;
}

// What csg1991 makes of the REFERENCE intervals (K7-filtered, rounded to
// double): separates the printed operators' set errors (semantic) from
// rounding.
ProfileHit listingOnReference(const Subject& s, const Ray& ray) {
  ProfileHit p;
  double nearest = 1e100;
  const RefRay<LD> w{cast3<LD>(ray.o), cast3<LD>(ray.d)};
  for (int k = 0; k < static_cast<int>(s.scene.objects.size()); ++k) {
    auto leaf = [&](int primNum) -> std::optional<PrimHit> {
      const RefPrim<LD>& rp = s.refLd[static_cast<std::size_t>(primNum)];
      const RefRay<LD> l{rp.toLocalPoint(w.o), rp.toLocalVector(w.d)};
      RefInterval<LD> in;
      if (!refIntersect(rp.type, l, in) || !(in.tIn > 0)) return std::nullopt;
      const Vec3 nIn{double(in.nIn[0]), double(in.nIn[1]), double(in.nIn[2])};
      const Vec3 nOut{double(in.nOut[0]), double(in.nOut[1]), double(in.nOut[2])};
      return PrimHit{double(in.tIn), double(in.tOut), nIn, nOut};
    };
    TList list;
    try {
      list = csg1991(s.scene.objects[static_cast<std::size_t>(k)].entries, leaf, {});
    } catch (const CsgError&) {
      p.error = true;
      return p;
    }
    if (list.empty()) continue;
    const double t = list.front().t;
    if (t != 0.0 && t < nearest) {
      nearest = t;
      p.hit = true, p.t = t, p.obj = k, p.prim = list.front().prim,
      p.exit = list.front().surfType == kSurfIn;
    }
  }
  return p;
}

// ------------------------------------------------------------------ the measurement

LD normInf(const Vec3& v) {
  return std::max({std::abs(LD(v[0])), std::abs(LD(v[1])), std::abs(LD(v[2]))});
}

LD angleBetween(const V3<LD>& a, const V3<LD>& b) {
  const V3<LD> c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(dot3(c, c)), dot3(a, b));
}

// PRIME_STRESS_DEBUG=1: print every wrong decision and every large normal
// error to stderr (for investigating a class).
bool debugOn() {
  static const bool on = std::getenv("PRIME_STRESS_DEBUG") != nullptr;
  return on;
}
void debugRay(const char* what, const std::string& types, const Ray& ray, double pt, long double rt,
              bool listing) {
  if (!debugOn()) return;
  std::fprintf(stderr,
               "%s %s [%s] o=(%.17g,%.17g,%.17g) d=(%.17g,%.17g,%.17g) p.t=%.17g r.t=%.17Lg\n",
               what, listing ? "1991" : "modern", types.c_str(), ray.o[0], ray.o[1], ray.o[2],
               ray.d[0], ray.d[1], ray.d[2], pt, rt);
}

bool finiteV(const Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

class Measurer {
 public:
  Measurer(const Subject& s, const StressOptions& o)
      : s_(s), c_(o.toleranceUlps), quad_(o.quad && kHaveQuad) {}

  // The reference for `ray` (design semantics for the 1991 profile when k7).
  RefResult reference(const Ray& ray, bool k7, Figures& f) const {
    RefResult ld = refNearest(s_, s_.refLd, ray, k7);
    if (!quad_) return ld;
    RefResult q = refNearest(s_, s_.refQ, ray, k7);
    const LD scale = std::abs(q.t) + LD(s_.size);
    if (ld.hit != q.hit ||
        (q.hit && (ld.exit != q.exit || std::abs(ld.t - q.t) > 1e-12L * scale))) {
      ++f.refDisagree;
      return q;
    }
    return ld;
  }

  // Tolerance (local units of prim k) at parameter t of the world ray.
  LD tolerance(int k, const Ray& ray, LD t, const V3<LD>& pl) const {
    const RefPrim<LD>& rp = s_.refLd[static_cast<std::size_t>(k)];
    const LD tr = std::max({std::abs(rp.tr[0]), std::abs(rp.tr[1]), std::abs(rp.tr[2])});
    const LD world = normInf(ray.o) + std::abs(t) * normInf(ray.d) + tr;
    const LD local = 1 + std::max({std::abs(pl[0]), std::abs(pl[1]), std::abs(pl[2])});
    return LD(c_) * LD(kU) * (world * rp.invNorm + local);
  }

  // Signed distance in tolerances of the object's solid at ray(t).
  LD objectNsdf(int obj, const Ray& ray, LD t) const {
    const RefRay<LD> w{cast3<LD>(ray.o), cast3<LD>(ray.d)};
    const V3<LD> pw = w.at(t);
    const auto& e = s_.scene.objects[static_cast<std::size_t>(obj)].entries;
    return nsdf(e, 0, pw, ray, t, 0);
  }
  LD sceneNsdf(const Ray& ray, LD t) const {
    LD best = std::numeric_limits<LD>::infinity();
    for (int o = 0; o < static_cast<int>(s_.scene.objects.size()); ++o) {
      const LD v = objectNsdf(o, ray, t);
      if (std::abs(v) < std::abs(best)) best = v;
    }
    return best;
  }
  // The extreme (min when `inside`, else max) of the object's normalised
  // signed distance along [a, b] of the ray: sampled, then refined by
  // ternary search around the best sample.
  LD extreme(int obj, const Ray& ray, LD a, LD b, bool inside) const {
    const LD sign = inside ? 1 : -1;
    auto f = [&](LD t) { return sign * objectNsdf(obj, ray, t); };
    constexpr int n = 16;
    LD best = std::numeric_limits<LD>::infinity();
    int bi = 0;
    for (int i = 0; i <= n; ++i) {
      const LD v = f(a + (b - a) * i / n);
      if (v < best) best = v, bi = i;
    }
    LD lo = a + (b - a) * std::max(0, bi - 1) / n, hi = a + (b - a) * std::min(n, bi + 1) / n;
    for (int it = 0; it < 40; ++it) {
      const LD m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      const LD v1 = f(m1), v2 = f(m2);
      best = std::min({best, v1, v2});
      if (v1 < v2)
        hi = m2;
      else
        lo = m1;
    }
    return sign * best;
  }
  // True when the object's solid along [a, b] is nowhere deeper than one tolerance.
  bool thin(int obj, const Ray& ray, LD a, LD b) const {
    a = std::max(a, LD(0));
    if (!(b > a)) return true;
    return extreme(obj, ray, a, b, true) >= -1;
  }
  // Backward error of a hit at tp where the reference has its nearest
  // boundary at tr: the profile's point lies on the boundary within the
  // tolerance (a near touch, when tp < tr), and when tp > tr the stretch the
  // profile skipped is within the tolerance of the boundary too.
  bool explainable(int obj, const Ray& ray, LD tp, LD tr, bool refEnters) const {
    if (std::abs(objectNsdf(obj, ray, tp)) > 1) return false;
    if (tp < tr) return true;  // a near touch before the reference's boundary
    const LD a = std::min(tp, tr), b = std::max(tp, tr);
    // Entering at tr: inside after tr, outside before; leaving: the opposite.
    const bool insideBetween = (tp > tr) == refEnters;
    const LD e = extreme(obj, ray, a, b, insideBetween);
    return insideBetween ? e >= -1 : e <= 1;
  }

  // Compares a profile's answer with the reference; returns true when the
  // decisions agree without ambiguity (a clean hit, usable for secondaries).
  bool compare(const ProfileHit& p, const RefResult& r, const Ray& ray, bool listing,
               Figures& f) const {
    ++f.rays;
    if (r.hit) ++f.refHits;
    if (p.hit && (!std::isfinite(p.t) || !finiteV(p.point) || !finiteV(p.normal))) {
      ++f.nanInf;
      return false;
    }
    if (p.hit != r.hit) {
      bool amb;
      if (p.hit)
        amb = std::abs(sceneNsdf(ray, p.t)) <= 1;
      else
        amb = thin(r.obj, ray, r.exit ? 0 : r.a, r.b);
      ++(amb ? f.ambiguousHitMiss : f.wrongHitMiss);
      if (!amb)
        debugRay("wrong-hit/miss", describe(), ray, p.hit ? p.t : -1, r.hit ? r.t : -1, listing);
      return false;
    }
    if (!p.hit) return false;
    if (p.exit != r.exit) {
      const bool amb = std::abs(sceneNsdf(ray, 0)) <= 1 ||
                       thin(r.obj, ray, r.exit ? 0 : r.a, r.b) ||
                       std::abs(sceneNsdf(ray, p.t)) <= 1;
      ++(amb ? f.ambiguousInOut : f.wrongInOut);
      if (!amb) debugRay("wrong-in/out", describe(), ray, p.t, r.t, listing);
      return false;
    }
    const RefPrim<LD>& rp = s_.refLd[static_cast<std::size_t>(r.prim)];
    const RefRay<LD> w{cast3<LD>(ray.o), cast3<LD>(ray.d)};
    const RefRay<LD> l{rp.toLocalPoint(w.o), rp.toLocalVector(w.d)};
    const V3<LD> pl = l.at(r.t);
    const LD tol = tolerance(r.prim, ray, r.t, pl);
    const LD dLen = std::sqrt(dot3(l.d, l.d));
    const LD dt = std::abs(LD(p.t) - r.t);
    const bool sameSurface = p.prim == r.prim && dt <= 1e-6L * std::max(std::abs(r.t), LD(s_.size));
    if (dt * dLen > tol && !sameSurface) {  // not the reference's nearest surface
      const bool amb = (p.obj == r.obj && explainable(r.obj, ray, p.t, r.t, !r.exit)) ||
                       (LD(p.t) > r.t && thin(r.obj, ray, r.exit ? 0 : r.a, r.b)) ||
                       std::abs(sceneNsdf(ray, 0)) <= 1;
      ++(amb ? f.ambiguousSurface : f.wrongSurface);
      if (!amb && debugOn()) {
        debugRay("wrong-surface", describe(), ray, p.t, r.t, listing);
        const LD a = std::min(LD(p.t), r.t), b = std::max(LD(p.t), r.t);
        std::fprintf(stderr,
                     "  nsdf(p.t) %.3Lg nsdf(r.t) %.3Lg min %.3Lg max %.3Lg exit %d prim %d/%d\n",
                     objectNsdf(r.obj, ray, p.t), objectNsdf(r.obj, ray, r.t),
                     extreme(r.obj, ray, a, b, true), extreme(r.obj, ray, a, b, false), r.exit,
                     p.prim, r.prim);
      }
      return false;
    }
    ++f.compared;
    f.tRel.add(double(dt / std::max(std::abs(r.t), LD(s_.size))));
    // Normals: every face within the tolerance of the reference point.
    std::vector<V3<LD>> cands = refNormals(rp.type, pl, tol);
    if (!cands.empty()) {
      const V3<LD> d = unit3(cast3<LD>(ray.d));
      const V3<LD> pn = unit3(cast3<LD>(p.normal));
      LD best = std::numeric_limits<LD>::infinity();
      for (const V3<LD>& c : cands) {
        const V3<LD> cw = listing ? rp.normalByForward(c) : rp.normalToWorld(c);
        LD a = angleBetween(pn, cw);
        if (listing || std::abs(dot3(cw, d)) < 1e-6L)
          a = std::min(a, kPi - a);  // up to sign
        else if (dot3(cw, d) > 0)
          a = kPi - a;  // the profile faces it to the ray
        best = std::min(best, a);
      }
      if (listing && best > 1e-6L &&
          s_.scene.objects[static_cast<std::size_t>(r.obj)].entries.size() > 1) {
        // K31 and kin: the printed operators hand on another node's normal.
        const ProfileHit d = listingOnReference(s_, ray);
        if (d.hit && d.prim == p.prim) {
          const LD a = angleBetween(unit3(cast3<LD>(d.normal)), pn);
          if (std::min(a, kPi - a) < 1e-6L) {
            ++f.semanticCsg;
            best = -1;
          }
        }
      }
      if (best >= 0) f.normalAngle.add(double(best));
      if (best > 1e-6L && debugOn()) {
        debugRay("normal", describe(), ray, double(best), r.t, listing);
        const V3<LD> cw = listing ? rp.normalByForward(cands[0]) : rp.normalToWorld(cands[0]);
        std::fprintf(stderr,
                     "  p.prim %d r.prim %d exit %d/%d pn (%.6Lg %.6Lg %.6Lg) cand (%.6Lg %.6Lg "
                     "%.6Lg) n=%zu\n",
                     p.prim, r.prim, p.exit, r.exit, pn[0], pn[1], pn[2], cw[0], cw[1], cw[2],
                     cands.size());
      }
      if (listing) {
        const LD k4 = angleBetween(rp.normalByForward(cands[0]), rp.normalToWorld(cands[0]));
        if (std::min(k4, kPi - k4) > 1e-6L) ++f.semanticK4;
      }
    }
    // (u, v) by the listing's inverse mapping at both local points.
    if (p.prim == r.prim) {
      const Vec3 refLocal{double(pl[0]), double(pl[1]), double(pl[2])};
      const io::PrimType type = s_.scene.prims[static_cast<std::size_t>(r.prim)].type;
      const InverseMapResult a = inverseMap1991(type, p.local), b = inverseMap1991(type, refLocal);
      if (!std::isfinite(a.u) || !std::isfinite(a.v)) {
        ++f.uvNan;
      } else if (a.surface != b.surface) {
        ++f.uvFaceChanges;
      } else if (std::isfinite(b.u) && std::isfinite(b.v)) {
        double du = std::abs(a.u - b.u);
        if ((rp.type == 'S' || ((rp.type == 'C' || rp.type == 'N') && a.surface == 0)) && du > 0.5)
          du = std::abs(du - 1);
        f.uv.add(std::max(du, std::abs(a.v - b.v)));
      }
    }
    return true;
  }

  const Subject& subject() const { return s_; }
  // World unit normals of every face of the reference hit's primitive within
  // the tolerance of the reference hit point.
  std::vector<Vec3> worldNormalsAt(const RefResult& r, const Ray& ray) const {
    std::vector<Vec3> out;
    if (!r.hit) return out;
    const RefPrim<LD>& rp = s_.refLd[static_cast<std::size_t>(r.prim)];
    const RefRay<LD> w{cast3<LD>(ray.o), cast3<LD>(ray.d)};
    const RefRay<LD> l{rp.toLocalPoint(w.o), rp.toLocalVector(w.d)};
    const V3<LD> pl = l.at(r.t);
    for (const V3<LD>& c : refNormals(rp.type, pl, tolerance(r.prim, ray, r.t, pl))) {
      const V3<LD> n = rp.normalToWorld(c);
      out.push_back({double(n[0]), double(n[1]), double(n[2])});
    }
    return out;
  }
  std::string describe() const {
    std::string d;
    for (const auto& p : s_.scene.prims) d += static_cast<char>(p.type);
    for (const auto& o : s_.scene.objects) d += std::string(" ") + o.entries[0].op;
    return d;
  }

 private:
  LD nsdf(const std::vector<CsgEntry>& e, int node, const V3<LD>& pw, const Ray& ray, LD t,
          int depth) const {
    if (node < 0 || node >= static_cast<int>(e.size()) || depth > static_cast<int>(e.size()))
      return 1e30L;
    const CsgEntry& c = e[static_cast<std::size_t>(node)];
    if (c.op == 'P') {
      const RefPrim<LD>& rp = s_.refLd[static_cast<std::size_t>(c.l)];
      const V3<LD> pl = rp.toLocalPoint(pw);
      return refSdf(rp.type, pl) / tolerance(c.l, ray, t, pl);
    }
    const LD a = nsdf(e, c.l, pw, ray, t, depth + 1), b = nsdf(e, c.r, pw, ray, t, depth + 1);
    switch (c.op) {
      case '+':
        return std::min(a, b);
      case '&':
        return std::max(a, b);
      default:
        return std::max(a, -b);
    }
  }

  const Subject& s_;
  double c_;
  bool quad_;
};

// ------------------------------------------------------------------ one configuration

enum class Kind { Prim, Csg };

struct Config {
  Subject subject;
  std::vector<Ray> rays;  // world rays (unit directions)
  bool chainTir = false, chainMirror = false;
};

Ray toWorld(const LocalRay& l, const Matrix4& m) {
  Ray r{pointMatrixMul(l.o, m), vectorMatrixMul(l.d, m)};
  r.d = unitV(r.d);
  return r;
}

Vec3 randomAngles(Rng& rng) {
  return {rng.uniform(0, 360), rng.uniform(0, 360), rng.uniform(0, 360)};
}

Matrix4 classTransform(const std::string& cls, Rng& rng) {
  if (cls == "scale") {
    const double s = std::pow(10.0, rng.uniform(-6, 6));
    const Vec3 sv{s * rng.uniform(0.5, 2), s * rng.uniform(0.5, 2), s * rng.uniform(0.5, 2)};
    return listingTransform(sv,
                            Vec3{rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)} * s,
                            randomAngles(rng));
  }
  if (cls == "translate") {
    const double mag = std::pow(10.0, rng.uniform(3, 6));
    const Vec3 t{mag * rng.uniform(-1, 1), mag * rng.uniform(-1, 1), mag * rng.uniform(-1, 1)};
    const double s = std::pow(10.0, rng.uniform(-1, 2));
    return listingTransform({s, s * rng.uniform(0.5, 2), s}, t, randomAngles(rng));
  }
  if (cls == "near-singular") {
    const double thin = std::pow(10.0, -rng.uniform(4, 9));
    Vec3 sv{1, rng.uniform(0.5, 2), rng.uniform(0.5, 2)};
    sv[static_cast<std::size_t>(rng.below(3))] = thin;
    return listingTransform(sv * 10.0,
                            {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)},
                            randomAngles(rng));
  }
  // moderate: scale 0.1 .. 100, ratio up to 3, any rotation, translation up to 100
  const double s = std::pow(10.0, rng.uniform(-1, 2));
  return listingTransform(
      {s * rng.uniform(0.6, 1.8), s * rng.uniform(0.6, 1.8), s * rng.uniform(0.6, 1.8)},
      {rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100)}, randomAngles(rng));
}

LocalRay classRay(const std::string& cls, char type, Rng& rng) {
  if (cls == "grazing") return grazingRay(type, rng);
  if (cls == "tangent") return tangentRay(type, rng);
  if (cls == "face") return faceRay(type, rng);
  if (cls == "edge") return edgeRay(type, rng);
  if (cls == "vertex") return vertexRay(type, rng);
  if (cls == "on-surface") return onSurfaceRay(type, rng);
  if (cls == "rot90" || cls == "coincident") {
    switch (rng.below(5)) {
      case 0:
        return faceRay(type, rng);
      case 1:
        return edgeRay(type, rng);
      case 2:
        return vertexRay(type, rng);
      case 3:
        return onSurfaceRay(type, rng);
      default:
        return uniformRay(type, rng);
    }
  }
  if (cls == "scale" || cls == "translate" || cls == "near-singular") {
    switch (rng.below(4)) {
      case 0:
        return grazingRay(type, rng);
      case 1:
        return onSurfaceRay(type, rng);
      default:
        return uniformRay(type, rng);
    }
  }
  return uniformRay(type, rng);
}

constexpr char kTypes[5] = {'S', 'B', 'C', 'N', 'Y'};
constexpr char kOps[3] = {'+', '-', '&'};

// A CSG pair: B placed relative to A (row vectors: M_B = R * M_A).
Matrix4 csgRelative(Rng& rng, char ta, char tb, bool coincident) {
  if (!coincident) {
    const double s = rng.uniform(0.5, 1.1);
    const Vec3 ca = centreOf(ta), cb = centreOf(tb);
    const Vec3 t =
        ca - cb * s + Vec3{rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4)};
    return listingTransform({s, s, s}, t, {0, 0, 0});
  }
  switch (rng.below(4)) {
    case 0:
      return identity4();  // identical operands
    case 1: {              // touching along a whole face (shifted by exactly 1 or 0.5 on one axis)
      Vec3 t{0, 0, 0};
      t[static_cast<std::size_t>(rng.below(3))] = rng.coin() ? 1.0 : 0.5;
      return listingTransform({1, 1, 1}, t, {0, 0, 0});
    }
    case 2: {  // sharing faces: squashed on one axis (still from the same corner)
      Vec3 s{1, 1, 1};
      s[static_cast<std::size_t>(rng.below(3))] = 0.5;
      return listingTransform(s, {0, 0, 0}, {0, 0, 0});
    }
    default: {  // half-size, offset so that three faces coincide
      return listingTransform({0.5, 0.5, 0.5}, {0, 0, 0}, {0, 0, 0});
    }
  }
}

Config makeConfig(const std::string& cls, Kind kind, int which, int rays, Rng& rng) {
  Config c;
  if (cls == "mirrors") {
    const double g = std::pow(10.0, rng.uniform(-3, 3));
    const double w = 1e3 * g;
    const Matrix4 frame = listingTransform(
        {1, 1, 1}, {rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3), 0}, randomAngles(rng));
    const Matrix4 a =
        mul(listingTransform({w, w, 0.1 * g}, {-w / 2, -w / 2, -0.1 * g}, {0, 0, 0}), frame);
    const Matrix4 b = mul(listingTransform({w, w, 0.1 * g}, {-w / 2, -w / 2, g}, {0, 0, 0}), frame);
    c.subject = makeSubject({{'B', a}, {'B', b}}, {{{'P', 0, 0}}, {{'P', 1, 0}}});
    c.subject.size = g;
    c.chainMirror = true;
    for (int i = 0; i < rays; ++i) {
      const double th = rng.uniform(0, 1.0), ph = rng.uniform(0, 2 * kPi);
      const LocalRay l{{rng.uniform(-g, g), rng.uniform(-g, g), g * rng.uniform(0.2, 0.8)},
                       {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                        rng.coin() ? std::cos(th) : -std::cos(th)}};
      c.rays.push_back(toWorld(l, frame));
    }
    return c;
  }
  const bool rot90 = cls == "rot90";
  Matrix4 m, exact{};
  std::array<int, 3> q{};
  if (rot90) {
    q = {rng.below(4), rng.below(4), rng.below(4)};
    const Vec3 s{double(1 + rng.below(4)), double(1 + rng.below(4)), double(1 + rng.below(4))};
    const Vec3 t{double(rng.below(2001) - 1000), double(rng.below(2001) - 1000),
                 double(rng.below(2001) - 1000)};
    m = listingTransform(s, t, {90.0 * q[0], 90.0 * q[1], 90.0 * q[2]});
    exact = exactQuarterTransform(s, t, q);
  } else {
    m = classTransform(cls, rng);
  }
  std::vector<PrimSpec> prims;
  if (kind == Kind::Prim) {
    prims.push_back({kTypes[which], m});
    c.subject = makeSubject(prims, {{{'P', 0, 0}}});
  } else {
    const bool coincident = cls == "coincident";
    char ta = kTypes[rng.below(5)], tb = kTypes[rng.below(5)];
    if (coincident) {
      static const char pairs[5][2] = {{'B', 'B'}, {'B', 'Y'}, {'C', 'C'}, {'S', 'S'}, {'Y', 'Y'}};
      const int k = rng.below(5);
      ta = pairs[k][0], tb = pairs[k][1];
      if (ta == 'S' || ta == 'C') {  // identical or sharing the axis/caps only
        ta = tb;
      }
    }
    Matrix4 rel = csgRelative(rng, ta, tb, coincident);
    if (coincident && ta != 'B' && ta != 'Y' && rng.coin()) rel = identity4();
    prims.push_back({ta, m});
    prims.push_back({tb, mul(rel, m)});
    c.subject = makeSubject(prims, {{{kOps[which], 1, 2}, {'P', 0, 0}, {'P', 1, 0}}});
  }
  c.chainTir = cls == "tir-chain";
  for (int i = 0; i < rays; ++i) {
    const int k = rng.below(static_cast<int>(prims.size()));
    const char type = prims[static_cast<std::size_t>(k)].type;
    if (c.chainTir) {  // start inside the object's solid (an operand's interior may not be)
      for (int attempt = 0; attempt < 32; ++attempt) {
        const int q = rng.below(static_cast<int>(prims.size()));
        const Ray r =
            toWorld({interiorPoint(prims[static_cast<std::size_t>(q)].type, rng), rng.unitVector()},
                    prims[static_cast<std::size_t>(q)].m);
        const RefResult ref = refNearest(c.subject, c.subject.refLd, r, false);
        if (ref.hit && ref.exit) {
          c.rays.push_back(r);
          break;
        }
      }
      continue;
    }
    const LocalRay l = classRay(cls, type, rng);
    if (rot90) {
      c.rays.push_back(toWorld(l, k == 0 ? exact : prims[1].m));
    } else {
      c.rays.push_back(toWorld(l, prims[static_cast<std::size_t>(k)].m));
    }
  }
  return c;
}

Vec3 reflect(const Vec3& d, const Vec3& n) {
  return unitV(d - n * (2.0 * dot(d, n)));
}

// Is the origin of `ray` inside object `obj` (reference)?
bool refInside(const Measurer& m, int obj, const Ray& ray) {
  const Subject& s = m.subject();
  std::vector<std::optional<RefInterval<LD>>> iv(s.refLd.size());
  const RefRay<LD> w{cast3<LD>(ray.o), cast3<LD>(ray.d)};
  for (std::size_t k = 0; k < s.refLd.size(); ++k) {
    const RefRay<LD> l{s.refLd[k].toLocalPoint(w.o), s.refLd[k].toLocalVector(w.d)};
    RefInterval<LD> in;
    if (refIntersect(s.refLd[k].type, l, in)) iv[k] = in;
  }
  for (const auto& span : refObject(s.scene.objects[static_cast<std::size_t>(obj)].entries, 0, iv))
    if (span.in.t < 0 && span.out.t > 0) return true;
  return false;
}

void runModern(const Config& c, const Measurer& m, Figures& f) {
  TracerModern tracer(c.subject.scene);
  std::vector<Vec3> refWorldNormals;
  auto secondary = [&](const ProfileHit& p, const Ray& from, const Vec3& dir, bool wantInside) {
    ++f.secondary;
    const Ray sec{spawnOrigin(p.surf, dir), dir};
    const bool inside = refInside(m, p.obj, sec);
    // A direction within 1e-6 rad of a surface through the point (the
    // reference's faces there) has no defined side: not counted.
    bool grazing = false;
    for (const Vec3& n : refWorldNormals) grazing = grazing || std::abs(dot(n, dir)) < 1e-6;
    if (inside != wantInside && !grazing && !refWorldNormals.empty()) {
      ++f.wrongSide;
      if (debugOn()) {
        debugRay("wrong-side", m.describe(), from, p.t, wantInside, false);
        std::fprintf(stderr,
                     "  sec o=(%.17g,%.17g,%.17g) d=(%.17g,%.17g,%.17g) n=(%.6g,%.6g,%.6g) "
                     "err=(%.3g,%.3g,%.3g)\n",
                     sec.o[0], sec.o[1], sec.o[2], dir[0], dir[1], dir[2], p.normal[0], p.normal[1],
                     p.normal[2], p.pointError[0], p.pointError[1], p.pointError[2]);
      }
    }
    const ProfileHit q = modernHit(tracer, sec);
    // A self-hit: the new ray meets its own object again within a thousand
    // error bounds of its origin, where the reference (for the same origin)
    // has no boundary within twice that distance.
    const double tiny = 1e3 * std::max({p.pointError[0], p.pointError[1], p.pointError[2], 1e-300});
    if (q.hit && q.obj == p.obj && q.t < tiny) {
      Figures scratch;
      const RefResult r2 = m.reference(sec, false, scratch);
      if (!(r2.hit && r2.obj == p.obj && r2.t < 2 * tiny)) {
        ++f.selfHits;
        debugRay("self-hit", m.describe(), sec, q.t, r2.hit ? r2.t : -1, false);
        if (debugOn()) {
          TraceStats st;
          const TList l = tracer.objectIntervals(
              c.subject.scene.objects[static_cast<std::size_t>(p.obj)], sec, st);
          for (const TNode& nd : l)
            std::fprintf(stderr, "  node t=%.17g prim %d surf %d\n", nd.t, nd.prim, nd.surfType);
          const Ray loc = transformRay(
              sec,
              accurateInverse(c.subject.scene.prims[static_cast<std::size_t>(p.prim)].transform));
          const Ray loc0 = transformRay(
              from,
              accurateInverse(c.subject.scene.prims[static_cast<std::size_t>(p.prim)].transform));
          std::fprintf(stderr,
                       "  primary hit exit %d local hit (%.17g %.17g %.17g) sec local o (%.17g "
                       "%.17g %.17g) d (%.6g %.6g %.6g) n=(%.6g,%.6g,%.6g)\n",
                       p.exit, p.local[0], p.local[1], p.local[2], loc.o[0], loc.o[1], loc.o[2],
                       loc.d[0], loc.d[1], loc.d[2], p.normal[0], p.normal[1], p.normal[2]);
          (void)loc0;
        }
      }
    }
  };
  for (const Ray& start : c.rays) {
    if (c.chainTir || c.chainMirror) {
      ++f.chains;
      Ray ray = start;
      int step = 0;
      for (; step < 16; ++step) {
        const RefResult r = m.reference(ray, false, f);
        const ProfileHit p = modernHit(tracer, ray);
        const bool clean = m.compare(p, r, ray, false, f);
        ++f.chainSteps;
        if (debugOn() && (!p.hit || !clean))
          std::fprintf(stderr, "chain-break %s step %d p.hit %d r.hit %d r.exit %d p.exit %d\n",
                       m.describe().c_str(), step, p.hit, r.hit, r.exit, p.exit);
        if (!p.hit || !clean) break;
        const Vec3 d = reflect(ray.d, p.normal);
        ray = {spawnOrigin(p.surf, d), d};
      }
      if (step == 16) ++f.chainsComplete;
      continue;
    }
    const RefResult r = m.reference(start, false, f);
    const ProfileHit p = modernHit(tracer, start);
    if (!m.compare(p, r, start, false, f)) continue;
    if (m.thin(r.obj, start, r.exit ? 0 : r.a, r.b)) continue;
    refWorldNormals = m.worldNormalsAt(r, start);
    secondary(p, start, reflect(start.d, p.normal), p.exit);  // reflected: stays on its side
    secondary(p, start, start.d, !p.exit);                    // transmitted: crosses
  }
}

void run1991(const Config& c, const Measurer& m, Figures& f) {
  const Scene& scene = c.subject.scene;
  Tracer1991 tracer(scene);
  const double tau = 1e-6 * c.subject.size;
  for (const Ray& start : c.rays) {
    if (c.chainTir || c.chainMirror) {
      ++f.chains;
      // The listing's chains: TransmittedRay's TIR loop steps one unit back
      // along the new direction (K19); ReflectedRay one unit forward (K18).
      Ray ray = start;
      if (c.chainTir) ray.o = ray.o - ray.d;
      int step = 0;
      for (; step < 16; ++step) {
        const RefResult r = m.reference(ray, true, f);
        const ProfileHit p = listingHit(scene, ray);
        if (p.error) {
          ++f.listingErrors;
          break;
        }
        const bool clean = m.compare(p, r, ray, true, f);
        ++f.chainSteps;
        Figures scratchFull;
        const RefResult rFull = m.reference(ray, false, scratchFull);
        if (rFull.hit && !r.hit) ++f.semanticK7;
        if (!p.hit || !clean) break;
        if (c.chainTir) {
          // TransmittedRay 6960-6975 with total internal reflection forced.
          const SceneObject& obj = scene.objects[static_cast<std::size_t>(p.obj)];
          auto leaf = [&](int primNum) -> std::optional<PrimHit> {
            const ScenePrim& sp = scene.prims[static_cast<std::size_t>(primNum)];
            PrimHit h;
            if (!intersectPrimitive1991(sp.type, transformRay(ray, sp.inverse), h))
              return std::nullopt;
            return h;
          };
          TList list;
          try {
            list = csg1991(obj.entries, leaf, {});
          } catch (const CsgError&) {
            ++f.listingErrors;
            break;
          }
          if (list.size() < 2) break;  // E46
          const TNode& exit = list[1];
          const double c1 = dot(ray.d, exit.norm);
          for (int i = 0; i < 3; ++i) {
            ray.o[i] += exit.t * ray.d[i];
            ray.d[i] += 2.0 * c1 * -exit.norm[i];
            ray.o[i] -= ray.d[i];
          }
        } else {
          ray = tracer.reflectedRay(ray, p.t, p.normal);
        }
      }
      if (step == 16) ++f.chainsComplete;
      continue;
    }
    const RefResult r = m.reference(start, true, f);
    const ProfileHit p = listingHit(scene, start);
    if (p.error) {
      ++f.listingErrors;
      continue;
    }
    Figures scratchFull;  // (its ld/f128 disagreements are counted once, above)
    const RefResult rFull = m.reference(start, false, scratchFull);
    if (rFull.hit && (!r.hit || std::abs(rFull.t - r.t) > 1e-9L * (std::abs(r.t) + c.subject.size)))
      ++f.semanticK7;
    Figures probe;
    const bool cleanVsMeaning = m.compare(p, r, start, true, probe);
    if (scene.objects[0].entries.size() > 1 && !cleanVsMeaning && probe.wrongDecisions() > 0) {
      // Would the printed operators give this with exact intervals too?
      const ProfileHit d = listingOnReference(c.subject, start);
      if (d.hit == p.hit &&
          (!p.hit ||
           (d.exit == p.exit && std::abs(d.t - p.t) <= 1e-7 * (std::abs(p.t) + c.subject.size)))) {
        ++f.semanticCsg;
        ++f.rays;
        continue;
      }
    }
    f += probe;
    if (!cleanVsMeaning) continue;
    if (m.thin(r.obj, start, r.exit ? 0 : r.a, r.b)) continue;
    ++f.secondary;
    const Ray sec = tracer.reflectedRay(start, p.t, p.normal);  // K18: one unit along
    const ProfileHit q = listingHit(scene, sec);
    if (q.hit && q.obj == p.obj && q.t < tau) {
      Figures scratch;
      const RefResult r2 = m.reference(sec, true, scratch);
      m.compare(q, r2, sec, true, scratch);
      if (!(r2.hit && r2.obj == p.obj && r2.t < 2 * tau) && scratch.wrongDecisions() > 0)
        ++f.selfHits;
    }
  }
}

}  // namespace

Figures measureRays(char type, const Matrix4& m, const std::vector<RayCase>& rays, bool listing,
                    const StressOptions& options) {
  Config c;
  c.subject = makeSubject({{type, m}}, {{{'P', 0, 0}}});
  for (const RayCase& r : rays) c.rays.push_back({r.o, unitV(r.d)});
  const Measurer meas(c.subject, options);
  Figures f;
  if (listing)
    run1991(c, meas, f);
  else
    runModern(c, meas, f);
  return f;
}

std::vector<ClassResult> runStress(const StressOptions& options) {
  std::vector<ClassResult> out;
  for (std::size_t ci = 0; ci < stressClasses().size(); ++ci) {
    const std::string& cls = stressClasses()[ci].name;
    if (!options.classes.empty() &&
        std::find(options.classes.begin(), options.classes.end(), cls) == options.classes.end())
      continue;
    // Subjects: the five primitives and the three operators (mirrors: one setup).
    std::vector<std::pair<Kind, int>> subjects;
    if (cls == "mirrors") {
      subjects.push_back({Kind::Prim, 1});
    } else {
      if (cls != "coincident")
        for (int i = 0; i < 5; ++i) subjects.push_back({Kind::Prim, i});
      for (int i = 0; i < 3; ++i) subjects.push_back({Kind::Csg, i});
    }
    const bool chain = cls == "tir-chain" || cls == "mirrors";
    const int raysPerConfig = chain ? 2 : 32;
    const std::uint64_t perSubject =
        std::max<std::uint64_t>(1, options.raysPerClass / subjects.size());
    const std::uint64_t configs =
        std::max<std::uint64_t>(1, perSubject / (chain ? raysPerConfig * 16 : raysPerConfig));
    const std::uint64_t jobs = configs * subjects.size();
    std::atomic<std::uint64_t> nextJob{0};
    std::mutex lock;
    ClassResult result{cls, {}, {}};
    auto worker = [&] {
      Figures f91, fm;
      for (;;) {
        const std::uint64_t j = nextJob.fetch_add(1);
        if (j >= jobs) break;
        const auto& subj = subjects[static_cast<std::size_t>(j % subjects.size())];
        Rng rng(mix(mix(options.seed, ci), j));
        const Config c = makeConfig(cls, subj.first, subj.second, raysPerConfig, rng);
        const Measurer m(c.subject, options);
        if (options.runModern) runModern(c, m, fm);
        if (options.run1991) run1991(c, m, f91);
      }
      std::lock_guard<std::mutex> g(lock);
      result.f1991 += f91;
      result.modern += fm;
    };
    const int threads = std::max(1, options.threads);
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (options.log)
      options.log("class " + cls + ": " + std::to_string(result.modern.rays) + " modern rays, " +
                  std::to_string(result.f1991.rays) + " 1991 rays");
    out.push_back(result);
  }
  return out;
}

}  // namespace prime::stress
