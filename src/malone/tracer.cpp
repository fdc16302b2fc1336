#include "src/malone/tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "src/render/render_rows.h"

namespace prime::malone {

TraceStats& TraceStats::operator+=(const TraceStats& o) {
  RayCounts::operator+=(o);
  primitiveTests += o.primitiveTests;
  totalInternalReflections += o.totalInternalReflections;
  cutByDepth += o.cutByDepth;
  cutByWeight += o.cutByWeight;
  return *this;
}

ViewerRays::ViewerRays(const Viewer& viewer)
    : v_(viewer), forward_(normalized(viewer.lookAt - viewer.eye)) {}

MRay ViewerRays::operator()(int X, int Y) const {
  const double alpha = (2.0 * X - v_.xRes) / v_.xRes;
  const double beta = -(2.0 * Y - v_.yRes) / v_.yRes;
  // v(alpha, beta) - e = (l - e)/|l - e| + alpha x + beta y.
  MRay ray;
  ray.o = v_.eye;
  ray.d = normalized(forward_ + v_.x * alpha + v_.y * beta);
  return ray;
}

Tracer::Tracer(const Scene& scene, TraceSettings settings, const std::atomic<bool>* abort)
    : scene_(scene), settings_(settings), abort_(abort), rays_(scene.viewer) {
  std::vector<Aabb> boxes;
  for (int i = 0; i < static_cast<int>(scene.primitives.size()); ++i) {
    Aabb box = bounds(scene, scene.primitives[i]);
    if (box.empty() || settings_.linearSearch) {
      unbounded_.push_back(i);
      box = Aabb{};
    }
    boxes.push_back(box);
  }
  bvh_ = Bvh(std::move(boxes));
}

MRay Tracer::primaryRay(int X, int Y) const {
  return rays_(X, Y);
}

Rgb Tracer::pixel(const MRay& ray, TraceStats& stats) const {
  ++stats.primaryRays;
  if (settings_.debug != TraceSettings::Debug::None) return debugValue(ray, stats);
  return trace(ray, 1, 1.0, 1.0, stats, nullptr);
}

Tracer::Hit Tracer::nearest(const MRay& ray, TraceStats& stats) const {
  Hit best;
  best.t = ray.length;
  auto test = [&](int i) {
    ++stats.primitiveTests;
    double t = 0;
    if (!intersect(scene_, scene_.primitives[i], ray, settings_.eps, t)) return;
    // The nearest; an equal t keeps the earlier primitive of the file.
    if (t < best.t || (t == best.t && best.primitive >= 0 && i < best.primitive)) {
      best.t = t;
      best.primitive = i;
    }
  };
  for (int i : unbounded_) test(i);
  if (!settings_.linearSearch)
    bvh_.traverse(
        BoxRay(Ray{ray.o, ray.d}), [&](int i, double) { test(i); }, [&] { return best.t; });
  return best;
}

bool Tracer::blocked(const MRay& ray, TraceStats& stats) const {
  // Any hit with eps < t < l shadows the light, transparent objects included
  // (section 1.7, footnote 2: "a bit simplistic").
  for (int i : unbounded_) {
    ++stats.primitiveTests;
    double t = 0;
    if (intersect(scene_, scene_.primitives[i], ray, settings_.eps, t)) return true;
  }
  if (settings_.linearSearch) return false;
  bool found = false;
  bvh_.traverse(
      BoxRay(Ray{ray.o, ray.d}),
      [&](int i, double) {
        if (found) return;
        ++stats.primitiveTests;
        double t = 0;
        if (intersect(scene_, scene_.primitives[i], ray, settings_.eps, t)) found = true;
      },
      [&] { return found ? -1.0 : ray.length; });
  return found;
}

Rgb Tracer::pixel(int X, int Y, TraceStats& stats, Probe* probe) const {
  const MRay ray = primaryRay(X, Y);
  ++stats.primaryRays;
  if (probe) probe->pixel(X, Y, ray);
  if (settings_.debug != TraceSettings::Debug::None) return debugValue(ray, stats);
  return trace(ray, 1, 1.0, 1.0, stats, probe);
}

Rgb Tracer::debugValue(const MRay& ray, TraceStats& stats) const {
  const Hit hit = nearest(ray, stats);
  if (hit.primitive < 0) return {0, 0, 0};
  ++stats.hits;
  const Primitive& p = scene_.primitives[hit.primitive];
  switch (settings_.debug) {
    case TraceSettings::Debug::Depth: {
      const double g = std::min(1.0, 1.0 / hit.t);  // grey level r^-1
      return {g, g, g};
    }
    case TraceSettings::Debug::Colour:
      return scene_.surfaces[p.surface].kd;
    case TraceSettings::Debug::Normal: {
      const Vec3 x = ray.o + ray.d * hit.t;
      const double g = std::fabs(dot(normal(scene_, p, x), ray.d));
      return {g, g, g};
    }
    case TraceSettings::Debug::None:
      break;
  }
  return {0, 0, 0};
}

// Phong as written (section 1.7): I_a k_d c for the ambient light, and for
// every light sample the surface faces and no object blocks,
// I (k_d c (d.s) + k_s' (r.s)^k_e) / l^2 (without / l^2 for 104); the
// specular term only where r.s > 0 (MAL-E9).
Rgb Tracer::illumination(const Surface& s, const Vec3& x, const Vec3& df, const Vec3& r, double ks,
                         TraceStats& stats, Probe* probe, int depth) const {
  Rgb colour{0, 0, 0};
  if (settings_.ambient && scene_.hasAmbient)
    for (int k = 0; k < 3; ++k) colour[k] += scene_.ambient[k] * s.kd[k];

  for (const LightSample& light : scene_.lights) {
    const Vec3 toLight = light.position - x;
    const double l = length(toLight);
    if (!(l > 0)) continue;
    const Vec3 sdir = toLight * (1.0 / l);
    const double ds = dot(df, sdir);
    if (!(ds > 0)) continue;  // the surface does not face the light
    if (settings_.shadows) {
      if ((++stats.shadowRays & 4095) == 0) checkAbort(abort_);  // R9, within the pixel
      MRay shadow;
      shadow.o = x;
      shadow.d = sdir;
      shadow.length = l;
      if (blocked(shadow, stats)) {
        if (probe) probe->shadowed(depth, light.light, light.position);
        continue;
      }
    }
    const double rs = dot(r, sdir);
    const double spec = settings_.specular && rs > 0 && ks > 0 ? ks * std::pow(rs, s.ke) : 0.0;
    const double falloff = light.inverseSquare ? 1.0 / (l * l) : 1.0;
    Rgb add{};
    for (int k = 0; k < 3; ++k) {
      const double diffuse = settings_.diffuse ? s.kd[k] * ds : 0.0;
      add[k] = light.rgb[k] * (diffuse + spec) * falloff;
      colour[k] += add[k];
    }
    if (probe) probe->light(depth, light.light, light.position, ds, rs, l, add);
  }

  return colour;
}

Rgb Tracer::trace(const MRay& ray, int depth, double weight, double index, TraceStats& stats,
                  Probe* probe) const {
  const Hit hit = nearest(ray, stats);
  if (hit.primitive < 0) {
    if (probe) probe->miss(depth);
    return {0, 0, 0};  // an escaped ray contributes nothing (MAL-Q6)
  }
  ++stats.hits;
  const Primitive& p = scene_.primitives[hit.primitive];
  const Surface& s = scene_.surfaces[p.surface];
  const Vec3& i = ray.d;
  const Vec3 x = ray.o + i * hit.t;
  const Vec3 n = normal(scene_, p, x);
  const Vec3 df = dot(i, n) <= 0 ? n : -n;  // the normal facing the ray (section 1.7)
  if (probe)
    probe->hit(depth, p.objectNumber, objectName(static_cast<int>(p.id)), scene_.where(p), hit.t, x,
               n);

  double ks = s.ks;  // k_s', augmented by k_t on total internal reflection
  Rgb colour{0, 0, 0};

  // Transmission first (section 1.10: TIR can change k_s).
  if (s.kt > 0 && settings_.refraction) {
    const bool leaving = dot(i, n) > 0;
    const double n2 = leaving ? 1.0 : s.index;
    const double eta = index / n2;
    const double c = dot(i, df);
    const double D = 1 - eta * eta * (1 - c * c);
    if (D < 0) {
      ks += s.kt;
      ++stats.totalInternalReflections;
      if (probe) probe->tir(depth, ks);
    } else if (depth + 1 > settings_.maxDepth) {
      ++stats.cutByDepth;
    } else if (weight * s.kt < settings_.minWeight) {
      ++stats.cutByWeight;
    } else {
      // t = eta i - (eta c + sqrt(D)) d (the printed sign corrected, MAL-E2).
      MRay refracted;
      refracted.o = x;
      refracted.d = normalized(i * eta - df * (eta * c + std::sqrt(D)));
      ++stats.transmittedRays;
      if (probe) probe->transmitted(depth, leaving, eta, refracted.d);
      const Rgb t = trace(refracted, depth + 1, weight * s.kt, n2, stats, probe);
      for (int k = 0; k < 3; ++k) colour[k] += s.kt * t[k];
    }
  }

  // r = i - 2 (i.d) d (the printed sign corrected, MAL-E1).
  const Vec3 r = i - df * (2 * dot(i, df));

  const Rgb local = illumination(s, x, df, r, ks, stats, probe, depth);
  for (int k = 0; k < 3; ++k) colour[k] += local[k];

  if (ks > 0 && settings_.reflection) {
    if (depth + 1 > settings_.maxDepth) {
      ++stats.cutByDepth;
    } else if (weight * ks < settings_.minWeight) {
      ++stats.cutByWeight;
    } else {
      MRay reflected;
      reflected.o = x;
      reflected.d = r;
      ++stats.reflectedRays;
      if (probe) probe->reflected(depth, ks, r);
      const Rgb refl = trace(reflected, depth + 1, weight * ks, index, stats, probe);
      for (int k = 0; k < 3; ++k) colour[k] += ks * refl[k];
    }
  }
  if (probe) probe->returns(depth, colour);
  return colour;
}

}  // namespace prime::malone
