// The packet path of the 1991 primitives: see primitives_1991_packet.h. Each
// block below names the scalar function (primitives_1991.cpp) whose
// expressions it repeats, operand for operand.
#include "src/prime/geom/primitives_1991_packet.h"

#include <cmath>
#include <cstring>

#include "src/prime/geom/primitives_1991.h"
#include "src/prime/math/listing_math.h"

// A 32-byte vector passed by value changes the ABI between -mavx and the
// baseline; these helpers are internal, so the compilers' note about it
// (GCC's and Clang's -Wpsabi) says nothing here.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wunknown-warning-option"
#pragma clang diagnostic ignored "-Wpsabi"
#elif defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace prime {

using io::PrimType;

namespace {

using Lanes = double __attribute__((vector_size(kPacketLanes * sizeof(double))));

Lanes load(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
Lanes splat(double x) {
  return Lanes{x, x, x, x};
}
// The lanes whose comparison holds, as bits.
template <class Mask>
unsigned bits(const Mask& m) {
  unsigned b = 0;
  for (int l = 0; l < kPacketLanes; ++l)
    if (m[l]) b |= 1u << l;
  return b;
}
// sqrt per lane where `where` is set (the scalar code only takes the root of
// a value > 0); 0 elsewhere.
Lanes sqrtWhere(const Lanes& v, unsigned where) {
  Lanes r = splat(0.0);
  for (int l = 0; l < kPacketLanes; ++l)
    if (where & (1u << l)) r[l] = std::sqrt(v[l]);
  return r;
}

// The packet's coordinates as vectors.
struct Packet {
  Lanes o[3], d[3];
  explicit Packet(const RayPacket& p) {
    for (int a = 0; a < 3; ++a) {
      o[a] = load(p.o[a]);
      d[a] = load(p.d[a]);
    }
  }
};

// One candidate face for every lane: its t and the lanes where the scalar
// code finds it (those lanes' t is the scalar t).
struct Face {
  Lanes t;
  unsigned ok = 0;
};

// hitsUnitSquare: t = (1 - o) / d or -o / d, then both other coordinates in
// [0, 1]. `ok` also holds d != 0 (the callers' guard).
Face unitSquare(const Packet& r, int axis, bool levelOne) {
  Face f;
  const Lanes o = r.o[axis], d = r.d[axis];
  f.t = levelOne ? (splat(1.0) - o) / d : -o / d;
  const int a = axis == X ? Y : X;
  const int b = axis == Z ? Y : Z;
  const Lanes ca = r.o[a] + f.t * r.d[a];
  const Lanes cb = r.o[b] + f.t * r.d[b];
  const Lanes zero = splat(0.0), one = splat(1.0);
  f.ok = bits(d != zero) & bits(f.t > zero) & bits(ca >= zero) & bits(ca <= one) &
         bits(cb >= zero) & bits(cb <= one);
  return f;
}

// hitsUnitDisc (z = 0 or z = 1, x^2 + y^2 <= 1), with d[Z] != 0 in `ok`.
Face unitDisc(const Packet& r, bool levelOne) {
  Face f;
  const Lanes o = r.o[Z], d = r.d[Z];
  f.t = levelOne ? (splat(1.0) - o) / d : -o / d;
  const Lanes x = r.o[X] + f.t * r.d[X];
  const Lanes y = r.o[Y] + f.t * r.d[Y];
  const Lanes zero = splat(0.0);
  f.ok = bits(d != zero) & bits(f.t > zero) & bits(x * x + y * y <= splat(1.0));
  return f;
}

// The two roots of a body's quadratic: cylinderRoots, coneRoots and
// sphereRoots share the shape a, b, c -> d = b*b - a*c > 0, sqrt,
// (-b + d) / a and (-b - d) / a; `ok` holds a != 0 (where the scalar checks
// it) and d > 0.
struct Roots {
  Lanes t1, t2;
  unsigned ok = 0;
};
Roots roots(const Lanes& a, const Lanes& b, const Lanes& c, unsigned aChecked) {
  Roots r;
  const Lanes disc = b * b - (a * c);
  r.ok = aChecked & bits(disc > splat(0.0));
  const Lanes s = sqrtWhere(disc, r.ok);
  r.t1 = (-b + s) / a;
  r.t2 = (-b - s) / a;
  return r;
}
Roots cylinderRoots(const Packet& r) {
  const Lanes a = r.d[X] * r.d[X] + r.d[Y] * r.d[Y];
  const Lanes b = r.o[X] * r.d[X] + r.o[Y] * r.d[Y];
  const Lanes c = r.o[X] * r.o[X] + r.o[Y] * r.o[Y] - splat(1.0);
  return roots(a, b, c, bits(a != splat(0.0)));
}
Roots coneRoots(const Packet& r) {
  const Lanes a = r.d[X] * r.d[X] + r.d[Y] * r.d[Y] - r.d[Z] * r.d[Z];
  const Lanes b = r.o[X] * r.d[X] + r.o[Y] * r.d[Y] - r.o[Z] * r.d[Z];
  const Lanes c = r.o[X] * r.o[X] + r.o[Y] * r.o[Y] - r.o[Z] * r.o[Z];
  return roots(a, b, c, bits(a != splat(0.0)));
}
Roots sphereRoots(const Packet& r) {
  const Lanes a = r.d[X] * r.d[X] + r.d[Y] * r.d[Y] + r.d[Z] * r.d[Z];
  const Lanes b = r.o[X] * r.d[X] + r.o[Y] * r.d[Y] + r.o[Z] * r.d[Z];
  const Lanes c = r.o[X] * r.o[X] + r.o[Y] * r.o[Y] + r.o[Z] * r.o[Z] - splat(1.0);
  return roots(a, b, c, (1u << kPacketLanes) - 1);  // the sphere divides unguarded
}
// The sphere's hit and its bound alike: both roots ahead (K7, K8).
unsigned bothAhead(const Roots& q) {
  return q.ok & bits(q.t1 > splat(0.0)) & bits(q.t2 > splat(0.0));
}

// A body root t > 0 whose z lies in [0, 1] (the cylinder's `z <= 1.0 &&
// z >= -0.0`, the cone's inUnitRange: the same test).
unsigned rootInSlab(const Packet& r, const Lanes& t, unsigned ok) {
  const Lanes z = r.o[Z] + t * r.d[Z];
  return ok & bits(t > splat(0.0)) & bits(z <= splat(1.0)) & bits(z >= splat(0.0));
}

// intersectRayPlane1991 for every lane: vD = Roundoff(n.d) (dot summed from
// 0.0 in X, Y, Z order), vO = -(Roundoff(n.o) + d), t = vO / vD; ok where
// vD != 0 and t > 0. Roundoff is the listing's scalar function, per lane.
Face plane(const Packet& r, const Plane4& p, Lanes pt[3]) {
  Lanes dotD = splat(0.0), dotO = splat(0.0);
  for (int a = 0; a < 3; ++a) {
    dotD = dotD + splat(p[a]) * r.d[a];
    dotO = dotO + splat(p[a]) * r.o[a];
  }
  Lanes vD = splat(0.0), vO = splat(0.0);
  for (int l = 0; l < kPacketLanes; ++l) {
    vD[l] = roundoff(dotD[l]);
    vO[l] = -(roundoff(dotO[l]) + p[3]);
  }
  Face f;
  f.t = vO / vD;
  f.ok = bits(vD != splat(0.0)) & bits(f.t > splat(0.0));
  for (int a = 0; a < 3; ++a) pt[a] = r.o[a] + f.t * r.d[a];
  return f;
}

// hitsPyramidFace: the plane, then the crossing-number test per lane.
Face pyramidFace(const Packet& r, const PyramidFace1991& face) {
  Lanes pt[3];
  Face f = plane(r, face.plane, pt);
  for (int l = 0; l < kPacketLanes; ++l)
    if ((f.ok & (1u << l)) &&
        !intersectPoly1991(3, {pt[face.uAxis][l], pt[face.vAxis][l]}, face.poly))
      f.ok &= ~(1u << l);
  return f;
}

// The faces of one primitive in the order its scalar function tests them,
// each with its normal for Swap (per lane where the normal depends on the hit).
struct Candidates {
  static constexpr int kMax = 6;
  Face face[kMax];
  Lanes normal[kMax][3];
  int count = 0;
  void add(const Face& f, const Vec3& n) {
    face[count] = f;
    for (int a = 0; a < 3; ++a) normal[count][a] = splat(n[a]);
    ++count;
  }
  void add(const Face& f, const Lanes n[3]) {
    face[count] = f;
    for (int a = 0; a < 3; ++a) normal[count][a] = n[a];
    ++count;
  }
  // Each lane: tIn = tOut = 0, then Swap with every face it finds, in order,
  // until Swap reports the second (the scalar functions' loop, K6/K7).
  unsigned sequence(std::array<PrimHit, kPacketLanes>& hits) const {
    unsigned hitLanes = 0;
    for (int l = 0; l < kPacketLanes; ++l) {
      PrimHit& hit = hits[l];
      hit.tIn = 0.0;
      hit.tOut = 0.0;
      for (int k = 0; k < count; ++k) {
        if (!(face[k].ok & (1u << l))) continue;
        const Vec3 n{normal[k][X][l], normal[k][Y][l], normal[k][Z][l]};
        if (swap1991(face[k].t[l], n, hit)) {
          hitLanes |= 1u << l;
          break;
        }
      }
    }
    return hitLanes;
  }
};

unsigned sphere(const Packet& r, std::array<PrimHit, kPacketLanes>& hits) {
  const Roots q = sphereRoots(r);
  const unsigned ok = bothAhead(q);
  for (int l = 0; l < kPacketLanes; ++l) {
    if (!(ok & (1u << l))) continue;
    PrimHit& hit = hits[l];
    hit.tIn = q.t1[l];
    hit.tOut = q.t2[l];
    if (hit.tOut < hit.tIn) {
      const double tmp = hit.tOut;
      hit.tOut = hit.tIn;
      hit.tIn = tmp;
    }
    for (int i = X; i < W; i++) {
      hit.nIn[i] = r.o[i][l] + hit.tIn * r.d[i][l];
      hit.nOut[i] = -(r.o[i][l] + hit.tOut * r.d[i][l]);
    }
  }
  return ok;
}

unsigned cube(const Packet& r, std::array<PrimHit, kPacketLanes>& hits) {
  Candidates c;
  for (int axis = X; axis <= Z; axis++)
    for (const bool levelOne : {false, true}) {
      Vec3 n0{0.0, 0.0, 0.0};
      n0[axis] = levelOne ? 1.0 : -1.0;
      c.add(unitSquare(r, axis, levelOne), n0);
    }
  return c.sequence(hits);
}

// The cylinder's and the cone's bodies: the normal at a root t.
void bodyNormal(const Packet& r, const Lanes& t, bool cone, Lanes n[3]) {
  n[X] = r.o[X] + t * r.d[X];
  n[Y] = r.o[Y] + t * r.d[Y];
  n[Z] = cone ? -(r.o[Z] + t * r.d[Z]) : splat(0.0);
}

unsigned cylinder(const Packet& r, std::array<PrimHit, kPacketLanes>& hits) {
  Candidates c;
  c.add(unitDisc(r, false), {0.0, 0.0, -1.0});
  c.add(unitDisc(r, true), {0.0, 0.0, 1.0});
  const Roots q = cylinderRoots(r);
  Lanes n[3];
  for (const Lanes* t : {&q.t1, &q.t2}) {
    bodyNormal(r, *t, false, n);
    c.add(Face{*t, rootInSlab(r, *t, q.ok)}, n);
  }
  return c.sequence(hits);
}

unsigned cone(const Packet& r, std::array<PrimHit, kPacketLanes>& hits) {
  Candidates c;
  c.add(unitDisc(r, true), {0.0, 0.0, 1.0});
  const Roots q = coneRoots(r);
  Lanes n[3];
  for (const Lanes* t : {&q.t1, &q.t2}) {
    bodyNormal(r, *t, true, n);
    c.add(Face{*t, rootInSlab(r, *t, q.ok)}, n);
  }
  return c.sequence(hits);
}

unsigned pyramid(const Packet& r, std::array<PrimHit, kPacketLanes>& hits) {
  Candidates c;
  c.add(unitSquare(r, Y, false), {0.0, -1.0, 0.0});
  for (const PyramidFace1991& face : kPyramidFaces1991) c.add(pyramidFace(r, face), face.normal);
  return c.sequence(hits);
}

}  // namespace

RayPacket transformRayPacket(const RayPacket& world, const Matrix4& m) {
  const Packet w(world);
  RayPacket out;
  for (int i = 0; i < 3; ++i) {
    Lanes o = splat(m[3][i]), d = splat(0.0);  // pointMatrixMul, vectorMatrixMul
    for (int j = 0; j < 3; ++j) {
      o = o + w.o[j] * splat(m[j][i]);
      d = d + w.d[j] * splat(m[j][i]);
    }
    std::memcpy(out.o[i], &o, sizeof o);
    std::memcpy(out.d[i], &d, sizeof d);
  }
  return out;
}

unsigned intersectPrimitive1991x4(PrimType type, const RayPacket& local,
                                  std::array<PrimHit, kPacketLanes>& hits) {
  const Packet r(local);
  switch (type) {
    case PrimType::Sphere:
      return sphere(r, hits);
    case PrimType::Cube:
      return cube(r, hits);
    case PrimType::Pyramid:
      return pyramid(r, hits);
    case PrimType::Cylinder:
      return cylinder(r, hits);
    case PrimType::Cone:
      return cone(r, hits);
  }
  return 0;  // not reached: types are checked when the scene is loaded
}

unsigned boundHit1991x4(PrimType type, const RayPacket& local) {
  const Packet r(local);
  switch (type) {
    case PrimType::Sphere:  // boundSphere1991
      return bothAhead(sphereRoots(r));
    case PrimType::Cube: {  // boundCube1991: any face ahead
      unsigned any = 0;
      for (int axis = X; axis <= Z; axis++)
        any |= unitSquare(r, axis, false).ok | unitSquare(r, axis, true).ok;
      return any;
    }
    case PrimType::Cylinder: {
      const Roots q = cylinderRoots(r);
      return unitDisc(r, false).ok | unitDisc(r, true).ok | rootInSlab(r, q.t1, q.ok) |
             rootInSlab(r, q.t2, q.ok);
    }
    case PrimType::Cone: {
      const Roots q = coneRoots(r);
      return unitDisc(r, true).ok | rootInSlab(r, q.t1, q.ok) | rootInSlab(r, q.t2, q.ok);
    }
    case PrimType::Pyramid: {
      unsigned any = unitSquare(r, Y, false).ok;
      for (const PyramidFace1991& face : kPyramidFaces1991) any |= pyramidFace(r, face).ok;
      return any;
    }
  }
  return 0;  // not reached
}

}  // namespace prime
