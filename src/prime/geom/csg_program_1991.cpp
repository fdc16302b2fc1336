#include "src/prime/geom/csg_program_1991.h"

#include <algorithm>
#include <string>
#include <utility>

#include "src/prime/geom/csg_sets.h"

namespace prime {

namespace {

using Kind = CsgProgram1991::StepKind;

// The reachable entries of a valid tree in post-order (children before
// parents), found without recursion; throws the CsgError csg1991 would give.
std::vector<int> postOrder(std::span<const CsgEntry> entries) {
  const std::size_t n = entries.size();
  auto bad = [n](int index) {
    throw CsgError(CsgError::Kind::kBadEntryIndex,
                   "ReadObj(): Invalid read attempt: CSG entry " + std::to_string(index) +
                       " is outside the object's " + std::to_string(n) + " entries");
  };
  if (n == 0) bad(0);
  std::vector<std::uint8_t> colour(n, 0);          // 0 unseen, 1 on the path, 2 done
  std::vector<std::pair<int, int>> stack{{0, 0}};  // entry, children pushed
  std::vector<int> order;
  colour[0] = 1;
  while (!stack.empty()) {
    auto& [entry, next] = stack.back();
    const CsgEntry& e = entries[static_cast<std::size_t>(entry)];
    if (e.op != 'P' && next == 0 && e.op != '+' && e.op != '-' && e.op != '&')
      throw CsgError(CsgError::Kind::kBadOpcode,
                     std::string("switch case fell to default. Module Roth. Program CSG "
                                 "(opcode '") +
                         e.op + "' at entry " + std::to_string(entry) + ")");
    if (e.op != 'P' && next < 2) {
      const int child = next++ == 0 ? e.l : e.r;
      if (child < 0 || static_cast<std::size_t>(child) >= n) bad(child);
      if (colour[static_cast<std::size_t>(child)] == 1)
        throw CsgError(
            CsgError::Kind::kCycle,
            "CSG(): the object's tree has a cycle through entry " + std::to_string(child));
      if (colour[static_cast<std::size_t>(child)] == 0) {
        colour[static_cast<std::size_t>(child)] = 1;
        stack.emplace_back(child, 0);  // (invalidates `entry`, `next`: not used after)
      }
      continue;
    }
    colour[static_cast<std::size_t>(entry)] = 2;
    order.push_back(entry);
    stack.pop_back();
  }
  return order;
}

std::uint64_t addCapped(std::uint64_t a, std::uint64_t b) {
  return std::min(CsgProgram1991::kExpansionCap, a + b);  // a, b <= 2^62: no wrap
}

std::vector<std::uint64_t> expansion(std::span<const CsgEntry> entries,
                                     const std::vector<int>& order) {
  std::vector<std::uint64_t> visits(entries.size(), 0);
  for (int i : order) {
    const CsgEntry& e = entries[static_cast<std::size_t>(i)];
    visits[static_cast<std::size_t>(i)] =
        e.op == 'P' ? 1
                    : addCapped(1, addCapped(visits[static_cast<std::size_t>(e.l)],
                                             visits[static_cast<std::size_t>(e.r)]));
  }
  return visits;
}

// Per-thread scratch of run(): reused from ray to ray, so a warm thread
// allocates nothing for the walk itself.
struct Scratch {
  std::vector<TList> operands;               // operands[0..top): the operand stack
  std::vector<TList> stored;                 // each shared subtree's list on this ray
  std::vector<std::uint64_t> storedOn;       // the ray (`ray` below) it was stored on
  std::vector<std::pair<int, int>> returns;  // Call: step to go on at, subtree
  std::uint64_t ray = 0;
  bool busy = false;
};

thread_local Scratch tlsScratch;

}  // namespace

std::optional<std::uint64_t> csgExpandedVisits(std::span<const CsgEntry> entries) {
  try {
    const std::vector<int> order = postOrder(entries);
    return expansion(entries, order)[0];
  } catch (const CsgError&) {
    return std::nullopt;
  }
}

CsgProgram1991 CsgProgram1991::compileChecked(std::span<const CsgEntry> entries,
                                              const Csg1991Options& options) {
  const std::vector<int> order = postOrder(entries);
  const std::vector<std::uint64_t> visits = expansion(entries, order);
  CsgProgram1991 p;
  p.expandedVisits_ = visits[0];
  if (p.expandedVisits_ > options.maxVisits)
    throw CsgError(CsgError::Kind::kTooManyVisits, "CSG(): more than " +
                                                       std::to_string(options.maxVisits) +
                                                       " tree entries visited (shared subtrees)");

  // References from reachable operators: an operator entry used twice or
  // more is a shared subtree with a body of its own.
  std::vector<int> refs(entries.size(), 0), sub(entries.size(), -1);
  for (int i : order) {
    const CsgEntry& e = entries[static_cast<std::size_t>(i)];
    if (e.op == 'P') continue;
    ++refs[static_cast<std::size_t>(e.l)];
    ++refs[static_cast<std::size_t>(e.r)];
  }
  std::vector<int> bodies{0};
  for (int i : order)
    if (i != 0 && refs[static_cast<std::size_t>(i)] > 1 &&
        entries[static_cast<std::size_t>(i)].op != 'P') {
      sub[static_cast<std::size_t>(i)] = static_cast<int>(bodies.size()) - 1;
      bodies.push_back(i);
    }

  // Each body in post-order, with an explicit stack; a shared subtree met
  // inside a body becomes a Call.
  struct Item {
    int entry;
    int stage;         // 0 start, 1 left done, 2 right done
    std::size_t skip;  // the SkipRightIfEmpty step, if any
  };
  std::vector<Item> stack;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (b > 0) p.subStart_.push_back(static_cast<int>(p.steps_.size()));
    stack.push_back({bodies[b], 0, 0});
    while (!stack.empty()) {
      Item& it = stack.back();
      const CsgEntry& e = entries[static_cast<std::size_t>(it.entry)];
      const int shared = sub[static_cast<std::size_t>(it.entry)];
      if (shared >= 0 && it.entry != bodies[b]) {
        p.steps_.push_back({Kind::Call, shared});
        stack.pop_back();
        continue;
      }
      if (e.op == 'P') {
        p.steps_.push_back({Kind::Leaf, e.l});
        stack.pop_back();
        continue;
      }
      if (it.stage == 0) {
        it.stage = 1;
        stack.push_back({e.l, 0, 0});
      } else if (it.stage == 1) {
        it.stage = 2;
        if (e.op != '+' && options.skipRightWhenLeftEmpty) {  // Q4
          it.skip = p.steps_.size();
          p.steps_.push_back({Kind::SkipRightIfEmpty, 0});
        }
        stack.push_back({e.r, 0, 0});
      } else {
        p.steps_.push_back({e.op == '+'   ? Kind::Union
                            : e.op == '-' ? Kind::Difference
                                          : Kind::Intersection,
                            0});
        // (A skip step never comes first in a body: the left subtree's steps precede it.)
        if (it.skip != 0) p.steps_[it.skip].arg = static_cast<int>(p.steps_.size());
        stack.pop_back();
      }
    }
    p.steps_.push_back({Kind::Return, 0});
  }
  return p;
}

std::optional<CsgProgram1991> CsgProgram1991::compile(std::span<const CsgEntry> entries,
                                                      const Csg1991Options& options) {
  try {
    return compileChecked(entries, options);
  } catch (const CsgError&) {
    return std::nullopt;
  }
}

std::vector<int> CsgProgram1991::unionLeaves() const {
  std::vector<int> prims;
  if (!subStart_.empty() || steps_.size() < 4 || steps_.back().kind != StepKind::Return) return {};
  for (std::size_t k = 0; k + 1 < steps_.size(); ++k) {
    if (steps_[k].kind == StepKind::Leaf)
      prims.push_back(steps_[k].arg);
    else if (steps_[k].kind != StepKind::Union)
      return {};
  }
  return prims;
}

template <class Combine>
TList CsgProgram1991::execute(LeafFn leaf, Combine combine) const {
  Scratch local;  // only when a leaf callback runs a program itself
  Scratch& s = tlsScratch.busy ? local : tlsScratch;
  struct Busy {
    Scratch& s;
    explicit Busy(Scratch& x) : s(x) { s.busy = true; }
    ~Busy() { s.busy = false; }
    Busy(const Busy&) = delete;
    Busy& operator=(const Busy&) = delete;
  } busy(s);
  ++s.ray;
  if (s.stored.size() < subStart_.size()) {
    s.stored.resize(subStart_.size());
    s.storedOn.resize(subStart_.size(), 0);
  }
  s.returns.clear();
  std::size_t top = 0;
  auto push = [&]() -> TList& {
    if (top == s.operands.size()) s.operands.emplace_back();
    TList& l = s.operands[top++];
    l.clear();
    return l;
  };
  std::size_t pc = 0;
  for (;;) {
    const Step& st = steps_[pc];
    switch (st.kind) {
      case StepKind::Leaf: {  // IntersectPrim: the pair, or an empty list on a miss
        TList& l = push();
        if (const std::optional<PrimHit> hit = leaf(st.arg))
          l.addPair(hit->tIn, hit->tOut, hit->nIn, hit->nOut, st.arg);
        ++pc;
        break;
      }
      case StepKind::SkipRightIfEmpty:  // Q4: an empty left list is the result
        pc = s.operands[top - 1].empty() ? static_cast<std::size_t>(st.arg) : pc + 1;
        break;
      case StepKind::Call: {
        const auto k = static_cast<std::size_t>(st.arg);
        if (s.storedOn[k] == s.ray) {
          push() = s.stored[k];
          ++pc;
        } else {
          s.returns.emplace_back(static_cast<int>(pc) + 1, st.arg);
          pc = static_cast<std::size_t>(subStart_[k]);
        }
        break;
      }
      case StepKind::Return: {
        if (s.returns.empty()) return std::move(s.operands[top - 1]);
        const auto [next, k] = s.returns.back();
        s.returns.pop_back();
        s.stored[static_cast<std::size_t>(k)] = s.operands[top - 1];
        s.storedOn[static_cast<std::size_t>(k)] = s.ray;
        pc = static_cast<std::size_t>(next);
        break;
      }
      default:
        combine(st.kind, s.operands[top - 2], s.operands[top - 1]);
        --top;
        ++pc;
        break;
    }
  }
}

TList CsgProgram1991::run(LeafFn leaf) const {
  return execute(leaf, [](StepKind kind, TList& left, TList& right) {
    if (kind == StepKind::Union)
      union1991(left, right);
    else if (kind == StepKind::Difference)
      difference1991(left, right);
    else
      intersection1991(left, right);
  });
}

TList CsgProgram1991::runModern(LeafFn leaf) const {
  return execute(leaf, [](StepKind kind, TList& left, const TList& right) {
    // An empty operand against a normalised one: setCombine's sweep would
    // hand back the normalised operand's nodes with their surface types
    // alternating (or nothing), so that list is the result as it stands.
    // The common case once rays are culled by primitive boxes (N18).
    const bool rightEmpty = right.empty(), leftEmpty = left.empty();
    if ((rightEmpty && isNormalized(left)) || (leftEmpty && isNormalized(right))) {
      if (rightEmpty) {
        if (kind == StepKind::Intersection) left.clear();  // A & {} = {}; A | {} = A - {} = A
      } else if (kind == StepKind::Union) {
        left = right;  // {} | B = B; {} - B = {} & B = {}
      }
      for (std::size_t k = 0; k < left.size(); ++k)
        left[k].surfType = k % 2 == 0 ? kSurfOut : kSurfIn;
      return;
    }
    if (kind == StepKind::Union)
      left = setUnion(left, right);
    else if (kind == StepKind::Difference)
      left = setDifference(left, right, NormalConvention::kOutward);
    else
      left = setIntersection(left, right);
  });
}

}  // namespace prime
