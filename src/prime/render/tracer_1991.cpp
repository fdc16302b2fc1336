#include "src/prime/render/tracer_1991.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "src/prime/geom/primitives_1991.h"
#include "src/prime/geom/uv_mapping_1991.h"
#include "src/prime/math/listing_math.h"
#include "src/prime/math/listing_vec.h"
#include "src/prime/render/texture_lookup.h"

namespace prime {

namespace {
// A normal taken from a primitive's frame to the world's: n (M^-1)^T with
// row vectors, M^-1 the primitive's inverse matrix (--fix K4, K5).
Vec3 byInverseTranspose(const Vec3& n, const Matrix4& inverse) {
  Vec3 out{};
  for (int i = 0; i < 3; ++i)
    out[i] = n[0] * inverse[i][0] + n[1] * inverse[i][1] + n[2] * inverse[i][2];
  return out;
}
}  // namespace

namespace {
constexpr double kInfinity = 1E100;  // Rays module: const double Infinity
}

Tracer1991::Tracer1991(const Scene& scene, TraceOptions options)
    : scene_(scene), options_(options), bvh_(scene) {
  if (options_.skipUnneededWork) options_.csg.skipRightWhenLeftEmpty = true;  // Q4
  for (const auto& obj : scene.objects)
    programs_.push_back(CsgProgram1991::compile(obj.entries, options_.csg));
  for (const auto& l : scene.lights) lights_.push_back({l.pt, {l.rgb[0], l.rgb[1], l.rgb[2]}});
  if (options_.skipUnneededWork)
    hallSkipping_ =
        HallSkipping::forScene(lights_, {scene.ambient[0], scene.ambient[1], scene.ambient[2]});
}

std::vector<Aabb> Tracer1991::primaryMaskBoxes() const {
  return bvh_.primitiveBoxesOfObjects(scene_);
}

bool Tracer1991::hitsBound(const SceneObject& obj, const Ray& ray, TraceStats& stats, Probe* probe,
                           int depth) const {
  if (obj.boundPrim == -1) return true;  // no bounding volume
  ++stats.boundTests;
  const ScenePrim& b = scene_.prims[obj.boundPrim];
  const bool hit = boundHit1991(b.type, transformRay(ray, b.inverse));
  if (probe) probe->boundTest(depth, obj.number, b.type, obj.boundPrim, hit);
  return hit;
}

// IntersectObj's CSG(): the object's Roth list for `ray`.
TList Tracer1991::objectList(const SceneObject& obj, const BoxRay& boxRay, TraceStats& stats,
                             Probe* probe, int depth) const {
  const Ray& ray = boxRay.ray;
  ++stats.objectTests;
  const bool cull = options_.skipUnneededWork && !probe;
  auto leaf = [&](int primNum) -> std::optional<PrimHit> {
    // A ray that misses the primitive's (padded) box ahead cannot hit it.
    if (cull && bvh_.primBox(primNum).entry(boxRay) == std::numeric_limits<double>::infinity())
      return std::nullopt;
    ++stats.primitiveTests;
    const ScenePrim& p = scene_.prims[primNum];
    PrimHit hit;
    const bool ok = intersectPrimitive1991(p.type, transformRay(ray, p.inverse), hit);
    std::optional<PrimHit> in;
    if (ok) in = hit;
    if (probe) probe->primitive(depth, obj.number, primNum, p.type, in);
    return in;
  };
  TList list;
  const auto& program = programs_[static_cast<std::size_t>(&obj - scene_.objects.data())];
  if (program && program->isSingleLeaf()) {
    // A lone primitive: exactly what csg1991 returns for a one-entry tree
    // (the leaf's pair, or nothing), without the walk.
    if (const std::optional<PrimHit> hit = leaf(obj.entries[0].l))
      list.addPair(hit->tIn, hit->tOut, hit->nIn, hit->nOut, obj.entries[0].l);
  } else
    try {
      // The flattened tree where it compiled, else the walk (which reports
      // the tree's error as the listing would).
      list = program ? program->run(leaf) : csg1991(obj.entries, leaf, options_.csg);
    } catch (const CsgError& e) {
      // The original stopped with Error() here; name the object and the ray.
      throw std::runtime_error("object " + std::to_string(obj.number) + " (obj/O" +
                               std::to_string(obj.number) + "), ray from " + fmt(ray.o) + " dir " +
                               fmt(ray.d) + ": " + e.what());
    }
  if (probe) probe->csgList(depth, obj.number, list);
  return list;
}

// ReflectedRay (6896-6925, K18): Heckbert's reflection, normalised, origin
// moved one world unit along it.
Ray Tracer1991::reflectedRay(const Ray& ray, double t, const Vec3& n) const {
  Ray r;
  const double twoDot = dot(ray.d, n) * 2.0;
  for (int i = 0; i < 3; ++i) {
    r.o[i] = ray.o[i] + t * ray.d[i];
    r.d[i] = ray.d[i] - (n[i] * twoDot);
  }
  unitVector(r.d, r.d);
  if (options_.fixes.k18) return r;  // --fix K18: from the hit point
  for (int i = 0; i < 3; ++i) r.o[i] += r.d[i];
  return r;
}

// K5: the exit normal as the primitive routine returned it, in the
// primitive's frame and unnormalised; with --fix K5 in the world frame (the
// inverse transpose of its matrix) and normalised.
Vec3 Tracer1991::exitNormal(const TNode& exit) const {
  if (!options_.fixes.k5) return exit.norm;
  Vec3 n = byInverseTranspose(exit.norm, scene_.prims[exit.prim].inverse);
  unitVector(n, n);
  return n;
}

// TransmittedRay (6927-7012, K19, K5): refract in, walk through the whole
// object (its CSG list, without the bound), reflect internally while the exit
// is beyond the critical angle, refract out, step one unit on.
Ray Tracer1991::transmittedRay(const Ray& ray, const SceneObject& obj, double t, const Vec3& n,
                               double indx, double& distance, TraceStats& stats, Probe* probe,
                               int depth) const {
  Ray tr;
  distance = 0.0;
  const double indxInv = 1.0 / indx;
  double c1 = -dot(ray.d, n);
  double c2 = std::sqrt(1.0 - sqr(indxInv) * (1.0 - sqr(c1)));
  for (int i = 0; i < 3; ++i) {
    tr.d[i] = indxInv * ray.d[i] + (indxInv * c1 - c2) * n[i];
    tr.o[i] = ray.o[i] + t * ray.d[i] - tr.d[i];
  }
  bool ok = false;
  TList list;
  int iterations = 0;
  while (!ok) {
    list = objectList(obj, BoxRay(tr), stats, nullptr, depth);
    if (list.size() < 2) {  // E46: the original read through a NULL list
      ++stats.emptyTransmitLists;
      break;
    }
    if (options_.tirCap > 0 && iterations >= options_.tirCap) {  // E59
      ++stats.cappedTirLoops;
      list.clear();
      break;
    }
    ++iterations;
    const TNode& exit = list[1];  // tList->next
    const Vec3 exitNorm = exitNormal(exit);
    c1 = dot(tr.d, exitNorm);
    if ((c2 = (1.0 - sqr(indx) * (1.0 - sqr(c1)))) < 0.0) {  // total internal reflection
      ++stats.totalInternalReflections;
      for (int i = 0; i < 3; ++i) {
        tr.o[i] += exit.t * tr.d[i];
        tr.d[i] += 2.0 * c1 * -exitNorm[i];
        tr.o[i] -= tr.d[i];
      }
      distance += exit.t;
    } else {
      c2 = std::sqrt(c2);
      ok = true;
      distance += exit.t;
    }
  }
  if (ok) {
    const TNode& exit = list[1];
    const Vec3 exitNorm = exitNormal(exit);
    for (int i = 0; i < 3; ++i) {
      tr.o[i] += exit.t * tr.d[i];
      tr.d[i] = indx * tr.d[i] + (indx * c1 - c2) * -exitNorm[i];
    }
  }
  for (int i = 0; i < 3; ++i) tr.o[i] += tr.d[i];
  if (probe)
    probe->transmit(depth, obj.number, iterations, distance, ok, tr,
                    "no exit found: E46/E59, entry refraction kept");
  return tr;
}

// The children's weights in the pixel for the adaptive tree-depth control
// (TraceOptions::minWeight): the parent's weight times kSR*FSR(acos(N.R)),
// or kST*FST(0)*tT^sT, largest channel.
void Tracer1991::childWeights(const SceneObject& obj, const Vec3& n, const Vec3& reflectedDir,
                              const Rgb& surfColor, double sT, double& wR, double& wT) const {
  const double cosR = cosDeg(acosDeg(dot(n, reflectedDir)));
  double fR = 0.0, fT = 0.0;
  for (int c = 0; c < 3; ++c) {
    fR = std::max(fR, std::abs(fsrFromCos1991(surfColor[c], scene_.ambient[c], cosR)));
    fT = std::max(fT, std::abs(1.0 - fsrFromCos1991(surfColor[c], scene_.ambient[c], 1.0)));
  }
  wR *= std::abs(1.0 - obj.hue.kDR) * fR;
  wT *= std::abs(1.0 - obj.hue.kDT) * fT * std::abs(std::pow(obj.hue.tT, sT));
}

Rgb Tracer1991::castRay(Ray ray, int depth, TraceStats& stats, Probe* probe, RayKind kind,
                        double weight) const {
  stats.countRay(kind);
  unitVector(ray.d, ray.d);  // E41
  if (probe) probe->ray(depth, kind, ray);

  const BoxRay boxRay(ray);  // prepared once for all the box tests
  double nearest = kInfinity;
  Nearest best;
  // One object of obj/List: its bound, its CSG list, and the listing's
  // `t != 0.0 && t < nearest` with ties going to the earlier object.
  auto consider = [&](int k) {
    const SceneObject& obj = scene_.objects[k];
    if (!hitsBound(obj, ray, stats, probe, depth)) return;
    const TList list = objectList(obj, boxRay, stats, probe, depth);
    if (list.empty()) return;
    const double t = list.front().t;  // K30: the FIRST node, not the smallest
    if (t != 0.0 && (t < nearest || (t == nearest && k < best.obj))) {
      nearest = t;
      best.t = t;
      best.obj = k;
      best.prim = list.front().prim;
      best.surfType = list.front().surfType;
      unitVector(list.front().norm, best.norm);
    }
  };
  if (options_.skipUnneededWork && !probe) {
    // Nearest boxes first; an object whose box starts beyond the nearest hit
    // cannot win (its list's t values all lie in its box).
    bvh_.traverse(
        boxRay, [&](int k, double) { consider(k); }, [&] { return nearest; });
  } else {
    for (int k = 0; k < static_cast<int>(scene_.objects.size()); ++k) consider(k);  // GetObj order
  }
  if (nearest == kInfinity) {
    if (probe) probe->miss(depth, scene_.background);
    return scene_.background;
  }
  ++stats.hits;

  const SceneObject& obj = scene_.objects[best.obj];
  const ScenePrim& prim = scene_.prims[best.prim];
  const Ray local = transformRay(ray, prim.inverse);
  Vec3 surfPt{}, tmpV{};
  for (int i = 0; i < 3; ++i) {
    surfPt[i] = ray.o[i] + nearest * ray.d[i];
    tmpV[i] = local.o[i] + nearest * local.d[i];
  }
  const InverseMapResult mapped = inverseMap1991(prim.type, tmpV);
  const InverseMapResult* const uv = &mapped;
  if (uv->noFaceMatched) ++stats.noFaceMatched;
  Vec3 n = vectorMatrixMul(best.norm, prim.transform);                     // K4: forward matrix
  if (options_.fixes.k4) n = byInverseTranspose(best.norm, prim.inverse);  // --fix K4
  unitVector(n, n);
  if (probe)
    probe->hit(depth, obj.number, best.prim, prim.type, nearest, surfPt, tmpV, n,
               best.surfType != 0);

  const int mapNum = prim.map[uv->surface][best.surfType];
  const SceneTexture& map = scene_.maps[mapNum];
  Rgb surfColor{};
  for (int c = 0; c < 3; ++c) {
    TextureReadCounters counters;
    surfColor[c] = readMap1991({map.uScale, map.vScale, map.channel[c]}, uv->u, uv->v, &counters);
    stats.failedTexelReads += counters.failedReads;
  }
  if (probe)
    probe->texture(depth, uv->u, uv->v, uv->surface, uv->noFaceMatched, mapNum, map.uScale,
                   map.vScale, surfColor);

  // kSR = 1 - kDR and kST = 1 - kDT weigh the reflected and transmitted
  // colours in Hall's sum; where one is 0 its ray tree cannot change the
  // pixel (see TraceOptions::skipUnneededWork).
  const bool skip = options_.skipUnneededWork;
  const bool wantReflected = !skip || 1.0 - obj.hue.kDR != 0.0;
  const bool wantTransmitted = !skip || 1.0 - obj.hue.kDT != 0.0;
  const Ray reflected = reflectedRay(ray, nearest, n);  // its direction is a Hall input
  double sT = 0.0;
  Ray transmitted{surfPt, ray.d};  // unused by Hall (S13) when not traced
  if (wantTransmitted)
    transmitted = transmittedRay(ray, obj, nearest, n, obj.hue.indx, sT, stats, probe, depth);
  Rgb colorReflected{}, colorTransmitted{};
  if (depth++ < options_.maxDepth) {  // K20
    double wR = weight, wT = weight;
    const double cut = options_.minWeight;
    if (cut > 0.0) childWeights(obj, n, reflected.d, surfColor, sT, wR, wT);
    if (wantReflected && !(cut > 0.0 && wR < cut))
      colorReflected = castRay(reflected, depth, stats, probe, RayKind::Reflected, wR);
    if (wantTransmitted && !(cut > 0.0 && wT < cut))
      colorTransmitted = castRay(transmitted, depth, stats, probe, RayKind::Transmitted, wT);
  }
  const HallHue hue{obj.hue.kDR, obj.hue.kDT, obj.hue.fDR, obj.hue.tT,
                    obj.hue.kRH, obj.hue.kTH, obj.hue.indx};
  const bool k10 = options_.fixes.k10;  // --fix K10: v towards the eye, l towards the light
  const HallGeometry geom{surfPt, k10 ? -ray.d : ray.d, n, reflected.d, transmitted.d, k10};
  const Rgb color = processColor1991(hue, surfColor, colorReflected, colorTransmitted, sT, geom,
                                     lights_, scene_.ambient, hallSkipping_, options_.fixes.k15);
  if (probe) {  // at the hit's depth (depth++ above)
    probe->hallTerms(depth - 1, hallTermsRgb1991(hue, surfColor, colorReflected, colorTransmitted,
                                                 sT, geom, lights_, scene_.ambient));
    probe->shade(depth - 1, colorReflected, colorTransmitted, sT, color);
  }
  return color;
}

}  // namespace prime
