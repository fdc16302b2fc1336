// The modern spline intersector (CGL-D180, `--profile modern`): not the
// document's section 6.5-6.7 walk but the analogue of PRIME's modern
// profile: tight boxes, nearest-first traversal with early exit. Its cells
// are the dense reference's knot cells (intersectSplineReference), each
// boxed by its piece of surface's Bezier points instead of the 16 refined
// B-spline vertices (a box about a quarter the size each way); in a cell,
// the patch seen along the ray is halved until it rules the cell out or
// gives Newton a start close to the hit.
#include <algorithm>
#include <cmath>
#include <limits>

#include "src/cgl/spline.h"
#include "src/cgl/spline_kernels.h"

namespace prime::cgl {

using spline_detail::knotsInRange;

namespace {

// The Bezier points of a cubic from its values at 0, 1/3, 2/3 and 1 (the
// inverse of the Bernstein matrix at those nodes).
template <class T>
void bezierFromSamples(const T p[4], T b[4]) {
  b[0] = p[0];
  b[1] = (p[0] * -5.0 + p[1] * 18.0 - p[2] * 9.0 + p[3] * 2.0) * (1.0 / 6.0);
  b[2] = (p[0] * 2.0 - p[1] * 9.0 + p[2] * 18.0 - p[3] * 5.0) * (1.0 / 6.0);
  b[3] = p[3];
}

}  // namespace

void buildModernCells(SplineSurface& s) {
  s.cells.clear();
  const std::vector<int> ua = knotsInRange(s.m, s.divisions, {s.umin, s.umax});
  const std::vector<int> vb = knotsInRange(s.n, s.divisions, {s.vmin, s.vmax});
  std::vector<Aabb> boxes;
  for (std::size_t jb = 0; jb + 1 < vb.size(); ++jb)
    for (std::size_t ia = 0; ia + 1 < ua.size(); ++ia) {
      const int a = ua[ia], b = vb[jb];
      SplineCell cell;
      cell.u0 = refinedKnot(a, s.m, s.divisions);
      cell.u1 = refinedKnot(a + 1, s.m, s.divisions);
      cell.v0 = refinedKnot(b, s.n, s.divisions);
      cell.v1 = refinedKnot(b + 1, s.n, s.divisions);
      // The surface over the cell is one bicubic polynomial (the cell lies
      // in one knot interval pair of the original graph): 4 x 4 samples fix
      // it, and its Bezier points follow, row by row, then column by column.
      Vec3 q[4][4], rows[4][4];
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
          q[j][i] = evaluate(s, cell.u0 + (cell.u1 - cell.u0) * i / 3.0,
                             cell.v0 + (cell.v1 - cell.v0) * j / 3.0)
                        .q;
      for (int j = 0; j < 4; ++j) bezierFromSamples(q[j], rows[j]);
      for (int i = 0; i < 4; ++i) {
        const Vec3 column[4] = {rows[0][i], rows[1][i], rows[2][i], rows[3][i]};
        Vec3 out[4];
        bezierFromSamples(column, out);
        for (int j = 0; j < 4; ++j) cell.bezier[static_cast<std::size_t>(j * 4 + i)] = out[j];
      }
      // Padded for Newton's tolerance (a point within it of the ray is a
      // hit) and for the rounding of the samples and the conversion.
      Aabb box;
      for (const Vec3& p : cell.bezier) box.add(p);
      double extent = 0;
      for (int k = 0; k < 3; ++k) extent = std::max(extent, box.hi[k] - box.lo[k]);
      const double pad = 4.0 * s.tolerance + 1e-9 * extent;
      box.lo = box.lo - Vec3{pad, pad, pad};
      box.hi = box.hi + Vec3{pad, pad, pad};
      s.cells.push_back(cell);
      boxes.push_back(box);
    }
  s.cellBvh = Bvh(std::move(boxes));
}

namespace {

// The cell's Bezier patch seen along the ray: each point's (E_1, E_2),
// its signed distances from the ray's two planes. The ray meets the patch
// where the projected patch covers the origin; the projected patch lies in
// the convex hull of the projected points, and halves by de Casteljau's
// construction like the patch itself (an affine map commutes with it).
struct Flat {
  double e[16][2];
};

// Halves a flat patch in u (dir 0) or v (dir 1) at the middle.
void halve(const Flat& p, int dir, Flat& lo, Flat& hi) {
  for (int line = 0; line < 4; ++line) {
    auto at = [&](int k) { return dir == 0 ? line * 4 + k : k * 4 + line; };
    for (int c = 0; c < 2; ++c) {
      const double p0 = p.e[at(0)][c], p1 = p.e[at(1)][c], p2 = p.e[at(2)][c], p3 = p.e[at(3)][c];
      const double a = (p0 + p1) / 2, b = (p1 + p2) / 2, d = (p2 + p3) / 2;
      const double ab = (a + b) / 2, bd = (b + d) / 2, m = (ab + bd) / 2;
      lo.e[at(0)][c] = p0;
      lo.e[at(1)][c] = a;
      lo.e[at(2)][c] = ab;
      lo.e[at(3)][c] = m;
      hi.e[at(0)][c] = m;
      hi.e[at(1)][c] = bd;
      hi.e[at(2)][c] = d;
      hi.e[at(3)][c] = p3;
    }
  }
}

// Whether the flat patch's hull can hold the origin (to `tol`).
bool coversOrigin(const Flat& p, double tol) {
  double lo0 = p.e[0][0], hi0 = lo0, lo1 = p.e[0][1], hi1 = lo1;
  for (int k = 1; k < 16; ++k) {
    lo0 = std::min(lo0, p.e[k][0]);
    hi0 = std::max(hi0, p.e[k][0]);
    lo1 = std::min(lo1, p.e[k][1]);
    hi1 = std::max(hi1, p.e[k][1]);
  }
  return lo0 < tol && hi0 > -tol && lo1 < tol && hi1 > -tol;
}

// The parameter squares of the cell (u0 .. u0 + size, v0 .. v0 + size, in
// the cell's own [0, 1] x [0, 1]) whose flat patch, halved `depth` times,
// may hold the origin: calls found(u0, v0, size) for each.
template <class Found>
void candidates(const Flat& p, double tol, int depth, double u0, double v0, double size,
                Found&& found) {
  if (!coversOrigin(p, tol)) return;
  if (depth == 0) {
    found(u0, v0, size);
    return;
  }
  Flat left, right, quarter[4];
  halve(p, 0, left, right);
  halve(left, 1, quarter[0], quarter[2]);
  halve(right, 1, quarter[1], quarter[3]);
  const double h = size / 2;
  candidates(quarter[0], tol, depth - 1, u0, v0, h, found);
  candidates(quarter[1], tol, depth - 1, u0 + h, v0, h, found);
  candidates(quarter[2], tol, depth - 1, u0, v0 + h, h, found);
  candidates(quarter[3], tol, depth - 1, u0 + h, v0 + h, h, found);
}

// How often a cell's patch is halved (each way) before Newton: once, into
// quarters. Measured on the donut and bump-triple (paired CPU, one thread):
// 0, 1, 2 and 3 halvings all leave no hole on the shipped spline scenes; one
// was the fastest on the donut (Newton runs per ray 1.05, 1.06, 1.01, 0.91,
// but each halving costs more than the runs it saves).
constexpr int kDepth = 1;

// Newton in one cell: the cell's patch projected along the ray, halved
// kDepth times, its squares that may hold the ray's point each give Newton
// a start at their centre (then their corners, when that run does not
// converge). Calls take(r, u0, v0) for every converged run.
template <class Take>
void newtonInCell(const SplineSurface& s, const SplineCell& c, const RayPlanes& planes,
                  const Ray& ray, const NewtonOptions& options, SplineCounters& counters,
                  Take&& take) {
  Flat flat;
  for (int k = 0; k < 16; ++k) {
    const Vec3& w = c.bezier[static_cast<std::size_t>(k)];
    flat.e[k][0] = dot(planes.n1, w) - planes.a1;
    flat.e[k][1] = dot(planes.n2, w) - planes.a2;
  }
  const double du = c.u1 - c.u0, dv = c.v1 - c.v0;
  auto inCell = [&](const NewtonResult& r) {
    return r.hit && r.u >= c.u0 && r.u <= c.u1 && r.v >= c.v0 && r.v <= c.v1;
  };
  // A square holding a hit already found in this cell would find it again.
  double foundU[4], foundV[4];
  int founds = 0;
  // Newton from (u, v): true when it converges (the hit is taken wherever
  // it lies, and remembered when it lies in this cell).
  auto run = [&](double u, double v) {
    ++counters.newtonCalls;
    const NewtonResult r = newton(s, planes, ray, u, v, options);
    counters.iterations += static_cast<std::uint64_t>(r.iterations);
    if (!r.hit) return false;
    take(r, u, v);
    if (inCell(r) && founds < 4) {
      foundU[founds] = r.u;
      foundV[founds++] = r.v;
    }
    return true;
  };
  // Twice the tolerance: the points' own rounding on top of Newton's. The
  // square's corners only when the run from its centre does not converge.
  candidates(flat, 2.0 * s.tolerance, kDepth, 0.0, 0.0, 1.0, [&](double a, double b, double size) {
    const double ua = c.u0 + du * a, ub = c.u0 + du * (a + size);
    const double va = c.v0 + dv * b, vb = c.v0 + dv * (b + size);
    for (int k = 0; k < founds; ++k)
      if (foundU[k] >= ua && foundU[k] <= ub && foundV[k] >= va && foundV[k] <= vb) return;
    if (run((ua + ub) / 2, (va + vb) / 2)) return;
    const double corners[4][2] = {{ua, va}, {ub, va}, {ua, vb}, {ub, vb}};
    for (const auto& k : corners)
      if (run(k[0], k[1])) return;
  });
}

// The cells whose boxes the ray enters before limit(), nearest first (the
// limit re-read after each: the nearest hit so far, or below every entry
// once a shadow ray is blocked), each searched by newtonInCell. The ray's
// planes are made at the first cell.
template <class Limit, class Take>
void walkCells(const SplineSurface& s, const BoxRay& boxRay, SplineCounters& counters,
               Limit&& limit, Take&& take) {
  RayPlanes planes;
  bool havePlanes = false;
  NewtonOptions options;
  options.tolerance = s.tolerance;
  s.cellBvh.traverse(
      boxRay,
      [&](int k, double entry) {
        ++counters.boxes;
        // A box entered at the limit or beyond holds nothing nearer (the
        // traversal's limit is inclusive).
        if (!(entry < limit())) return;
        if (!havePlanes) {
          planes = rayPlanes(boxRay.ray);
          havePlanes = true;
        }
        if (!planes.ok) return;
        newtonInCell(s, s.cells[static_cast<std::size_t>(k)], planes, boxRay.ray, options, counters,
                     take);
      },
      limit);
}

}  // namespace

bool intersectSplineModern(const SplineSurface& s, const BoxRay& boxRay, double tMin, double tMax,
                           SplineHit& hit, SplineCounters& counters) {
  ++counters.calls;
  double best = tMax;
  bool found = false;
  walkCells(
      s, boxRay, counters, [&] { return best; },
      [&](const NewtonResult& r, double u0, double v0) {
        if (!(r.t > tMin && r.t < best)) return;
        best = r.t;
        found = true;
        hit = {r.t, r.u, r.v, u0, v0, r.iterations, r.qu, r.qv};
      });
  if (found) ++counters.hits;
  return found;
}

bool occludesSplineModern(const SplineSurface& s, const BoxRay& boxRay, double tMin, double tMax,
                          SplineCounters& counters) {
  ++counters.calls;
  bool found = false;
  // Any hit in range will do: the limit drops below every entry once found.
  walkCells(
      s, boxRay, counters, [&] { return found ? -1.0 : tMax; },
      [&](const NewtonResult& r, double, double) {
        if (r.t > tMin && r.t < tMax) found = true;
      });
  if (found) ++counters.hits;
  return found;
}

}  // namespace prime::cgl
