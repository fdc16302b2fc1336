// The stress suite's configurations (a subject and its rays, per class) and
// its runs of both profiles against the reference (see stress.h and
// docs/prime/numerics.md). Generator: stress_rays.h; subjects and the
// profiles' answers: subjects.h; the measurement: measurer.h.
#include "src/prime/stress/stress.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>
#include <thread>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/primitives_1991.h"
#include "src/prime/math/listing_matrix.h"
#include "src/prime/math/listing_vec.h"
#include "src/prime/render/tracer_1991.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/stress/measurer.h"
#include "src/prime/stress/stress_rays.h"
#include "src/prime/stress/subjects.h"
#include "src/render/render_rows.h"

namespace prime::stress {

namespace {

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
    startThreads(pool, threads - 1, [&](int) { worker(); });
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