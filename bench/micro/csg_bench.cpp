// The three Roth-list operators as printed (union1991, difference1991,
// intersection1991), the correct set operations (csg_sets.h), and the CSG
// tree walk, on the lists a ray through a few primitives gives.
//
// The 1991 operators consume their right operand and overwrite the left, so
// each iteration starts from fresh copies; `csg/copy-only` times just those
// copies, to subtract.
#include <benchmark/benchmark.h>

#include <optional>
#include <vector>

#include "src/prime/geom/csg_1991.h"
#include "src/prime/geom/csg_sets.h"

namespace {

using prime::TList;

TList pairs(std::initializer_list<std::pair<double, double>> spans, int prim) {
  TList l;
  for (auto [a, b] : spans) l.addPair(a, b, {0, 0, -1}, {0, 0, 1}, prim);
  return l;
}

// Typical operands: one pair each, overlapping (a ray through two
// overlapping primitives), and two pairs each (a ray through a union).
struct Operands {
  const char* name;
  TList a, b;
};
const std::vector<Operands>& operands() {
  static const std::vector<Operands> k = {
      {"overlap", pairs({{1.0, 3.0}}, 1), pairs({{2.0, 4.0}}, 2)},
      {"inside", pairs({{1.0, 4.0}}, 1), pairs({{2.0, 3.0}}, 2)},
      {"disjoint", pairs({{1.0, 2.0}}, 1), pairs({{3.0, 4.0}}, 2)},
      {"two-pairs", pairs({{1.0, 3.0}, {5.0, 7.0}}, 1), pairs({{2.0, 6.0}, {8.0, 9.0}}, 2)},
  };
  return k;
}

void copyOnly(benchmark::State& state, const TList& a0, const TList& b0) {
  for (auto _ : state) {
    TList a = a0, b = b0;
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(b);
  }
}

template <void (*Op)(TList&, TList&)>
void op1991(benchmark::State& state, const TList& a0, const TList& b0) {
  for (auto _ : state) {
    TList a = a0, b = b0;
    Op(a, b);
    benchmark::DoNotOptimize(a);
  }
}

template <TList (*Op)(const TList&, const TList&)>
void opSet(benchmark::State& state, const TList& a, const TList& b) {
  for (auto _ : state) {
    TList r = Op(a, b);
    benchmark::DoNotOptimize(r);
  }
}

TList setDifferenceOutward(const TList& a, const TList& b) {
  return prime::setDifference(a, b);
}

// The thesis example tree of scenes/prime/default object 1 (section 5.3.2):
// "+ 1 4 / - 2 3 / P / P / P", i.e. (A - B) + C, every leaf hit.
void walk(benchmark::State& state) {
  const std::vector<prime::CsgEntry> tree = {
      {'+', 1, 4}, {'-', 2, 3}, {'P', 0, 0}, {'P', 1, 0}, {'P', 2, 0}};
  auto leaf = [](int prim) -> std::optional<prime::PrimHit> {
    const double t0 = 1.0 + prim;
    return prime::PrimHit{t0, t0 + 1.5, {0, 0, -1}, {0, 0, 1}};
  };
  for (auto _ : state) {
    TList l = prime::csg1991(tree, leaf);
    benchmark::DoNotOptimize(l);
  }
}

const int kRegistered = [] {
  for (const Operands& o : operands()) {
    const std::string n = o.name;
    const TList *a = &o.a, *b = &o.b;
    benchmark::RegisterBenchmark(("csg/copy-only/" + n).c_str(),
                                 [a, b](benchmark::State& s) { copyOnly(s, *a, *b); });
    benchmark::RegisterBenchmark(("csg/union1991/" + n).c_str(), [a, b](benchmark::State& s) {
      op1991<prime::union1991>(s, *a, *b);
    });
    benchmark::RegisterBenchmark(("csg/difference1991/" + n).c_str(), [a, b](benchmark::State& s) {
      op1991<prime::difference1991>(s, *a, *b);
    });
    benchmark::RegisterBenchmark(
        ("csg/intersection1991/" + n).c_str(),
        [a, b](benchmark::State& s) { op1991<prime::intersection1991>(s, *a, *b); });
    benchmark::RegisterBenchmark(("csg/setUnion/" + n).c_str(), [a, b](benchmark::State& s) {
      opSet<prime::setUnion>(s, *a, *b);
    });
    benchmark::RegisterBenchmark(("csg/setDifference/" + n).c_str(), [a, b](benchmark::State& s) {
      opSet<setDifferenceOutward>(s, *a, *b);
    });
    benchmark::RegisterBenchmark(("csg/setIntersection/" + n).c_str(), [a, b](benchmark::State& s) {
      opSet<prime::setIntersection>(s, *a, *b);
    });
  }
  benchmark::RegisterBenchmark("csg/csg1991-walk/thesis-tree", walk);
  return 0;
}();

}  // namespace
