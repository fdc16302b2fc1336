// An object's CSG tree flattened once, at load, into post-order steps, so
// that each ray runs down a short list instead of walking the tree with a
// stack of frames. run() returns exactly what csg1991 returns on the same
// tree: the leaves are asked in the same order (left to right), the operators
// are the same union1991/difference1991/intersection1991 calls on the same
// operands, Q4's early exit becomes a jump over the right subtree, and the
// operators' errors (E57) propagate the same way.
//
// Shared subtrees (M30): an operator entry referenced more than once (a DAG,
// which obj/O<n> can hold and the listing evaluated once per reference) is
// compiled once, as a subroutine, and evaluated at most once per ray: its
// first use stores its list, later uses copy it. The operators are pure
// functions of their operands and a leaf's answer depends only on the ray,
// so the lists, and hence the pixels, are those of the per-reference walk;
// only the leaf calls of the repeated references (statistics, probe lines)
// are not made again. A tree whose full expansion exceeds the visit budget
// is not compiled (the caller keeps csg1991, which reports kTooManyVisits
// as before), so the visit limit behaves as it did.
//
// Compiling and running are iterative (no recursion): a chain of any depth
// cannot overflow a stack (M31). The per-ray operand stack, the stored
// lists of shared subtrees and the call stack are per-thread scratch that is
// reused from ray to ray (no allocation once warm).
//
// A tree that csg1991 would reject on some ray (a child index outside the
// entries, a cycle, an unknown operator, more visits than the budget) is not
// compiled: compile() gives nothing and the caller keeps calling csg1991,
// which reports the error exactly as before; compileChecked() throws that
// CsgError instead.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "src/prime/geom/csg_1991.h"

namespace prime {

class CsgProgram1991 {
 public:
  static std::optional<CsgProgram1991> compile(std::span<const CsgEntry> entries,
                                               const Csg1991Options& options = {});
  // As compile, but a tree that cannot be compiled throws the CsgError
  // csg1991 would report for it (kBadEntryIndex, kCycle, kBadOpcode,
  // kTooManyVisits).
  static CsgProgram1991 compileChecked(std::span<const CsgEntry> entries,
                                       const Csg1991Options& options = {});

  // csg1991(entries, leaf, options) for the tree this program was compiled from.
  TList run(LeafFn leaf) const;
  // The modern profile's walk (csgModern) over the same program: correct set
  // operations (csg_sets) instead of the listing's operators. Compile it with
  // skipRightWhenLeftEmpty (csgModern skips the right operand of '-' and '&'
  // when the left is empty).
  TList runModern(LeafFn leaf) const;

  // A lone primitive: the whole program is one leaf.
  bool isSingleLeaf() const { return steps_.size() == 2 && steps_[0].kind == StepKind::Leaf; }
  // A union of two or more primitives and nothing else (no other operator,
  // no shared subtree): their numbers in the order the leaves are asked
  // (left to right). Empty otherwise.
  std::vector<int> unionLeaves() const;
  std::size_t size() const { return steps_.size(); }
  // Operator entries referenced more than once (evaluated once per ray).
  std::size_t sharedSubtrees() const { return subStart_.size(); }
  // Entry visits of the per-reference walk (the tree fully expanded, no Q4
  // skip); saturates at kExpansionCap.
  std::uint64_t expandedVisits() const { return expandedVisits_; }
  static constexpr std::uint64_t kExpansionCap = std::uint64_t{1} << 62;

  enum class StepKind : std::uint8_t {
    Leaf,
    Union,
    Difference,
    Intersection,
    SkipRightIfEmpty,
    Call,    // a shared subtree: its stored list, or run its body first
    Return,  // end of a body (the main one: end of the program)
  };
  struct Step {
    StepKind kind;
    int arg;  // Leaf: primitive number; SkipRightIfEmpty: the step after the
              // operator; Call: the shared subtree's number
  };
  // The main body, then each shared subtree's (from subStart).
  std::span<const Step> steps() const { return steps_; }

 private:
  template <class Combine>
  TList execute(LeafFn leaf, Combine combine) const;

  std::vector<Step> steps_;    // the main body (from step 0), then each shared subtree's
  std::vector<int> subStart_;  // first step of each shared subtree's body
  std::uint64_t expandedVisits_ = 0;
};

// Entry visits of the per-reference walk of `entries` from entry 0 (each
// shared subtree counted once per reference; saturates at
// CsgProgram1991::kExpansionCap), or nothing when the tree has a bad child
// index, an unknown operator or a cycle. For the model-time warning (M30).
std::optional<std::uint64_t> csgExpandedVisits(std::span<const CsgEntry> entries);

}  // namespace prime
