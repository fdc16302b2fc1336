// B-spline surfaces: the box tree over the refined surface (section 6.4),
// its four-wide packets and the spatial build, the packet cost model and the
// layout choice.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "src/cgl/spline.h"
#include "src/cgl/spline_kernels.h"

namespace prime::cgl {

using namespace spline_detail;

// The refined knot indices a with w-bar_a in the range, both ends included
// (CGL-Q141: for a closed direction too, so that Newton from the last leaf
// reaches the seam without leaving the range).
std::vector<int> spline_detail::knotsInRange(int m, int divisions, ParamRange range) {
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
                          EndCondition vEnd, int divisions, double overlap, bool documentTree) {
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

  if (documentTree) {
    const auto treeStart = std::chrono::steady_clock::now();
    TreeBuilder tb(s, knotsInRange(s.m, s.divisions, ru), knotsInRange(s.n, s.divisions, rv));
    tb.build();
    s.hull.add(s.nodes[0].box);
    buildTraversal(s);
    s.treeSeconds = secondsSince(treeStart);
  }

  // CGL-Q143: the tolerance, in scene units, relative to the surface's size.
  const Vec3 ext = s.hull.hi - s.hull.lo;
  s.tolerance = 1e-9 * std::max(1e-300, length(ext));
  return s;
}

}  // namespace prime::cgl
