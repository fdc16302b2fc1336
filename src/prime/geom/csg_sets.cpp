#include "src/prime/geom/csg_sets.h"

#include <algorithm>
#include <cstddef>

namespace prime {
namespace {

void requirePairs(const TList& l) {
  if (!l.wellFormed())
    throw CsgError(CsgError::Kind::kOddList,
                   "set operation: tList with an odd number of nodes (not a list of pairs)");
}

// Classification of the result from the operands' classifications (Table 3.1).
bool composite(SetOp op, bool inA, bool inB) {
  switch (op) {
    case SetOp::kUnion:
      return inA || inB;
    case SetOp::kIntersection:
      return inA && inB;
    case SetOp::kDifference:
      return inA && !inB;
  }
  return false;
}

// Sweep over two normalised lists. In a normalised list the nodes alternate
// entry/exit with strictly increasing t, so each list has at most one
// boundary at any t and passing a node toggles the list's classification.
TList sweep(SetOp op, const TList& a, const TList& b, NormalConvention normals) {
  TList out;
  out.reserve(a.size() + b.size());
  const std::size_t na = a.size();
  const std::size_t nb = b.size();
  std::size_t i = 0;
  std::size_t j = 0;
  bool inA = false;
  bool inB = false;
  bool in = false;
  const bool invertB = op == SetOp::kDifference;
  while (i < na || j < nb) {
    double t;
    if (i < na && j < nb)
      t = std::min(a[i].t, b[j].t);
    else
      t = i < na ? a[i].t : b[j].t;
    const TNode* nodeA = nullptr;
    const TNode* nodeB = nullptr;
    if (i < na && a[i].t == t) {
      nodeA = &a[i++];
      inA = !inA;
    }
    if (j < nb && b[j].t == t) {
      nodeB = &b[j++];
      inB = !inB;
    }
    const bool now = composite(op, inA, inB);
    if (now == in) continue;
    in = now;
    // The composite is monotone in (inA, inB) -- in (inA, !inB) for a
    // difference -- so at least one operand changed in its direction.
    const bool aQualifies = nodeA != nullptr && inA == now;
    TNode n = aQualifies ? *nodeA : *nodeB;
    if (!aQualifies && invertB && normals == NormalConvention::kOutward) n.norm = -n.norm;
    n.surfType = now ? kSurfOut : kSurfIn;
    out.push_back(n);
  }
  return out;
}

}  // namespace

bool isNormalized(const TList& l) noexcept {
  if (!l.wellFormed()) return false;
  for (std::size_t k = 0; k < l.pairCount(); ++k) {
    if (!(l.entry(k).t < l.exit(k).t)) return false;  // also false for NaN
    if (k > 0 && !(l.exit(k - 1).t < l.entry(k).t)) return false;
  }
  return true;
}

TList normalized(const TList& l) {
  requirePairs(l);
  TList out;
  if (isNormalized(l)) {
    out = l;
  } else {
    SmallVec<std::size_t, 8> order;  // indices of the pairs with positive length
    for (std::size_t k = 0; k < l.pairCount(); ++k)
      if (l.entry(k).t < l.exit(k).t) order.push_back(k);
    std::stable_sort(order.begin(), order.end(),
                     [&l](std::size_t x, std::size_t y) { return l.entry(x).t < l.entry(y).t; });
    out.reserve(2 * order.size());
    for (std::size_t k : order) {
      const TNode& in = l.entry(k);
      const TNode& ex = l.exit(k);
      if (!out.empty() && in.t <= out[out.size() - 1].t) {
        if (ex.t > out[out.size() - 1].t) out[out.size() - 1] = ex;  // extend
      } else {
        out.pushPair(in, ex);
      }
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) out[k].surfType = k % 2 == 0 ? kSurfOut : kSurfIn;
  return out;
}

TList setCombine(SetOp op, const TList& a, const TList& b, NormalConvention normals) {
  requirePairs(a);
  requirePairs(b);
  TList tmpA;
  TList tmpB;
  const TList& na = isNormalized(a) ? a : (tmpA = normalized(a));
  const TList& nb = isNormalized(b) ? b : (tmpB = normalized(b));
  return sweep(op, na, nb, normals);
}

TList setUnion(const TList& a, const TList& b) {
  return setCombine(SetOp::kUnion, a, b);
}

TList setIntersection(const TList& a, const TList& b) {
  return setCombine(SetOp::kIntersection, a, b);
}

TList setDifference(const TList& a, const TList& b, NormalConvention normals) {
  return setCombine(SetOp::kDifference, a, b, normals);
}

}  // namespace prime
