// The modern profile's CSG tree walk: correct set operations (csg_sets) on
// whole-line intervals, one consistent tie rule, normals kept outward of the
// result solid (a subtracted primitive's normals are negated).
#pragma once
#include <optional>
#include <span>
#include <vector>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/csg_program_1991.h"
#include "src/prime/geom/interval_list.h"
#include "src/prime/geom/primitives_modern.h"

namespace prime {

// The program csgModern runs: the tree compiled with the modern profile's
// skip (Q4's rule: '-' and '&' skip their right subtree when the left is
// empty) and no visit budget (each shared subtree is evaluated once per ray,
// M30, so the work is the number of entries). CsgError kBadEntryIndex,
// kCycle or kBadOpcode for a tree that is not one.
CsgProgram1991 compileModern(std::span<const CsgEntry> entries);

// The result list is normalised: sorted pairs [entry, exit], entry nodes
// with surfType Out and exit nodes In. Entries with '-' or '&' skip their
// right subtree when the left is empty (the result is empty either way).
// `leaf(prim)` gives the primitive's whole-line interval, or nothing.
// Iterative (M31): no tree depth can overflow the stack. Compiles the tree
// on every call: a renderer compiles once (compileModern) and calls
// runModern per ray.
TList csgModern(std::span<const CsgEntry> entries, LeafFn leaf);

// The primitives whose solid holds the whole solid of the tree, by its
// structure: a leaf holds itself; A - B lies in what holds A; A & B in what
// holds A or B; A + B in what holds both. Sorted, no repeats; empty for a
// union of different primitives. For a tree compileModern accepts.
std::vector<int> containingPrimitives(std::span<const CsgEntry> entries);

}  // namespace prime
