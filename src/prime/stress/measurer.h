// The stress suite's measurement: a profile's answer for a ray against the
// reference's (decisions, distance, normal, (u, v)), with the conditioning
// tolerance that tells a wrong decision from an ambiguous one
// (docs/prime/numerics.md).
#pragma once
#include <string>
#include <vector>

#include "src/prime/stress/common.h"
#include "src/prime/stress/stress.h"
#include "src/prime/stress/subjects.h"

namespace prime::stress {

// PRIME_STRESS_DEBUG=1: print every wrong decision and every large normal
// error to stderr (for investigating a class).
bool debugOn();
void debugRay(const char* what, const std::string& types, const Ray& ray, double pt, long double rt,
              bool listing);

class Measurer {
 public:
  Measurer(const Subject& s, const StressOptions& o)
      : s_(s), c_(o.toleranceUlps), quad_(o.quad && kHaveQuad) {}

  // The reference for `ray` (design semantics for the 1991 profile when k7).
  RefResult reference(const Ray& ray, bool k7, Figures& f) const;
  // Tolerance (local units of prim k) at parameter t of the world ray.
  LD tolerance(int k, const Ray& ray, LD t, const V3<LD>& pl) const;
  // Signed distance in tolerances of the object's solid at ray(t).
  LD objectNsdf(int obj, const Ray& ray, LD t) const;
  LD sceneNsdf(const Ray& ray, LD t) const;
  // The extreme (min when `inside`, else max) of the object's normalised
  // signed distance along [a, b] of the ray.
  LD extreme(int obj, const Ray& ray, LD a, LD b, bool inside) const;
  // True when the object's solid along [a, b] is nowhere deeper than one tolerance.
  bool thin(int obj, const Ray& ray, LD a, LD b) const;
  // Backward error of a hit at tp where the reference has its nearest boundary at tr.
  bool explainable(int obj, const Ray& ray, LD tp, LD tr, bool refEnters) const;

  // Compares a profile's answer with the reference; returns true when the
  // decisions agree without ambiguity (a clean hit, usable for secondaries).
  bool compare(const ProfileHit& p, const RefResult& r, const Ray& ray, bool listing,
               Figures& f) const;

  const Subject& subject() const { return s_; }
  // World unit normals of every face of the reference hit's primitive within
  // the tolerance of the reference hit point.
  std::vector<Vec3> worldNormalsAt(const RefResult& r, const Ray& ray) const;
  std::string describe() const;  // the subject's type letters and operators

 private:
  // The reference hit's primitive, the ray in its frame, the local hit point
  // and the tolerance there.
  struct RefPoint {
    const RefPrim<LD>* prim;
    RefRay<LD> local;
    V3<LD> p;
    LD tol;
  };
  RefPoint refPointAt(const RefResult& r, const Ray& ray) const;

  // The steps of compare().
  bool sameHitDecisions(const ProfileHit& p, const RefResult& r, const Ray& ray, bool listing,
                        Figures& f) const;
  bool sameSurface(const ProfileHit& p, const RefResult& r, const Ray& ray, const RefPoint& at,
                   LD dt, bool listing, Figures& f) const;
  void measureNormal(const ProfileHit& p, const RefResult& r, const Ray& ray, const RefPoint& at,
                     bool listing, Figures& f) const;
  void measureUv(const ProfileHit& p, const RefResult& r, const RefPoint& at, Figures& f) const;

  LD nsdf(const std::vector<CsgEntry>& e, int node, const V3<LD>& pw, const Ray& ray, LD t,
          int depth) const;

  const Subject& s_;
  double c_;
  bool quad_;
};

}  // namespace prime::stress
