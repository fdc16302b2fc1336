// ReflectedRay and TransmittedRay (Rays module, 6896-7012) on scenes built in
// memory, against hand computation: a ray caught by total internal reflection
// in a cube and in a sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "src/prime/math/listing_matrix.h"
#include "src/prime/render/tracer_1991.h"

namespace prime {
namespace {

// One object made of one primitive of `type`, scaled by `scale` about the
// origin and rotated by `rotZ` degrees about z (listing Transform order).
Scene oneObject(char type, double scale, double rotZ = 0.0) {
  Scene s;
  ScenePrim p;
  p.type = io::primType(type).value();
  p.transform = identity4();
  transform(p.transform, {scale, scale, scale}, {0, 0, 0}, {0, 0, 0}, {0, 0, rotZ});
  EXPECT_TRUE(inverse(p.transform, p.inverse));
  s.prims.push_back(p);
  SceneObject o;
  o.number = 1;
  o.entries = {CsgEntry{'P', 0, 0}};
  o.hue.indx = 1.5;
  s.objects.push_back(o);
  return s;
}

void expectVec(const Vec3& got, const Vec3& want, double tol = 1e-9) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
}

TEST(ReflectedRay, MirrorsAboutTheNormalAndStepsOneUnit) {
  // d = (1,-1,0)/sqrt2 onto n = (0,1,0) at t = 2 from (0,2,0)/...:
  // twoDot = 2*(-1/sqrt2); r = d - n*twoDot = (1/sqrt2, 1/sqrt2, 0), unit;
  // origin = o + t*d + r.
  const Scene s = oneObject('B', 1.0);
  const Tracer1991 tracer(s);
  const double h = 1.0 / std::sqrt(2.0);
  const Ray r = tracer.reflectedRay({{0, 2, 0}, {h, -h, 0}}, 2.0, {0, 1, 0});
  expectVec(r.d, {h, h, 0}, 1e-15);
  expectVec(r.o, {2 * h + h, 2 - 2 * h + h, 0}, 1e-15);
}

TEST(TransmittedRay, CubeSideFaceTotalInternalReflection_K19_K6) {
  // Cube [0,100]^3, indx 1.5. Incident d = (sin60, 0, cos60) hits the front
  // face z = 0 at (90,50,0) with n = (0,0,-1).
  //   entry: c1 = 0.5, c2 = sqrt(1 - (4/9)(3/4)) = sqrt(2/3);
  //          T = (2/3)d + (1/3 - sqrt(2/3)) n = (1/sqrt3, 0, sqrt(2/3)) (unit);
  //          origin = (90,50,0) - T.
  //   walk 1: enters z=0 at t=1, leaves x=100 at t1 = 10*sqrt3 + 1, at z = 10*sqrt2.
  //          IntersectCube tests x=1 first, then z=0 (nearer): Swap hands the
  //          x=1 face's OUTWARD (1,0,0) to nOut (K6). c1 = 1/sqrt3,
  //          1 - 2.25*(2/3) = -0.5 < 0: TIR. d.x -> -1/sqrt3;
  //          origin = exit - d = (100 + 1/sqrt3, 50, 10*sqrt2 - sqrt(2/3)).
  //   walk 2: enters x=1 at t=1 (first face: nIn=(1,0,0)), leaves z=1 at
  //          t2 = (100 - 10*sqrt2)/sqrt(2/3) + 1; that face is farther, so
  //          nOut = -(0,0,1) = (0,0,-1), INWARD (K6). c1 = -sqrt(2/3),
  //          c2 = sqrt(1 - 2.25/3) = 0.5.
  //   exit:  d = 1.5 d + (1.5 c1 - c2)(-nOut) = (-sqrt3/2, 0, 1.5 sqrt(2/3) - 1.5 sqrt(2/3) - 0.5)
  //          = (-sqrt3/2, 0, -0.5): the inward normal turns the ray back (K6).
  //   origin = exit point (100 - (t2-1)/sqrt3, 50, 100) + d;  sT = t1 + t2.
  const Scene s = oneObject('B', 100.0);
  const Tracer1991 tracer(s);
  const double sq3 = std::sqrt(3.0), sq2 = std::sqrt(2.0), k = std::sqrt(2.0 / 3.0);
  const Vec3 d{std::sin(M_PI / 3), 0, std::cos(M_PI / 3)};
  const Ray incident{{90 - 10 * d[0], 50, -10 * d[2]}, d};
  TraceStats stats;
  double sT = 0;
  const Ray out = tracer.transmittedRay(incident, s.objects[0], 10.0, {0, 0, -1}, 1.5, sT, stats);
  const double t1 = 10 * sq3 + 1, t2 = (100 - 10 * sq2) / k + 1;
  EXPECT_EQ(stats.totalInternalReflections, 1u);
  EXPECT_NEAR(sT, t1 + t2, 1e-9);
  expectVec(out.d, {-sq3 / 2, 0, -0.5});
  expectVec(out.o, {100 - (t2 - 1) / sq3 - sq3 / 2, 50, 99.5});
}

TEST(TransmittedRay, SphereRotatedSoTheLocalExitNormalReflectsInternally_K5_E46) {
  // Sphere of radius 100 rotated 90 degrees about z (Roundoff: cos ~ 1.3e-8,
  // sin = 1). Incident d = (1,0,0) hits (-100,0,0) with world n = (-1,0,0):
  //   entry: c1 = 1, c2 = 1, T = d (straight in); origin = (-101,0,0).
  //   walk 1: exits at world (100,0,0), t = 201. The exit normal is the
  //          LOCAL point negated (K5): the local point is the world point
  //          rotated back by 90 degrees, (0,-1,0) (to ~1e-8), so nOut = (0,1,0).
  //          c1 = T.nOut = 0 -> 1 - 2.25 < 0: total internal reflection. The
  //          reflection d += 2*c1*(-nOut) changes nothing, so the ray steps
  //          back to x = 100 - 1 = 99 with the same d, and the next walk
  //          finds no pair ahead inside (K7: origin inside): E46 ends it.
  // With the listing's raw local normal the refraction out never happens and
  // the ray leaves from the entry point region, with sT = 201.
  const Scene s = oneObject('S', 100.0, 90.0);
  const Tracer1991 tracer(s);
  TraceStats stats;
  double sT = 0;
  const Ray out = tracer.transmittedRay({{-110, 0, 0}, {1, 0, 0}}, s.objects[0], 10.0, {-1, 0, 0},
                                        1.5, sT, stats);
  EXPECT_EQ(stats.totalInternalReflections, 1u);
  EXPECT_EQ(stats.emptyTransmitLists, 1u);
  EXPECT_NEAR(sT, 201.0, 1e-6);
  expectVec(out.d, {1, 0, 0}, 1e-6);
  // After TIR the origin is (100,0,0) - d = (99,0,0); E46 keeps it and the
  // final step adds d: (100,0,0).
  expectVec(out.o, {100, 0, 0}, 1e-6);
}

TEST(TransmittedRay, CapStopsARayTrappedForEver_E59) {
  // The cube walk above, with the TIR cap at 1: the second walk is not
  // taken; the ray leaves from where the first reflection put it, plus d.
  const Scene s = oneObject('B', 100.0);
  TraceOptions options;
  options.tirCap = 1;
  const Tracer1991 tracer(s, options);
  const double sq2 = std::sqrt(2.0), k = std::sqrt(2.0 / 3.0), r3 = 1 / std::sqrt(3.0);
  const Vec3 d{std::sin(M_PI / 3), 0, std::cos(M_PI / 3)};
  TraceStats stats;
  double sT = 0;
  const Ray out = tracer.transmittedRay({{90 - 10 * d[0], 50, -10 * d[2]}, d}, s.objects[0], 10.0,
                                        {0, 0, -1}, 1.5, sT, stats);
  EXPECT_EQ(stats.cappedTirLoops, 1u);
  expectVec(out.d, {-r3, 0, k});
  expectVec(out.o, {100 + r3 - r3, 50, 10 * sq2 - k + k});  // (exit - d) + d
}

}  // namespace
}  // namespace prime
