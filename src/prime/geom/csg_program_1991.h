// An object's CSG tree flattened once, at load, into post-order steps, so
// that each ray runs down a short list instead of walking the tree with a
// stack of frames. run() returns exactly what csg1991 returns on the same
// tree: the leaves are asked in the same order (left to right, each once per
// reference), the operators are the same union1991/difference1991/
// intersection1991 calls on the same operands, Q4's early exit becomes a
// jump over the right subtree, and the operators' errors (E57) propagate the
// same way.
//
// A tree that csg1991 would reject on some ray (a child index outside the
// entries, a cycle, an unknown operator, more visits than the budget) or
// that flattens to more than kMaxSteps steps is not compiled: the caller
// keeps calling csg1991, which reports the error exactly as before.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "src/prime/geom/csg_1991.h"

namespace prime {

class CsgProgram1991 {
 public:
  static constexpr std::size_t kMaxSteps = 4096;

  static std::optional<CsgProgram1991> compile(std::span<const CsgEntry> entries,
                                               const Csg1991Options& options = {});

  // csg1991(entries, leaf, options) for the tree this program was compiled from.
  TList run(LeafFn leaf) const;

  // A lone primitive: the whole program is one leaf.
  bool isSingleLeaf() const { return steps_.size() == 1; }
  std::size_t size() const { return steps_.size(); }

  enum class StepKind : std::uint8_t { Leaf, Union, Difference, Intersection, SkipRightIfEmpty };
  struct Step {
    StepKind kind;
    int arg;  // Leaf: primitive number; SkipRightIfEmpty: the step after the operator
  };

 private:
  std::vector<Step> steps_;
  int maxDepth_ = 0;  // operand lists alive at once
};

}  // namespace prime
