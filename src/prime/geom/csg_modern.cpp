#include "src/prime/geom/csg_modern.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>

namespace prime {

CsgProgram1991 compileModern(std::span<const CsgEntry> entries) {
  Csg1991Options options;
  options.skipRightWhenLeftEmpty = true;
  options.maxVisits = std::numeric_limits<std::size_t>::max();
  return CsgProgram1991::compileChecked(entries, options);
}

TList csgModern(std::span<const CsgEntry> entries, LeafFn leaf) {
  return compileModern(entries).runModern(leaf);
}

std::vector<int> containingPrimitives(std::span<const CsgEntry> entries) {
  if (entries.empty()) return {};
  // Post-order over the entries reachable from the root, without recursion
  // (M31); a shared subtree is worked out once.
  std::vector<std::optional<std::vector<int>>> held(entries.size());
  std::vector<char> open(entries.size(), 0);  // on the path from the root
  std::vector<std::pair<std::size_t, bool>> stack{{0, false}};
  auto valid = [&](int k) { return k >= 0 && static_cast<std::size_t>(k) < entries.size(); };
  while (!stack.empty()) {
    const auto [k, childrenDone] = stack.back();
    const CsgEntry& e = entries[k];
    if (held[k]) {
      stack.pop_back();
      continue;
    }
    if (e.op == 'P') {
      held[k] = std::vector<int>{e.l};
      stack.pop_back();
      continue;
    }
    if (!valid(e.l) || !valid(e.r)) return {};  // (compileModern refuses such a tree)
    const auto l = static_cast<std::size_t>(e.l), r = static_cast<std::size_t>(e.r);
    if (!childrenDone) {
      stack.back().second = true;
      open[k] = 1;
      for (const std::size_t c : {l, r}) {
        if (open[c]) return {};  // a cycle (compileModern refuses it)
        if (!held[c]) stack.emplace_back(c, false);
      }
      continue;
    }
    open[k] = 0;
    stack.pop_back();
    if (!held[l] || !held[r]) return {};  // a cycle (compileModern refuses it)
    const std::vector<int>&a = *held[l], &b = *held[r];
    std::vector<int> out;
    if (e.op == '-') {
      out = a;
    } else if (e.op == '&') {
      std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    } else if (e.op == '+') {
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    } else {
      return {};  // an unknown operator (compileModern refuses it)
    }
    held[k] = std::move(out);
  }
  return held[0] ? *held[0] : std::vector<int>{};
}

}  // namespace prime
