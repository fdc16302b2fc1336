// Unit tests of the correct (regularised) set operations, csg_sets.h.
//
// The oracle is Table 3.1 of the thesis (Sec. 3.6):
//   Union:        in,in->in  in,out->in  out,in->in  out,out->out
//   Intersection: in,in->in  in,out->out out,in->out out,out->out
//   Difference:   in,in->out in,out->in  out,in->out out,out->out
// The explicit expectations below are written by hand from that table and the
// documented tie rule (regularised result; at a shared boundary the left
// operand's node wins; B's nodes in a difference flip role and, with outward
// normals, are negated).
//
// Node shorthand: en(t,p) = entry node of prim p (surfType Out, nIn(p));
// ex(t,p) = exit node (surfType In, nOut(p)).
#include "src/prime/geom/csg_sets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "src/prime/geom/interval_list.h"
#include "tests/prime/unit/geom/tlist_builders.h"

namespace prime {
namespace {

using namespace tlist_builders;
// A node of the subtracted list B as a difference outputs it (outward convention).
TNode flippedEntryAsExit(double t, int prim) {
  return TNode{t, prim, kSurfIn, -nIn(prim)};
}
TNode flippedExitAsEntry(double t, int prim) {
  return TNode{t, prim, kSurfOut, -nOut(prim)};
}

bool table31(SetOp op, bool left, bool right) {
  switch (op) {
    case SetOp::kUnion:
      return left || right;
    case SetOp::kIntersection:
      return left && right;
    case SetOp::kDifference:
      return left && !right;
  }
  return false;
}

// Classification of point t against a list of pairs (t strictly inside a pair).
bool inside(const TList& l, double t) {
  for (std::size_t k = 0; k < l.pairCount(); ++k)
    if (l.entry(k).t < t && t < l.exit(k).t) return true;
  return false;
}

const TList kA = L({{2, 4, 1}});  // A of the relative-position tests; B is prim 2

// ---------------------------------------------------------------------------
// Every relative position of two intervals (Allen's 13 relations), each op.

struct Case {
  const char* name;
  TList b;
  TList uni;
  TList inter;
  TList diff;
};

std::vector<Case> relations() {
  return {
      // B before A, disjoint.
      {"before",
       L({{0, 1, 2}}),
       {en(0, 2), ex(1, 2), en(2, 1), ex(4, 1)},
       {},
       {en(2, 1), ex(4, 1)}},
      // B touches A from before: union merges, intersection is only a point.
      {"meets", L({{1, 2, 2}}), {en(1, 2), ex(4, 1)}, {}, {en(2, 1), ex(4, 1)}},
      // B overlaps A's start.
      {"overlaps",
       L({{1, 3, 2}}),
       {en(1, 2), ex(4, 1)},
       {en(2, 1), ex(3, 2)},
       {flippedExitAsEntry(3, 2), ex(4, 1)}},
      // Same start, B shorter: A's entry wins the tie.
      {"starts",
       L({{2, 3, 2}}),
       {en(2, 1), ex(4, 1)},
       {en(2, 1), ex(3, 2)},
       {flippedExitAsEntry(3, 2), ex(4, 1)}},
      // B nested inside A: the difference splits A.
      {"during",
       L({{2.5, 3.5, 2}}),
       {en(2, 1), ex(4, 1)},
       {en(2.5, 2), ex(3.5, 2)},
       {en(2, 1), flippedEntryAsExit(2.5, 2), flippedExitAsEntry(3.5, 2), ex(4, 1)}},
      // Same end, B shorter: A's exit wins the tie.
      {"finishes",
       L({{3, 4, 2}}),
       {en(2, 1), ex(4, 1)},
       {en(3, 2), ex(4, 1)},
       {en(2, 1), flippedEntryAsExit(3, 2)}},
      // Equal.
      {"equal", L({{2, 4, 2}}), {en(2, 1), ex(4, 1)}, {en(2, 1), ex(4, 1)}, {}},
      // Same start, B longer.
      {"startedBy", L({{2, 5, 2}}), {en(2, 1), ex(5, 2)}, {en(2, 1), ex(4, 1)}, {}},
      // A nested inside B.
      {"contains", L({{1, 5, 2}}), {en(1, 2), ex(5, 2)}, {en(2, 1), ex(4, 1)}, {}},
      // Same end, B longer.
      {"finishedBy", L({{1, 4, 2}}), {en(1, 2), ex(4, 1)}, {en(2, 1), ex(4, 1)}, {}},
      // B overlaps A's end.
      {"overlappedBy",
       L({{3, 5, 2}}),
       {en(2, 1), ex(5, 2)},
       {en(3, 2), ex(4, 1)},
       {en(2, 1), flippedEntryAsExit(3, 2)}},
      // B touches A from after.
      {"metBy", L({{4, 6, 2}}), {en(2, 1), ex(6, 2)}, {}, {en(2, 1), ex(4, 1)}},
      // B after A, disjoint.
      {"after", L({{5, 6, 2}}), {en(2, 1), ex(4, 1), en(5, 2), ex(6, 2)}, {}, {en(2, 1), ex(4, 1)}},
  };
}

TEST(CsgSets, EveryRelativePositionOfTwoIntervals) {
  for (const Case& c : relations()) {
    EXPECT_EQ(setUnion(kA, c.b), c.uni) << c.name;
    EXPECT_EQ(setIntersection(kA, c.b), c.inter) << c.name;
    EXPECT_EQ(setDifference(kA, c.b), c.diff) << c.name;
  }
}

TEST(CsgSets, UnionAndIntersectionAreSymmetricUpToTheTieRule) {
  // Swapping the operands gives the same spans; only tied nodes change owner.
  for (const Case& c : relations()) {
    const TList u1 = setUnion(kA, c.b);
    const TList u2 = setUnion(c.b, kA);
    const TList i1 = setIntersection(kA, c.b);
    const TList i2 = setIntersection(c.b, kA);
    ASSERT_EQ(u1.size(), u2.size()) << c.name;
    ASSERT_EQ(i1.size(), i2.size()) << c.name;
    for (std::size_t k = 0; k < u1.size(); ++k) EXPECT_EQ(u1[k].t, u2[k].t) << c.name;
    for (std::size_t k = 0; k < i1.size(); ++k) EXPECT_EQ(i1[k].t, i2[k].t) << c.name;
  }
  // The tie itself: equal intervals, the left operand's nodes.
  EXPECT_EQ(setUnion(L({{2, 4, 2}}), kA), (TList{en(2, 2), ex(4, 2)}));
}

TEST(CsgSets, DifferenceOfBFromA_ReverseDirection) {
  // B - A for the "during" case: A=[2,4] inside B=[1,5] -> [1,2] and [4,5], the
  // inner boundaries being A's nodes flipped.
  EXPECT_EQ(setDifference(L({{1, 5, 2}}), kA),
            (TList{en(1, 2), flippedEntryAsExit(2, 1), flippedExitAsEntry(4, 1), ex(5, 2)}));
}

TEST(CsgSets, FacingRayConventionKeepsTheSubtractedNormals) {
  // kFacingRay: roles flip, normals are kept (already facing the ray origin).
  EXPECT_EQ(setDifference(kA, L({{2.5, 3.5, 2}}), NormalConvention::kFacingRay),
            (TList{en(2, 1), TNode{2.5, 2, kSurfIn, nIn(2)}, TNode{3.5, 2, kSurfOut, nOut(2)},
                   ex(4, 1)}));
}

// ---------------------------------------------------------------------------
// Truth table, exhaustively, on a grid: every list of at most two intervals
// with integer ends in [0,5] (touching, nested, equal and degenerate included)
// against every other, every op, checked at every non-grid sample point.

std::vector<TList> gridLists(int prim) {
  std::vector<TList> lists{TList{}};
  for (int a = 0; a <= 5; ++a)
    for (int b = a; b <= 5; ++b) {  // b == a: a zero-length pair
      lists.push_back(L({{double(a), double(b), prim}}));
      for (int c = b; c <= 5; ++c)
        for (int d = c + 1; d <= 5; ++d)
          lists.push_back(L({{double(a), double(b), prim}, {double(c), double(d), prim + 1}}));
    }
  return lists;
}

TEST(CsgSets, Table31_ExhaustiveOnAGrid) {
  const std::vector<TList> as = gridLists(1);
  const std::vector<TList> bs = gridLists(11);
  int checked = 0;
  for (const TList& a : as)
    for (const TList& b : bs)
      for (SetOp op : {SetOp::kUnion, SetOp::kIntersection, SetOp::kDifference}) {
        const TList r = setCombine(op, a, b);
        ASSERT_TRUE(isNormalized(r)) << r;
        for (double s = -0.75; s < 6.0; s += 0.25) {
          if (s == std::floor(s)) continue;  // boundaries: regularised, not classified
          ASSERT_EQ(inside(r, s), table31(op, inside(a, s), inside(b, s)))
              << "op " << int(op) << " A " << a << " B " << b << " -> " << r << " at " << s;
        }
        // Provenance: every output node is a node of A or B at that t, with
        // its surfType set by role.
        for (std::size_t k = 0; k < r.size(); ++k) {
          ASSERT_EQ(r[k].surfType, k % 2 == 0 ? kSurfOut : kSurfIn);
          bool found = false;
          for (const TList* src : {&a, &b})
            for (const TNode& n : *src)
              if (n.t == r[k].t && n.prim == r[k].prim) found = true;
          ASSERT_TRUE(found) << r;
        }
        ++checked;
      }
  // 1 empty + 21 single (6 of them zero-length) + 70 two-pair lists, each side.
  EXPECT_EQ(as.size(), 92u);
  EXPECT_EQ(checked, static_cast<int>(3 * as.size() * bs.size()));
}

// ---------------------------------------------------------------------------
// Multi-interval lists, by hand.

TEST(CsgSets, MultiIntervalLists) {
  // A = [0,2]/1 [3,5]/3 [6,8]/5, B = [1,4]/2 [7,9]/4.
  const TList a = L({{0, 2, 1}, {3, 5, 3}, {6, 8, 5}});
  const TList b = L({{1, 4, 2}, {7, 9, 4}});
  // Union: in from 0 to 5 (B bridges the gap 2..3), from 6 to 9.
  EXPECT_EQ(setUnion(a, b), (TList{en(0, 1), ex(5, 3), en(6, 5), ex(9, 4)}));
  // Intersection: [1,2] [3,4] [7,8].
  EXPECT_EQ(setIntersection(a, b),
            (TList{en(1, 2), ex(2, 1), en(3, 3), ex(4, 2), en(7, 4), ex(8, 5)}));
  // Difference: [0,1] [4,5] [6,7]; the cuts at 1, 4 and 7 are B's nodes flipped.
  EXPECT_EQ(setDifference(a, b),
            (TList{en(0, 1), flippedEntryAsExit(1, 2), flippedExitAsEntry(4, 2), ex(5, 3), en(6, 5),
                   flippedEntryAsExit(7, 4)}));
}

TEST(CsgSets, ChainedOperationsStayNormalised) {
  // ((A + B) - C) & D with A=[0,2]/1, B=[2,6]/2 (touching: merged), C=[3,4]/3,
  // D=[1,10]/4 -> (A+B) = [0,6]; minus C = [0,3] [4,6]; & D = [1,3] [4,6].
  const TList ab = setUnion(L({{0, 2, 1}}), L({{2, 6, 2}}));
  EXPECT_EQ(ab, (TList{en(0, 1), ex(6, 2)}));
  const TList abc = setDifference(ab, L({{3, 4, 3}}));
  EXPECT_EQ(abc, (TList{en(0, 1), flippedEntryAsExit(3, 3), flippedExitAsEntry(4, 3), ex(6, 2)}));
  EXPECT_EQ(setIntersection(abc, L({{1, 10, 4}})),
            (TList{en(1, 4), flippedEntryAsExit(3, 3), flippedExitAsEntry(4, 3), ex(6, 2)}));
}

TEST(CsgSets, EmptyOperands) {
  EXPECT_EQ(setUnion(kA, TList{}), kA);
  EXPECT_EQ(setUnion(TList{}, kA), kA);
  EXPECT_EQ(setIntersection(kA, TList{}), TList{});
  EXPECT_EQ(setDifference(kA, TList{}), kA);
  EXPECT_EQ(setDifference(TList{}, kA), TList{});
}

TEST(CsgSets, InfiniteEnds) {
  const double inf = std::numeric_limits<double>::infinity();
  const TList all = L({{-inf, inf, 9}});
  EXPECT_EQ(setIntersection(kA, all), kA);
  EXPECT_EQ(setDifference(all, kA),
            (TList{en(-inf, 9), flippedEntryAsExit(2, 1), flippedExitAsEntry(4, 1), ex(inf, 9)}));
}

TEST(CsgSets, OperandsAreUnchanged) {
  const TList a = L({{3, 4, 2}, {0, 1, 1}});  // unsorted: normalised internally
  const TList b = L({{0.5, 3.5, 3}});
  const TList a0 = a;
  const TList b0 = b;
  (void)setDifference(a, b);
  EXPECT_EQ(a, a0);
  EXPECT_EQ(b, b0);
}

TEST(CsgSets, OddListIsRejected) {
  EXPECT_THROW((void)setUnion(TList{en(1, 1)}, kA), CsgError);
  EXPECT_THROW((void)normalized(TList{en(1, 1)}), CsgError);
}

// ---------------------------------------------------------------------------
// normalized(): the regularised union of a list's own pairs.

TEST(Normalized, SortsMergesAndDropsEmptyPairs) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Unsorted.
  EXPECT_EQ(normalized(L({{3, 4, 2}, {0, 1, 1}})), (TList{en(0, 1), ex(1, 1), en(3, 2), ex(4, 2)}));
  // Overlapping: first entry, farthest exit.
  EXPECT_EQ(normalized(L({{0, 2, 1}, {1, 3, 2}})), (TList{en(0, 1), ex(3, 2)}));
  // Touching: merged.
  EXPECT_EQ(normalized(L({{0, 1, 1}, {1, 2, 2}})), (TList{en(0, 1), ex(2, 2)}));
  // Nested: the outer pair.
  EXPECT_EQ(normalized(L({{0, 5, 1}, {1, 2, 2}})), (TList{en(0, 1), ex(5, 1)}));
  // Equal ends: the earlier pair's exit.
  EXPECT_EQ(normalized(L({{0, 5, 1}, {1, 5, 2}})), (TList{en(0, 1), ex(5, 1)}));
  // Zero-length, inverted and NaN pairs are dropped.
  TList junk = L({{1, 1, 1}, {3, 2, 2}, {5, 6, 3}});
  junk.addPair(nan, 7, nIn(4), nOut(4), 4);
  EXPECT_EQ(normalized(junk), (TList{en(5, 3), ex(6, 3)}));
  EXPECT_FALSE(isNormalized(junk));
  EXPECT_TRUE(isNormalized(normalized(junk)));
}

TEST(Normalized, CleansThe1991QuirkShapes) {
  // Union1991 U3 output [en1/2 ex4/1 | ex5/2 ex5/2] (Q3): the degenerate pair goes.
  EXPECT_EQ(normalized(TList{en(1, 2), ex(4, 1), ex(5, 2), ex(5, 2)}), (TList{en(1, 2), ex(4, 1)}));
  // Difference1991 D3 output, the inverted pair [ex5/2 ex4/1] (Q3): empty.
  EXPECT_EQ(normalized(TList{ex(5, 2), ex(4, 1)}), TList{});
  // Difference1991 D2 output [ex3/2 ex4/1]: the entry node gets its role (Out).
  EXPECT_EQ(normalized(TList{ex(3, 2), ex(4, 1)}),
            (TList{TNode{3, 2, kSurfOut, nOut(2)}, ex(4, 1)}));
}

}  // namespace
}  // namespace prime
