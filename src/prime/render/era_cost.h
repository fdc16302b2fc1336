// How long the 1991 program took: an estimate of RayTrace.c's time on the
// machine it ran on (an IBM PS/2 with a 20 MHz 80386 and an 80387, Turbo C
// 2.0 doubles), from the counts the tracer keeps. `--pace 1991` draws at this
// rate and `--record` times its frames by it (docs/prime/pace-1991.md).
//
// Each counted event (a primary ray, a bound test, a primitive test, a hit
// shaded with L lights, a pixel written and put on the screen) is a number of
// double operations of each kind, read off the listing's routines; each kind
// costs what a 387 instruction sequence compiled by Turbo C costs: load the
// operand, operate, store the result (Turbo C kept no double in the 387's
// registers across a statement), plus the 386-387 protocol. The clock counts
// are Intel's 80387 and 80386 timing tables (80387 Programmer's Reference
// Manual, 1987; 80386 Programmer's Reference Manual, 1986, ch. 17), at 50 ns a
// clock. The estimate is good to about a factor of two (see the page).
#pragma once
#include <cstdint>

#include "src/prime/render/trace_stats.h"

namespace prime {

// Microseconds one operation of each kind took in RayTrace.c's code.
struct OpCosts1991 {
  double add = 7.0;         // FLD m64 25 + FADD m64 33 + FSTP m64 45 + protocol 36 clocks
  double mul = 7.6;         // FLD 25 + FMUL m64 45 + FSTP 45 + 36
  double div = 10.0;        // FLD 25 + FDIV m64 94 + FSTP 45 + 36
  double sqrt = 13.0;       // FLD 25 + FSQRT 125 + FSTP 45 + 36 + the library call 29
  double compare = 5.2;     // FLD 25 + FCOMP m64 31 + FSTSW 15 + SAHF 3 + Jcc 5 + 24
  double trig = 50.0;       // Turbo C's cos / acos in degrees: FPTAN or FPATAN (191-497,
                            // 314-487) with the argument's reduction and checks, ~1000
  double pow = 75.0;        // pow(x, y): FYL2X (120-538) + F2XM1 (211-476) + FSCALE and
                            // the checks, ~1500
  double call = 2.0;        // a far CALL (17+m), RET (18+m) and the frame, ~40
  double putPixel = 40.0;   // one putpixel through the BGI driver to the 8514/A
  double fileWrite = 20.0;  // fwrite of one 2-byte value (buffered)
};

// The double operations of one event, as the listing performs it.
struct EventOps {
  double add = 0, mul = 0, div = 0, sqrt = 0, compare = 0, trig = 0, pow = 0, call = 0;
  double microseconds(const OpCosts1991& c) const;
};

// The listing's operations for each counted event.
struct EventOps1991 {
  EventOps primaryRay;     // the eye ray of a pixel: its direction, normalised
  EventOps secondaryRay;   // ReflectedRay / TransmittedRay, normalised
  EventOps boundTest;      // Transfrm of the ray into the bound's frame, the unit test
  EventOps objectTest;     // IntersectObj's CSG over the Roth lists (the walk itself)
  EventOps primitiveTest;  // Transfrm, the unit primitive's roots, both normals
  EventOps hit;            // the nearest hit shaded: point, normal, map, the ray terms
  EventOps lightChannel;   // one light in one of the three channels (Hall's terms)
  EventOps pixel;          // ColorNum, fwrite and putpixel of the pixel's value
};
EventOps1991 listingOps1991();

// Seconds the 1991 program spent on the work `stats` counted (the listing's
// work: count it with skipUnneededWork off), for `pixels` pixels and a scene
// of `lights` lights.
double seconds1991(const TraceStats& stats, std::uint64_t pixels, int lights,
                   const OpCosts1991& costs = {}, const EventOps1991& ops = listingOps1991());

}  // namespace prime
