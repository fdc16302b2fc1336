#include "src/cgl/tracer.h"

#include <cmath>
#include <utility>

#include "src/cgl/cook.h"

namespace prime::cgl {

namespace {
// Sections 8.2, 8.4, 8.5: "the initial t_min = 10^10".
constexpr double kTMin0 = 1e10;
}  // namespace

TraceStats& TraceStats::operator+=(const TraceStats& o) {
  rays += o.rays;
  for (int k = 0; k < kPrimitiveKinds; ++k) {
    tests[k] += o.tests[k];
    hits[k] += o.hits[k];
  }
  boxTests += o.boxTests;
  boxHits += o.boxHits;
  for (int k = 0; k < 3; ++k) shadeCalls[k] += o.shadeCalls[k];
  totalInternalReflections += o.totalInternalReflections;
  fractal += o.fractal;
  shadowedLights += o.shadowedLights;
  spline += o.spline;
  return *this;
}

Vec3 reflectDirection(const Vec3& d, const Vec3& n) {
  Vec3 nn = dot(d, n) > 0.0 ? -n : n;  // D.N < 0
  const double dn = std::fabs(dot(d, nn));
  if (!(dn > 0.0)) return d;  // grazing: the ray goes on as it was
  const Vec3 omega = d * (1.0 / dn);
  return normalized(omega + nn * 2.0);
}

bool refractDirection(const Vec3& d, const Vec3& n, double index, Vec3& out) {
  // CGL-Q45: a ray leaving the object (D.N > 0 before the sign adjustment)
  // uses 1/index.
  const bool leaving = dot(d, n) > 0.0;
  const Vec3 nn = leaving ? -n : n;
  const double ratio = leaving ? 1.0 / index : index;
  const double dn = std::fabs(dot(d, nn));
  if (!(dn > 0.0) || !std::isfinite(ratio)) return false;
  const Vec3 omega = d * (1.0 / dn);
  const Vec3 on = omega + nn;
  const double radicand = ratio * ratio * dot(omega, omega) - dot(on, on);
  if (!(radicand > 0.0)) return false;  // total internal reflection: no refracted ray
  const double kf = 1.0 / std::sqrt(radicand);
  out = normalized(on * kf - nn);
  return true;
}

Tracer::Tracer(const Scene& scene, const TraceSettings& settings)
    : scene_(scene), settings_(settings) {
  if (!settings.linearSearch) {
    // Box object nodes get an empty box: the BVH never visits them.
    std::vector<Aabb> boxes(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      if (scene.objects[i].kind != ObjectKind::Box) boxes[i] = scene.objects[i].box;
    bvh_ = Bvh(std::move(boxes));
  }
  // CGL-Q49: secondary rays that miss, and the depth limit, return the
  // background as a colour-vector.
  background_ =
      rgbToSpectrum(Rgb8{settings.background[0], settings.background[1], settings.background[2]},
                    settings.phosphors);
}

namespace {

// One object node's intersection routine (sections 2.2, 3.2, 4.2, 5.5): a
// hit with t in (tMin, tMax); a fractal's facet and tree work are reported.
// Boxes are the callers' business.
inline bool hitObject(const Scene& scene, const Object& o, const BoxRay& br, double tMin,
                      double tMax, double& t, double& axial, int& facet, SplineHit& sh,
                      TraceStats& stats, bool anyHit = false) {
  switch (o.kind) {
    case ObjectKind::Sphere:
      return hitSphere(o, br.ray, tMin, tMax, t);
    case ObjectKind::Cylinder:
      return hitCylinder(o, br.ray, tMin, tMax, t, axial);
    case ObjectKind::Polygon:
      return hitPolygon(o, br.ray, tMin, tMax, t);
    case ObjectKind::Fractal:
      return hitFractal(scene.fractals[static_cast<std::size_t>(o.fractal)], br, tMin, tMax, t,
                        facet, stats.fractal);
    case ObjectKind::Spline: {
      // The surface's own intersector: the document's walk, or the modern
      // one (--profile modern, CGL-D180). A shadow ray needs only whether
      // there is a hit (CGL-D170: the same answer as the nearest hit's
      // search, found sooner).
      const SplineSurface& s = scene.splines[static_cast<std::size_t>(o.spline)];
      if (anyHit) return occludesSplineAsBuilt(s, br, tMin, tMax, stats.spline);
      if (!intersectSplineAsBuilt(s, br, tMin, tMax, sh, stats.spline)) return false;
      t = sh.t;
      return true;
    }
    case ObjectKind::Box:
      break;
  }
  return false;
}

}  // namespace

bool Tracer::intersect(const Ray& ray, double tMax, Hit& hit, TraceStats& stats) const {
  return settings_.linearSearch ? intersectList(ray, tMax, hit, stats)
                                : intersectBvh(ray, tMax, hit, stats);
}

// Figure 41's Intersect: the object list in order, the nearest hit kept (a
// later object must be strictly nearer), super boxes skipping their contents.
bool Tracer::intersectList(const Ray& ray, double tMax, Hit& hit, TraceStats& stats) const {
  const std::vector<Object>& objects = scene_.objects;
  const int count = static_cast<int>(objects.size());
  const double eps = settings_.epsilon;
  double tmin = tMax;
  bool found = false;
  const BoxRay boxRay(ray);
  for (int i = 0; i < count;) {
    const Object& o = objects[static_cast<std::size_t>(i)];
    if (o.kind == ObjectKind::Box) {
      ++stats.boxTests;
      // CGL-Q48: the contents are tested only if the ray meets the box
      // ahead of it, nearer than the nearest hit so far.
      if (boxEntry(o, boxRay) < tmin) {
        ++stats.boxHits;
        ++i;
      } else {
        i = o.skip;
      }
      continue;
    }
    double t = 0, axial = 0;
    int facet = -1;
    SplineHit sh;
    const bool h = hitObject(scene_, o, boxRay, eps, tmin, t, axial, facet, sh, stats);
    const auto kind = static_cast<std::size_t>(o.kind);
    ++stats.tests[kind];
    if (h) {
      ++stats.hits[kind];
      tmin = t;
      hit = {t, i, axial, facet, sh};
      found = true;
    }
    ++i;
  }
  return found;
}

// The same nearest hit through the shared BVH over the objects' boxes
// (CGL-D43): every object whose box the ray meets before the nearest hit so
// far is tested, and of two hits at the same t the one earlier in the object
// list wins, as in the list; so the hit, and the picture, are the list's.
bool Tracer::intersectBvh(const Ray& ray, double tMax, Hit& hit, TraceStats& stats) const {
  const std::vector<Object>& objects = scene_.objects;
  const double eps = settings_.epsilon;
  double best = tMax;
  int bestIndex = -1;
  double bestAxial = 0;
  int bestFacet = -1;
  SplineHit bestSpline;
  const BoxRay boxRay(ray);
  bvh_.traverse(
      boxRay,
      [&](int i, double) {
        const Object& o = objects[static_cast<std::size_t>(i)];
        double t = 0, axial = 0;
        int facet = -1;
        SplineHit sh;
        // Hits at exactly `best` are kept for the tie rule below.
        const double limit = bestIndex < 0 ? best : std::nextafter(best, HUGE_VAL);
        const bool h = hitObject(scene_, o, boxRay, eps, limit, t, axial, facet, sh, stats);
        const auto kind = static_cast<std::size_t>(o.kind);
        ++stats.tests[kind];
        if (!h) return;
        ++stats.hits[kind];
        if (t < best || (t == best && i < bestIndex)) {
          best = t;
          bestIndex = i;
          bestAxial = axial;
          bestFacet = facet;
          bestSpline = sh;
        }
      },
      [&] { return best; });
  if (bestIndex < 0) return false;
  hit = {best, bestIndex, bestAxial, bestFacet, bestSpline};
  return true;
}

int Tracer::shadowed(const Ray& ray, double tMax, TraceStats& stats) const {
  const std::vector<Object>& objects = scene_.objects;
  const double eps = settings_.epsilon;
  if (!settings_.linearSearch) {
    // Any opaque object in the way will do: the light is skipped either way.
    int found = -1;
    const BoxRay boxRay(ray);
    bvh_.traverse(
        boxRay,
        [&](int i, double) {
          const Object& o = objects[static_cast<std::size_t>(i)];
          if (found >= 0 || !o.opaque) return;  // section 9.3: transparent objects cast no shadow
          double t = 0, axial = 0;
          int facet = -1;
          SplineHit sh;
          const auto kind = static_cast<std::size_t>(o.kind);
          ++stats.tests[kind];
          if (hitObject(scene_, o, boxRay, eps, tMax, t, axial, facet, sh, stats, true)) {
            ++stats.hits[kind];
            found = i;
          }
        },
        [&] { return found >= 0 ? -1.0 : tMax; });
    return found;
  }
  const int count = static_cast<int>(objects.size());
  const BoxRay boxRay(ray);
  for (int i = 0; i < count;) {
    const Object& o = objects[static_cast<std::size_t>(i)];
    if (o.kind == ObjectKind::Box) {
      ++stats.boxTests;
      if (boxEntry(o, boxRay) < tMax) {
        ++stats.boxHits;
        ++i;
      } else {
        i = o.skip;
      }
      continue;
    }
    // Section 9.3: objects that are not opaque are ignored by shadow rays.
    if (o.opaque) {
      double t = 0, axial = 0;
      int facet = -1;
      SplineHit sh;
      const bool h = hitObject(scene_, o, boxRay, eps, tMax, t, axial, facet, sh, stats, true);
      const auto kind = static_cast<std::size_t>(o.kind);
      ++stats.tests[kind];
      if (h) {
        ++stats.hits[kind];
        return i;
      }
    }
    ++i;
  }
  return -1;
}

Spectrum Tracer::trace(const Ray& ray, int level, RayKind kind, TraceStats& stats,
                       ProbeReport* probe) const {
  return traceRay(ray, level, kind, stats, probe);
}

std::size_t Tracer::startRay(const Ray& ray, int level, RayKind kind, TraceStats& stats,
                             ProbeReport* probe) const {
  stats.rays.countRay(kind);
  if (!probe) return 0;
  const std::size_t probeIndex = probe->rays.size();
  ProbeRay pr;
  pr.kind = kind;
  pr.level = level;
  pr.origin = ray.o;
  pr.direction = ray.d;
  probe->rays.push_back(pr);
  return probeIndex;
}

Spectrum Tracer::traceRay(const Ray& ray, int level, RayKind kind, TraceStats& stats,
                          ProbeReport* probe) const {
  const std::size_t probeIndex = startRay(ray, level, kind, stats, probe);
  Hit hit;
  if (!intersect(ray, kTMin0, hit, stats)) {
    if (probe) probe->rays[probeIndex].colour = background_;
    return background_;
  }
  return hitColour(ray, hit, level, stats, probe, probeIndex);
}

Spectrum Tracer::hitColour(const Ray& ray, const Hit& hit, int level, TraceStats& stats,
                           ProbeReport* probe, std::size_t probeIndex) const {
  ++stats.rays.hits;
  const Object& object = scene_.objects[static_cast<std::size_t>(hit.object)];
  const Surface& surface = scene_.surfaces[static_cast<std::size_t>(object.surface)];
  const Vec3 point = ray.o + ray.d * hit.t;
  const Vec3 normal =
      object.kind == ObjectKind::Fractal
          ? facetNormal(scene_.fractals[static_cast<std::size_t>(object.fractal)], hit.facet)
      : object.kind == ObjectKind::Spline
          ? splineNormal(scene_.splines[static_cast<std::size_t>(object.spline)], hit.spline)
          : normalAt(object, point, hit.axial);

  Spectrum reflected = background_, refracted = background_;
  // Cook-Torrance treats the reflected and transmitted rays as lights
  // (section 9.9), so it needs their directions even at the depth limit.
  const bool cook = surface.model == ShadingModel::Cook;
  Vec3 reflectDir{}, refractDir{};
  bool hasReflect = false, hasRefract = false;
  // Figure 41 with CGL-E42: level >= depth stops the recursion; Shade still
  // adds k_r and k_t times the background.
  if (level >= settings_.depth) {
    if (probe) probe->rays[probeIndex].atDepthLimit = true;
    if (cook) {  // CGL-Q107: the background arrives from these directions
      if (surface.kr > 0.0) {
        reflectDir = reflectDirection(ray.d, normal);
        hasReflect = true;
      }
      if (surface.kt > 0.0) hasRefract = refractDirection(ray.d, normal, surface.index, refractDir);
    }
  } else {
    if (surface.kr > 0.0) {
      reflectDir = reflectDirection(ray.d, normal);
      hasReflect = true;
      reflected = traceRay({point, reflectDir}, level + 1, RayKind::Reflected, stats, probe);
    }
    if (surface.kt > 0.0) {
      if (refractDirection(ray.d, normal, surface.index, refractDir)) {
        hasRefract = true;
        refracted = traceRay({point, refractDir}, level + 1, RayKind::Transmitted, stats, probe);
      } else {
        ++stats.totalInternalReflections;  // CGL-Q45: the background stays
      }
    }
  }
  return shade(ray, hit, point, normal, reflected, refracted, hasReflect ? &reflectDir : nullptr,
               hasRefract ? &refractDir : nullptr, stats, probe, probeIndex);
}

Spectrum Tracer::shade(const Ray& ray, const Hit& hit, const Vec3& point, const Vec3& normal,
                       const Spectrum& reflected, const Spectrum& refracted, const Vec3* reflectDir,
                       const Vec3* refractDir, TraceStats& stats, ProbeReport* probe,
                       std::size_t probeIndex) const {
  const Object& object = scene_.objects[static_cast<std::size_t>(hit.object)];
  const Surface& surface = scene_.surfaces[static_cast<std::size_t>(object.surface)];
  ++stats.shadeCalls[static_cast<std::size_t>(surface.model)];

  // Section 9.7: "the sign of N is adjusted so that N.V >= 0".
  const Vec3 v = -ray.d;
  Vec3 n = normal;
  if (dot(n, v) < 0.0) n = -n;
  const double nv = dot(n, v);

  // D_lambda: the surface colour, or the texel's (section 10).
  Spectrum colour{};
  double u = 0, w = 0;
  int ui = 0, vi = 0;
  if (surface.texture >= 0) {
    if (object.kind == ObjectKind::Spline)  // section 6.9
      splineTexture(scene_.splines[static_cast<std::size_t>(object.spline)], hit.spline.u,
                    hit.spline.v, u, w);
    else
      textureUv(object, point, normal, hit.axial, u, w);
    ui = textureIndex(u, surface.umod);
    vi = textureIndex(w, surface.vmod);
    // CGL-Q50: texel = row u_i from the top of the image, column v_i.
    const Texture& tex = scene_.textures[static_cast<std::size_t>(surface.texture)];
    const auto& texel =
        tex.texels[static_cast<std::size_t>(ui) * 512 + static_cast<std::size_t>(vi)];
    for (int k = 0; k < 3; ++k) colour[Texture::kSamples[k]] = texel[static_cast<std::size_t>(k)];
  } else {
    colour = surface.colour;
  }

  ProbeRay* pr = probe ? &probe->rays[probeIndex] : nullptr;
  if (pr) recordHit(*pr, hit, point, n, u, w, ui, vi);

  // Z = k_a((N.V) + 0.5) I_a pi D + k_r R + k_t T (sections 9.6-9.8); Cook
  // (section 9.9) replaces k_r R + k_t T by Psi(R, D_reflect, k_r) +
  // Psi(T, -D_refract, k_t): the rays as lights (CGL-Q107).
  const bool cook = surface.model == ShadingModel::Cook;
  Spectrum z{};
  const double ambience = nv + 0.5;
  const double kr = cook ? 0.0 : surface.kr, kt = cook ? 0.0 : surface.kt;
  for (int k = 0; k < kSpectrumSamples; ++k)
    z[k] = ambience * scene_.ambient[k] * colour[k] + kr * reflected[k] + kt * refracted[k];
  // One Cook-Torrance Psi, with the probe's record of it.
  const auto cookPsi = [&](const Spectrum& intensity, const Vec3& l, double dw, ProbeLight* pl) {
    const CookTerms t = cookTerms(n, v, l, surface.m);
    addPsi(z, intensity, dw, t, surface.ks, surface.kd, colour, surface.fresnel);
    if (pl) pl->cookTorrance(t, dw, surface.kd, surface.ks);
  };
  if (cook) {
    const std::pair<const Vec3*, int> rays[2] = {{reflectDir, ProbeLight::kReflectedLight},
                                                 {refractDir, ProbeLight::kTransmittedLight}};
    for (const auto& [dir, which] : rays) {
      const double dw = which == ProbeLight::kReflectedLight ? surface.kr : surface.kt;
      if (!dir || !(dw > 0.0)) continue;  // CGL-Q107: k = 0 or no ray, no term
      const Vec3 l = which == ProbeLight::kReflectedLight ? *dir : -*dir;
      ProbeLight* pl = pr ? &pr->addLight(which, l, dot(n, l)) : nullptr;
      if (pl && !(pl->nl > 0.0)) pl->skip("N.L <= 0");
      cookPsi(which == ProbeLight::kReflectedLight ? reflected : refracted, l, dw, pl);
    }
  }

  const int lights = static_cast<int>(scene_.lights.size());
  for (int li = 0; li < lights; ++li) {
    const Light& light = scene_.lights[static_cast<std::size_t>(li)];
    Vec3 l{};
    double tLight = kTMin0;
    if (light.inScene) {
      // Section 9.3 (CGL-E43): L = l - I, normalised; the shadow ray stops
      // at the light, t_min = |l - I| (L is a unit vector).
      const Vec3 toLight = light.xyz - point;
      tLight = length(toLight);
      l = normalized(toLight);
    } else {
      l = light.xyz;
    }
    const double nl = dot(n, l);
    ProbeLight* pl = pr ? &pr->addLight(li, l, nl) : nullptr;
    if (nl < 0.0) {
      if (pl) pl->skip("N.L < 0");
      continue;
    }
    if (settings_.shadows) {
      stats.rays.countRay(RayKind::Shadow);
      const int by = shadowed({point, l}, tLight, stats);
      if (by >= 0) {
        ++stats.shadowedLights;
        if (pl) pl->skip("shadowed", by);
        continue;
      }
    }
    if (cook) {
      cookPsi(light.intensity, l, light.dw, pl);
      continue;
    }
    const double diffuse = surface.kd * nl;
    double specular = 0.0;
    if (surface.model == ShadingModel::Phong && nl > 0.0) {
      // P = 2N - L/(N.L), normalised; CGL-Q51: no highlight when P.V <= 0
      // (or N.L = 0, where P is undefined).
      const Vec3 p = normalized(n * 2.0 - l * (1.0 / nl));
      const double pv = dot(p, v);
      if (pv > 0.0) specular = surface.ks * std::pow(pv, surface.e);
    }
    if (pl) {
      pl->diffuse = diffuse;
      pl->specular = specular;
    }
    for (int k = 0; k < kSpectrumSamples; ++k)
      z[k] += (diffuse * colour[k] + specular) * light.intensityDw[k];
  }
  if (pr) pr->colour = z;
  return z;
}

void Tracer::recordHit(ProbeRay& pr, const Hit& hit, const Vec3& point, const Vec3& normal,
                       double u, double v, int ui, int vi) const {
  const Object& object = scene_.objects[static_cast<std::size_t>(hit.object)];
  const Surface& surface = scene_.surfaces[static_cast<std::size_t>(object.surface)];
  pr.hit = true;
  pr.object = hit.object;
  pr.node = object.node;
  pr.surface = surface.number;
  pr.objectKind = object.kind;
  pr.facet = hit.facet;
  pr.t = hit.t;
  pr.point = point;
  pr.normal = normal;
  pr.textured = surface.texture >= 0;
  pr.u = u;
  pr.v = v;
  pr.ui = ui;
  pr.vi = vi;
  if (object.kind == ObjectKind::Spline) {
    pr.splineU = hit.spline.u;
    pr.splineV = hit.spline.v;
    pr.newtonU0 = hit.spline.u0;
    pr.newtonV0 = hit.spline.v0;
    pr.newtonIterations = hit.spline.iterations;
  }
}

Rgb8 Tracer::screenPoint(double x, double y, TraceStats& stats, ProbeReport* probe) const {
  return tracePrimary(scene_.camera, x, y, stats, probe);
}

Rgb8 Tracer::screenPoint(const Camera& camera, double x, double y, TraceStats& stats) const {
  return tracePrimary(camera, x, y, stats, nullptr);
}

Rgb8 Tracer::tracePrimary(const Camera& camera, double x, double y, TraceStats& stats,
                          ProbeReport* probe) const {
  const Ray ray = camera.primaryRay(x, y);
  // traceRay's steps, without its copy of the background spectrum for a
  // miss: the pixel of a primary ray that misses is the background RGB.
  const std::size_t probeIndex = startRay(ray, 0, RayKind::Primary, stats, probe);
  Hit hit;
  const bool hitSomething = intersect(ray, kTMin0, hit, stats);
  if (!hitSomething && !probe)  // CGL-Q49: exactly the background RGB
    return Rgb8{settings_.background[0], settings_.background[1], settings_.background[2]};
  Rgb8 rgb;
  Spectrum cv;
  if (!hitSomething) {
    probe->rays[probeIndex].colour = background_;
    cv = background_;
    rgb = Rgb8{settings_.background[0], settings_.background[1], settings_.background[2]};
  } else {
    cv = hitColour(ray, hit, 0, stats, probe, probeIndex);
    rgb = toRgb(cv, settings_.phosphors);
  }
  if (probe) {
    probe->x = x;
    probe->y = y;
    probe->colour = cv;
    probe->xyz = spectrumToXyz(cv);
    probe->rgb = rgb;
    probe->background = !hitSomething;
  }
  return rgb;
}

}  // namespace prime::cgl
