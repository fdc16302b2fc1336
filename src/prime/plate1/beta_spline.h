// Uniformly shaped beta-splines (Barsky): the curves and surfaces of thesis
// section 3.4.2 and Colour Plate 1. The 1991 listing has no spline code; this
// is our own implementation of the published formulas, cited in
// docs/prime/plates.md ("Colour Plate 1"):
//
//   B. A. Barsky and J. C. Beatty, "Local control of bias and tension in
//   Beta-splines", ACM Transactions on Graphics 2(2), 1983, 109-134 (also
//   SIGGRAPH '83, Computer Graphics 17(3), 193-218: the thesis' [BARS83]);
//   R. H. Bartels, J. C. Beatty and B. A. Barsky, "An Introduction to Splines
//   for Use in Computer Graphics and Geometric Modeling", Morgan Kaufmann,
//   1987, the chapter on Beta-splines.
//
// beta1 is the bias (the thesis calls it "skew") and beta2 the tension. With
// delta = 2 beta1^3 + 4 beta1^2 + 4 beta1 + beta2 + 2, segment i of a curve
// with control vertices V is, for u in [0, 1],
//   Q_i(u) = sum over r = -2..1 of b_r(u) V_{i+r}
//   b_-2(u) = 2 beta1^3 (1-u)^3 / delta
//   b_-1(u) = [2 beta1^3 u (u^2 - 3u + 3) + 2 beta1^2 (u^3 - 3u^2 + 2)
//              + 2 beta1 (u^3 - 3u + 2) + beta2 (2u^3 - 3u^2 + 1)] / delta
//   b_0(u)  = [2 beta1^2 u^2 (3 - u) + 2 beta1 u (3 - u^2)
//              + beta2 u^2 (3 - 2u) + 2 (1 - u^3)] / delta
//   b_1(u)  = 2 u^3 / delta
// The four sum to 1; beta1 = 1, beta2 = 0 gives the uniform cubic B-spline.
// Joints meet with the beta-constraints (G2 continuity):
//   Q_{i+1}(0) = Q_i(1),  Q'_{i+1}(0) = beta1 Q'_i(1),
//   Q''_{i+1}(0) = beta1^2 Q''_i(1) + beta2 Q'_i(1).
// A surface is the tensor product: patch (i, j) uses the 4 x 4 control
// vertices V_{i+r, j+s}, r, s = -2..1.
#pragma once
#include <array>
#include <stdexcept>
#include <vector>

#include "src/math/vec.h"

namespace prime::spline {

struct BetaShape {
  double beta1 = 1.0;  // bias ("skew")
  double beta2 = 0.0;  // tension
};

// The basis functions b_-2, b_-1, b_0, b_1 at u. Throws std::invalid_argument
// when delta is not positive (beta1 > 0 and beta2 >= 0 always qualify).
std::array<double, 4> betaBasis(const BetaShape& shape, double u);
// Their first and second derivatives with respect to u.
std::array<double, 4> betaBasisD1(const BetaShape& shape, double u);
std::array<double, 4> betaBasisD2(const BetaShape& shape, double u);

// Control vertices in rows x cols, row-major: V(r, c) = at(r, c).
class KnotGrid {
 public:
  KnotGrid(int rows, int cols, std::vector<Vec3> knots);
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  const Vec3& at(int r, int c) const { return knots_[static_cast<std::size_t>(r) * cols_ + c]; }
  // Patches along each direction: a k-knot direction has k - 3 segments.
  int patchRows() const { return rows_ - 3; }
  int patchCols() const { return cols_ - 3; }

 private:
  int rows_, cols_;
  std::vector<Vec3> knots_;
};

// The curve segment of four control vertices at u.
Vec3 curvePoint(const BetaShape& shape, const std::array<Vec3, 4>& v, double u);

// Surface point of patch (pr, pc), 0 <= pr < patchRows(), 0 <= pc <
// patchCols(), at (u, v) in [0, 1]^2; u runs along a row (columns), v down the
// rows. The patch uses rows pr..pr+3 and columns pc..pc+3.
Vec3 surfacePoint(const BetaShape& shape, const KnotGrid& grid, int pr, int pc, double u, double v);

}  // namespace prime::spline
