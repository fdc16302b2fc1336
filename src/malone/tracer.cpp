#include "src/malone/tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace prime::malone {

namespace {

std::string fmt(const char* format, double a = 0, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, a, b, c, d);
  return buf;
}
std::string vec(const Vec3& v) {
  return fmt("(%.6g, %.6g, %.6g)", v[0], v[1], v[2]);
}

}  // namespace

TraceStats& TraceStats::operator+=(const TraceStats& o) {
  primaryRays += o.primaryRays;
  reflectedRays += o.reflectedRays;
  transmittedRays += o.transmittedRays;
  shadowRays += o.shadowRays;
  primitiveTests += o.primitiveTests;
  hits += o.hits;
  totalInternalReflections += o.totalInternalReflections;
  cutByDepth += o.cutByDepth;
  cutByWeight += o.cutByWeight;
  return *this;
}

Tracer::Tracer(const Scene& scene, TraceSettings settings) : scene_(scene), settings_(settings) {
  forward_ = normalized(scene.viewer.lookAt - scene.viewer.eye);
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
  const Viewer& v = scene_.viewer;
  const double alpha = (2.0 * X - v.xRes) / v.xRes;
  const double beta = -(2.0 * Y - v.yRes) / v.yRes;
  // v(alpha, beta) - e = (l - e)/|l - e| + alpha x + beta y.
  MRay ray;
  ray.o = v.eye;
  ray.d = normalized(forward_ + v.x * alpha + v.y * beta);
  return ray;
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

Rgb Tracer::pixel(int X, int Y, TraceStats& stats, ProbeLog* probe) const {
  const MRay ray = primaryRay(X, Y);
  ++stats.primaryRays;
  if (probe)
    probe->add(0, "pixel",
               "pixel (" + std::to_string(X) + ", " + std::to_string(Y) + "): primary ray from " +
                   vec(ray.o) + " along " + vec(ray.d),
               JsonObject().add("x", X).add("y", Y).add("origin", ray.o).add("direction", ray.d));
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
                         TraceStats& stats, ProbeLog* probe, int depth) const {
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
      ++stats.shadowRays;
      MRay shadow;
      shadow.o = x;
      shadow.d = sdir;
      shadow.length = l;
      if (blocked(shadow, stats)) {
        if (probe)
          probe->add(depth, "light",
                     "light " + std::to_string(light.light + 1) + " at " + vec(light.position) +
                         ": shadowed",
                     JsonObject()
                         .add("light", light.light + 1)
                         .add("position", light.position)
                         .add("shadowed", true));
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
    if (probe)
      probe->add(depth, "light",
                 "light " + std::to_string(light.light + 1) + " at " + vec(light.position) +
                     ": d.s = " + fmt("%.6g", ds) + ", r.s = " + fmt("%.6g", rs) +
                     ", l = " + fmt("%.6g", l) + ", adds " + vec(add),
                 JsonObject()
                     .add("light", light.light + 1)
                     .add("position", light.position)
                     .add("shadowed", false)
                     .add("ds", ds)
                     .add("rs", rs)
                     .add("distance", l)
                     .add("adds", add));
  }

  return colour;
}

Rgb Tracer::trace(const MRay& ray, int depth, double weight, double index, TraceStats& stats,
                  ProbeLog* probe) const {
  const Hit hit = nearest(ray, stats);
  if (hit.primitive < 0) {
    if (probe)
      probe->add(depth, "miss", "depth " + std::to_string(depth) + ": no hit (black)",
                 JsonObject().add("colour", Vec3{0, 0, 0}));
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
    probe->add(depth, "hit",
               "depth " + std::to_string(depth) + ": hit object " + std::to_string(p.objectNumber) +
                   " (" + objectName(static_cast<int>(p.id)) + ", " +
                   io::describe(scene_.where(p)) + ") at t = " + fmt("%.9g", hit.t) + ", point " +
                   vec(x) + ", normal " + vec(n),
               JsonObject()
                   .add("object", p.objectNumber)
                   .add("primitive", objectName(static_cast<int>(p.id)))
                   .add("where", io::describe(scene_.where(p)))
                   .add("t", hit.t)
                   .add("point", x)
                   .add("normal", n));

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
      if (probe)
        probe->add(depth, "tir", "total internal reflection: k_s' = " + fmt("%.6g", ks),
                   JsonObject().add("ks", ks));
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
      if (probe)
        probe->add(
            depth, "transmitted",
            std::string("transmitted (") + (leaving ? "leaving" : "entering") +
                ", eta = " + fmt("%.6g", eta) + ") along " + vec(refracted.d),
            JsonObject().add("leaving", leaving).add("eta", eta).add("direction", refracted.d));
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
      if (probe)
        probe->add(depth, "reflected", "reflected (k_s' = " + fmt("%.6g", ks) + ") along " + vec(r),
                   JsonObject().add("ks", ks).add("direction", r));
      const Rgb refl = trace(reflected, depth + 1, weight * ks, index, stats, probe);
      for (int k = 0; k < 3; ++k) colour[k] += ks * refl[k];
    }
  }
  if (probe)
    probe->add(depth, "returns", "depth " + std::to_string(depth) + " returns " + vec(colour),
               JsonObject().add("colour", colour));
  return colour;
}

}  // namespace prime::malone
