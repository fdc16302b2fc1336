// The Waterloo CGL package's Trace and Shade (M. A. J. Sweeney, "The
// Waterloo CGL Ray Tracing Package", University of Waterloo CS-85-35, 1985,
// sections 8 and 9, Figure 41): the nearest hit over the object list (boxes
// skipping their contents when missed), Whitted's reflected and refracted
// rays up to the `depth` parameter, one shadow ray per light through opaque
// objects only, and Lambert, Phong or Cook-Torrance (src/cgl/cook.h) with the
// improved ambience term, all in
// 33-sample colour-vectors. A primary ray's colour-vector becomes RGB by
// ToRGB (src/cgl/colour.h).
//
// Per ray nothing is allocated; the probe (a report of one pixel's rays) is
// the only path that does, and only when asked for.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "src/cgl/colour.h"
#include "src/cgl/cook.h"
#include "src/cgl/scene.h"
#include "src/geom/bvh.h"
#include "src/render/ray_counts.h"

namespace prime::cgl {

struct TraceSettings {
  int depth = 0;         // program parameter: level >= depth stops recursion (CGL-E42)
  bool shadows = false;  // program parameter
  std::array<int, 3> background{0, 0, 0};  // program parameter, RGB 0-255
  Phosphors phosphors = Phosphors::Electrohome;
  // The self-intersection guard: hits at t <= epsilon are rejected. The
  // document rejects only t <= 0 (section 2.2); CGL-Q44 says why the port
  // uses a small epsilon (set 0 for the document's rule).
  double epsilon = 1e-6;
  // Figure 41's Intersect as printed: the object list in order, super boxes
  // skipping their contents. Otherwise the shared BVH over the objects'
  // boxes finds the same nearest hit with fewer tests (CGL-D43): the same
  // pixels, not the document's operation counts.
  bool linearSearch = false;
};

struct TraceStats {
  RayCounts rays;  // primary, reflected, refracted (transmitted), shadow; hits of non-shadow rays
  std::array<std::uint64_t, kPrimitiveKinds> tests{}, hits{};  // by ObjectKind
  std::uint64_t boxTests = 0, boxHits = 0;
  std::array<std::uint64_t, 3> shadeCalls{};  // by ShadingModel: Lambert, Phong, Cook
  std::uint64_t totalInternalReflections = 0, shadowedLights = 0;
  FractalWork fractal;  // the fractal trees' box and facet tests (section 5.5)
  // B-spline surfaces (section 6.7, Table 6): intersection calls, boxes
  // checked, Newton calls and iterations, hits; and the time in them.
  SplineCounters spline;
  TraceStats& operator+=(const TraceStats& o);
};

// The probe's record of one ray (kind, level, origin, direction) and what it
// met.
struct ProbeLight {
  // 0-based; Cook-Torrance's extra "lights" (section 9.9): kReflectedLight
  // (R, D_reflect, k_r) and kTransmittedLight (T, -D_refract, k_t).
  static constexpr int kReflectedLight = -1, kTransmittedLight = -2;
  int light = 0;
  Vec3 l{};             // the unit vector to the light
  double nl = 0;        // N.L
  std::string skipped;  // "" = used; else why ("N.L < 0", "shadowed")
  int shadowedBy = -1;  // object index of the first opaque object found in the way
  double diffuse = 0;   // k_d (N.L) (multiplies D I dw)
  double specular = 0;  // k_s (P.V)^e (multiplies I dw); Phong only
  // Cook only (src/cgl/cook.h): Beckmann D, G, the Fresnel row, and
  // S / F_lambda = D G / (pi (N.L)(N.V)); dw the solid angle used.
  bool cook = false;
  double d = 0, g = 0, s = 0, dw = 0;
  int fresnel = 0;

  // Not used: why, and the object in the way (shadowed).
  void skip(std::string why, int by = -1) {
    skipped = std::move(why);
    shadowedBy = by;
  }
  // Cook-Torrance's terms with solid angle dw, for a surface's k_d and k_s.
  void cookTorrance(const CookTerms& t, double solidAngle, double kd, double ks) {
    cook = true;
    d = t.d;
    g = t.g;
    s = t.s;
    dw = solidAngle;
    fresnel = t.fresnel;
    diffuse = kd * t.nl;
    specular = ks * t.specular;
  }
};
struct ProbeRay {
  RayKind kind = RayKind::Primary;
  int level = 0;
  Vec3 origin{}, direction{};
  bool hit = false;
  int object = -1, node = 0, surface = 0;  // object index, scene node, 1-based surface
  ObjectKind objectKind = ObjectKind::Sphere;
  int facet = -1;  // a fractal's facet (leaf order), else -1
  double t = 0;
  Vec3 point{}, normal{};  // the normal after facing the viewer
  bool textured = false;
  double u = 0, v = 0;
  int ui = 0, vi = 0;
  // A spline hit: the surface parameters, the leaf's Newton start and the
  // iterations of the successful call (section 6.8).
  double splineU = 0, splineV = 0, newtonU0 = 0, newtonV0 = 0;
  int newtonIterations = 0;
  bool atDepthLimit = false;  // Shade called with the background for R and T
  std::vector<ProbeLight> lights;
  Spectrum colour{};  // what this ray returned

  // A light (or Cook-Torrance's reflected or transmitted ray) considered at
  // the hit: its direction and N.L; the record to complete.
  ProbeLight& addLight(int which, const Vec3& toLight, double nDotL) {
    ProbeLight& pl = lights.emplace_back();
    pl.light = which;
    pl.l = toLight;
    pl.nl = nDotL;
    return pl;
  }
};
struct ProbeReport {
  double x = 0, y = 0;         // the screen point traced
  std::vector<ProbeRay> rays;  // in the order traced (a ray before its children)
  Spectrum colour{};           // the primary ray's colour-vector
  Xyz xyz;
  Rgb8 rgb;
  bool background = false;  // the primary ray missed: rgb is the background exactly
};

class Tracer {
 public:
  Tracer(const Scene& scene, const TraceSettings& settings);

  // The RGB of a primary ray through the screen point (x, y): the background
  // exactly when it misses everything (CGL-Q49), else ToRGB(Trace(ray, 0)).
  Rgb8 screenPoint(double x, double y, TraceStats& stats, ProbeReport* probe = nullptr) const;
  // The same through another camera (`prime walk`'s camera of the moment).
  Rgb8 screenPoint(const Camera& camera, double x, double y, TraceStats& stats) const;
  // Trace(ray, level) of Figure 41; `kind` is for the statistics and probe.
  Spectrum trace(const Ray& ray, int level, RayKind kind, TraceStats& stats,
                 ProbeReport* probe) const;

  const Scene& scene() const { return scene_; }
  const TraceSettings& settings() const { return settings_; }
  const Spectrum& backgroundSpectrum() const { return background_; }

  struct Hit {
    double t = 0;
    int object = -1;
    double axial = 0;  // a cylinder's u_i
    int facet = -1;    // a fractal's facet
    SplineHit spline;  // a spline's parameters and Newton start
  };
  // Intersect (section 8.1): the nearest hit with t in (epsilon, tMax).
  bool intersect(const Ray& ray, double tMax, Hit& hit, TraceStats& stats) const;
  // The shadow test (section 9.3): the first opaque object met with t in
  // (epsilon, tMax), or -1.
  int shadowed(const Ray& ray, double tMax, TraceStats& stats) const;

 private:
  Rgb8 tracePrimary(const Camera& camera, double x, double y, TraceStats& stats,
                    ProbeReport* probe) const;
  bool intersectList(const Ray& ray, double tMax, Hit& hit, TraceStats& stats) const;
  bool intersectBvh(const Ray& ray, double tMax, Hit& hit, TraceStats& stats) const;
  // Trace: startRay (the count, the probe's record: its index), Intersect,
  // then the background for a miss or hitColour for a hit.
  Spectrum traceRay(const Ray& ray, int level, RayKind kind, TraceStats& stats,
                    ProbeReport* probe) const;
  std::size_t startRay(const Ray& ray, int level, RayKind kind, TraceStats& stats,
                       ProbeReport* probe) const;
  Spectrum hitColour(const Ray& ray, const Hit& hit, int level, TraceStats& stats,
                     ProbeReport* probe, std::size_t probeIndex) const;
  // reflectDir / refractDir: the directions of the reflected and
  // transmitted rays (nullptr: none), Cook's extra lights.
  Spectrum shade(const Ray& ray, const Hit& hit, const Vec3& point, const Vec3& normal,
                 const Spectrum& reflected, const Spectrum& refracted, const Vec3* reflectDir,
                 const Vec3* refractDir, TraceStats& stats, ProbeReport* probe,
                 std::size_t probeIndex) const;
  // The probe's record of a hit: what was hit, where, and the texture lookup.
  void recordHit(ProbeRay& pr, const Hit& hit, const Vec3& point, const Vec3& normal, double u,
                 double v, int ui, int vi) const;

  const Scene& scene_;
  TraceSettings settings_;
  Bvh bvh_;  // over scene_.objects' boxes (boxes of super-box nodes empty); unless linearSearch
  Spectrum background_{};  // rgbToSpectrum(background): secondary misses and the depth limit
};

// Section 8.4: D_reflect = Omega + 2N, Omega = D / |D.N|, N turned so that
// D.N < 0; normalised.
Vec3 reflectDirection(const Vec3& d, const Vec3& n);
// Section 8.5: D_refract = k_f (N + Omega) - N, k_f = (n^2 |Omega|^2 - |Omega +
// N|^2)^(-1/2), N turned so that D.N < 0, n = index, or 1/index when the ray
// leaves the object (D.N > 0 before the turn, CGL-Q45). False on total
// internal reflection (a radicand <= 0): no refracted ray.
bool refractDirection(const Vec3& d, const Vec3& n, double index, Vec3& out);

}  // namespace prime::cgl
