#include "src/prime/geom/csg_modern.h"

#include "src/prime/geom/csg_sets.h"

namespace prime {

namespace {

TList walk(std::span<const CsgEntry> entries,
           const std::function<std::optional<PrimHit>(int)>& leaf, int node, int depth) {
  if (node < 0 || node >= static_cast<int>(entries.size()) ||
      depth > static_cast<int>(entries.size()))
    throw CsgError(CsgError::Kind::kBadEntryIndex,
                   "CSG entry " + std::to_string(node) + " out of range or in a cycle");
  const CsgEntry& e = entries[node];
  if (e.op == 'P') {
    TList l;
    if (auto in = leaf(e.l)) l.addPair(in->tIn, in->tOut, in->nIn, in->nOut, e.l);
    return l;
  }
  TList a = walk(entries, leaf, e.l, depth + 1);
  if (a.empty() && (e.op == '-' || e.op == '&')) return a;
  const TList b = walk(entries, leaf, e.r, depth + 1);
  switch (e.op) {
    case '+':
      return setUnion(a, b);
    case '-':
      return setDifference(a, b, NormalConvention::kOutward);
    case '&':
      return setIntersection(a, b);
    default:
      break;
  }
  throw CsgError(CsgError::Kind::kBadOpcode, std::string("unknown CSG opcode '") + e.op + "'");
}

}  // namespace

TList csgModern(std::span<const CsgEntry> entries,
                const std::function<std::optional<PrimHit>(int)>& leaf, int root) {
  return walk(entries, leaf, root, 0);
}

}  // namespace prime
