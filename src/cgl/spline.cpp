#include "src/cgl/spline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

namespace prime::cgl {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The knot interval i of u (clamped to -1 .. last) and the local parameter.
// (Forced inline, as basisWeights() below: GCC's own choice changes with the
// size of this file, and out of line they cost Newton's evaluation 3 % more
// instructions, 6-9 % more time on the spline figures.)
[[gnu::always_inline]] inline int interval(double u, int last, double& local) {
  int i = static_cast<int>(std::floor(u));
  i = std::clamp(i, -1, last);
  local = u - i;
  return i;
}

// CGL-D172: the evaluation and the box test on GCC/Clang vector types, four
// doubles wide (x, y, z and a zero pad for a point; four boxes for a
// packet). Each lane gets the same IEEE operations in the same order as the
// scalar code (the build has -ffp-contract=off: no fused multiply-add), so
// the same doubles. On x86-64 GCC the hot functions are also compiled for
// AVX2 (`target_clones`, chosen once at load time by the CPU); the baseline
// clone runs the same vectors as SSE2 pairs, with the same results.
using V4 = double __attribute__((vector_size(32)));
// (V4 is loaded into a reference, not returned: a 32-byte vector return
// would change the ABI of the baseline clone.)
[[gnu::always_inline]] inline void load4(V4& v, const double* p) {
  std::memcpy(&v, p, sizeof v);
}

}  // namespace

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define PRIME_SPLINE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PRIME_SPLINE_CLONES
#endif

namespace {

[[gnu::always_inline]] inline void basisWeights(double u, double w[4], double dw[4]) {
  const double u2 = u * u, u3 = u2 * u, t = 1.0 - u;
  w[0] = t * t * t / 6.0;                              // b_3: 1 - 3u + 3u^2 - u^3
  w[1] = (4.0 - 6.0 * u2 + 3.0 * u3) / 6.0;            // b_2
  w[2] = (1.0 + 3.0 * u + 3.0 * u2 - 3.0 * u3) / 6.0;  // b_1
  w[3] = u3 / 6.0;                                     // b_0
  dw[0] = -t * t / 2.0;
  dw[1] = (-12.0 * u + 9.0 * u2) / 6.0;
  dw[2] = (3.0 + 6.0 * u - 9.0 * u2) / 6.0;
  dw[3] = u2 / 2.0;
}

}  // namespace

void bsplineWeights(double u, double w[4], double dw[4]) {
  basisWeights(u, w, dw);
}

std::vector<int> extendedIndices(int count, EndCondition end) {
  std::vector<int> out(static_cast<std::size_t>(count + 4));
  for (int k = 0; k < count + 4; ++k) {
    const int i = k - 4;  // the extended index, -4 .. m
    if (end == EndCondition::Closed) {
      // Section 6.4: U_i = U_{i + nu} (the donut's U_{i,j} = U_{i+5,j}).
      out[static_cast<std::size_t>(k)] = ((i % count) + count) % count;
    } else {
      // Section 6.4: U_{-4} = U_{-3} = U_{-2} (the user's first vertex) and
      // likewise at the far end.
      out[static_cast<std::size_t>(k)] = std::clamp(k - 2, 0, count - 1);
    }
  }
  return out;
}

ParamRange parameterRange(int count, EndCondition end) {
  const double m = count - 1;
  switch (end) {
    case EndCondition::Triple:
      return {-1.0, m + 1.0};
    case EndCondition::Double:
      return {0.0, m};
    case EndCondition::Single:
      return {1.0, m - 1.0};
    case EndCondition::Closed:
      return {-1.0, m};  // CGL-Q141
  }
  return {-1.0, m + 1.0};
}

int refinedLast(int m, int divisions) {
  return (m + 2) * divisions - 2;
}

double refinedKnot(int r, int m, int divisions) {
  const int p = refinedLast(m, divisions);
  if (r <= -1) return r;
  if (r >= p + 1) return (m + 1) + (r - p - 1);
  return -1.0 + static_cast<double>(r + 1) / divisions;
}

std::vector<double> osloAlphas(int m, int divisions) {
  const int p = refinedLast(m, divisions);
  const int cols = m + 5;
  std::vector<double> out(static_cast<std::size_t>((p + 5) * cols), 0.0);
  // alpha_{i,l}(r) for i = -4 .. m + 4 - l (knots u_i = i, i = -4 .. m + 4).
  const int span = m + 9;
  std::vector<double> prev(static_cast<std::size_t>(span)), cur(static_cast<std::size_t>(span));
  for (int r = -4; r <= p; ++r) {
    auto at = [](std::vector<double>& a, int i) -> double& {
      return a[static_cast<std::size_t>(i + 4)];
    };
    const double wr = refinedKnot(r, m, divisions);
    std::fill(prev.begin(), prev.end(), 0.0);
    for (int i = -4; i <= m + 3; ++i) at(prev, i) = (i <= wr && wr < i + 1) ? 1.0 : 0.0;
    for (int l = 2; l <= 4; ++l) {
      std::fill(cur.begin(), cur.end(), 0.0);
      const double wk = refinedKnot(r + l - 1, m, divisions);
      for (int i = -4; i <= m + 4 - l; ++i) {
        // (6.3.2) with u-bar_i = i.
        const double a = (i + l - wk) / static_cast<double>(l - 1) * at(prev, i + 1);
        const double b = (wk - i) / static_cast<double>(l - 1) * at(prev, i);
        at(cur, i) = a + b;
      }
      std::swap(prev, cur);
    }
    for (int i = -4; i <= m; ++i)
      out[static_cast<std::size_t>((r + 4) * cols + (i + 4))] = at(prev, i);
  }
  return out;
}

std::size_t SplineSurface::bytes() const {
  return sizeof(SplineSurface) + u.size() * sizeof(Vec3) + w.size() * sizeof(Vec3) +
         nodes.size() * sizeof(SplineNode);
}

std::size_t SplineSurface::traversalBytes() const {
  return packets.size() * sizeof(SplinePacket) + leafData.size() * sizeof(SplineLeaf);
}

namespace {

class TreeBuilder {
 public:
  TreeBuilder(SplineSurface& s, std::vector<int> ua, std::vector<int> vb)
      : s_(s), ua_(std::move(ua)), vb_(std::move(vb)) {}

  void build() {
    // Every interior node has at least two children, so a tree of L leaves
    // has at most 2L - 1 nodes: reserved at once (growing the vector node by
    // node touched twice its final size in fresh pages).
    const std::size_t leaves = ua_.size() * vb_.size();
    s_.nodes.clear();
    s_.nodes.reserve(2 * leaves);
    s_.nodes.assign(1, SplineNode{});
    node(0, 0, static_cast<int>(ua_.size()) - 1, 0, static_cast<int>(vb_.size()) - 1);
  }

 private:
  const Vec3& wAt(int r, int s) const {
    return s_.w[static_cast<std::size_t>((r + 4) + (s + 4) * s_.pu)];
  }

  // Section 6.5's leaf box over W_{r,s} and its four neighbours.
  Aabb leafBox(int r, int s) const {
    const Vec3& c = wAt(r, s);
    Vec3 lo = c, hi = c;
    const int nr[4] = {r + 1, r - 1, r, r};
    const int ns[4] = {s, s, s + 1, s - 1};
    for (int k = 0; k < 4; ++k) {
      // CGL-Q145: a neighbour beyond the refined graph is left out.
      if (nr[k] < -4 || nr[k] > s_.pu - 5 || ns[k] < -4 || ns[k] > s_.pv - 5) continue;
      const Vec3& q = wAt(nr[k], ns[k]);
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], q[a]);
        hi[a] = std::max(hi[a], q[a]);
      }
    }
    Aabb box;
    const double o = s_.overlap;
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = (1.0 - o) * c[a] + o * lo[a];
      box.hi[a] = (1.0 - o) * c[a] + o * hi[a];
    }
    return box;
  }

  // Quarters the knot-index rectangle [a0, a1] x [b0, b1] (a side of one
  // knot is not split: 2 children then, CGL-Q145).
  void node(int at, int a0, int a1, int b0, int b1) {
    if (a0 == a1 && b0 == b1) {
      const int a = ua_[static_cast<std::size_t>(a0)], b = vb_[static_cast<std::size_t>(b0)];
      SplineNode& leaf = s_.nodes[static_cast<std::size_t>(at)];
      leaf.box = leafBox(a - 2, b - 2);
      leaf.count = 0;
      leaf.u0 = refinedKnot(a, s_.m, s_.divisions);
      leaf.v0 = refinedKnot(b, s_.n, s_.divisions);
      ++s_.leaves;
      return;
    }
    int as[2][2], bs[2][2];
    int na = 1, nb = 1;
    as[0][0] = a0;
    as[0][1] = a1;
    bs[0][0] = b0;
    bs[0][1] = b1;
    if (a1 > a0) {
      const int mid = (a0 + a1) / 2;
      as[0][1] = mid;
      as[1][0] = mid + 1;
      as[1][1] = a1;
      na = 2;
    }
    if (b1 > b0) {
      const int mid = (b0 + b1) / 2;
      bs[0][1] = mid;
      bs[1][0] = mid + 1;
      bs[1][1] = b1;
      nb = 2;
    }
    const int first = static_cast<int>(s_.nodes.size());
    s_.nodes.resize(s_.nodes.size() + static_cast<std::size_t>(na * nb));
    int k = 0;
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i < na; ++i) node(first + k++, as[i][0], as[i][1], bs[j][0], bs[j][1]);
    Aabb box;
    for (int c = 0; c < na * nb; ++c) box.add(s_.nodes[static_cast<std::size_t>(first + c)].box);
    SplineNode& n = s_.nodes[static_cast<std::size_t>(at)];
    n.box = box;
    n.first = first;
    n.count = na * nb;
  }

  SplineSurface& s_;
  std::vector<int> ua_, vb_;  // the refined knot indices in the parameter range
};

// The refined knot indices a with w-bar_a in the range, both ends included
// (CGL-Q141: for a closed direction too, so that Newton from the last leaf
// reaches the seam without leaving the range).
std::vector<int> knotsInRange(int m, int divisions, ParamRange range) {
  std::vector<int> out;
  const int p = refinedLast(m, divisions);
  const double eps = 1e-9;
  for (int a = -1; a <= p + 1; ++a) {
    const double w = refinedKnot(a, m, divisions);
    if (w < range.min - eps) continue;
    if (w > range.max + eps) continue;
    out.push_back(a);
  }
  return out;
}

// CGL-D170: the packets and leaf data of the tree (see spline.h).
void setLane(SplinePacket& p, int lane, const Aabb& box, int ref) {
  for (int a = 0; a < 3; ++a) {
    p.lo[a][lane] = box.lo[a];
    p.hi[a][lane] = box.hi[a];
  }
  p.ref[lane] = ref;
  p.plain = p.plain && box.lo[0] <= box.hi[0] && box.lo[1] <= box.hi[1] && box.lo[2] <= box.hi[2];
}

int laneRef(SplineSurface& s, int node);

// A new packet of `count` lanes, every lane cleared (unused lanes: an empty
// box that no ray enters, never read: count); returns its index. (Filling its
// lanes may add packets: index it again after, never keep a reference.)
int newPacket(SplineSurface& s, int count) {
  const int at = static_cast<int>(s.packets.size());
  s.packets.emplace_back();
  SplinePacket& p = s.packets.back();
  p.count = count;
  for (int lane = 0; lane < 4; ++lane) {
    for (int a = 0; a < 3; ++a) p.lo[a][lane] = p.hi[a][lane] = 0.0;
    p.ref[lane] = 0;
  }
  return at;
}

// A packet for the children first .. first + count - 1; returns its index.
int addPacket(SplineSurface& s, int first, int count) {
  const int at = newPacket(s, count);
  for (int c = 0; c < count; ++c) {
    const int ref = laneRef(s, first + c);
    setLane(s.packets[static_cast<std::size_t>(at)], c,
            s.nodes[static_cast<std::size_t>(first + c)].box, ref);
  }
  return at;
}

int laneRef(SplineSurface& s, int node) {
  const SplineNode& n = s.nodes[static_cast<std::size_t>(node)];
  if (n.count == 0) {
    SplineLeaf leaf;
    leaf.u0 = n.u0;
    leaf.v0 = n.v0;
    leaf.start = evaluate(s, n.u0, n.v0);
    leaf.node = node;
    s.leafData.push_back(leaf);
    return ~static_cast<int>(s.leafData.size() - 1);
  }
  return addPacket(s, n.first, n.count);
}

void buildPackets(SplineSurface& s) {
  s.packets.clear();
  s.leafData.clear();
  s.leafData.reserve(static_cast<std::size_t>(s.leaves));
  // At most one packet per interior node and the root's: no reallocation.
  s.packets.reserve(s.nodes.size() - static_cast<std::size_t>(s.leaves) + 1);
  if (s.nodes.empty()) return;
  // packets[0]: the root alone, so that the traversal starts like any node.
  s.packets.emplace_back();
  for (int lane = 0; lane < 4; ++lane) {
    for (int a = 0; a < 3; ++a) s.packets[0].lo[a][lane] = s.packets[0].hi[a][lane] = 0.0;
    s.packets[0].ref[lane] = 0;
  }
  s.packets[0].count = 1;
  const int ref = laneRef(s, 0);
  setLane(s.packets[0], 0, s.nodes[0].box, ref);
}

// CGL-D175: the packets' hierarchy over the document's leaves, grouped in
// space rather than by knot rectangle: each packet splits its leaves in
// four by two cuts on the centres of their boxes (splitAlongLongest).
// Interior boxes are the unions of their leaves' boxes, so a leaf's box is
// entered only if every packet box above it is, no later: the walk lists the
// same leaves with the same entries. The root's box is the union of all
// leaves' boxes, the document's root box (unions of the same boxes by min
// and max: the same doubles).
struct SpatialLeaf {
  Aabb box;
  Vec3 centre;
  int node;
};

int spatialRef(SplineSurface& s, LargeBuffer<SpatialLeaf>& items, int first, int count);

// Splits items [first, first + count) along the longest extent of their
// centres: at the middle of that extent, or, when a side would be empty,
// into the `at` smallest by (centre on that axis, node index). Both sides
// are sets defined by the items alone (a predicate, a strict order), so the
// same with every library. Returns the size of the first side.
int splitAlongLongest(LargeBuffer<SpatialLeaf>& items, int first, int count, int at) {
  Aabb c;
  for (int k = first; k < first + count; ++k) c.add(items[static_cast<std::size_t>(k)].centre);
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (c.hi[a] - c.lo[a] > c.hi[axis] - c.lo[axis]) axis = a;
  {
    const double mid = (c.lo[axis] + c.hi[axis]) * 0.5;
    const auto m = std::partition(items.begin() + first, items.begin() + first + count,
                                  [&](const SpatialLeaf& x) { return x.centre[axis] < mid; });
    const int n = static_cast<int>(m - (items.begin() + first));
    if (n > 0 && n < count) return n;
  }
  std::nth_element(items.begin() + first, items.begin() + first + at, items.begin() + first + count,
                   [axis](const SpatialLeaf& x, const SpatialLeaf& y) {
                     return x.centre[axis] < y.centre[axis] ||
                            (x.centre[axis] == y.centre[axis] && x.node < y.node);
                   });
  return at;
}

int spatialPacket(SplineSurface& s, LargeBuffer<SpatialLeaf>& items, int first, int count) {
  int groupFirst[4], groupCount[4];
  int groups = 0;
  if (count <= 4) {
    // The lanes in node order (nth_element leaves a group's order open).
    std::sort(items.begin() + first, items.begin() + first + count,
              [](const SpatialLeaf& x, const SpatialLeaf& y) { return x.node < y.node; });
    for (int k = 0; k < count; ++k) {
      groupFirst[groups] = first + k;
      groupCount[groups++] = 1;
    }
  } else {
    const int half = splitAlongLongest(items, first, count, count / 2);
    const int halves[2][2] = {{first, half}, {first + half, count - half}};
    for (const auto& h : halves) {
      if (h[1] == 1) {
        groupFirst[groups] = h[0];
        groupCount[groups++] = 1;
        continue;
      }
      const int q = splitAlongLongest(items, h[0], h[1], h[1] / 2);
      groupFirst[groups] = h[0];
      groupCount[groups++] = q;
      groupFirst[groups] = h[0] + q;
      groupCount[groups++] = h[1] - q;
    }
  }
  const int at = newPacket(s, groups);
  for (int g = 0; g < groups; ++g) {
    Aabb box;
    for (int k = groupFirst[g]; k < groupFirst[g] + groupCount[g]; ++k)
      box.add(items[static_cast<std::size_t>(k)].box);
    const int ref = spatialRef(s, items, groupFirst[g], groupCount[g]);
    setLane(s.packets[static_cast<std::size_t>(at)], g, box, ref);
  }
  return at;
}

int spatialRef(SplineSurface& s, LargeBuffer<SpatialLeaf>& items, int first, int count) {
  if (count == 1) {
    const int node = items[static_cast<std::size_t>(first)].node;
    const SplineNode& n = s.nodes[static_cast<std::size_t>(node)];
    SplineLeaf leaf;
    leaf.u0 = n.u0;
    leaf.v0 = n.v0;
    leaf.start = evaluate(s, n.u0, n.v0);
    leaf.node = node;
    s.leafData.push_back(leaf);
    return ~static_cast<int>(s.leafData.size() - 1);
  }
  return spatialPacket(s, items, first, count);
}

void buildSpatialPackets(SplineSurface& s) {
  s.packets.clear();
  s.leafData.clear();
  s.leafData.reserve(static_cast<std::size_t>(s.leaves));
  // A packet has at least two lanes but the root's: fewer packets than leaves.
  s.packets.reserve(static_cast<std::size_t>(s.leaves) + 1);
  if (s.nodes.empty()) return;
  LargeBuffer<SpatialLeaf> items;
  items.reserve(static_cast<std::size_t>(s.leaves));
  for (std::size_t k = 0; k < s.nodes.size(); ++k) {
    const SplineNode& n = s.nodes[k];
    if (n.count != 0) continue;
    items.push_back({n.box, (n.box.lo + n.box.hi) * 0.5, static_cast<int>(k)});
  }
  s.packets.emplace_back();
  for (int lane = 0; lane < 4; ++lane) {
    for (int a = 0; a < 3; ++a) s.packets[0].lo[a][lane] = s.packets[0].hi[a][lane] = 0.0;
    s.packets[0].ref[lane] = 0;
  }
  s.packets[0].count = 1;
  const int ref = spatialRef(s, items, 0, static_cast<int>(items.size()));
  setLane(s.packets[0], 0, s.nodes[0].box, ref);
}

}  // namespace

// The expected box tests of a ray through the root's box (the surface area
// heuristic): each packet's lanes are tested when its box, the lane above
// it, is entered, in proportion to that box's area.
namespace {
// Half a box's surface area from its extents (the heuristic's measure).
double halfArea(double x, double y, double z) {
  return x * y + y * z + z * x;
}
}  // namespace

double packetCost(const SplineSurface& s) {
  auto area = [](const SplinePacket& p, int lane) {
    return halfArea(p.hi[0][lane] - p.lo[0][lane], p.hi[1][lane] - p.lo[1][lane],
                    p.hi[2][lane] - p.lo[2][lane]);
  };
  if (s.packets.empty()) return 0.0;
  const double root = area(s.packets[0], 0);
  if (!(root > 0.0)) return 0.0;
  double cost = 0.0;
  for (const SplinePacket& p : s.packets)
    for (int lane = 0; lane < p.count; ++lane)
      if (p.ref[lane] >= 0)
        cost += area(p, lane) / root * s.packets[static_cast<std::size_t>(p.ref[lane])].count;
  return cost;
}

// packetCost(s) of the packets buildPackets(s) makes, from the tree alone,
// the same terms summed in the same order, so the same double: buildPackets
// makes one packet per interior node, depth first (a node's packet, then
// each child's subtree in turn), its lanes the node's children; a lane
// whose child is interior adds area(child's box) / root * child's count.
double documentPacketCost(const SplineSurface& s) {
  auto area = [](const Aabb& b) {
    return halfArea(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]);
  };
  if (s.nodes.empty()) return 0.0;
  const SplineNode& rootNode = s.nodes[0];
  const double root = area(rootNode.box);
  if (!(root > 0.0)) return 0.0;
  double cost = 0.0;
  // packets[0]: the root's lane.
  if (rootNode.count != 0) cost += area(rootNode.box) / root * rootNode.count;
  const auto visit = [&](const auto& self, const SplineNode& n) -> void {
    for (int c = 0; c < n.count; ++c) {
      const SplineNode& child = s.nodes[static_cast<std::size_t>(n.first + c)];
      if (child.count != 0) cost += area(child.box) / root * child.count;
    }
    for (int c = 0; c < n.count; ++c) {
      const SplineNode& child = s.nodes[static_cast<std::size_t>(n.first + c)];
      if (child.count != 0) self(self, child);
    }
  };
  visit(visit, rootNode);
  return cost;
}

// CGL-D175: the document's grouping (knot rectangles) or the grouping in
// space, whichever the surface area heuristic expects fewer box tests of.
void buildTraversal(SplineSurface& s, PacketLayout layout) {
  if (layout == PacketLayout::Document) {
    buildPackets(s);
    return;
  }
  buildSpatialPackets(s);
  if (layout == PacketLayout::Spatial) return;
  // The document's grouping is built again, into the same storage (pages
  // already touched), when it costs no more box tests than the spatial one:
  // packetCost of it is documentPacketCost, to the bit.
  if (!(packetCost(s) < documentPacketCost(s))) buildPackets(s);
}

SplineSurface buildSpline(const std::vector<Vec3>& controls, int nu, int nv, EndCondition uEnd,
                          EndCondition vEnd, int divisions, double overlap) {
  SplineSurface s;
  s.mu = nu + 4;
  s.mv = nv + 4;
  s.m = nu - 1;
  s.n = nv - 1;
  s.uEnd = uEnd;
  s.vEnd = vEnd;
  s.divisions = std::max(1, divisions);
  s.overlap = overlap;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<int> eu = extendedIndices(nu, uEnd), ev = extendedIndices(nv, vEnd);
  s.u.resize(static_cast<std::size_t>(s.mu * s.mv));
  for (int j = 0; j < s.mv; ++j)
    for (int i = 0; i < s.mu; ++i) {
      const Vec3& c = controls[static_cast<std::size_t>(ev[static_cast<std::size_t>(j)] * nu +
                                                        eu[static_cast<std::size_t>(i)])];
      s.u[static_cast<std::size_t>(i + j * s.mu)] = c;
      s.hull.add(c);
    }
  s.u4.assign(s.u.size() * 4, 0.0);
  for (std::size_t k = 0; k < s.u.size(); ++k)
    for (int a = 0; a < 3; ++a) s.u4[4 * k + static_cast<std::size_t>(a)] = s.u[k][a];
  const ParamRange ru = parameterRange(nu, uEnd), rv = parameterRange(nv, vEnd);
  s.umin = ru.min;
  s.umax = ru.max;
  s.vmin = rv.min;
  s.vmax = rv.max;

  // Refinement (6.3.3), one direction after the other.
  const int p = refinedLast(s.m, s.divisions), q = refinedLast(s.n, s.divisions);
  s.pu = p + 5;
  s.pv = q + 5;
  const std::vector<double> au = osloAlphas(s.m, s.divisions), av = osloAlphas(s.n, s.divisions);
  std::vector<Vec3> half(static_cast<std::size_t>(s.pu * s.mv), Vec3{0, 0, 0});
  for (int j = 0; j < s.mv; ++j)
    for (int r = 0; r < s.pu; ++r) {
      Vec3 sum{0, 0, 0};
      for (int i = 0; i < s.mu; ++i) {
        const double a = au[static_cast<std::size_t>(r * s.mu + i)];
        if (a != 0.0) sum = sum + s.u[static_cast<std::size_t>(i + j * s.mu)] * a;
      }
      half[static_cast<std::size_t>(r + j * s.pu)] = sum;
    }
  s.w.assign(static_cast<std::size_t>(s.pu * s.pv), Vec3{0, 0, 0});
  for (int t = 0; t < s.pv; ++t)
    for (int r = 0; r < s.pu; ++r) {
      Vec3 sum{0, 0, 0};
      for (int j = 0; j < s.mv; ++j) {
        const double a = av[static_cast<std::size_t>(t * s.mv + j)];
        if (a != 0.0) sum = sum + half[static_cast<std::size_t>(r + j * s.pu)] * a;
      }
      s.w[static_cast<std::size_t>(r + t * s.pu)] = sum;
    }
  s.refineSeconds = secondsSince(start);

  const auto treeStart = std::chrono::steady_clock::now();
  TreeBuilder tb(s, knotsInRange(s.m, s.divisions, ru), knotsInRange(s.n, s.divisions, rv));
  tb.build();
  s.hull.add(s.nodes[0].box);
  buildTraversal(s);
  s.treeSeconds = secondsSince(treeStart);

  // CGL-Q143: the tolerance, in scene units, relative to the surface's size.
  const Vec3 ext = s.hull.hi - s.hull.lo;
  s.tolerance = 1e-9 * std::max(1e-300, length(ext));
  return s;
}

namespace {

// Q, Q_u, Q_v as the scalar loop over Vec3 computed them (rows summed from
// zero in a, then weighted into the sums from zero in b), lane by lane
// (CGL-D172).
[[gnu::always_inline]] inline SplinePoint evaluateImpl(const SplineSurface& s, double u, double v) {
  double lu = 0, lv = 0;
  const int i = interval(u, s.m, lu), j = interval(v, s.n, lv);
  double wu[4], dwu[4], wv[4], dwv[4];
  basisWeights(lu, wu, dwu);
  basisWeights(lv, wv, dwv);
  const V4 zero = {0.0, 0.0, 0.0, 0.0};
  V4 q = zero, qu = zero, qv = zero;
  for (int b = 0; b < 4; ++b) {
    V4 row = zero, drow = zero;
    const double* base = s.u4.data() + 4 * static_cast<std::size_t>((i + 1) + (j + 1 + b) * s.mu);
    for (int a = 0; a < 4; ++a) {
      V4 c;
      load4(c, base + 4 * a);
      row = row + c * wu[a];
      drow = drow + c * dwu[a];
    }
    q = q + row * wv[b];
    qu = qu + drow * wv[b];
    qv = qv + row * dwv[b];
  }
  SplinePoint out;
  out.q = {q[0], q[1], q[2]};
  out.qu = {qu[0], qu[1], qu[2]};
  out.qv = {qv[0], qv[1], qv[2]};
  return out;
}

}  // namespace

PRIME_SPLINE_CLONES SplinePoint evaluate(const SplineSurface& s, double u, double v) {
  return evaluateImpl(s, u, v);
}

void evaluateLong(const SplineSurface& s, long double u, long double v, long double out[3]) {
  auto weights = [](long double t, long double w[4]) {
    const long double r = 1.0L - t;
    w[0] = r * r * r / 6.0L;
    w[1] = (4.0L - 6.0L * t * t + 3.0L * t * t * t) / 6.0L;
    w[2] = (1.0L + 3.0L * t + 3.0L * t * t - 3.0L * t * t * t) / 6.0L;
    w[3] = t * t * t / 6.0L;
  };
  int i = std::clamp(static_cast<int>(std::floor(u)), -1, s.m);
  int j = std::clamp(static_cast<int>(std::floor(v)), -1, s.n);
  long double wu[4], wv[4];
  weights(u - i, wu);
  weights(v - j, wv);
  out[0] = out[1] = out[2] = 0.0L;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const Vec3& c = s.u[static_cast<std::size_t>((i + 1 + a) + (j + 1 + b) * s.mu)];
      for (int k = 0; k < 3; ++k) out[k] += static_cast<long double>(c[k]) * wu[a] * wv[b];
    }
}

RayPlanes rayPlanes(const Ray& ray) {
  RayPlanes p;
  const Vec3& d = ray.d;
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(d[a]) < std::fabs(d[k])) k = a;
  Vec3 e{0, 0, 0};
  e[k] = 1.0;
  const Vec3 n1 = cross(d, e);
  const double l1 = length(n1);
  if (!(l1 > 0.0)) return p;
  p.n1 = n1 * (1.0 / l1);
  const Vec3 n2 = cross(p.n1, d);
  const double l2 = length(n2);
  if (!(l2 > 0.0)) return p;
  p.n2 = n2 * (1.0 / l2);
  p.a1 = dot(p.n1, ray.o);
  p.a2 = dot(p.n2, ray.o);
  p.ok = true;
  return p;
}

RayPlanes documentRayPlanes(const Ray& ray) {
  RayPlanes p;
  p.n1 = cross(ray.o, ray.d);
  p.n2 = cross(p.n1, ray.d);
  p.a1 = dot(p.n1, ray.o);
  p.a2 = dot(p.n2, ray.o);
  p.ok = true;  // degenerate (N_1 = 0) when O = 0 or O || D: Newton's Jacobian is then singular
  return p;
}

namespace {

[[gnu::always_inline]] inline NewtonResult newtonImpl(const SplineSurface& s,
                                                      const RayPlanes& planes, const Ray& ray,
                                                      double u0, double v0,
                                                      const SplinePoint& start,
                                                      const NewtonOptions& options) {
  NewtonResult res;
  if (!planes.ok) return res;
  double u = u0, v = v0;
  SplinePoint sp = start;
  // (6.8.1) with the basis factor B_{i,4}(u) B_{j,4}(v) (CGL-E140).
  double e1 = dot(planes.n1, sp.q) - planes.a1, e2 = dot(planes.n2, sp.q) - planes.a2;
  double err = std::fabs(e1) + std::fabs(e2);
  for (int it = 1; it <= options.maxIterations; ++it) {
    const double j11 = dot(planes.n1, sp.qu), j12 = dot(planes.n1, sp.qv);
    const double j21 = dot(planes.n2, sp.qu), j22 = dot(planes.n2, sp.qv);
    const double det = j11 * j22 - j12 * j21;
    res.iterations = it;
    if (!(det != 0.0) || !std::isfinite(det)) return res;
    const double du = (e1 * j22 - e2 * j12) / det, dv = (j11 * e2 - j21 * e1) / det;
    u -= du;
    v -= dv;
    // Failure: the iterate leaves the parameter range ...
    if (!(u >= s.umin && u <= s.umax && v >= s.vmin && v <= s.vmax)) return res;
    sp = evaluateImpl(s, u, v);
    e1 = dot(planes.n1, sp.q) - planes.a1;
    e2 = dot(planes.n2, sp.q) - planes.a2;
    const double next = std::fabs(e1) + std::fabs(e2);
    if (next < options.tolerance) {
      const Vec3 od = sp.q - ray.o;
      res.hit = true;
      res.u = u;
      res.v = v;
      res.t = dot(od, ray.d) / dot(ray.d, ray.d);  // CGL-E141
      res.qu = sp.qu;
      res.qv = sp.qv;
      return res;
    }
    // ... or |E_1| + |E_2| increased.
    if (next > err) return res;
    err = next;
  }
  return res;  // CGL-Q144: the iteration cap
}

}  // namespace

PRIME_SPLINE_CLONES NewtonResult newton(const SplineSurface& s, const RayPlanes& planes,
                                        const Ray& ray, double u0, double v0,
                                        const NewtonOptions& options) {
  if (!planes.ok) return {};
  return newtonImpl(s, planes, ray, u0, v0, evaluateImpl(s, u0, v0), options);
}

PRIME_SPLINE_CLONES NewtonResult newtonFrom(const SplineSurface& s, const RayPlanes& planes,
                                            const Ray& ray, double u0, double v0,
                                            const SplinePoint& start,
                                            const NewtonOptions& options) {
  return newtonImpl(s, planes, ray, u0, v0, start, options);
}

SplineCounters& SplineCounters::operator+=(const SplineCounters& o) {
  calls += o.calls;
  boxes += o.boxes;
  newtonCalls += o.newtonCalls;
  iterations += o.iterations;
  hits += o.hits;
  return *this;
}

namespace {

struct Active {
  double d;
  int node;
};
// Min-heap order on (distance, node): deterministic for ties.
bool later(const Active& a, const Active& b) {
  return a.d > b.d || (a.d == b.d && a.node > b.node);
}

// The per-thread active list (section 6.7): reserved once for the largest
// tree the thread meets, so a ray never allocates (each node enters the list
// at most once, so the size never exceeds the node count).
thread_local std::vector<Active> tActive;

}  // namespace

bool intersectSplineDocument(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                             SplineHit& hit, SplineCounters& counters,
                             std::vector<NewtonStart>* record) {
  ++counters.calls;
  if (s.nodes.empty()) return false;
  std::vector<Active>& active = tActive;
  if (active.capacity() < s.nodes.size()) active.reserve(s.nodes.size());
  active.clear();
  const BoxRay boxRay(ray);
  ++counters.boxes;
  const double d0 = s.nodes[0].box.entry(boxRay);
  if (!(d0 < tMax)) return false;
  active.push_back({d0, 0});
  const RayPlanes planes = rayPlanes(ray);
  NewtonOptions options;
  options.tolerance = s.tolerance;
  double best = tMax;
  bool found = false;
  while (!active.empty()) {
    std::pop_heap(active.begin(), active.end(), later);
    const Active a = active.back();
    active.pop_back();
    // Success: the hit is nearer than the first node on the list.
    if (!(a.d < best)) break;
    const SplineNode& n = s.nodes[static_cast<std::size_t>(a.node)];
    if (n.count == 0) {
      ++counters.newtonCalls;
      if (record) record->push_back({n.u0, n.v0});
      const NewtonResult r = newton(s, planes, ray, n.u0, n.v0, options);
      counters.iterations += static_cast<std::uint64_t>(r.iterations);
      if (r.hit && r.t > tMin && r.t < best) {
        best = r.t;
        found = true;
        hit = {r.t, r.u, r.v, n.u0, n.v0, r.iterations, r.qu, r.qv};
      }
      continue;
    }
    for (int c = 0; c < n.count; ++c) {
      const int ci = n.first + c;
      ++counters.boxes;
      const double d = s.nodes[static_cast<std::size_t>(ci)].box.entry(boxRay);
      if (d < best) {
        active.push_back({d, ci});
        std::push_heap(active.begin(), active.end(), later);
      }
    }
  }
  if (found) ++counters.hits;
  return found;
}

namespace {

// Aabb::entry(BoxRay) on the lanes of a packet: the same operations in the
// same order per lane, so the same doubles (CGL-D170).
inline void packetEntries(const SplinePacket& p, const BoxRay& r, double d[4]) {
  if (!r.simple || !p.plain) {
    for (int lane = 0; lane < p.count; ++lane) {
      Aabb b;
      b.lo = {p.lo[0][lane], p.lo[1][lane], p.lo[2][lane]};
      b.hi = {p.hi[0][lane], p.hi[1][lane], p.hi[2][lane]};
      d[lane] = b.entry(r);
    }
    return;
  }
  // Four lanes at once (CGL-D172; GCC/Clang vector extensions: AVX2 or two
  // SSE2 halves on x86-64): x > t0 ? x : t0 is std::max(t0, x) and y < t1 ?
  // y : t1 is std::min(t1, y) for the NaN-free values here, lane by lane.
  V4 t0 = {0.0, 0.0, 0.0, 0.0}, t1 = {kInf, kInf, kInf, kInf};
  for (int a = 0; a < 3; ++a) {
    V4 nearPlane, farPlane;
    load4(nearPlane, r.neg[a] ? p.hi[a] : p.lo[a]);
    load4(farPlane, r.neg[a] ? p.lo[a] : p.hi[a]);
    const double o = r.ray.o[a], inv = r.inv[a];
    const V4 x = (nearPlane - o) * inv;
    const V4 y = (farPlane - o) * inv;
    t0 = x > t0 ? x : t0;
    t1 = y < t1 ? y : t1;
  }
  const V4 miss = {kInf, kInf, kInf, kInf};
  const V4 out = t0 <= t1 ? t0 : miss;
  std::memcpy(d, &out, sizeof out);
}

// A leaf the ray enters: its box entry, node index (the document's order)
// and leaf record.
struct Tried {
  double d;
  int node;
  int leaf;
};
thread_local std::vector<Tried> tTried;

struct StackEntry {
  double d;
  int ref;
};
// The tree's depth is at most 1 + log2 of the knots per side (< 32 for int
// counts); a packet adds at most 3 entries net per level: 128 is plenty.
constexpr int kStack = 128;
// Newton runs once ahead of the document's order, at the first leaf
// reached, for a bound (running ahead until a first hit cost
// as much as the boxes it spared on the shipped scenes).

// Pushes the lanes of packet `p` whose box the ray enters before tMax; with
// `Nearest`, the nearest on top (for the shadow query's early end).
template <bool Nearest>
inline void pushLanes(const SplinePacket& p, const BoxRay& boxRay, double tMax, double bound,
                      StackEntry* stack, int& top, SplineCounters& counters) {
  double d[4];
  packetEntries(p, boxRay, d);
  counters.boxes += static_cast<std::uint64_t>(p.count);
  if (!Nearest) {
    for (int lane = 0; lane < p.count; ++lane)
      if (d[lane] < tMax && !(d[lane] > bound)) stack[top++] = {d[lane], p.ref[lane]};
    return;
  }
  int order[4];
  int k = 0;
  for (int lane = 0; lane < p.count; ++lane)
    if (d[lane] < tMax && !(d[lane] > bound)) {
      int j = k++;
      for (; j > 0 && d[order[j - 1]] < d[lane]; --j) order[j] = order[j - 1];
      order[j] = lane;  // order: farthest first
    }
  for (int j = 0; j < k; ++j) stack[top++] = {d[order[j]], p.ref[order[j]]};
}

}  // namespace

bool intersectSpline(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                     SplineHit& hit, SplineCounters& counters, std::vector<NewtonStart>* record) {
  return intersectSpline(s, BoxRay(ray), tMin, tMax, hit, counters, record);
}

PRIME_SPLINE_CLONES bool intersectSplineBelowRoot(const SplineSurface& s, const BoxRay& boxRay,
                                                  double rootEntry, double tMin, double tMax,
                                                  SplineHit& hit, SplineCounters& counters,
                                                  std::vector<NewtonStart>* record) {
  const Ray& ray = boxRay.ray;
  std::vector<Tried>& tried = tTried;
  if (tried.size() < s.leafData.size()) tried.resize(s.leafData.size());
  // Each leaf is listed at most once: the sized scratch is enough.
  Tried* const list = tried.data();
  int listed = 0;
  RayPlanes planes;
  NewtonOptions options;
  options.tolerance = s.tolerance;
  // Depth first, nearest child first, listing the leaves the ray's box
  // entry puts before `bound`; Newton runs at the first leaf reached; if it
  // hits, bound = max(t_F, d_F) for that leaf F:
  // a leaf L with d_L > bound comes after F in the document's order (entry,
  // node index), where the nearest hit so far is at most t_F < d_L, so the
  // document's walk has stopped before L, and L need not be listed.
  double bound = tMax;
  // The one run ahead of the document's order: its leaf
  // and result, reused by the replay below.
  int aheadLeaf = -1;
  NewtonResult ahead;
  StackEntry stack[kStack];
  // The root, entered at rootEntry < tMax (the caller's test, CGL-D174).
  stack[0] = {rootEntry, s.packets[0].ref[0]};
  int top = 1;
  while (top > 0) {
    const StackEntry e = stack[--top];
    if (e.d > bound) continue;
    if (e.ref >= 0) {
      pushLanes<true>(s.packets[static_cast<std::size_t>(e.ref)], boxRay, tMax, bound, stack, top,
                      counters);
      continue;
    }
    const int leafIndex = ~e.ref;
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(leafIndex)];
    if (aheadLeaf < 0) {
      // The planes when a first leaf is reached (CGL-D173: most rays that
      // enter the root's box reach no leaf); every later run follows this one.
      planes = rayPlanes(ray);
      aheadLeaf = leafIndex;
      ahead = newtonImpl(s, planes, ray, leaf.u0, leaf.v0, leaf.start, options);
      if (ahead.hit && ahead.t > tMin && ahead.t < tMax) bound = std::max(ahead.t, e.d);
    }
    list[listed++] = {e.d, leaf.node, leafIndex};
  }
  if (listed == 0) return false;
  // The document's walk over the listed leaves: nearest entry first (ties
  // by node index, the heap's order), Newton at each (the run ahead
  // reused), stopping at the first leaf no nearer than the hit.
  // (entry, node index) is a strict order (node indices are unique), so
  // any sort gives the same list; a short list, the common case, by
  // insertion.
  const auto before = [](const Tried& a, const Tried& b) {
    return a.d < b.d || (a.d == b.d && a.node < b.node);
  };
  if (listed <= 16) {
    for (int i = 1; i < listed; ++i) {
      const Tried x = list[i];
      int j = i;
      for (; j > 0 && before(x, list[j - 1]); --j) list[j] = list[j - 1];
      list[j] = x;
    }
  } else {
    std::sort(list, list + listed, before);
  }
  double best = tMax;
  bool found = false;
  bool aheadUsed = false;
  for (int k = 0; k < listed; ++k) {
    const Tried& x = list[k];
    if (!(x.d < best)) break;
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(x.leaf)];
    NewtonResult r;
    if (x.leaf == aheadLeaf) {
      r = ahead;
      aheadUsed = true;
    } else {
      r = newtonImpl(s, planes, ray, leaf.u0, leaf.v0, leaf.start, options);
    }
    ++counters.newtonCalls;
    counters.iterations += static_cast<std::uint64_t>(r.iterations);
    if (record) record->push_back({leaf.u0, leaf.v0});
    if (r.hit && r.t > tMin && r.t < best) {
      best = r.t;
      found = true;
      hit = {r.t, r.u, r.v, leaf.u0, leaf.v0, r.iterations, r.qu, r.qv};
    }
  }
  if (aheadLeaf >= 0 && !aheadUsed) {
    // The run ahead at a leaf the document's walk does not reach.
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(aheadLeaf)];
    ++counters.newtonCalls;
    counters.iterations += static_cast<std::uint64_t>(ahead.iterations);
    if (record) record->push_back({leaf.u0, leaf.v0});
  }
  if (found) ++counters.hits;
  return found;
}

bool occludesSpline(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                    SplineCounters& counters) {
  return occludesSpline(s, BoxRay(ray), tMin, tMax, counters);
}

PRIME_SPLINE_CLONES bool occludesSplineBelowRoot(const SplineSurface& s, const BoxRay& boxRay,
                                                 double rootEntry, double tMin, double tMax,
                                                 SplineCounters& counters) {
  const Ray& ray = boxRay.ray;
  RayPlanes planes;
  bool havePlanes = false;  // CGL-D173: computed at the first leaf
  NewtonOptions options;
  options.tolerance = s.tolerance;
  StackEntry stack[kStack];
  stack[0] = {rootEntry, s.packets[0].ref[0]};
  int top = 1;
  while (top > 0) {
    const StackEntry e = stack[--top];
    if (e.ref >= 0) {
      pushLanes<true>(s.packets[static_cast<std::size_t>(e.ref)], boxRay, tMax, kInf, stack, top,
                      counters);
      continue;
    }
    const SplineLeaf& leaf = s.leafData[static_cast<std::size_t>(~e.ref)];
    if (!havePlanes) {
      planes = rayPlanes(ray);
      havePlanes = true;
    }
    ++counters.newtonCalls;
    const NewtonResult r = newtonImpl(s, planes, ray, leaf.u0, leaf.v0, leaf.start, options);
    counters.iterations += static_cast<std::uint64_t>(r.iterations);
    if (r.hit && r.t > tMin && r.t < tMax) {
      ++counters.hits;
      return true;
    }
  }
  return false;
}

bool intersectSplineReference(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                              SplineHit& hit) {
  const BoxRay boxRay(ray);
  const RayPlanes planes = rayPlanes(ray);
  NewtonOptions options;
  options.tolerance = s.tolerance;
  options.maxIterations = 40;
  const std::vector<int> ua = knotsInRange(s.m, s.divisions, {s.umin, s.umax});
  const std::vector<int> vb = knotsInRange(s.n, s.divisions, {s.vmin, s.vmax});
  double best = tMax;
  bool found = false;
  for (std::size_t jb = 0; jb + 1 < vb.size(); ++jb)
    for (std::size_t ia = 0; ia + 1 < ua.size(); ++ia) {
      const int a = ua[ia], b = vb[jb];
      // The surface over [w_a, w_{a+1}) x [t_b, t_{b+1}) lies in the convex
      // hull of W_{a-3..a, b-3..b} (section 6.1's convex hull property).
      Aabb box;
      for (int sj = b - 3; sj <= b; ++sj)
        for (int ri = a - 3; ri <= a; ++ri)
          box.add(s.w[static_cast<std::size_t>((ri + 4) + (sj + 4) * s.pu)]);
      const double pad = 4.0 * s.tolerance;
      box.lo = box.lo - Vec3{pad, pad, pad};
      box.hi = box.hi + Vec3{pad, pad, pad};
      if (!(box.entry(boxRay) < best)) continue;
      const double u0 = refinedKnot(a, s.m, s.divisions), u1 = refinedKnot(a + 1, s.m, s.divisions);
      const double v0 = refinedKnot(b, s.n, s.divisions), v1 = refinedKnot(b + 1, s.n, s.divisions);
      const double starts[5][2] = {
          {(u0 + u1) / 2, (v0 + v1) / 2}, {u0, v0}, {u1, v0}, {u0, v1}, {u1, v1}};
      for (const auto& st : starts) {
        const NewtonResult r = newton(s, planes, ray, st[0], st[1], options);
        if (r.hit && r.t > tMin && r.t < best) {
          best = r.t;
          found = true;
          hit = {r.t, r.u, r.v, st[0], st[1], r.iterations, r.qu, r.qv};
        }
      }
    }
  return found;
}

namespace {

// Section 6.9's normal, the first evaluation at (u, v) given (Q_u, Q_v).
Vec3 normalFrom(const SplineSurface& s, double u, double v, Vec3 qu, Vec3 qv) {
  const double cu = (s.umin + s.umax) / 2, cv = (s.vmin + s.vmax) / 2;
  for (int k = 0;; ++k) {
    const Vec3 n = cross(qu, qv);
    const double l = length(n);
    if (l > 1e-12 * (1.0 + length(qu) * length(qv))) return n * (1.0 / l);
    if (k == 5) return {0.0, 0.0, 1.0};
    // CGL-Q146: Q_u or Q_v vanishes (a tripled edge): step inwards.
    u += (cu - u) * 1e-4 * (k + 1);
    v += (cv - v) * 1e-4 * (k + 1);
    const SplinePoint sp = evaluate(s, u, v);
    qu = sp.qu;
    qv = sp.qv;
  }
}

}  // namespace

Vec3 splineNormal(const SplineSurface& s, double u, double v) {
  const SplinePoint sp = evaluate(s, u, v);
  return normalFrom(s, u, v, sp.qu, sp.qv);
}

Vec3 splineNormal(const SplineSurface& s, const SplineHit& hit) {
  return normalFrom(s, hit.u, hit.v, hit.qu, hit.qv);
}

void splineTexture(const SplineSurface& s, double u, double v, double& tu, double& tv) {
  tu = std::clamp((u - s.umin) / (s.umax - s.umin), 0.0, 1.0);
  tv = std::clamp((v - s.vmin) / (s.vmax - s.vmin), 0.0, 1.0);
}

std::vector<std::array<Vec3, 16>> bezierPatches(const SplineSurface& s) {
  // Uniform cubic B-spline segment -> Bezier: P_0 = (U_0 + 4U_1 + U_2)/6,
  // P_1 = (2U_1 + U_2)/3, P_2 = (U_1 + 2U_2)/3, P_3 = (U_1 + 4U_2 + U_3)/6.
  static constexpr double k[4][4] = {{1.0 / 6, 4.0 / 6, 1.0 / 6, 0.0},
                                     {0.0, 2.0 / 3, 1.0 / 3, 0.0},
                                     {0.0, 1.0 / 3, 2.0 / 3, 0.0},
                                     {0.0, 1.0 / 6, 4.0 / 6, 1.0 / 6}};
  std::vector<std::array<Vec3, 16>> out;
  const int i0 = static_cast<int>(std::lround(s.umin)), i1 = static_cast<int>(std::lround(s.umax));
  const int j0 = static_cast<int>(std::lround(s.vmin)), j1 = static_cast<int>(std::lround(s.vmax));
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i) {
      // The segment [i, i + 1) x [j, j + 1) uses U_{i-3..i, j-3..j}.
      std::array<Vec3, 16> patch{};
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) {
          Vec3 p{0, 0, 0};
          for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
              const double w = k[a][x] * k[b][y];
              if (w != 0.0)
                p = p + s.u[static_cast<std::size_t>((i + 1 + x) + (j + 1 + y) * s.mu)] * w;
            }
          patch[static_cast<std::size_t>(b * 4 + a)] = p;
        }
      out.push_back(patch);
    }
  return out;
}

void countHoles(const SplineSurface& s, const Ray& ray, double tMin, HoleCount& count) {
  ++count.rays;
  SplineHit ref, path;
  SplineCounters c;
  const bool r = intersectSplineReference(s, ray, tMin, kInf, ref);
  const bool p = intersectSpline(s, ray, tMin, kInf, path, c);
  if (r) ++count.referenceHits;
  if (p) ++count.pathHits;
  if (r && !p) ++count.holes;
  if (p && !r) ++count.extra;
  if (p && r && path.t > ref.t + 1e-6 * (1.0 + ref.t)) ++count.farther;
}

}  // namespace prime::cgl
