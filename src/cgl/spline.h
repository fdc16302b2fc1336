// The Waterloo CGL package's free-form B-spline surfaces (M. A. J. Sweeney,
// "The Waterloo CGL Ray Tracing Package", University of Waterloo CS-85-35,
// 1985, section 6, "Splines"): a uniform bicubic B-spline surface from the
// spline node's control graph, extended per end condition (section 6.4),
// refined by the Oslo algorithm (section 6.3), a tree of nested boxes over
// the refined vertices (section 6.5), Kajiya's sorted active list (section
// 6.7) and Newton's iteration on two planes through the ray (section 6.8),
// then the normal, point, distance and texture indices of section 6.9.
//
// Parameters: the knots are the integers, u-bar_i = i, i = -4 .. m + 4 with
// m = nu - 1 (likewise v-bar with n = nv - 1). The readings chosen where the
// text is damaged or silent are CGL-E140.., CGL-Q140.. in
// docs/cgl/deviations.md.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "src/geom/aabb.h"
#include "src/geom/bvh.h"
#include "src/geom/ray.h"
#include "src/math/vec.h"
#include "src/render/picture_buffer.h"

namespace prime::cgl {

// The uniform cubic B-spline segments of section 6.1 at the local parameter
// u in [0, 1]: w[k] weights U_{i-3+k} on the knot interval [u_i, u_{i+1}),
// i.e. w = (b_3, b_2, b_1, b_0)(u); dw their derivatives (d/du).
void bsplineWeights(double u, double w[4], double dw[4]);

// The extended control graph in one direction (CGL-Q140): nu user vertices
// become nu + 4, indices -4 .. m (m = nu - 1); element k (index k - 4) is the
// user vertex it copies. Open ends triple the first and last vertex (two
// copies added at each end); closed ends wrap, U_i = U_{i + nu}.
std::vector<int> extendedIndices(int count, EndCondition end);

// The parameter range (6.4.1) of one direction with nu vertices (m = nu -
// 1): triple [-1, m + 1], double [0, m], single [1, m - 1], closed [-1, m)
// (CGL-Q141: nu distinct segments, each once).
struct ParamRange {
  double min = 0, max = 0;
};
ParamRange parameterRange(int count, EndCondition end);

// Oslo refinement (6.3.2) for uniform knots u-bar_i = i, i = -4 .. m + 4, each
// interval [u_{-1}, u_{m+1}) split into `divisions` parts. refinedKnot(r) is
// w-bar_r, r = -4 .. p + 4, p = (m + 2) divisions - 2. The alphas are a
// (p + 5) x (m + 5) matrix, alpha[(r + 4)(m + 5) + (i + 4)] = alpha_{i,4}(r).
int refinedLast(int m, int divisions);  // p
double refinedKnot(int r, int m, int divisions);
std::vector<double> osloAlphas(int m, int divisions);

// A node of the box tree (section 6.5): children are `count` consecutive
// nodes from `first`; a leaf (count 0) carries the Newton start.
struct SplineNode {
  Aabb box;
  int first = 0;
  int count = 0;
  double u0 = 0, v0 = 0;  // leaf: (w-bar_{r+2}, t-bar_{s+2})
};

// Q, Q_u and Q_v at (u, v) from the original (extended) control vertices.
struct SplinePoint {
  Vec3 q{}, qu{}, qv{};
};

// The same tree laid out for the traversal (CGL-D170): per interior node
// its children's boxes side by side (structure of arrays, four lanes, the
// slab test of Aabb::entry on each lane with the same arithmetic), and per
// leaf its Newton start with Q, Q_u, Q_v there evaluated once.
struct SplinePacket {
  double lo[3][4], hi[3][4];
  int ref[4];  // >= 0: the child's packet; < 0: leaf ~ref
  int count = 0;
  bool plain = true;  // every box has lo <= hi (the branch-free test applies)
};
struct SplineLeaf {
  double u0 = 0, v0 = 0;
  SplinePoint start;  // evaluate(u0, v0)
  int node = 0;       // the leaf's index in `nodes` (the document's tie order)
};

// A knot cell of the modern intersector (CGL-D180, `--profile modern`): the
// parameter rectangle [u0, u1] x [v0, v1] of one refined interval pair and
// its Bezier points.
struct SplineCell {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  // The cell's piece of surface as a bicubic Bezier patch (it is one
  // polynomial over a knot cell): it lies in the convex hull of these 16
  // points, far tighter than the hull of the 16 refined B-spline vertices.
  std::array<Vec3, 16> bezier{};
};

struct SplineSurface {
  int node = 0;  // the scene node
  int mu = 0;    // extended vertices in u: nu + 4 (indices -4 .. m)
  int mv = 0;    // extended vertices in v: nv + 4
  int m = 0, n = 0;
  EndCondition uEnd = EndCondition::Triple, vEnd = EndCondition::Triple;
  int divisions = 1;
  double overlap = 0.5;
  // The extended, transformed control graph: U_{i,j} = u[(i + 4) + (j + 4) mu].
  std::vector<Vec3> u;
  // The same vertices padded to four doubles (x, y, z, 0), for the
  // evaluation's vector arithmetic (CGL-D172): u4[4 k + a] = u[k][a].
  std::vector<double> u4;
  double umin = 0, umax = 0, vmin = 0, vmax = 0;
  // The refined vertices W_{r,s} = w[(r + 4) + (s + 4) pu], r = -4 .. p.
  int pu = 0, pv = 0;
  std::vector<Vec3> w;
  // (The large arrays in whole huge pages where the system grants them:
  // LargeBufferAllocator, src/render/picture_buffer.h.)
  LargeBuffer<SplineNode> nodes;  // nodes[0] is the root
  int leaves = 0;
  // CGL-D170: packets[0] holds the root alone (one lane); every interior
  // node has one packet; leafData[k] is leaf k.
  LargeBuffer<SplinePacket> packets;
  LargeBuffer<SplineLeaf> leafData;
  // The modern intersector's cells and a BVH over their boxes (each the box
  // of the cell's Bezier points, padded): built by buildModernCells, empty
  // for the document's path.
  std::vector<SplineCell> cells;
  Bvh cellBvh;
  double tolerance = 0;  // |E_1| + |E_2| for success, scene units (CGL-Q143)
  Aabb hull;             // the control vertices' box: contains every surface point
  double refineSeconds = 0, treeSeconds = 0;
  // The document's structures (refined vertices, the tree's nodes), for
  // Table 3; traversalBytes() the packets and leaf data added by CGL-D170.
  std::size_t bytes() const;
  std::size_t traversalBytes() const;
};

// The packets and leaf records of CGL-D170 over the surface's tree (CGL-D175):
// Document groups the leaves as the tree does (knot rectangles quartered),
// Spatial by two cuts per packet on the centres of the leaves' boxes;
// Auto (buildSpline's) takes whichever the surface area heuristic expects to
// cost fewer box tests. Every layout lists the same leaves with the same
// entries, so the walk's hits are the same.
enum class PacketLayout { Auto, Document, Spatial };
struct SplineSurface;
void buildTraversal(SplineSurface& s, PacketLayout layout = PacketLayout::Auto);
// The surface area heuristic of CGL-D175: the box tests a ray through the
// root's box is expected to make, for the surface's packets as built;
// documentPacketCost, the same for the Document layout's packets, from the
// tree alone (the same double as packetCost after buildTraversal(Document)).
// Auto builds the spatial grouping, and the document's instead when its cost
// is no higher.
double packetCost(const SplineSurface& s);
double documentPacketCost(const SplineSurface& s);

// Builds a surface from the transformed user control vertices (nv groups of
// nu, controls[v * nu + u], as the reader stores them). Throws nothing: the
// reader has checked the counts; divisions >= 1, nu, nv >= 1.
// Without `documentTree` (the modern profile, CGL-D180) the box tree and its
// packets are not built: the surface is then for buildModernCells only.
SplineSurface buildSpline(const std::vector<Vec3>& controls, int nu, int nv, EndCondition uEnd,
                          EndCondition vEnd, int divisions, double overlap,
                          bool documentTree = true);

SplinePoint evaluate(const SplineSurface& s, double u, double v);
// Long-double evaluation of Q, for the references.
void evaluateLong(const SplineSurface& s, long double u, long double v, long double out[3]);

// The two planes through the ray (section 6.8).
struct RayPlanes {
  Vec3 n1{}, n2{};
  double a1 = 0, a2 = 0;
  bool ok = false;
};
// The port's planes (CGL-Q142): N_1 = normalise(D x e) with e the axis of D's
// smallest component, N_2 = normalise(N_1 x D); E_k is then a distance.
RayPlanes rayPlanes(const Ray& ray);
// The document's planes: N_1 = O x D, N_2 = N_1 x D, not normalised.
RayPlanes documentRayPlanes(const Ray& ray);

struct NewtonOptions {
  double tolerance = 0;    // |E_1| + |E_2| < tolerance is success
  int maxIterations = 16;  // CGL-Q144
};
struct NewtonResult {
  bool hit = false;
  double u = 0, v = 0, t = 0;
  int iterations = 0;
  Vec3 qu{}, qv{};  // on a hit: Q_u, Q_v at (u, v), the last evaluation (CGL-D173)
};
// Newton's iteration (6.8.1) from (u0, v0); on success the distance t =
// (I - O).D/|D|^2 (CGL-E141) of I = Q(u, v).
NewtonResult newton(const SplineSurface& s, const RayPlanes& planes, const Ray& ray, double u0,
                    double v0, const NewtonOptions& options);

// Newton from the start (u0, v0) whose Q, Q_u, Q_v are `start` (the same
// iterates, bit for bit, as newton(), which evaluates them).
NewtonResult newtonFrom(const SplineSurface& s, const RayPlanes& planes, const Ray& ray, double u0,
                        double v0, const SplinePoint& start, const NewtonOptions& options);

struct SplineCounters {
  std::uint64_t calls = 0, boxes = 0, newtonCalls = 0, iterations = 0, hits = 0;
  SplineCounters& operator+=(const SplineCounters& o);
};
struct SplineHit {
  double t = 0, u = 0, v = 0;  // the surface parameters (u-bar, v-bar)
  double u0 = 0, v0 = 0;       // the leaf's Newton start
  int iterations = 0;
  Vec3 qu{}, qv{};  // Q_u, Q_v at (u, v): evaluate(s, u, v)'s, for the normal (CGL-D173)
};
// Section 6.7: the nearest hit with t in (tMin, tMax) by the sorted active
// list. The list is a per-thread scratch sized once for the largest tree
// seen by the thread (no allocation per ray).
// `record`, when given (the Table 6 report only), receives every Newton
// start tried, to time Newton apart from the boxes.
struct NewtonStart {
  double u0 = 0, v0 = 0;
};
//
// intersectSplineDocument is that walk as the document describes it: a
// sorted active list (a binary heap, CGL-D141), nodes taken nearest first,
// Newton at each leaf taken, the end when the first node left is no nearer
// than the hit. intersectSpline (CGL-D170) returns the same hit, bit for bit:
// it walks the packets depth first, nearest child first, with an explicit
// stack, listing the leaves whose box the ray enters before tMax (the heap
// pops exactly these, in the order (entry, node index), since a child's box
// lies in its parent's and has a larger index); Newton runs once ahead, at
// the first leaf reached, and a hit there (t_F at entry d_F) lets boxes
// entered beyond max(t_F, d_F) be skipped (the heap stops before them). The
// list is then sorted and Newton runs, from the leaves' cached starts, in
// that order with the document's stopping rule (the run ahead reused). It
// makes the heap's Newton runs plus at most the one ahead, and tests more
// boxes than the heap, each far cheaper.
bool intersectSpline(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                     SplineHit& hit, SplineCounters& counters,
                     std::vector<NewtonStart>* record = nullptr);
// The same with the ray's box data prepared by the caller (the renderer's
// BoxRay of the same ray: the same doubles, made once per ray, CGL-D174).
// The root's box is tested here, inline (the walk's first test, the same
// double: most rays that reach a surface's object box miss its root box),
// and the walk below it runs only for a ray that enters it before tMax.
bool intersectSplineBelowRoot(const SplineSurface& s, const BoxRay& boxRay, double rootEntry,
                              double tMin, double tMax, SplineHit& hit, SplineCounters& counters,
                              std::vector<NewtonStart>* record);
inline bool intersectSpline(const SplineSurface& s, const BoxRay& boxRay, double tMin, double tMax,
                            SplineHit& hit, SplineCounters& counters,
                            std::vector<NewtonStart>* record = nullptr) {
  ++counters.calls;
  if (s.nodes.empty()) return false;
  ++counters.boxes;
  const double rootEntry = s.nodes[0].box.entry(boxRay);
  if (!(rootEntry < tMax)) return false;
  return intersectSplineBelowRoot(s, boxRay, rootEntry, tMin, tMax, hit, counters, record);
}
bool intersectSplineDocument(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                             SplineHit& hit, SplineCounters& counters,
                             std::vector<NewtonStart>* record = nullptr);
// Whether intersectSpline would find a hit with t in (tMin, tMax), for
// shadow rays: true as soon as any leaf's Newton converges there (the
// document's walk finds a hit exactly when some leaf the ray's box entry
// puts before tMax converges in range, whatever the order; CGL-D170).
bool occludesSpline(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                    SplineCounters& counters);
bool occludesSplineBelowRoot(const SplineSurface& s, const BoxRay& boxRay, double rootEntry,
                             double tMin, double tMax, SplineCounters& counters);
inline bool occludesSpline(const SplineSurface& s, const BoxRay& boxRay, double tMin, double tMax,
                           SplineCounters& counters) {
  ++counters.calls;
  if (s.nodes.empty()) return false;
  ++counters.boxes;
  const double rootEntry = s.nodes[0].box.entry(boxRay);
  if (!(rootEntry < tMax)) return false;
  return occludesSplineBelowRoot(s, boxRay, rootEntry, tMin, tMax, counters);
}

// The modern intersector (CGL-D180, the profile `modern`; not the
// document's): the surface's knot cells, each boxed by its piece of
// surface's Bezier points (padded), in a BVH visited nearest box first; in
// a cell, the patch seen along the ray (its points' distances from the
// ray's two planes) is passed over when its hull cannot hold the ray, else
// halved each way, and each quarter whose hull may hold the ray gives Newton
// a start at its centre (then its corners, when that run does not
// converge); the walk ends at the first box entered beyond the nearest hit.
// buildModernCells adds the cells to a built surface.
void buildModernCells(SplineSurface& s);
bool intersectSplineModern(const SplineSurface& s, const BoxRay& boxRay, double tMin, double tMax,
                           SplineHit& hit, SplineCounters& counters);
bool occludesSplineModern(const SplineSurface& s, const BoxRay& boxRay, double tMin, double tMax,
                          SplineCounters& counters);
// The intersector the surface was built for: the modern one when it has
// cells (BuildOptions::modernSplines), else the document's walk. The
// renderer and the hole counts of either profile call these.
inline bool intersectSplineAsBuilt(const SplineSurface& s, const BoxRay& boxRay, double tMin,
                                   double tMax, SplineHit& hit, SplineCounters& counters) {
  if (!s.cells.empty()) return intersectSplineModern(s, boxRay, tMin, tMax, hit, counters);
  return intersectSpline(s, boxRay, tMin, tMax, hit, counters);
}
inline bool occludesSplineAsBuilt(const SplineSurface& s, const BoxRay& boxRay, double tMin,
                                  double tMax, SplineCounters& counters) {
  if (!s.cells.empty()) return occludesSplineModern(s, boxRay, tMin, tMax, counters);
  return occludesSpline(s, boxRay, tMin, tMax, counters);
}

// The reference for holes: every knot cell (a refined interval pair) boxed by
// the convex hull of its 16 refined vertices (so the boxes contain the
// surface), Newton from the cell's centre and four corners, the nearest hit.
bool intersectSplineReference(const SplineSurface& s, const Ray& ray, double tMin, double tMax,
                              SplineHit& hit);

// Section 6.9: N = Q_u x Q_v normalised (nudged inwards where Q_u or Q_v
// vanishes at a tripled edge, CGL-Q146); texture u, v in [0, 1].
Vec3 splineNormal(const SplineSurface& s, double u, double v);
// The same normal from a hit, whose Q_u, Q_v at (u, v) Newton's last step
// has already evaluated (CGL-D173: the same vectors, so the same normal).
Vec3 splineNormal(const SplineSurface& s, const SplineHit& hit);
void splineTexture(const SplineSurface& s, double u, double v, double& tu, double& tv);

// The surface over its parameter range as bicubic Bezier patches, exactly:
// each knot-interval pair's 4 x 4 B-spline vertices times the uniform
// B-spline-to-Bezier matrix in u and in v (for POV-Ray's bicubic_patch).
// Patch k's control points are patches[k][row * 4 + column], row along v.
std::vector<std::array<Vec3, 16>> bezierPatches(const SplineSurface& s);

// Holes: rays the reference hits but the Newton path does not; `extra`:
// the path hits, the reference not; `farther`: both hit, the path's hit
// farther than the reference's (a nearer sheet missed).
struct HoleCount {
  std::uint64_t rays = 0, referenceHits = 0, pathHits = 0, holes = 0, extra = 0, farther = 0;
};
void countHoles(const SplineSurface& s, const Ray& ray, double tMin, HoleCount& count);

}  // namespace prime::cgl
