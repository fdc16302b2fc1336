#include "src/prime/render/tracer_thesis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "legacy_io/prime/text_inputs.h"
#include "src/prime/geom/interval_list.h"
#include "src/prime/geom/primitives_modern.h"
#include "src/prime/render/hall_modern.h"
#include "src/prime/render/sample_random.h"

namespace prime {

namespace {

// An orthonormal pair perpendicular to the unit vector w (Duff et al.,
// "Building an orthonormal basis, revisited", JCGT 2017).
void basis(const Vec3& w, Vec3& u, Vec3& v) {
  const double sign = std::copysign(1.0, w[2]);
  const double a = -1.0 / (sign + w[2]);
  const double b = w[0] * w[1] * a;
  u = {1.0 + sign * w[0] * w[0] * a, sign * b, -sign * w[0]};
  v = {b, sign + w[1] * w[1] * a, -w[1]};
}

// The unit square onto the unit disc, area-preserving and keeping strata
// compact (Shirley and Chiu's concentric map).
void concentricDisc(double s, double t, double& x, double& y) {
  const double a = 2.0 * s - 1.0, b = 2.0 * t - 1.0;
  if (a == 0.0 && b == 0.0) {
    x = y = 0.0;
    return;
  }
  constexpr double kQuarterPi = 0.78539816339744830962;
  double r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = kQuarterPi * (b / a);
  } else {
    r = b;
    phi = 2.0 * kQuarterPi - kQuarterPi * (a / b);
  }
  x = r * std::cos(phi);
  y = r * std::sin(phi);
}

}  // namespace

TracerThesis::TracerThesis(const Scene& scene, RayTreeOptions options, ThesisOptions thesis)
    : modern_(scene, options), options_(options), thesis_(std::move(thesis)) {
  radius_.assign(scene.lights.size(), std::max(0.0, thesis_.lightRadius));
  for (std::size_t j = 0; j < radius_.size() && j < thesis_.lightRadii.size(); ++j)
    if (thesis_.lightRadii[j] >= 0.0) radius_[j] = thesis_.lightRadii[j];
  opacity_.reserve(scene.objects.size());
  for (const SceneObject& obj : scene.objects) opacity_.push_back(1.0 - obj.hue.kDT);
}

Vec3 TracerThesis::lightPoint(int j, const Vec3& from, const SampleId& sample, int depth) const {
  const Vec3& centre = scene().lights[static_cast<std::size_t>(j)].pt;
  const double r = radius_[static_cast<std::size_t>(j)];
  if (!(r > 0.0)) return centre;
  const Vec3 toLight = centre - from;
  const double len = std::sqrt(dot(toLight, toLight));
  if (!(len > 0.0)) return centre;
  // Sample k: the k-th Halton point (bases 2, 3), stratified over the first
  // n samples for every n, shifted by a random offset of the pixel, light
  // and depth (Cranley-Patterson rotation), onto the disc facing `from`.
  const auto k = static_cast<std::uint32_t>(std::max(0, sample.sample));
  const std::uint64_t stream = 2 + 2 * (static_cast<std::uint64_t>(j) * 64 + std::min(depth, 63));
  const PixelKey& p = sample.pixel;
  double s = radicalInverse2(k) + sampleUniform(p.seed, p.row, p.column, ~0ULL, stream);
  double t = radicalInverse3(k) + sampleUniform(p.seed, p.row, p.column, ~0ULL, stream + 1);
  s -= std::floor(s);
  t -= std::floor(t);
  double x, y;
  concentricDisc(s, t, x, y);
  Vec3 u, v;
  basis(toLight * (1.0 / len), u, v);
  return centre + u * (r * x) + v * (r * y);
}

Rgb TracerThesis::transmittance(const Vec3& origin, const Vec3& target, TraceStats& stats,
                                Probe* probe, int depth, int leaves) const {
  stats.countRay(RayKind::Shadow);
  const Vec3 d = target - origin;
  const double dist = std::sqrt(dot(d, d));
  if (!(dist > 0.0)) return {1.0, 1.0, 1.0};
  const Ray ray{origin, d * (1.0 / dist)};
  if (probe) probe->ray(depth, RayKind::Shadow, ray);
  const Scene& sc = scene();
  double pass = 1.0;
  bool blocked = false;
  const BoxRay boxRay(ray);
  auto consider = [&](int k, double) {
    if (blocked) return;
    if (k == leaves) return;
    const SceneObject& obj = sc.objects[static_cast<std::size_t>(k)];
    if (obj.boundPrim >= 0) {  // the bound must be met between the point and the light
      ++stats.boundTests;
      const ScenePrim& b = sc.prims[static_cast<std::size_t>(obj.boundPrim)];
      PrimHit in;
      // Not entering the bound's padded box before the light: not met (N18).
      const bool met =
          (probe || modern_.bvh().primBox(obj.boundPrim).entry(boxRay) <= dist) &&
          (probe
               ? intersectModern(b.type, transformRay(ray, modern_.primInverse(obj.boundPrim)), in)
               : intersectModernT(b.type, transformRay(ray, modern_.primInverse(obj.boundPrim)),
                                  in)) &&
          in.tOut > 0.0 && in.tIn < dist;
      if (probe) probe->boundTest(depth, obj.number, b.type, obj.boundPrim, met);
      if (!met) return;
    }
    // The length of the segment inside the solid. Only the segment up to
    // the light matters (N18; all of it for a probe).
    double inside = 0.0;
    if (probe) {
      const TList list = modern_.objectIntervals(obj, ray, stats, probe, depth);
      for (std::size_t i = 0; i + 1 < list.size(); i += 2) {
        const double lo = std::max(0.0, list[i].t), hi = std::min(dist, list[i + 1].t);
        if (hi > lo) inside += hi - lo;
      }
    } else if (!(opacity_[static_cast<std::size_t>(k)] > 0.0)) {
      // Opaque: only whether the segment meets the solid matters (below).
      if (modern_.blocks(static_cast<std::size_t>(k), boxRay, dist, stats)) blocked = true;
      return;
    } else {
      inside = modern_.insideLength(static_cast<std::size_t>(k), boxRay, dist, stats);
    }
    if (!(inside > 0.0)) return;
    const double kST = opacity_[static_cast<std::size_t>(k)];
    if (!(kST > 0.0)) {
      blocked = true;  // opaque: stop the walk (any hit will do)
      return;
    }
    pass *= std::min(1.0, kST) * std::pow(std::clamp(obj.hue.tT, 0.0, 1.0), inside);
    if (!(pass > 0.0)) blocked = true;
  };
  modern_.bvh().traverse(boxRay, consider,
                         [&] { return blocked ? -std::numeric_limits<double>::infinity() : dist; });
  if (blocked) return {0.0, 0.0, 0.0};
  return {pass, pass, pass};
}

Rgb TracerThesis::castRay(Ray ray, int depth, TraceStats& stats, const SampleId& sample,
                          Probe* probe, RayKind kind, double weight, int leaves) const {
  const Scene& sc = scene();
  stats.countRay(kind);
  ray.d = normalized(ray.d);
  if (probe) probe->ray(depth, kind, ray);
  SurfaceHit hit;
  if (!modern_.nearestHit(ray, hit, stats, probe, depth, probe ? -1 : leaves)) {
    if (probe) probe->miss(depth, sc.background);
    return sc.background;
  }
  ++stats.hits;
  const SceneObject& obj = sc.objects[static_cast<std::size_t>(hit.obj)];
  const ScenePrim& prim = sc.prims[static_cast<std::size_t>(hit.prim)];
  if (probe)
    probe->hit(depth, obj.number, hit.prim, prim.type, hit.t, hit.point, hit.local, hit.normal,
               hit.fromInsidePrim);
  const Rgb surfColor = modern_.surfaceColour(hit, depth, probe);

  const io::Hue& h = obj.hue;
  const Vec3& n = hit.normal;
  const Vec3 refl = normalized(ray.d - n * (2.0 * dot(ray.d, n)));
  double sT = 0.0;
  bool through = false;
  const double kSR = 1.0 - h.kDR, kST = 1.0 - h.kDT;
  Ray transmitted{};
  int leavesT = -1;  // the object the transmitted ray leaves, as castRay's `leaves`
  // At the depth limit no transmitted ray is cast, and the distance inside
  // only scales that ray's colour, which is zero: with 0 <= tT <= 1 the
  // scale tT^sT is finite and the term the same zero whatever sT, so the
  // walk through the solid is not made (N18; a probe still sees it).
  if (kST != 0.0 && (probe || depth < options_.maxDepth || !(h.tT >= 0.0 && h.tT <= 1.0)))
    transmitted = modern_.transmit(ray, hit, h.indx, sT, through, stats, probe, depth, &leavesT);
  Rgb iSR{}, iST{};
  if (depth < options_.maxDepth) {
    if (kSR != 0.0 && weight * std::abs(kSR) >= options_.minWeight)
      iSR = castRay({spawnOrigin(hit, refl), refl}, depth + 1, stats, sample, probe,
                    RayKind::Reflected, weight * std::abs(kSR), modern_.leavingSolid(hit, refl));
    if (through && weight * std::abs(kST) >= options_.minWeight)
      iST = castRay(transmitted, depth + 1, stats, sample, probe, RayKind::Transmitted,
                    weight * std::abs(kST), leavesT);
  }

  // The lights this point sees, through shadow rays (thesis 2.3.2). A light
  // whose every term the hue multiplies by 0 gets no shadow ray: on the
  // viewer's side only the reflection terms (kSR, kDR) use it, behind the
  // surface only the transmission terms (kST, kDT).
  // (Only the scene's lights are made: a hit does not pay for ten.)
  SmallVec<ThesisLight, io::kMaxLights> lights;
  const int count = std::min<int>(static_cast<int>(sc.lights.size()), io::kMaxLights);
  for (int j = 0; j < count; ++j) {
    const auto& src = sc.lights[static_cast<std::size_t>(j)];
    ThesisLight& l = lights.emplace_back();
    l.pt = lightPoint(j, hit.point, sample, depth);
    l.intensity = {src.rgb[0], src.rgb[1], src.rgb[2]};
    const Vec3 toLight = l.pt - hit.point;
    const double nl = dot(n, toLight);
    const bool used = nl > 0.0 ? (kSR != 0.0 || h.kDR != 0.0) : (kST != 0.0 || h.kDT != 0.0);
    if (!thesis_.shadows || !used) continue;
    const Vec3 w = normalized(toLight);
    l.dir = w;
    l.hasDir = true;
    l.visibility = transmittance(spawnOrigin(hit, w), l.pt, stats, probe, depth + 1,
                                 probe ? -1 : modern_.leavingSolid(hit, w));
    if (probe) probe->shadow(depth, j, l.pt, l.visibility);
  }

  const HallHue hue{h.kDR, h.kDT, h.fDR, h.tT, h.kRH, h.kTH, h.indx};
  const auto terms = hallTermsThesis(hue, surfColor, iSR, iST, sT, ray.d, n, hit.point,
                                     std::span<const ThesisLight>(lights.data(), lights.size()),
                                     sc.ambient, thesis_.texelInDiffuse);
  const Rgb color = hallColourModern(terms, stats.nanColours);
  if (probe) {
    probe->hallTerms(depth, terms);
    probe->shade(depth, iSR, iST, sT, color);
  }
  return color;
}

}  // namespace prime
