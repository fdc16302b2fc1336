// The flattened CSG program must return exactly what the tree walk csg1991
// returns: same lists node for node, same leaves asked in the same order
// (a shared subtree's leaves only on its first use, M30), same errors. Checked on random trees with
// random leaf intervals (hits, misses, touching and equal ends, so every operator branch and E57
// occur), with and without Q4's early exit; and the trees csg1991 rejects are not compiled.
#include "src/prime/geom/csg_program_1991.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "src/prime/geom/csg_modern.h"
#include "src/prime/geom/csg_pointwise.h"

namespace prime {
namespace {

// A random tree over `leaves` primitives numbered 0.., entry 0 the root;
// `share` makes some operators point at an existing subtree again.
std::vector<CsgEntry> randomTree(std::mt19937& rng, int leaves, bool share) {
  std::vector<CsgEntry> e;
  // Build bottom-up: a pool of subtree roots, combined pairwise at random.
  std::vector<CsgEntry> nodes;
  std::vector<int> pool;
  for (int i = 0; i < leaves; ++i) {
    nodes.push_back({'P', i, 0});
    pool.push_back(static_cast<int>(nodes.size()) - 1);
  }
  while (pool.size() > 1) {
    const auto a = rng() % pool.size();
    const int left = pool[a];
    pool.erase(pool.begin() + static_cast<long>(a));
    const auto b = rng() % pool.size();
    const int right = share && rng() % 5 == 0 ? left : pool[b];
    if (right != left) pool.erase(pool.begin() + static_cast<long>(b));
    nodes.push_back({"+-&"[rng() % 3], left, right});
    pool.push_back(static_cast<int>(nodes.size()) - 1);
  }
  // Renumber so the root is entry 0 (the listing's ReadObj(0)).
  const int n = static_cast<int>(nodes.size());
  auto renum = [&](int i) { return n - 1 - i; };
  e.resize(nodes.size());
  for (int i = 0; i < n; ++i) {
    CsgEntry c = nodes[static_cast<std::size_t>(i)];
    if (c.op != 'P') {
      c.l = renum(c.l);
      c.r = renum(c.r);
    }
    e[static_cast<std::size_t>(renum(i))] = c;
  }
  return e;
}

bool isSubsequence(const std::vector<int>& part, const std::vector<int>& whole) {
  std::size_t i = 0;
  for (int w : whole)
    if (i < part.size() && part[i] == w) ++i;
  return i == part.size();
}

struct Outcome {
  TList list;
  std::vector<int> asked;  // leaves in the order asked
  std::string error;       // CsgError kind, or empty
};

template <class Run>
Outcome outcome(Run&& run, const std::vector<std::optional<PrimHit>>& leafHits) {
  Outcome o;
  auto leaf = [&](int prim) -> std::optional<PrimHit> {
    o.asked.push_back(prim);
    return leafHits[static_cast<std::size_t>(prim)];
  };
  try {
    o.list = run(LeafFn(leaf));
  } catch (const CsgError& e) {
    o.error = std::to_string(static_cast<int>(e.kind()));
  }
  return o;
}

TEST(CsgProgram1991, RandomTreesGiveTheTreeWalksLists) {
  std::mt19937 rng(1991);
  int compared = 0, errors = 0, skipsTaken = 0, nonEmpty = 0, fewerAsked = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const int leaves = 1 + static_cast<int>(rng() % 7);
    const auto entries = randomTree(rng, leaves, trial % 3 == 0);
    Csg1991Options options;
    options.skipRightWhenLeftEmpty = trial % 2 == 0;
    const auto program = CsgProgram1991::compile(entries, options);
    ASSERT_TRUE(program.has_value()) << "trial " << trial;
    // Intervals on a coarse grid so that ends often coincide.
    std::vector<std::optional<PrimHit>> hits(static_cast<std::size_t>(leaves));
    for (auto& h : hits) {
      if (rng() % 4 == 0) continue;  // a miss
      const double a = static_cast<double>(rng() % 6), b = a + static_cast<double>(rng() % 4);
      h = PrimHit{a, b, {a, 0, 1}, {b, 1, 0}};
    }
    const Outcome walk = outcome([&](LeafFn f) { return csg1991(entries, f, options); }, hits);
    const Outcome flat = outcome([&](LeafFn f) { return program->run(f); }, hits);
    ASSERT_EQ(flat.error, walk.error) << "trial " << trial;
    if (program->sharedSubtrees() == 0) {
      ASSERT_EQ(flat.asked, walk.asked) << "trial " << trial;
    } else if (flat.error.empty()) {
      // M30: the repeated uses of a shared subtree ask nothing again, so the
      // program's questions are the walk's with some left out, in order,
      // and every primitive the walk asked about is asked once at least.
      ASSERT_TRUE(isSubsequence(flat.asked, walk.asked)) << "trial " << trial;
      ASSERT_EQ(std::set<int>(flat.asked.begin(), flat.asked.end()),
                std::set<int>(walk.asked.begin(), walk.asked.end()))
          << "trial " << trial;
      fewerAsked += flat.asked.size() < walk.asked.size();
    }
    ASSERT_TRUE(!walk.error.empty() || flat.list == walk.list) << "trial " << trial << "\n"
                                                               << flat.list << "\n"
                                                               << walk.list;
    ++compared;
    errors += !walk.error.empty();
    nonEmpty += walk.error.empty() && !walk.list.empty();
    skipsTaken +=
        static_cast<int>(walk.asked.size()) < static_cast<int>(entries.size() + 1) / 2 ? 1 : 0;
  }
  EXPECT_EQ(compared, 6000);
  EXPECT_GT(errors, 50);       // E57 (Difference's double Kill) is met ...
  EXPECT_GT(nonEmpty, 2000);   // ... and so are real lists
  EXPECT_GT(skipsTaken, 200);  // and Q4 skips right subtrees
  EXPECT_GT(fewerAsked, 100);  // and shared subtrees are evaluated once
}

TEST(CsgProgram1991, TreesTheWalkRejectsAreNotCompiled) {
  // Child index outside the entries (kBadEntryIndex).
  EXPECT_FALSE(
      CsgProgram1991::compile(std::vector<CsgEntry>{{'+', 1, 5}, {'P', 0, 0}}).has_value());
  // A cycle through the root (kCycle).
  EXPECT_FALSE(
      CsgProgram1991::compile(std::vector<CsgEntry>{{'+', 1, 0}, {'P', 0, 0}}).has_value());
  // An unknown operator (kBadOpcode).
  EXPECT_FALSE(CsgProgram1991::compile(std::vector<CsgEntry>{{'*', 1, 2}, {'P', 0, 0}, {'P', 1, 0}})
                   .has_value());
  // More visits than the budget (kTooManyVisits): 3 entries, 2 allowed.
  Csg1991Options tight;
  tight.maxVisits = 2;
  EXPECT_FALSE(
      CsgProgram1991::compile(std::vector<CsgEntry>{{'+', 1, 2}, {'P', 0, 0}, {'P', 1, 0}}, tight)
          .has_value());
  // No entries at all.
  EXPECT_FALSE(CsgProgram1991::compile(std::vector<CsgEntry>{}).has_value());
  // A lone primitive compiles to one leaf.
  const auto lone = CsgProgram1991::compile(std::vector<CsgEntry>{{'P', 7, 0}});
  ASSERT_TRUE(lone.has_value());
  EXPECT_TRUE(lone->isSingleLeaf());
}

TEST(CsgProgram1991, SharedSubtreesAreFlattenedOncePerReference) {
  // (a - a) with the same LEAF twice: two leaf steps, one Difference, the
  // end (a shared leaf is asked again: only operators are stored, M30).
  const std::vector<CsgEntry> e = {{'-', 1, 1}, {'P', 3, 0}};
  const auto p = CsgProgram1991::compile(e);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->size(), 4u);
  EXPECT_EQ(p->sharedSubtrees(), 0u);
  std::vector<int> asked;
  auto leaf = [&](int prim) -> std::optional<PrimHit> {
    asked.push_back(prim);
    return PrimHit{1, 2, {}, {}};
  };
  // Equal pairs in Difference: the printed code Kills both and then Kills
  // the exhausted list again (E57), in the program as in the tree walk.
  try {
    p->run(leaf);
    ADD_FAILURE() << "no E57";
  } catch (const CsgError& err) {
    EXPECT_EQ(err.kind(), CsgError::Kind::kKillEmptyList);
  }
  EXPECT_THROW(csg1991(e, leaf), CsgError);
  asked.resize(2);
  EXPECT_EQ(asked, (std::vector<int>{3, 3}));
}

// M30: an operator used twice is evaluated once per ray; the list is the
// walk's. (b & c) + (b & c): the walk asks 1, 2, 1, 2; the program 1, 2.
TEST(CsgProgram1991, ASharedOperatorIsEvaluatedOncePerRay) {
  const std::vector<CsgEntry> e = {{'+', 1, 1}, {'&', 2, 3}, {'P', 1, 0}, {'P', 2, 0}};
  const std::vector<std::optional<PrimHit>> hits = {std::nullopt, PrimHit{1, 4, {}, {}},
                                                    PrimHit{2, 6, {}, {}}};
  const auto p = CsgProgram1991::compile(e);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->sharedSubtrees(), 1u);
  EXPECT_EQ(p->expandedVisits(), 7u);  // root + 2 x (& + 2 leaves)
  const Outcome walk = outcome([&](LeafFn f) { return csg1991(e, f); }, hits);
  for (int ray = 0; ray < 3; ++ray) {  // stored lists are per ray: the same each time
    const Outcome flat = outcome([&](LeafFn f) { return p->run(f); }, hits);
    EXPECT_EQ(walk.asked, (std::vector<int>{1, 2, 1, 2}));
    EXPECT_EQ(flat.asked, (std::vector<int>{1, 2}));
    EXPECT_EQ(flat.list, walk.list);
    // [2,4] from the intersection, united with itself: the printed Union
    // keeps [2,4] (equal pairs, I13's union counterpart).
    ASSERT_FALSE(flat.list.empty());
    EXPECT_EQ(flat.list[0].t, 2.0);
  }
}

// 40 nested doublings: 2^41 - 1 entry visits for the listing's walk.
std::vector<CsgEntry> doublings(int levels) {
  std::vector<CsgEntry> e;
  for (int i = 0; i < levels; ++i) e.push_back({'+', i + 1, i + 1});
  e.push_back({'P', 0, 0});
  return e;
}

TEST(CsgProgram1991, NestedSharingPastTheBudgetIsLeftToTheWalk) {
  // The 1991 profile keeps the listing's visit limit: past maxVisits the
  // program is not compiled and csg1991 throws kTooManyVisits as before.
  const auto e = doublings(40);
  EXPECT_FALSE(CsgProgram1991::compile(e).has_value());
  EXPECT_EQ(csgExpandedVisits(e), (std::uint64_t{1} << 41) - 1);
  try {
    (void)CsgProgram1991::compileChecked(e);
    ADD_FAILURE() << "compiled";
  } catch (const CsgError& err) {
    EXPECT_EQ(err.kind(), CsgError::Kind::kTooManyVisits);
  }
  // Without a budget (the modern profile) it compiles, with entries 1..39
  // as stored subtrees, and asks the one leaf twice per ray (entry 39 uses
  // it twice, and leaves are not stored) instead of 2^40 times.
  Csg1991Options unlimited;
  unlimited.maxVisits = std::numeric_limits<std::size_t>::max();
  const auto p = CsgProgram1991::compile(e, unlimited);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->sharedSubtrees(), 39u);  // entries 1..39 (entry 40 is the leaf)
  int asked = 0;
  auto leaf = [&](int) -> std::optional<PrimHit> {
    ++asked;
    return PrimHit{1, 2, {}, {}};
  };
  const TList l = p->runModern(leaf);
  EXPECT_EQ(asked, 2);
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].t, 1.0);
  EXPECT_EQ(l[1].t, 2.0);
}

// M31: chains far deeper than any stack could recurse, on a thread with the
// default stack: compile and run are iterative. Left chain: ((p0 + p1) + p2)
// + ...; right chain: p1 - (p2 - (... - (pD - p0))).
TEST(CsgProgram1991, DeepChainsNeedNoStack) {
  constexpr int kDepth = 200000;
  std::vector<CsgEntry> left, right;
  for (int i = 0; i < kDepth; ++i) left.push_back({'+', i + 1, kDepth + 1 + i});
  left.push_back({'P', 0, 0});
  for (int i = 0; i < kDepth; ++i) left.push_back({'P', i + 1, 0});
  for (int i = 0; i < kDepth; ++i) right.push_back({'-', kDepth + 1 + i, i + 1});
  right.push_back({'P', 0, 0});
  for (int i = 0; i < kDepth; ++i) right.push_back({'P', i + 1, 0});
  // Primitive k covers [k, k + 1.5]: the union is [0, kDepth + 1.5]. In the
  // right chain pD - p0 = [D, D + 1.5], so p(D-1) - that = [D - 1, D], and
  // down the chain pk - (...) = [k, k + 1]: the root's list is [1, 2].
  auto leaf = [](int prim) -> std::optional<PrimHit> {
    return PrimHit{static_cast<double>(prim), prim + 1.5, {}, {}};
  };
  TList unionList, differenceList;
  std::thread t([&] {
    unionList = csgModern(left, leaf);
    differenceList = csgModern(right, leaf);
  });
  t.join();
  ASSERT_EQ(unionList.size(), 2u);
  EXPECT_EQ(unionList[0].t, 0.0);
  EXPECT_EQ(unionList[1].t, kDepth + 1.5);
  ASSERT_FALSE(differenceList.empty());
  ASSERT_EQ(differenceList.size(), 2u);
  EXPECT_EQ(differenceList[0].t, 1.0);
  EXPECT_EQ(differenceList[1].t, 2.0);
}

// The primitives that hold a tree's whole solid, by its structure (what
// lets a ray leaving such a primitive skip the object, N18), worked by hand.
TEST(ContainingPrimitives, FollowTheSetOperations) {
  using V = std::vector<int>;
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'P', 7, 0}}), V{7});
  // A - B lies in A; A & B in both; A + B in neither, unless they are one.
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'-', 1, 2}, {'P', 5, 0}, {'P', 3, 0}}),
            V{5});
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'&', 1, 2}, {'P', 5, 0}, {'P', 3, 0}}),
            (V{3, 5}));
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'+', 1, 2}, {'P', 5, 0}, {'P', 3, 0}}),
            V{});
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'+', 1, 2}, {'P', 5, 0}, {'P', 5, 0}}),
            V{5});
  // (S & (C + C)) - B, the union's operand a shared entry: S and C hold it.
  const std::vector<CsgEntry> nested{{'-', 1, 5}, {'&', 2, 3},  {'P', 10, 0},
                                     {'+', 4, 4}, {'P', 11, 0}, {'P', 12, 0}};
  EXPECT_EQ(containingPrimitives(nested), (V{10, 11}));
  // A tree compileModern refuses has none: a cycle, a child outside the
  // entries, an unknown operator.
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'-', 1, 2}, {'&', 0, 2}, {'P', 3, 0}}),
            V{});
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'-', 1, 9}, {'P', 3, 0}}), V{});
  EXPECT_EQ(containingPrimitives(std::vector<CsgEntry>{{'x', 1, 2}, {'P', 3, 0}, {'P', 4, 0}}),
            V{});
  // A chain of 200,000 differences needs no stack: its first primitive.
  constexpr int kDepth = 200000;
  std::vector<CsgEntry> chain;
  for (int i = 0; i < kDepth; ++i) chain.push_back({'-', i + 1, kDepth + 1 + i});
  chain.push_back({'P', 0, 0});
  for (int i = 0; i < kDepth; ++i) chain.push_back({'P', i + 1, 0});
  V held;
  std::thread t([&] { held = containingPrimitives(chain); });
  t.join();
  EXPECT_EQ(held, V{0});
}

// A leaf's answer as CsgPointwise takes it.
bool spanOf(const std::optional<PrimHit>& h, CsgPointwise::Span& span) {
  if (!h) return false;
  span.tIn = h->tIn;
  span.tOut = h->tOut;
  return true;
}

// The list's first node with t > 0, if any.
const TNode* firstNodeAhead(const TList& list) {
  for (const TNode& n : list)
    if (n.t > 0.0) return &n;
  return nullptr;
}

// CsgPointwise reads from the leaves' intervals what the renderer asks of
// runModern's list: on random trees of two to six leaves, with ends on a
// coarse grid so that they often coincide (and sit at t = 0), it asks the
// same leaves in the same order (Q4's skips included), and its first node
// ahead and length of solid are the list's to the bit, except where it
// hands the ray back (kGeneral: ends tied where the solid changes, or an
// empty interval).
TEST(CsgPointwise, ReadsTheModernListFromTheLeaves) {
  const Vec3 entryMarker{1, 0, 0}, exitMarker{1, 1, 0};
  std::mt19937 rng(1985);
  int found = 0, none = 0, general = 0, emptyLeaf = 0, skips = 0, lengths = 0;
  int lazyAnswers = 0, lazyFewer = 0, exits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int leaves = 2 + static_cast<int>(rng() % 5);
    const auto entries = randomTree(rng, leaves, false);
    const CsgProgram1991 program = compileModern(entries);
    const std::optional<CsgPointwise> pointwise = CsgPointwise::compile(program);
    ASSERT_TRUE(pointwise.has_value()) << "trial " << trial;
    ASSERT_EQ(pointwise->leafCount(), leaves);
    std::vector<std::optional<PrimHit>> hits(static_cast<std::size_t>(leaves));
    for (auto& h : hits) {
      if (rng() % 4 == 0) continue;  // a miss
      // Every other trial on a grid of eighths: ties are rarer there.
      const double a = static_cast<double>(rng() % 9) - 3.0 +
                       (trial % 2 == 0 ? 0.0 : static_cast<double>(rng() % 8) / 8.0);
      const double b = rng() % 25 == 0 ? a : a + 1.0 + static_cast<double>(rng() % 4);
      h = PrimHit{a, b, entryMarker, exitMarker};
    }
    const Outcome list = outcome([&](LeafFn f) { return program.runModern(f); }, hits);
    ASSERT_TRUE(list.error.empty()) << "trial " << trial;
    std::vector<int> asked;
    std::array<CsgPointwise::Span, CsgPointwise::kMaxLeaves> spans;
    const bool taken = pointwise->gather(
        [&](int prim, CsgPointwise::Span& span) {
          asked.push_back(prim);
          return spanOf(hits[static_cast<std::size_t>(prim)], span);
        },
        spans);
    if (!taken) {  // a met leaf with an empty interval: the list serves the ray
      bool degenerate = false;
      for (const int prim : asked) {
        const std::optional<PrimHit>& h = hits[static_cast<std::size_t>(prim)];
        degenerate = degenerate || (h && !(h->tIn < h->tOut));
      }
      ASSERT_TRUE(degenerate) << "trial " << trial;
      ++emptyLeaf;
      continue;
    }
    ASSERT_EQ(asked, list.asked) << "trial " << trial;
    skips += static_cast<int>(asked.size()) < leaves;

    const TNode* ahead = firstNodeAhead(list.list);
    TNode node;
    switch (pointwise->firstAhead(spans, entryMarker, exitMarker, node)) {
      case CsgPointwise::Answer::kFound:
        ASSERT_NE(ahead, nullptr) << "trial " << trial;
        ASSERT_EQ(node, *ahead) << "trial " << trial << "\n" << list.list;
        ++found;
        break;
      case CsgPointwise::Answer::kNone:
        ASSERT_EQ(ahead, nullptr) << "trial " << trial << "\n" << list.list;
        ++none;
        break;
      case CsgPointwise::Answer::kGeneral:
        ++general;
        break;
    }
    // The first exit ahead (a refracted ray's walk out of the solid).
    const TNode* exitNode = nullptr;
    for (const TNode& n : list.list)
      if (n.t > 0.0 && n.surfType == kSurfIn) {
        exitNode = &n;
        break;
      }
    const CsgPointwise::Answer exitAnswer =
        pointwise->firstExit(spans, entryMarker, exitMarker, node);
    if (exitAnswer != CsgPointwise::Answer::kGeneral) {
      ASSERT_EQ(exitAnswer == CsgPointwise::Answer::kFound, exitNode != nullptr)
          << "trial " << trial << "\n"
          << list.list;
      if (exitNode) {
        ASSERT_EQ(node, *exitNode) << "trial " << trial << "\n" << list.list;
      }
      exits += exitNode != nullptr;
    }
    // firstAheadLazy against the list of the leaves not culled: a leaf's
    // box entered at or before its interval (a miss's anywhere, or never),
    // culled when entered beyond tMax.
    std::vector<double> box(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i)
      box[i] = hits[i]          ? hits[i]->tIn - static_cast<double>(rng() % 3)
               : rng() % 2 == 0 ? std::numeric_limits<double>::infinity()
                                : static_cast<double>(rng() % 9) - 3.0;
    for (const double tMax : {1.5, 3.0, std::numeric_limits<double>::infinity()}) {
      std::vector<std::optional<PrimHit>> culled = hits;
      for (std::size_t i = 0; i < hits.size(); ++i)
        if (box[i] == std::numeric_limits<double>::infinity() || !(box[i] <= tMax))
          culled[i].reset();  // (as the tracer culls: a box not entered ahead, or beyond tMax)
      const Outcome expected = outcome([&](LeafFn f) { return program.runModern(f); }, culled);
      const TNode* first = firstNodeAhead(expected.list);
      std::vector<int> lazyAsked;
      const CsgPointwise::Answer a =
          pointwise->firstAheadLazy([&](int prim) { return box[static_cast<std::size_t>(prim)]; },
                                    [&](int prim, CsgPointwise::Span& span) {
                                      lazyAsked.push_back(prim);
                                      return spanOf(culled[static_cast<std::size_t>(prim)], span);
                                    },
                                    tMax, entryMarker, exitMarker, node);
      for (const int prim : lazyAsked)
        ASSERT_TRUE(culled[static_cast<std::size_t>(prim)] ||
                    box[static_cast<std::size_t>(prim)] <= tMax);
      for (const int prim : lazyAsked)
        ASSERT_LT(box[static_cast<std::size_t>(prim)], std::numeric_limits<double>::infinity());
      if (a == CsgPointwise::Answer::kGeneral) continue;
      ASSERT_EQ(a == CsgPointwise::Answer::kFound, first != nullptr)
          << "trial " << trial << " tMax " << tMax << "\n"
          << expected.list;
      if (first) {
        ASSERT_EQ(node, *first) << "trial " << trial << " tMax " << tMax;
      }
      ++lazyAnswers;
      lazyFewer += lazyAsked.size() < expected.asked.size();
      // (runModern asks a culled leaf too, and gets a miss)
      ASSERT_LE(lazyAsked.size(), expected.asked.size()) << "trial " << trial << " tMax " << tMax;
    }
    for (const double tMax : {2.5, 4.0, std::numeric_limits<double>::infinity()}) {
      double expected = 0.0;
      for (std::size_t i = 0; i + 1 < list.list.size(); i += 2) {
        const double lo = std::max(0.0, list.list[i].t), hi = std::min(tMax, list.list[i + 1].t);
        if (hi > lo) expected += hi - lo;
      }
      double length = -1.0;
      const CsgPointwise::Answer a = pointwise->insideLength(spans, tMax, length);
      ASSERT_EQ(length, expected) << "trial " << trial << " tMax " << tMax << "\n" << list.list;
      ASSERT_EQ(a, expected > 0.0 ? CsgPointwise::Answer::kFound : CsgPointwise::Answer::kNone);
      lengths += expected > 0.0;
    }
  }
  // Every kind of answer is met, and most rays are answered from the leaves.
  EXPECT_GT(found, 6000);
  EXPECT_GT(none, 6000);
  EXPECT_GT(general, 500);
  EXPECT_LT(general, found / 4);
  EXPECT_GT(emptyLeaf, 1000);
  EXPECT_GT(skips, 4000);
  EXPECT_GT(lengths, 15000);
  EXPECT_GT(lazyAnswers, 40000);
  EXPECT_GT(lazyFewer, 20000);  // ... and the lazy answers ask fewer leaves
  EXPECT_GT(exits, 6000);
}

// What the pointwise form takes: trees of up to six leaves and no shared
// subtree; the list walk serves the others.
TEST(CsgPointwise, TakesSmallTreesWithoutSharing) {
  std::mt19937 rng(7);
  EXPECT_TRUE(CsgPointwise::compile(compileModern(randomTree(rng, 6, false))).has_value());
  EXPECT_FALSE(CsgPointwise::compile(compileModern(randomTree(rng, 7, false))).has_value());
  // (A & B) + (A & B), one operator entry used twice (a Call).
  const std::vector<CsgEntry> shared{{'+', 1, 1}, {'&', 2, 3}, {'P', 10, 0}, {'P', 11, 0}};
  ASSERT_EQ(compileModern(shared).sharedSubtrees(), 1u);
  EXPECT_FALSE(CsgPointwise::compile(compileModern(shared)).has_value());
  // A difference by hand: [1, 5] - [2, 3] along the ray from t = 0. The
  // first node ahead is the entry at 1; from t = 2.5 on (the spans moved
  // back by 2.5) it is the subtracted leaf's exit at 0.5, an entry of the
  // solid with its marker negated. The solid is 3 long, 1 of it before 2.
  const std::vector<CsgEntry> diff{{'-', 1, 2}, {'P', 4, 0}, {'P', 9, 0}};
  const std::optional<CsgPointwise> pw = CsgPointwise::compile(compileModern(diff));
  ASSERT_TRUE(pw.has_value());
  std::array<CsgPointwise::Span, CsgPointwise::kMaxLeaves> spans;
  auto gather = [&](double shift) {
    return pw->gather(
        [&](int prim, CsgPointwise::Span& s) {
          s.tIn = (prim == 4 ? 1.0 : 2.0) - shift;
          s.tOut = (prim == 4 ? 5.0 : 3.0) - shift;
          return true;
        },
        spans);
  };
  const Vec3 in{1, 0, 0}, out{1, 1, 0};
  TNode node;
  ASSERT_TRUE(gather(0.0));
  ASSERT_EQ(pw->firstAhead(spans, in, out, node), CsgPointwise::Answer::kFound);
  EXPECT_EQ(node, (TNode{1.0, 4, kSurfOut, in}));
  double length = 0;
  EXPECT_EQ(pw->insideLength(spans, 2.0, length), CsgPointwise::Answer::kFound);
  EXPECT_EQ(length, 1.0);
  EXPECT_EQ(pw->insideLength(spans, 10.0, length), CsgPointwise::Answer::kFound);
  EXPECT_EQ(length, 3.0);
  ASSERT_TRUE(gather(2.5));
  ASSERT_EQ(pw->firstAhead(spans, in, out, node), CsgPointwise::Answer::kFound);
  EXPECT_EQ(node, (TNode{0.5, 9, kSurfOut, -out}));
}

}  // namespace
}  // namespace prime
