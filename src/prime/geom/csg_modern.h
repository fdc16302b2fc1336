// The modern profile's CSG tree walk: correct set operations (csg_sets) on
// whole-line intervals, one consistent tie rule, normals kept outward of the
// result solid (a subtracted primitive's normals are negated).
#pragma once
#include <functional>
#include <optional>
#include <span>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/interval_list.h"
#include "src/prime/geom/primitives_modern.h"

namespace prime {

// The result list is normalised: sorted pairs [entry, exit], entry nodes
// with surfType Out and exit nodes In. Entries with '-' or '&' skip their
// right subtree when the left is empty (the result is empty either way).
// `leaf(prim)` gives the primitive's whole-line interval, or nothing.
TList csgModern(std::span<const CsgEntry> entries,
                const std::function<std::optional<PrimHit>(int)>& leaf, int root = 0);

}  // namespace prime
