// Correct set operations on Roth interval lists, for the modern profile.
//
// Same node type as the 1991 operators (TNode: t, prim, surfType, norm), so
// primitive numbers and normals flow through to the shading code. Unlike the
// 1991 operators (csg_1991.h, errata Q3/K30/K31) these implement Table 3.1
// of the thesis (Sec. 3.6) exactly:
//   union:        in if left in OR right in
//   intersection: in if left in AND right in
//   difference:   in if left in AND right out
//
// Tie rule (one rule for everything): the operations are REGULARISED, i.e.
// the result is the closure of the interior of the point-set result. All
// boundaries at the same t are processed together, and a boundary is output
// only where the composite classification differs just before and just after
// t. Consequences: touching intervals merge in a union ([1,2] + [2,3] = [1,3]);
// intervals that only touch have an empty intersection; a difference never
// leaves a zero-length sliver; zero-length input pairs ([t,t]) are ignored.
// Comparisons are exact (no epsilon), as in the listing (thesis line 2144).
//
// Output form ("normalised"): pairs sorted by t, every pair [entry, exit] with
// entry.t < exit.t, consecutive pairs strictly apart (exit.t < next entry.t);
// entry nodes have surfType Out (0), exit nodes In (1), as AddToTList builds
// them. So front() is the nearest surface, and a list of n pairs is n disjoint
// solid spans of the ray.
//
// Which node is output at a boundary: the node of the operand whose own
// classification changes at t in the same direction as the composite (for the
// right operand of a difference, its classification is inverted). When both
// qualify, the LEFT operand's node is used. Its t and prim are kept; its
// surfType is set to the role it has in the result.
//
// Normals in a difference: a node taken from the subtracted list B bounds A-B
// from the other side of B's surface. Its role flips (B's exit becomes an entry
// of A-B, surfType Out; B's entry becomes an exit, surfType In), and its
// normal is handled according to the convention of the primitive routines:
//  - NormalConvention::kOutward (default): every normal is the outward normal
//    of its own solid. Then B's normal is negated, so it is outward for A-B.
//  - NormalConvention::kFacingRay: entry normals point outward and exit
//    normals inward, i.e. every normal faces the ray origin (the listing's
//    sphere: nOut = -point). Then B's normal already is A-B's outward (entry)
//    or inward (exit) normal there, and it is kept.
// Union and intersection never change a normal (roles are preserved).
#pragma once

#include "src/prime/geom/interval_list.h"

namespace prime {

enum class SetOp { kUnion, kIntersection, kDifference };

enum class NormalConvention { kOutward, kFacingRay };

// True when `l` is in the normalised form described above (surfTypes are not
// checked; the operations below set them).
[[nodiscard]] bool isNormalized(const TList& l) noexcept;

// Normalises any list of pairs: drops pairs with entry.t >= exit.t (zero
// length or inverted, e.g. the 1991 operators' Q3 outputs) and pairs with a NaN
// t, sorts the rest by entry t (stable), merges overlapping and touching pairs
// (the merged pair keeps the first entry node and the farthest exit node; on a
// tie of t, the earlier one in the list), and sets surfTypes by role. This is
// the regularised union of the list's own pairs.
[[nodiscard]] TList normalized(const TList& l);

// The set operations. Inputs need not be normalised (they are normalised
// first when they are not); the result is normalised. Both operands are
// unchanged. CsgError kOddList if an operand has an odd node count.
[[nodiscard]] TList setUnion(const TList& a, const TList& b);
[[nodiscard]] TList setIntersection(const TList& a, const TList& b);
[[nodiscard]] TList setDifference(const TList& a, const TList& b,
                                  NormalConvention normals = NormalConvention::kOutward);
[[nodiscard]] TList setCombine(SetOp op, const TList& a, const TList& b,
                               NormalConvention normals = NormalConvention::kOutward);

}  // namespace prime
