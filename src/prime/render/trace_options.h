// How a ray tree is traced: what every profile takes (RayTreeOptions) and
// what only the 1991 profile does (Listing1991Options: the errata's guards and
// the work it may skip). A render's settings carry both (TraceOptions); each
// tracer takes its part.
#pragma once
#include "src/prime/geom/csg_1991.h"
#include "src/prime/render/listing_fixes.h"

namespace prime {

struct RayTreeOptions {
  int maxDepth = 5;  // Define.h MaxDepth
  // Adaptive tree-depth control (thesis 2.4): a reflected or transmitted
  // ray whose weight in the pixel (the product of the kSR*FSR or
  // kST*FST*tT^sT factors above it, largest channel) falls below this is
  // not cast. 0 = off (the listing).
  double minWeight = 0.0;
};

struct Listing1991Options {
  int tirCap = 1000;   // E59: iterations of the TIR loop before giving up; 0 = no cap
  Csg1991Options csg;  // Q4 alternative etc.
  // Skip work whose result the listing multiplies by zero or throws away:
  // no reflected ray where kSR = 1 - kDR = 0, no transmitted ray (nor the
  // walk through the object) where kST = 1 - kDT = 0, and Roth's early exit
  // (Q4) for '-' and '&' with an empty left list. The pixels are identical
  // unless a skipped subtree would have produced NaN/Inf or a fatal listing
  // error (E57), which the original could not render either (docs/prime/deviations.md).
  // false: do every piece of work the listing did (for ray counts and checks).
  bool skipUnneededWork = true;
  // --fix: the listing quirks corrected on top of the 1991 profile (none:
  // the listing).
  ListingFixes fixes;
};

// Both parts: Tracer1991 takes all of it, TracerModern the RayTreeOptions.
struct TraceOptions : RayTreeOptions, Listing1991Options {};

}  // namespace prime
