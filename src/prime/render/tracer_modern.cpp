#include "src/prime/render/tracer_modern.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

#include "src/prime/geom/csg_modern.h"
#include "src/prime/geom/primitives_modern.h"
#include "src/prime/geom/uv_mapping_1991.h"
#include "src/prime/math/float_step.h"
#include "src/prime/math/listing_matrix.h"
#include "src/prime/math/robust.h"
#include "src/prime/render/hall_modern.h"

namespace prime {

namespace {

double clamp1(double x) {
  return std::clamp(x, -1.0, 1.0);
}
// Internal reflections inside one object before the light counts as trapped
// (docs/prime/deviations.md N9); the 1991 profile's --tir-cap is its own.
constexpr int kMaxInternalReflections = 64;
double finiteOr0(double x) {
  return std::isfinite(x) ? x : 0.0;
}

// Normals transform by the inverse transpose: with row vectors p' = p M,
// n' = n (M^-1)^T, i.e. n'[j] = sum_i n[i] inv[j][i].
Vec3 normalToWorld(const Vec3& n, const Matrix4& inv) {
  Vec3 w{};
  for (int j = 0; j < 3; ++j) w[j] = n[0] * inv[j][0] + n[1] * inv[j][1] + n[2] * inv[j][2];
  return normalized(w);
}

// Modern texel lookup: u, v clamped into [0, 1); NaN reads texel 0.
double texel(const SceneTexture& m, int c, double u, double v) {
  auto index = [](double x, int n) {
    if (!(x > 0.0)) return 0;  // also NaN
    return std::min(static_cast<int>(x * n), n - 1);
  };
  return m.channel[c][static_cast<std::size_t>(index(u, m.uScale) + m.uScale * index(v, m.vScale))];
}

// The one colour of a primitive whose every surface, outside and inside,
// has a map of a single colour, the same for all (bit for bit): texel() gives
// it for any (u, v). Nothing when a map differs, varies or is missing.
std::optional<Rgb> plainColourOf(const Scene& scene, const ScenePrim& p) {
  std::optional<Rgb> colour;
  const int surfaces = std::min<int>(io::surfaceCount(p.type), io::kMaxSurface);
  for (int s = 0; s < std::max(surfaces, 1); ++s)
    for (const int mapNum : p.map[static_cast<std::size_t>(s)]) {
      if (mapNum < 0 || static_cast<std::size_t>(mapNum) >= scene.maps.size()) return std::nullopt;
      const SceneTexture& m = scene.maps[static_cast<std::size_t>(mapNum)];
      const auto texels = static_cast<std::size_t>(m.uScale) * static_cast<std::size_t>(m.vScale);
      if (m.uScale <= 0 || m.vScale <= 0) return std::nullopt;
      Rgb c{};
      for (int k = 0; k < 3; ++k) {
        const std::vector<double>& channel = m.channel[static_cast<std::size_t>(k)];
        if (channel.size() < texels) return std::nullopt;
        c[k] = channel[0];
        for (std::size_t t = 1; t < texels; ++t)
          if (std::memcmp(&channel[t], &c[k], sizeof(double)) != 0) return std::nullopt;
      }
      if (!colour)
        colour = c;
      else if (std::memcmp(colour->data(), c.data(), sizeof c) != 0)
        return std::nullopt;
    }
  return colour;
}

}  // namespace

TracerModern::TracerModern(const Scene& scene, RayTreeOptions options)
    : scene_(scene), options_(options), bvh_(scene, ObjectBvh::ObjectBoxes::kSolid) {
  for (const auto& l : scene.lights) lights_.push_back({l.pt, {l.rgb[0], l.rgb[1], l.rgb[2]}});
  inverse_.reserve(scene.prims.size());
  for (const ScenePrim& p : scene.prims) inverse_.push_back(accurateInverse(p.transform));
  plainColour_.reserve(scene.prims.size());
  for (const ScenePrim& p : scene.prims) plainColour_.push_back(plainColourOf(scene, p));
  programs_.reserve(scene.objects.size());
  for (const SceneObject& obj : scene.objects) {
    try {
      programs_.push_back(compileModern(obj.entries));
      unionLeaves_.push_back(programs_.back().unionLeaves());
      containers_.push_back(containingPrimitives(obj.entries));
      pointwise_.push_back(
          programs_.back().isSingleLeaf() ? std::nullopt : CsgPointwise::compile(programs_.back()));
    } catch (const CsgError& e) {  // (loadScene refuses such trees: a scene built in code)
      throw std::runtime_error("object " + std::to_string(obj.number) + " (obj/O" +
                               std::to_string(obj.number) + "): " + e.what());
    }
  }
}

// The hit point o + t d of `node` and a bound on its distance from the true
// surface, derived from the computation that found it (Ray Tracing Gems
// ch. 6, pbrt-v4 3.9): the ray's transform into primitive space (one
// rounding per product and sum of the accurate inverse), the root or plane
// clip (a few roundings of the magnitudes involved), mapped back to the world
// by |A|, plus the rounding of o + t d itself. Then every surface of every
// primitive of the object that passes within that bound of the point (one at
// a face, two or three at an edge or corner, those of other operands where
// CSG faces meet), so that secondary rays can step off all of them.
void TracerModern::surfaceAt(const SceneObject& obj, const Ray& ray, const TNode& node,
                             SurfaceHit& hit, const Ray* inLocal) const {
  const ScenePrim& prim = scene_.prims[node.prim];
  const Matrix4& inv = inverse_[node.prim];
  const Matrix4& a = prim.transform;
  const Ray local = inLocal ? *inLocal : transformRay(ray, inv);
  const double t = node.t;
  hit.t = t;
  hit.prim = node.prim;
  hit.exitsObject = node.surfType == kSurfIn;
  double pl = 1.0;  // 1 + |local point|
  for (int i = 0; i < 3; ++i) {
    hit.point[i] = ray.o[i] + t * ray.d[i];
    hit.local[i] = local.o[i] + t * local.d[i];
    pl = std::max(pl, 1.0 + std::abs(hit.local[i]));
  }
  Vec3 el{};  // local error bound per axis
  for (int i = 0; i < 3; ++i) {
    double eo = std::abs(inv[3][i]), ed = 0;
    for (int k = 0; k < 3; ++k) {
      eo += std::abs(ray.o[k] * inv[k][i]);
      ed += std::abs(ray.d[k] * inv[k][i]);
    }
    el[i] = gamma(4) * (eo + std::abs(t) * ed) +
            gamma(10) * (std::abs(local.o[i]) + std::abs(t * local.d[i]) + pl);
  }
  for (int j = 0; j < 3; ++j) {
    double e = gamma(2) * (std::abs(ray.o[j]) + std::abs(t * ray.d[j]));
    for (int i = 0; i < 3; ++i) e += std::abs(a[i][j]) * el[i];
    hit.pointError[j] = e;
  }
  hit.normal = normalToWorld(node.norm, inv);  // outward of the primitive (not faced yet)
  // Surfaces near the point, in every primitive of the object.
  hit.nearCount = 0;
  hit.nearOwn = false;
  for (const CsgEntry& e : obj.entries) {
    if (e.op != 'P' || e.l < 0 || e.l >= static_cast<int>(scene_.prims.size())) continue;
    const ScenePrim& q = scene_.prims[e.l];
    const Matrix4& qi = inverse_[e.l];
    const Vec3 ql = e.l == node.prim ? hit.local : pointMatrixMul(hit.point, qi);
    Vec3 qe{}, mag{};  // mag: |P| |inv_q| + |inv_q[3]|, per local axis
    for (int i = 0; i < 3; ++i) {
      double spread = 0;
      mag[i] = std::abs(qi[3][i]);
      for (int k = 0; k < 3; ++k) {
        spread += hit.pointError[k] * std::abs(qi[k][i]);
        mag[i] += std::abs(hit.point[k] * qi[k][i]);
      }
      qe[i] = e.l == node.prim ? el[i] : spread + gamma(4) * mag[i];
    }
    Vec3 normals[10];
    const int n = nearSurfacesModern(q.type, ql, qe, normals, 10);
    if (n <= 0) continue;
    const int before = hit.nearCount;
    // The next ray's transform error at the point along each world axis:
    // gamma(4) |A_q|^T mag, the same for every surface of this primitive.
    Vec3 transformError{};
    for (int j = 0; j < 3; ++j) {
      double m = 0;
      for (int i = 0; i < 3; ++i) m += std::abs(q.transform[i][j]) * mag[i];
      transformError[j] = hit.pointError[j] + gamma(4) * m;
    }
    for (int k = 0; k < n && hit.nearCount < static_cast<int>(hit.near.size()); ++k) {
      const Vec3 nw = normalToWorld(normals[k], qi);
      // World distance to step off this surface: the point's error along
      // the normal, and the next ray's transform error at the point.
      double step = 0;
      for (int j = 0; j < 3; ++j) step += std::abs(nw[j]) * transformError[j];
      hit.near[static_cast<std::size_t>(hit.nearCount)] = nw;
      hit.nearStep[static_cast<std::size_t>(hit.nearCount)] = step;
      ++hit.nearCount;
    }
    if (e.l == node.prim && hit.nearCount > before) hit.nearOwn = true;
  }
}

Vec3 spawnOrigin(const SurfaceHit& hit, const Vec3& w) {
  if (hit.nearCount == 0) {  // no surface found near: the hit's own normal
    return offsetRayOrigin(hit.point, hit.pointError, hit.normal, w);
  }
  // Step to the side of every near surface that w travels into, far enough
  // that the step survives the other surfaces' tilt (a few rounds). w's
  // side of each surface is the same every round; while the offset is still
  // zero, the step it has along a (finite, unit) normal is zero.
  const int count = hit.nearCount;
  std::array<double, std::tuple_size_v<decltype(hit.near)>> side;
  for (int k = 0; k < count; ++k) {
    const double wn = dot(w, hit.near[static_cast<std::size_t>(k)]);
    // 0: along the surface, either side is as good
    side[static_cast<std::size_t>(k)] = wn == 0 ? 0.0 : wn > 0 ? 1.0 : -1.0;
  }
  Vec3 offset{0, 0, 0};
  bool moved = false;
  for (int round = 0; round < 64; ++round) {
    bool ok = true;
    for (int k = 0; k < count; ++k) {
      const double sk = side[static_cast<std::size_t>(k)];
      if (sk == 0.0) continue;
      const Vec3& n = hit.near[static_cast<std::size_t>(k)];
      const double want = hit.nearStep[static_cast<std::size_t>(k)];
      const double have = moved ? sk * dot(n, offset) : 0.0;
      if (have < want) {
        offset = offset + n * (sk * (want - have) * (round == 0 ? 1.0 : 1.5));
        moved = true;
        ok = false;
      }
    }
    if (ok) break;
  }
  Vec3 po = hit.point + offset;
  for (int i = 0; i < 3; ++i) {  // round away from the point so the step survives rounding
    if (offset[i] > 0)
      po[i] = stepAway(po[i], true);
    else if (offset[i] < 0)
      po[i] = stepAway(po[i], false);
  }
  return po;
}

bool TracerModern::nearestHit(const Ray& ray, SurfaceHit& hit, TraceStats& stats, Probe* probe,
                              int depth, int leaves) const {
  double nearest = std::numeric_limits<double>::infinity();
  int bestObj = -1;
  TNode bestNode{};
  const BoxRay boxRay(ray);
  auto consider = [&](int k) {
    if (k == leaves) return;  // (never for a probe)
    const SceneObject& obj = scene_.objects[k];
    if (obj.boundPrim >= 0) {  // the bound must be met ahead (from inside too)
      ++stats.boundTests;
      const ScenePrim& b = scene_.prims[obj.boundPrim];
      PrimHit in;
      // A ray that enters no part of the bound's padded box ahead cannot
      // meet the bound ahead (N18); the exact test only for the others.
      const bool met =
          (probe ||
           bvh_.primBox(obj.boundPrim).entry(boxRay) != std::numeric_limits<double>::infinity()) &&
          (probe ? intersectModern(b.type, transformRay(ray, inverse_[obj.boundPrim]), in)
                 : intersectModernT(b.type, transformRay(ray, inverse_[obj.boundPrim]), in)) &&
          in.tOut > 0.0;
      if (probe) probe->boundTest(depth, obj.number, b.type, obj.boundPrim, met);
      if (!met) return;
    }
    // The list is needed up to the nearest hit so far (N18; all of it for a probe).
    TNode node;
    bool ahead = false;
    if (probe) {
      for (const TNode& n : objectIntervals(obj, ray, stats, probe, depth))
        if (n.t > 0.0) {  // sorted: the first node ahead is this object's nearest
          node = n;
          ahead = true;
          break;
        }
    } else {
      ahead = firstNodeAhead(static_cast<std::size_t>(k), boxRay, nearest, stats, node);
    }
    if (ahead && (node.t < nearest || (node.t == nearest && k < bestObj))) {
      nearest = node.t;
      bestObj = k;
      bestNode = node;
    }
  };
  bvh_.traverse(
      boxRay, [&](int k, double) { consider(k); }, [&] { return nearest; });
  if (bestObj < 0) return false;

  // The hit primitive met in full: its normals (the candidates carried
  // markers, N18) and which side of its own surface the ray is on.
  PrimHit own;
  const Ray ownLocal = transformRay(ray, inverse_[bestNode.prim]);
  const bool ownHit = intersectModern(scene_.prims[bestNode.prim].type, ownLocal, own);
  if (!probe) {
    if (ownHit) {
      const Vec3& n = bestNode.norm[1] != 0.0 ? own.nOut : own.nIn;
      bestNode.norm = bestNode.norm[0] < 0.0 ? -n : n;
    } else {  // (not reached: the same test found this node) the list in full
      const TList list = objectIntervalsAhead(scene_.objects[bestObj], boxRay, nearest, stats);
      for (const TNode& node : list)
        if (node.t == bestNode.t && node.prim == bestNode.prim) {
          bestNode.norm = node.norm;
          break;
        }
    }
  }
  surfaceAt(scene_.objects[bestObj], ray, bestNode, hit, &ownLocal);
  hit.obj = bestObj;
  Vec3 n = hit.normal;
  // Which side of the PRIMITIVE's own surface the ray is on picks the
  // outside or inside map (a difference's cut face shows B's inside).
  if (ownHit) hit.fromInsidePrim = std::abs(nearest - own.tOut) < std::abs(nearest - own.tIn);
  if (dot(n, ray.d) > 0) n = -n;  // face the ray
  hit.normal = n;
  return true;
}

// Refract into the object at the hit, walk to where the ray leaves it
// (reflecting internally while beyond the critical angle), refract out.
Ray TracerModern::transmit(const Ray& ray, const SurfaceHit& hit, double indx, double& distance,
                           bool& through, TraceStats& stats, Probe* probe, int depth,
                           int* leaves) const {
  distance = 0.0;
  through = false;
  if (leaves) *leaves = -1;
  const SceneObject& obj = scene_.objects[hit.obj];
  const Vec3 d = normalized(ray.d);
  // Snell with the facing normal: entering, eta = 1/indx; a ray that starts
  // inside the object and leaves it here refracts out with eta = indx.
  const double eta = hit.exitsObject ? indx : 1.0 / indx;
  const double cosI = clamp1(-dot(d, hit.normal));
  const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
  auto report = [&](int steps, const Ray& leaving, std::string_view why) {
    if (probe) probe->transmit(depth, obj.number, steps, distance, through, leaving, why);
    return leaving;
  };
  if (!(k >= 0.0))  // total internal reflection: nothing transmitted
    return report(0, {}, "total internal reflection at the surface: nothing transmitted");
  Ray r{{}, normalized(d * eta + hit.normal * (eta * cosI - std::sqrt(k)))};
  r.o = spawnOrigin(hit, r.d);
  if (hit.exitsObject) {
    through = true;
    if (leaves) *leaves = leavingSolid(hit, r.d);
    return report(0, r, {});
  }
  for (int step = 0; step < kMaxInternalReflections; ++step) {
    TNode exitNode;
    if (!exitAhead(static_cast<std::size_t>(hit.obj), r, stats, exitNode)) {
      // numerically outside already: leave as we are
      ++stats.emptyTransmitLists;
      through = true;
      return report(step, r, {});
    }
    const TNode* exit = &exitNode;
    distance += exit->t;
    SurfaceHit at;
    surfaceAt(obj, r, *exit, at);
    Vec3 nOut = at.normal;  // outward of the solid
    if (dot(nOut, r.d) < 0) nOut = -nOut;
    const double c = clamp1(dot(r.d, nOut));
    const double k2 = 1.0 - indx * indx * (1.0 - c * c);
    if (k2 < 0.0) {  // total internal reflection: stay inside
      ++stats.totalInternalReflections;
      r.d = normalized(r.d - nOut * (2.0 * c));
      r.o = spawnOrigin(at, r.d);
      continue;
    }
    r.d = normalized(r.d * indx + nOut * (std::sqrt(k2) - indx * c));
    r.o = spawnOrigin(at, r.d);
    through = true;
    if (leaves) *leaves = leavingSolid(static_cast<std::size_t>(hit.obj), at, r.d);
    return report(step + 1, r, {});
  }
  ++stats.cappedTirLoops;  // trapped: the light is absorbed
  return report(kMaxInternalReflections, {}, "trapped by internal reflection: absorbed");
}

Rgb TracerModern::surfaceColour(const SurfaceHit& hit, int depth, Probe* probe) const {
  if (!probe && plainColour_[hit.prim]) return *plainColour_[hit.prim];
  const ScenePrim& prim = scene_.prims[hit.prim];
  const InverseMapResult uv = inverseMap1991(prim.type, hit.local);
  const int surface = uv.surface >= 0 && uv.surface < io::surfaceCount(prim.type) ? uv.surface : 0;
  const int mapNum = prim.map[surface][hit.fromInsidePrim ? 1 : 0];
  const SceneTexture& map = scene_.maps[mapNum];
  const double u = finiteOr0(uv.u), v = finiteOr0(uv.v);
  Rgb surfColor{};
  for (int c = 0; c < 3; ++c) surfColor[c] = texel(map, c, u, v);
  if (probe)
    probe->texture(depth, u, v, surface, uv.noFaceMatched, mapNum, map.uScale, map.vScale,
                   surfColor);
  return surfColor;
}

Rgb TracerModern::castRay(Ray ray, int depth, TraceStats& stats, Probe* probe, RayKind kind,
                          double weight, int leaves) const {
  stats.countRay(kind);
  ray.d = normalized(ray.d);
  if (probe) probe->ray(depth, kind, ray);
  SurfaceHit hit;
  if (!nearestHit(ray, hit, stats, probe, depth, probe ? -1 : leaves)) {
    if (probe) probe->miss(depth, scene_.background);
    return scene_.background;
  }
  ++stats.hits;
  const SceneObject& obj = scene_.objects[hit.obj];
  const ScenePrim& prim = scene_.prims[hit.prim];
  if (probe)
    probe->hit(depth, obj.number, hit.prim, prim.type, hit.t, hit.point, hit.local, hit.normal,
               hit.fromInsidePrim);
  const Rgb surfColor = surfaceColour(hit, depth, probe);

  const io::Hue& h = obj.hue;
  const Vec3& n = hit.normal;
  const Vec3 refl = normalized(ray.d - n * (2.0 * dot(ray.d, n)));
  double sT = 0.0;
  bool through = false;
  const double kSR = 1.0 - h.kDR, kST = 1.0 - h.kDT;
  Ray transmitted{};
  int leavesT = -1;
  // At the depth limit no transmitted ray is cast, and the distance inside
  // only scales that ray's colour, which is zero: with 0 <= tT <= 1 the
  // scale tT^sT is finite and the term the same zero whatever sT, so the
  // walk through the solid is not made (N18; a probe still sees it).
  if (kST != 0.0 && (probe || depth < options_.maxDepth || !(h.tT >= 0.0 && h.tT <= 1.0)))
    transmitted = transmit(ray, hit, h.indx, sT, through, stats, probe, depth, &leavesT);
  Rgb iSR{}, iST{};
  if (depth < options_.maxDepth) {
    if (kSR != 0.0 && weight * std::abs(kSR) >= options_.minWeight)
      iSR = castRay({spawnOrigin(hit, refl), refl}, depth + 1, stats, probe, RayKind::Reflected,
                    weight * std::abs(kSR), leavingSolid(hit, refl));
    if (through && weight * std::abs(kST) >= options_.minWeight)
      iST = castRay(transmitted, depth + 1, stats, probe, RayKind::Transmitted,
                    weight * std::abs(kST), leavesT);
  }

  const HallHue hue{h.kDR, h.kDT, h.fDR, h.tT, h.kRH, h.kTH, h.indx};
  const auto terms = hallTermsModern(hue, surfColor, iSR, iST, sT, hit.point, ray.d, n, refl,
                                     lights_, scene_.ambient);
  const Rgb color = hallColourModern(terms, stats.nanColours);
  if (probe) {
    probe->hallTerms(depth, terms);
    probe->shade(depth, iSR, iST, sT, color);
  }
  return color;
}

}  // namespace prime
