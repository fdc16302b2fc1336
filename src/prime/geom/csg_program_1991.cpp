#include "src/prime/geom/csg_program_1991.h"

#include <algorithm>

namespace prime {

namespace {

// Post-order flattening of an object's tree into `steps`; each flatten()
// returns false where csg1991 would throw on some ray (or the program grows
// too big), and the caller then keeps csg1991.
struct CsgCompiler {
  using Kind = CsgProgram1991::StepKind;
  std::span<const CsgEntry> entries;
  const Csg1991Options& options;
  std::vector<CsgProgram1991::Step>& steps;
  int maxDepth = 0;         // operand lists alive at once
  std::vector<int> path{};  // entries from the root to here (cycle check)
  std::size_t visits = 0;

  bool add(Kind kind, int arg) {
    if (steps.size() >= CsgProgram1991::kMaxSteps) return false;
    steps.push_back({kind, arg});
    return true;
  }

  // `depth`: operand lists already on the stack below this subtree's result.
  bool flatten(int entry, int depth) {
    if (entry < 0 || static_cast<std::size_t>(entry) >= entries.size())
      return false;                                                              // kBadEntryIndex
    if (std::find(path.begin(), path.end(), entry) != path.end()) return false;  // kCycle
    if (++visits > options.maxVisits) return false;                              // kTooManyVisits
    maxDepth = std::max(maxDepth, depth + 1);
    const CsgEntry& e = entries[static_cast<std::size_t>(entry)];
    if (e.op == 'P') return add(Kind::Leaf, e.l);
    if (e.op != '+' && e.op != '-' && e.op != '&') return false;  // kBadOpcode
    path.push_back(entry);
    if (!flatten(e.l, depth)) return false;
    std::size_t skip = 0;
    if (e.op != '+' && options.skipRightWhenLeftEmpty) {  // Q4
      skip = steps.size();
      if (!add(Kind::SkipRightIfEmpty, 0)) return false;
    }
    if (!flatten(e.r, depth + 1)) return false;
    if (!add(e.op == '+' ? Kind::Union : e.op == '-' ? Kind::Difference : Kind::Intersection, 0))
      return false;
    // (A skip step never comes first: the left subtree's steps precede it.)
    if (skip != 0) steps[skip].arg = static_cast<int>(steps.size());  // the step after the operator
    path.pop_back();
    return true;
  }
};

}  // namespace

std::optional<CsgProgram1991> CsgProgram1991::compile(std::span<const CsgEntry> entries,
                                                      const Csg1991Options& options) {
  CsgProgram1991 p;
  CsgCompiler c{entries, options, p.steps_};
  if (!c.flatten(0, 0)) return std::nullopt;
  p.maxDepth_ = c.maxDepth;
  return p;
}

TList CsgProgram1991::run(LeafFn leaf) const {
  SmallVec<TList, 8> stack;  // the operands: left lists below right ones
  stack.reserve(static_cast<std::size_t>(maxDepth_) + 1);
  for (std::size_t pc = 0; pc < steps_.size(); ++pc) {
    const Step& s = steps_[pc];
    switch (s.kind) {
      case StepKind::Leaf: {  // IntersectPrim: the pair, or an empty list on a miss
        TList& l = stack.emplace_back();
        if (const std::optional<PrimHit> hit = leaf(s.arg))
          l.addPair(hit->tIn, hit->tOut, hit->nIn, hit->nOut, s.arg);
        break;
      }
      case StepKind::SkipRightIfEmpty:  // Q4: an empty left list is the result
        if (stack.back().empty()) pc = static_cast<std::size_t>(s.arg) - 1;
        break;
      default: {
        TList& right = stack.back();
        TList& left = stack[stack.size() - 2];
        if (s.kind == StepKind::Union)
          union1991(left, right);
        else if (s.kind == StepKind::Difference)
          difference1991(left, right);
        else
          intersection1991(left, right);
        stack.pop_back();
        break;
      }
    }
  }
  return std::move(stack.back());
}

}  // namespace prime
