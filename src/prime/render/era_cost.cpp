#include "src/prime/render/era_cost.h"

namespace prime {

double EventOps::microseconds(const OpCosts1991& c) const {
  return add * c.add + mul * c.mul + div * c.div + sqrt * c.sqrt + compare * c.compare +
         trig * c.trig + pow * c.pow + call * c.call;
}

EventOps1991 listingOps1991() {
  EventOps1991 o;
  // The eye ray: the screen point to world (ScrToWorld's products), the
  // direction from the eye, UnitVector (3 squares, a root, 3 divisions).
  o.primaryRay = {.add = 9, .mul = 9, .div = 3, .sqrt = 1, .call = 2};
  // ReflectedRay (6896-6925) / TransmittedRay: the point, the new direction
  // (Heckbert's formula; Snell's with its root for a transmission),
  // UnitVector, the origin moved along it.
  o.secondaryRay = {.add = 12, .mul = 10, .div = 3, .sqrt = 1, .compare = 1, .call = 2};
  // Transfrm of origin and direction (a 4 x 4 matrix: 24 products, 21
  // sums), then the unit sphere's or box's test.
  o.boundTest = {.add = 29, .mul = 32, .compare = 4, .call = 3};
  // The CSG walk over the object's lists: comparisons and the list's nodes.
  o.objectTest = {.compare = 6, .call = 2};
  // Transfrm, the quadric's (or the box's slabs') roots, both normals.
  o.primitiveTest = {.add = 32, .mul = 40, .div = 2, .sqrt = 1, .compare = 6, .call = 3};
  // The hit: the point in the world and the primitive's frame, the normal
  // through the inverse transpose and UnitVector, the map's texel, the
  // reflected and transmitted terms of each channel (a Cos(ACos) and a pow
  // each, three channels).
  o.hit = {
      .add = 40, .mul = 45, .div = 6, .sqrt = 2, .compare = 8, .trig = 6, .pow = 3, .call = 10};
  // Hall's terms for one light in one channel, recomputed per channel as
  // the listing's lambda loop does: the light's vector and UnitVector, Hj and
  // Hj' (a root and UnitVector each), the dot products, Cos(ACos) of both, a
  // pow of both, two Fresnel terms.
  o.lightChannel = {
      .add = 24, .mul = 30, .div = 12, .sqrt = 4, .compare = 6, .trig = 4, .pow = 2, .call = 6};
  // ColorNum: three products and the integer conversions (FIST ~ 90 clocks
  // each, counted as divisions).
  o.pixel = {.add = 3, .mul = 6, .div = 3, .compare = 3, .call = 2};
  return o;
}

double seconds1991(const TraceStats& s, std::uint64_t pixels, int lights, const OpCosts1991& c,
                   const EventOps1991& o) {
  const double us =
      static_cast<double>(s.primaryRays) * o.primaryRay.microseconds(c) +
      static_cast<double>(s.reflectedRays + s.transmittedRays + s.shadowRays) *
          o.secondaryRay.microseconds(c) +
      static_cast<double>(s.boundTests) * o.boundTest.microseconds(c) +
      static_cast<double>(s.objectTests) * o.objectTest.microseconds(c) +
      static_cast<double>(s.primitiveTests) * o.primitiveTest.microseconds(c) +
      static_cast<double>(s.hits) *
          (o.hit.microseconds(c) + 3.0 * lights * o.lightChannel.microseconds(c)) +
      static_cast<double>(pixels) * (o.pixel.microseconds(c) + c.putPixel + c.fileWrite);
  return us * 1e-6;
}

}  // namespace prime
