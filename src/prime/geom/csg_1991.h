// CSG module of the listing (lines 3216-3712): the recursive CSG tree walk and
// the three Roth-list operators Union, Difference and Intersection, AS PRINTED.
//
// These operators do not compute the set operations in every case (errata Q3,
// K30, K31): the 1991 profile reproduces them node for node, including node
// order, inverted and degenerate pairs and the fatal double Kill (E57). For
// correct set operations use csg_sets.h.
//
// Reading of the damaged text: E12 (dropped `)` after `*tList`/`*tList1`),
// E13 (`copy` = `Copy`), E10 (braces at page breaks, rebuilt from the
// `/* == */` comments), E14 (`tListPos`), E56 (AddToTList), E57 (Kill of an
// empty list), K29/Q4 (right subtree always evaluated).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>

#include "src/math/vec.h"
#include "src/prime/geom/interval_list.h"
#include "src/prime/geom/prim_hit.h"

namespace prime {

// Union(tList, tList1), Difference(tList, tList1), Intersection(tList, tList1):
// `a` is *tList (the left operand) and receives the result; `b` is *tList1
// (the right operand) and is consumed: it is empty afterwards, as the listing
// leaves *tList1 == NULL (every node has been Added to the result or Killed).
//
// Errors: CsgError kKillEmptyList when the printed code Kills an exhausted
// list (E57: Difference 3487-3488, 3537-3539, 3559-3560), kOddList when an
// operand has an odd node count. After an error `a` and `b` are valid lists
// with unspecified contents (the listing would have exited).
void union1991(TList& a, TList& b);
void difference1991(TList& a, TList& b);
void intersection1991(TList& a, TList& b);

// One entry of an object's CSG tree (Obj of obj.h: opCode[0], l, r). Entry 0
// is the root (IntersectObj: ReadObj(0, ...)). For an operator ('+', '-',
// '&'), l and r are entry indices; for a leaf ('P', IsPrim 6449-6460), l is
// the primitive number and r is unused.
struct CsgEntry {
  char op = 'P';
  int l = 0;
  int r = 0;
};

// Leaf callback: the primitive's interval for a primitive number, or nothing
// when the ray misses it (IntersectPrim with intersect == 0). A non-owning
// reference to any callable `std::optional<PrimHit>(int)`; the callable
// must outlive the call it is passed to (a lambda written in the call is fine).
class LeafFn {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, LeafFn> &&
           !std::is_function_v<std::remove_reference_t<F>> &&
           std::is_invocable_r_v<std::optional<PrimHit>, std::remove_reference_t<F>&, int>)
      LeafFn(F&& f)
  noexcept  // NOLINT(google-explicit-constructor): used like std::function_ref
      : obj_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
        call_([](void* obj, int prim) -> std::optional<PrimHit> {
          return std::invoke(*static_cast<std::remove_reference_t<F>*>(obj), prim);
        }) {}

  std::optional<PrimHit> operator()(int prim) const { return call_(obj_, prim); }

 private:
  void* obj_;
  std::optional<PrimHit> (*call_)(void*, int);
};

struct Csg1991Options {
  // Q4 alternative `(*tList != NULL)` at 3271: skip the right subtree of a
  // '-' or '&' whose left result is empty (the result is empty either way).
  // Default false = the printed `(tList != NULL)`, always true (K29).
  bool skipRightWhenLeftEmpty = false;
  // Guard against bad input, not a listing feature: at most this many entry
  // visits per call (a proper tree visits each entry once; an entry that is
  // referenced more than once is evaluated once per reference, as printed).
  std::size_t maxVisits = std::size_t{1} << 20;
};

// CSG(obj, tList, ray, objFile) (3248-3304) on the tree `entries`, starting at
// entry `root`: evaluates the left subtree, then (K29) the right one, then
// combines them with union1991/difference1991/intersection1991. A leaf adds
// the primitive's pair [tIn (Out, nIn), tOut (In, nOut), prim = l] when the
// callback reports a hit. Returns the object's tList (unsorted, K30: the
// caller takes its FIRST node, as IntersectObj does).
//
// Leaves are visited left to right, each once per reference (as the listing).
// The walk is iterative (no recursion), so deep trees cannot overflow the
// stack. Errors (CsgError): kBadEntryIndex for a child or root index outside
// `entries`; kCycle when a path from the root revisits an entry (it would
// recurse for ever); kTooManyVisits past options.maxVisits; kBadOpcode when an operator is not '+',
// '-' or '&' (the listing's Error at 3294, reported after both subtrees, as printed);
// kKillEmptyList from difference1991 (E57). Exceptions thrown by the callback
// propagate.
TList csg1991(std::span<const CsgEntry> entries, LeafFn leaf, const Csg1991Options& options = {},
              int root = 0);

}  // namespace prime
