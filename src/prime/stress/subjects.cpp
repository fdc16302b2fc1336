// The stress suite's subjects and the profiles' answers (subjects.h).
#include "src/prime/stress/subjects.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "src/prime/geom/primitives_1991.h"
#include "src/prime/math/listing_matrix.h"
#include "src/prime/math/listing_vec.h"

namespace prime::stress {

Matrix4 listingTransform(const Vec3& s, const Vec3& t, const Vec3& r) {
  Matrix4 m = identity4();
  transform(m, s, t, {0, 0, 0}, r);
  return m;
}

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

}  // namespace prime::stress
