#include "src/prime/geom/csg_pointwise.h"

#include <algorithm>
#include <limits>

namespace prime {

std::optional<CsgPointwise> CsgPointwise::compile(const CsgProgram1991& program) {
  using PK = CsgProgram1991::StepKind;
  if (program.sharedSubtrees() != 0) return std::nullopt;
  CsgPointwise p;
  // Per operand on the stack: its first step and its leaves [first, end).
  struct Operand {
    std::size_t step;
    int firstLeaf, endLeaf;
    int skip = -1;  // the skip step after this operand when it is a left operand
  };
  auto leaves = [](int first, int end) {
    unsigned m = 0;
    for (int i = first; i < end; ++i) m |= 1u << i;
    return m;
  };
  // The truth table of steps [from, to) over every set of leaves.
  auto table = [&p](std::size_t from, std::size_t to) {
    std::uint64_t t = 0;
    for (unsigned in = 0; in < (1u << kMaxLeaves); ++in)
      if (p.holds(in, from, to)) t |= std::uint64_t{1} << in;
    return t;
  };
  std::vector<std::size_t> skips;
  std::vector<Operand> stack;
  const std::span<const CsgProgram1991::Step> steps = program.steps();
  for (std::size_t pc = 0; pc < steps.size(); ++pc) {
    const CsgProgram1991::Step& st = steps[pc];
    switch (st.kind) {
      case PK::Leaf: {
        if (p.leafCount_ == kMaxLeaves) return std::nullopt;
        stack.push_back({pc, p.leafCount_, p.leafCount_ + 1});
        p.steps_.push_back({Kind::kLeaf, p.leafCount_});
        p.leafPrim_[static_cast<std::size_t>(p.leafCount_)] = st.arg;
        ++p.leafCount_;
        break;
      }
      case PK::SkipRightIfEmpty:
        if (stack.empty()) return std::nullopt;  // (compileChecked never writes one first)
        // (`left` holds the left operand's first step until its table is made)
        skips.push_back(p.steps_.size());
        stack.back().skip = static_cast<int>(p.steps_.size());
        p.steps_.push_back(
            {Kind::kSkipRightIfEmpty,
             stack.back().endLeaf - stack.back().firstLeaf == 1 ? stack.back().firstLeaf : -1,
             st.arg, stack.back().step});
        break;
      case PK::Union:
      case PK::Difference:
      case PK::Intersection: {
        if (stack.size() < 2) return std::nullopt;
        const Operand right = stack.back();
        stack.pop_back();
        if (st.kind == PK::Difference)
          for (int i = right.firstLeaf; i < right.endLeaf; ++i) p.leafNegated_ ^= 1u << i;
        if (const int k = stack.back().skip; k >= 0) {  // its skip: the gate of the right operand
          const Operand& left = stack.back();
          if (left.endLeaf - left.firstLeaf > 1)  // (one leaf: missed or not, depends_ sees it)
            p.gates_[static_cast<std::size_t>(p.gateCount_++)] = {
                leaves(left.firstLeaf, left.endLeaf), leaves(right.firstLeaf, right.endLeaf),
                static_cast<std::size_t>(k)};
          stack.back().skip = -1;
        }
        stack.back().endLeaf = right.endLeaf;
        p.steps_.push_back({st.kind == PK::Union        ? Kind::kUnion
                            : st.kind == PK::Difference ? Kind::kDifference
                                                        : Kind::kIntersection});
        break;
      }
      case PK::Return:
        if (stack.size() != 1 || pc + 1 != steps.size()) return std::nullopt;
        p.table_ = table(0, p.steps_.size());
        for (unsigned out = 0; out < (1u << kMaxLeaves); ++out) {
          bool never = true;
          for (unsigned in = 0; in < (1u << kMaxLeaves) && never; ++in)
            never = (in & out) != 0 || ((p.table_ >> in) & 1u) == 0;
          if (never) p.never_ |= std::uint64_t{1} << out;
        }
        for (unsigned out = 0; out < (1u << kMaxLeaves); ++out) {
          if (((p.never_ >> out) & 1u) != 0) continue;
          for (int i = 0; i < p.leafCount_; ++i) {
            const unsigned bit = 1u << i;
            if ((out & bit) != 0) continue;
            for (unsigned in = 0; in < (1u << kMaxLeaves); ++in)
              if ((in & (out | bit)) == 0 &&
                  ((p.table_ >> in) & 1u) != ((p.table_ >> (in | bit)) & 1u)) {
                p.depends_[out] |= bit;
                break;
              }
          }
        }
        for (const std::size_t k : skips) {
          Step& skip = p.steps_[k];
          skip.left = table(static_cast<std::size_t>(skip.left), k);
        }
        return p;
      case PK::Call:
        return std::nullopt;
    }
  }
  return std::nullopt;  // (no Return: not a compiled program)
}

bool CsgPointwise::holds(unsigned in, std::size_t from, std::size_t to) const {
  std::uint32_t stack = 0;  // a stack of bits, the top in bit 0 (at most kMaxLeaves deep)
  for (std::size_t pc = from; pc < to; ++pc) {
    const Step& st = steps_[pc];
    if (st.kind == Kind::kLeaf) {
      stack = (stack << 1) | ((in >> st.leaf) & 1u);
    } else if (st.kind != Kind::kSkipRightIfEmpty) {
      const std::uint32_t b = stack & 1u, a = (stack >> 1) & 1u;
      const std::uint32_t r = st.kind == Kind::kUnion        ? (a | b)
                              : st.kind == Kind::kDifference ? (a & ~b & 1u)
                                                             : (a & b);
      stack = ((stack >> 2) << 1) | r;
    }
  }
  return (stack & 1u) != 0;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct End {
  double t;
  int leaf;
  bool exit;
};

// The met leaves' ends (those with t > after, or all), sorted by t.
template <class Keep>
int sortedEnds(const std::array<CsgPointwise::Span, CsgPointwise::kMaxLeaves>& spans, int leaves,
               Keep keep, std::array<End, 2 * CsgPointwise::kMaxLeaves>& ends) {
  int n = 0;
  for (int i = 0; i < leaves; ++i) {
    const CsgPointwise::Span& s = spans[static_cast<std::size_t>(i)];
    if (!s.hit) continue;
    if (keep(s.tIn)) ends[static_cast<std::size_t>(n++)] = {s.tIn, i, false};
    if (keep(s.tOut)) ends[static_cast<std::size_t>(n++)] = {s.tOut, i, true};
  }
  // Insertion sort: a handful of ends.
  for (int i = 1; i < n; ++i) {
    const End e = ends[static_cast<std::size_t>(i)];
    int j = i;
    for (; j > 0 && ends[static_cast<std::size_t>(j - 1)].t > e.t; --j)
      ends[static_cast<std::size_t>(j)] = ends[static_cast<std::size_t>(j - 1)];
    ends[static_cast<std::size_t>(j)] = e;
  }
  return n;
}

}  // namespace

bool CsgPointwise::neverHolds(const std::array<Span, kMaxLeaves>& spans, const Step& st) const {
  if (st.leaf >= 0) return !spans[static_cast<std::size_t>(st.leaf)].hit;  // one leaf: met or not
  std::array<End, 2 * kMaxLeaves> ends;
  const int n = sortedEnds(
      spans, leafCount_, [](double) { return true; }, ends);
  // (The leaves outside the left operand, met or not, take no part in its table.)
  unsigned in = 0;
  for (int k = 0; k < n;) {
    const double t = ends[static_cast<std::size_t>(k)].t;
    for (; k < n && ends[static_cast<std::size_t>(k)].t == t; ++k)
      in ^= 1u << ends[static_cast<std::size_t>(k)].leaf;
    if (k < n && ((st.left >> in) & 1u) != 0) return false;  // the open interval after t
  }
  return true;
}

CsgPointwise::Answer CsgPointwise::firstChange(const std::array<Span, kMaxLeaves>& spans,
                                               const Vec3& entry, const Vec3& exit, bool exitsOnly,
                                               TNode& node) const {
  switch (leafCount_) {
    case 1:
      return firstChangeOf<1>(spans, entry, exit, exitsOnly, node);
    case 2:
      return firstChangeOf<2>(spans, entry, exit, exitsOnly, node);
    case 3:
      return firstChangeOf<3>(spans, entry, exit, exitsOnly, node);
    case 4:
      return firstChangeOf<4>(spans, entry, exit, exitsOnly, node);
    case 5:
      return firstChangeOf<5>(spans, entry, exit, exitsOnly, node);
    default:
      return firstChangeOf<kMaxLeaves>(spans, entry, exit, exitsOnly, node);
  }
}

template <int N>
CsgPointwise::Answer CsgPointwise::firstChangeOf(const std::array<Span, kMaxLeaves>& spans,
                                                 const Vec3& entry, const Vec3& exit,
                                                 bool exitsOnly, TNode& node) const {
  // The ends 0 < t < +inf of the met leaves, taken nearest first, every end
  // at one t together (a leaf not met has NaN ends: no comparison holds).
  // `cur`: the leaves holding the open interval just before the next end,
  // at first those with tIn <= 0 < tOut. At an end t, the leaves holding
  // just after it are those of `cur` not leaving there and those entering
  // there; the first t where the formula differs across it is the first
  // node, usually the first end or the second.
  std::array<double, 2 * N> at;
  std::array<unsigned char, 2 * N> end;  // 2 leaf + (1 for an exit)
  int n = 0;
  unsigned cur = 0;
  for (int i = 0; i < N; ++i) {
    const Span& s = spans[static_cast<std::size_t>(i)];
    if (s.tIn > 0.0 && s.tIn < kInf) {
      at[static_cast<std::size_t>(n)] = s.tIn;
      end[static_cast<std::size_t>(n++)] = static_cast<unsigned char>(2 * i);
    }
    if (s.tOut > 0.0 && s.tOut < kInf) {
      at[static_cast<std::size_t>(n)] = s.tOut;
      end[static_cast<std::size_t>(n++)] = static_cast<unsigned char>(2 * i + 1);
    }
    cur |= static_cast<unsigned>((s.tIn <= 0.0) & (s.tOut > 0.0)) << i;
  }
  // Insertion sort by t: a handful of ends.
  for (int i = 1; i < n; ++i) {
    const double t = at[static_cast<std::size_t>(i)];
    const unsigned char e = end[static_cast<std::size_t>(i)];
    int j = i;
    for (; j > 0 && at[static_cast<std::size_t>(j - 1)] > t; --j) {
      at[static_cast<std::size_t>(j)] = at[static_cast<std::size_t>(j - 1)];
      end[static_cast<std::size_t>(j)] = end[static_cast<std::size_t>(j - 1)];
    }
    at[static_cast<std::size_t>(j)] = t;
    end[static_cast<std::size_t>(j)] = e;
  }
  for (int k = 0; k < n;) {
    const double t = at[static_cast<std::size_t>(k)];
    unsigned entering = 0, leaving = 0;
    int last = 0;
    for (; k < n && at[static_cast<std::size_t>(k)] == t; ++k) {
      last = end[static_cast<std::size_t>(k)];
      (last & 1 ? leaving : entering) |= 1u << (last >> 1);
    }
    const unsigned after = (cur & ~leaving) | entering;
    const bool now = ((table_ >> after) & 1u) != 0;
    if (now != (((table_ >> cur) & 1u) != 0) && !(exitsOnly && now)) {
      // More than one end at the first node's t: which the sweeps keep is the list's.
      const unsigned tied = entering | leaving;
      if ((tied & (tied - 1)) != 0) return Answer::kGeneral;
      const int leaf = last >> 1;
      const Vec3& marker = (last & 1) != 0 ? exit : entry;
      node = TNode{t, leafPrim_[static_cast<std::size_t>(leaf)], now ? kSurfOut : kSurfIn,
                   (leafNegated_ >> leaf) & 1u ? -marker : marker};
      return Answer::kFound;
    }
    cur = after;
  }
  return Answer::kNone;
}

CsgPointwise::Answer CsgPointwise::insideLength(const std::array<Span, kMaxLeaves>& spans,
                                                double tMax, double& length) const {
  std::array<End, 2 * kMaxLeaves> ends;
  const int n = sortedEnds(
      spans, leafCount_, [](double) { return true; }, ends);
  length = 0.0;
  unsigned in = 0;
  bool now = false;  // before every end no leaf holds, nor does the formula
  double entry = 0.0;
  for (int k = 0; k < n;) {
    const double t = ends[static_cast<std::size_t>(k)].t;
    for (; k < n && ends[static_cast<std::size_t>(k)].t == t; ++k)
      in ^= 1u << ends[static_cast<std::size_t>(k)].leaf;
    const bool next = ((table_ >> in) & 1u) != 0;
    if (next == now) continue;
    now = next;
    if (now) {
      entry = t;
    } else {  // a run [entry, t]: the list's pair
      const double lo = std::max(0.0, entry), hi = std::min(tMax, t);
      if (hi > lo) length += hi - lo;
    }
  }
  return length > 0.0 ? Answer::kFound : Answer::kNone;
}

}  // namespace prime
