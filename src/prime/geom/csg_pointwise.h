// The modern profile's CSG tree read as what it is point by point: the
// solid holds a point of the ray exactly when the tree's boolean formula
// (union = or, intersection = and, difference = and-not) holds for which of
// its leaves hold the point. Every PRIME primitive is convex, so a leaf
// holds one interval of the ray, [tIn, tOut]; between two consecutive ends
// of those intervals nothing changes. The regularised set operations of
// csg_sets give, at every t, the list whose pairs are the runs where the
// formula holds (Table 3.1 applied open interval by open interval), so
// what the renderer asks of the list -- its first node ahead, the length
// of solid along a segment -- can be read from the leaves' ends without
// building a list (N18 of docs/prime/deviations.md):
//   - firstAhead: the first end t > 0 where the formula changes; the node
//     there is that end's leaf's entry or exit, its surface type the
//     formula's new state, its normal marker negated once for every
//     difference whose right operand the leaf is in (the sweep of
//     setDifference negates a subtracted node's normal);
//   - firstExit: the same for the first end t > 0 where it stops holding
//     (a refracted ray's way out of the solid);
//   - insideLength: the runs where the formula holds, each clipped to
//     [0, tMax] and added in order, as the list's pairs are.
// When the answer would depend on which of several ends at the same t the
// sweeps keep (two ends at the t where the formula changes), or a leaf's
// interval is empty or NaN (normalisation drops it; Q4 below sees it), the
// caller builds the list (kGeneral): the answer is then the list's.
//
// gather asks the leaves in the order and number runModern asks them: left
// to right, and the right operand of '-' and '&' is not asked when the
// left operand's list is empty (Q4 as compileModern compiles it). That
// list is empty exactly when the left subtree's formula holds on no open
// interval between its leaves' ends. firstAheadLazy asks some of those
// leaves, in the same order: only while the answer depends on them.
//
// The formula is kept as its truth table over the leaves (a bit per set of
// leaves holding the point), so trees with shared subtrees (Calls) or more
// than kMaxLeaves leaves are not taken (compile gives nothing); the list
// walk serves them.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "src/prime/geom/csg_program_1991.h"
#include "src/prime/geom/interval_list.h"

namespace prime {

class CsgPointwise {
 public:
  static constexpr int kMaxLeaves = 6;  // a truth table of 2^6 bits

  // The pointwise form of a program compiled by compileModern; nothing
  // for a program with shared subtrees or more than kMaxLeaves leaves.
  static std::optional<CsgPointwise> compile(const CsgProgram1991& program);

  enum class Answer { kNone, kFound, kGeneral };

  // One leaf's answer: its primitive's interval along the ray, if it has
  // one (a leaf not met, or not asked, keeps NaN ends).
  struct Span {
    double tIn = kNaN, tOut = kNaN;
    bool hit = false;
  };
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  // The leaves' intervals, asked as runModern asks them: `leaf(prim, span)`
  // fills span.tIn, span.tOut and returns whether the primitive is met.
  // False (kGeneral) when an interval met is NaN or not tIn < tOut.
  template <class Leaf>
  bool gather(Leaf&& leaf, std::array<Span, kMaxLeaves>& spans) const {
    for (int i = 0; i < leafCount_; ++i) spans[static_cast<std::size_t>(i)] = Span{};
    for (std::size_t pc = 0; pc < steps_.size(); ++pc) {
      const Step& st = steps_[pc];
      if (st.kind == Kind::kLeaf) {
        Span& s = spans[static_cast<std::size_t>(st.leaf)];
        s.hit = leaf(leafPrim_[static_cast<std::size_t>(st.leaf)], s);
        if (!s.hit) s = Span{};
        if (s.hit && !(s.tIn < s.tOut)) return false;  // also NaN
      } else if (st.kind == Kind::kSkipRightIfEmpty && neverHolds(spans, st)) {
        pc = static_cast<std::size_t>(st.to) - 1;  // (the right operand's leaves stay unmet)
      }
    }
    return true;
  }

  // firstAhead's answer with the leaves asked only while it could depend on
  // them (a render's question). A leaf's padded box, `entryOf(prim)` where
  // the ray enters it ahead (+inf for none), is a lower bound of where the
  // ray can enter the primitive, so until then the leaf holds no point
  // ahead. The leaves are asked (`leaf` as gather's) in runModern's order,
  // each only while the formula depends on it: not when a missed leaf makes
  // its part empty (with A missed, A - B and A & B do not depend on B), nor
  // when it is in the right operand of a '-' or '&' whose left operand is
  // known and holds on no open interval (Q4); so never a leaf runModern
  // would not ask. The answer is final once the first change lies before
  // every box still to be asked (every box entered at t <= 0 is asked
  // before t = 0+ is judged), or when no leaf is left to ask. A box not
  // entered by tMax counts as missed, as objectIntervalsAhead's leaves do;
  // the list of the leaves asked gives the same first node as runModern's in
  // [0, tMax] (and beyond, unless a leaf culled there would have changed it:
  // the render compares it with tMax).
  template <class EntryOf, class Leaf>
  Answer firstAheadLazy(EntryOf&& entryOf, Leaf&& leaf, double tMax, const Vec3& entry,
                        const Vec3& exit, TNode& node) const {
    switch (leafCount_) {  // (the loops over the leaves unrolled)
      case 2:
        return firstAheadLazyOf<2>(entryOf, leaf, tMax, entry, exit, node);
      case 3:
        return firstAheadLazyOf<3>(entryOf, leaf, tMax, entry, exit, node);
      case 4:
        return firstAheadLazyOf<4>(entryOf, leaf, tMax, entry, exit, node);
      default:
        return firstAheadLazyOf<0>(entryOf, leaf, tMax, entry, exit, node);
    }
  }

  // runModern's list's first node with t > 0, from the gathered spans: its
  // t, primitive and surface type, and for its normal the marker `entry`
  // or `exit` of the leaf's end, negated as the list would negate it.
  Answer firstAhead(const std::array<Span, kMaxLeaves>& spans, const Vec3& entry, const Vec3& exit,
                    TNode& node) const {
    return firstChange(spans, entry, exit, false, node);
  }
  // The same for runModern's list's first exit node (surface type In) with
  // t > 0: the first end t > 0 where the formula stops holding.
  Answer firstExit(const std::array<Span, kMaxLeaves>& spans, const Vec3& entry, const Vec3& exit,
                   TNode& node) const {
    return firstChange(spans, entry, exit, true, node);
  }
  // The sum over runModern's list's pairs of min(tMax, exit) - max(0, entry)
  // where positive, in list order (kFound, or kNone for 0: no run there).
  Answer insideLength(const std::array<Span, kMaxLeaves>& spans, double tMax, double& length) const;

  int leafCount() const { return leafCount_; }

 private:
  // firstAheadLazy for a tree of N leaves, or of leafCount_ leaves (N = 0).
  template <int N, class EntryOf, class Leaf>
  Answer firstAheadLazyOf(EntryOf& entryOf, Leaf& leaf, double tMax, const Vec3& entry,
                          const Vec3& exit, TNode& node) const {
    const int leaves = N > 0 ? N : leafCount_;
    std::array<Span, kMaxLeaves> spans;  // (every one not met: NaN ends)
    std::array<double, kMaxLeaves> enter;
    unsigned missed = 0;   // the leaves that hold no point (culled or missed)
    unsigned waiting = 0;  // the leaves not asked yet
    for (int i = 0; i < leaves; ++i) {
      const double e = entryOf(leafPrim_[static_cast<std::size_t>(i)]);
      enter[static_cast<std::size_t>(i)] = e;
      if (e == std::numeric_limits<double>::infinity() || !(e <= tMax))  // (also NaN)
        missed |= 1u << i;
      else
        waiting |= 1u << i;
    }
    Answer answer = Answer::kNone;
    bool known = true;  // `answer` is firstAhead's for the spans so far
    for (;;) {
      // The leaves still to ask: not gated, and the formula depends on them
      // (none when it cannot hold). A gate's left operand is known when no
      // leaf of it is still to ask (a leaf the formula does not depend on
      // lies in a part made empty by a missed leaf, which is the left
      // operand's own or holds the gate's right operand too); gates come in
      // post-order, an inner one's right operand known for an outer one.
      unsigned ask = waiting & depends_[missed];
      for (int g = 0; g < gateCount_; ++g) {
        const Gate& gate = gates_[static_cast<std::size_t>(g)];
        if ((gate.left & ask) == 0 && (gate.right & ask) != 0 &&
            neverHolds(spans, steps_[gate.skip]))
          ask &= ~gate.right;
      }
      if (ask == 0) break;
      // The nearest box of those still to be asked, and the one to ask now:
      // the leftmost (runModern's order).
      double next = std::numeric_limits<double>::infinity();
      int i = -1;
      for (int j = 0; j < leaves; ++j)
        if (((ask >> j) & 1u) != 0) {
          next = std::min(next, enter[static_cast<std::size_t>(j)]);
          if (i < 0) i = j;
        }
      if (next > 0.0) {  // t = 0+ is known (no box still to ask holds the origin)
        if (!known) {
          answer = firstAhead(spans, entry, exit, node);
          known = true;
        }
        if (answer == Answer::kFound && node.t < next) return answer;
      }
      waiting &= ~(1u << i);
      Span& s = spans[static_cast<std::size_t>(i)];
      s.hit = leaf(leafPrim_[static_cast<std::size_t>(i)], s);
      if (!s.hit) s = Span{};  // (a leaf may write its span and still miss)
      if (s.hit) {
        if (!(s.tIn < s.tOut)) return Answer::kGeneral;  // also NaN
        known = false;
      } else {
        missed |= 1u << i;
      }
    }
    // No leaf left that the formula depends on: those not asked are out.
    return known ? answer : firstAhead(spans, entry, exit, node);
  }
  enum class Kind : std::uint8_t { kLeaf, kUnion, kDifference, kIntersection, kSkipRightIfEmpty };
  struct Step {
    Kind kind;
    int leaf = 0;            // kLeaf: the leaf's index (left to right); kSkipRightIfEmpty:
                             // the left operand's leaf when it is one leaf, else -1
    int to = 0;              // kSkipRightIfEmpty: the step after the operator (where it goes on)
    std::uint64_t left = 0;  // kSkipRightIfEmpty: the left operand's truth table
  };
  // firstAhead, or with `exitsOnly` firstExit.
  Answer firstChange(const std::array<Span, kMaxLeaves>& spans, const Vec3& entry, const Vec3& exit,
                     bool exitsOnly, TNode& node) const;
  // firstChange for a tree of N leaves (the loops unrolled).
  template <int N>
  Answer firstChangeOf(const std::array<Span, kMaxLeaves>& spans, const Vec3& entry,
                       const Vec3& exit, bool exitsOnly, TNode& node) const;
  // The formula of steps [from, to) (one whole subtree) with leaf i holding
  // the point when bit i of `in` is set.
  bool holds(unsigned in, std::size_t from, std::size_t to) const;
  // Whether the left operand of skip step `st` holds on no open interval
  // between the met leaves' ends (its list is empty).
  bool neverHolds(const std::array<Span, kMaxLeaves>& spans, const Step& st) const;

  std::vector<Step> steps_;
  std::uint64_t table_ = 0;  // bit `in`: the whole formula
  // bit `out`: the formula holds for no set of leaves disjoint from `out`
  std::uint64_t never_ = 0;
  // [out]: the leaves the formula depends on when those of `out` hold no
  // point (none when it cannot hold).
  std::array<unsigned char, 64> depends_{};
  // The right operands of '-' and '&' whose left operand has more than one
  // leaf: when every leaf of the left operand is known and it holds on no
  // open interval (its list is empty: Q4), the right operand's leaves do
  // not matter.
  struct Gate {
    unsigned left = 0, right = 0;  // the operands' leaves
    std::size_t skip = 0;          // the skip step (its `left` table)
  };
  std::array<Gate, kMaxLeaves> gates_{};
  int gateCount_ = 0;
  std::array<int, kMaxLeaves> leafPrim_{};  // per leaf: its primitive
  unsigned leafNegated_ = 0;  // bit i: leaf i is in the right operand of an odd number of '-'
  int leafCount_ = 0;
};

}  // namespace prime
