// The flattened CSG program must return exactly what the tree walk csg1991
// returns: same lists node for node, same leaves asked in the same order,
// same errors. Checked on random trees with random leaf intervals (hits,
// misses, touching and equal ends, so every operator branch and E57 occur),
// with and without Q4's early exit; and the trees csg1991 rejects are not
// compiled.
#include "src/prime/geom/csg_program_1991.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

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
  int compared = 0, errors = 0, skipsTaken = 0, nonEmpty = 0;
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
    ASSERT_EQ(flat.asked, walk.asked) << "trial " << trial;
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
  // (a - a) with the same entry twice: two leaf steps, one Difference.
  const std::vector<CsgEntry> e = {{'-', 1, 1}, {'P', 3, 0}};
  const auto p = CsgProgram1991::compile(e);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->size(), 3u);
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

}  // namespace
}  // namespace prime
