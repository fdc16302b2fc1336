// B-spline surfaces (Sweeney 1985, section 6): the basis, the extended
// control points and Oslo refinement (section 6.3); and what a hit needs
// afterwards: the normal, the texture parameters, the Bezier patches of the
// POV-Ray export, the hole count of `prime cgl-splines`.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "src/cgl/spline.h"
#include "src/cgl/spline_kernels.h"

namespace prime::cgl {

using namespace spline_detail;

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
  const bool p = intersectSplineAsBuilt(s, BoxRay(ray), tMin, kInf, path, c);
  if (r) ++count.referenceHits;
  if (p) ++count.pathHits;
  if (r && !p) ++count.holes;
  if (p && !r) ++count.extra;
  if (p && r && path.t > ref.t + 1e-6 * (1.0 + ref.t)) ++count.farther;
}

}  // namespace prime::cgl
