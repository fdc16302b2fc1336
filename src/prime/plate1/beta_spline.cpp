#include "src/prime/plate1/beta_spline.h"

#include <string>

namespace prime::spline {

namespace {

// Power-basis coefficients: b_r(u) = c[0][r] + c[1][r] u + c[2][r] u^2 + c[3][r] u^3,
// r = 0..3 standing for b_-2 .. b_1 (the formulas of beta_spline.h expanded).
using Coefficients = std::array<std::array<double, 4>, 4>;

Coefficients coefficients(const BetaShape& s) {
  const double b1 = s.beta1, b2 = s.beta2;
  const double b1s = b1 * b1, b1c = b1s * b1;
  const double delta = 2.0 * b1c + 4.0 * b1s + 4.0 * b1 + b2 + 2.0;
  if (!(delta > 0.0))
    throw std::invalid_argument("beta-spline shape beta1 " + std::to_string(b1) + ", beta2 " +
                                std::to_string(b2) +
                                ": delta = 2b1^3 + 4b1^2 + 4b1 + b2 + 2 must be > 0");
  Coefficients c{};
  c[0] = {2.0 * b1c, 4.0 * b1s + 4.0 * b1 + b2, 2.0, 0.0};
  c[1] = {-6.0 * b1c, 6.0 * b1 * (b1s - 1.0), 6.0 * b1, 0.0};
  c[2] = {6.0 * b1c, -3.0 * (2.0 * b1c + 2.0 * b1s + b2), 3.0 * (2.0 * b1s + b2), 0.0};
  c[3] = {-2.0 * b1c, 2.0 * (b1c + b1s + b1 + b2), -2.0 * (b1s + b1 + b2 + 1.0), 2.0};
  for (auto& row : c)
    for (auto& x : row) x /= delta;
  return c;
}

}  // namespace

std::array<double, 4> betaBasis(const BetaShape& shape, double u) {
  const Coefficients c = coefficients(shape);
  std::array<double, 4> b{};
  for (int r = 0; r < 4; ++r) b[r] = c[0][r] + u * (c[1][r] + u * (c[2][r] + u * c[3][r]));
  return b;
}

std::array<double, 4> betaBasisD1(const BetaShape& shape, double u) {
  const Coefficients c = coefficients(shape);
  std::array<double, 4> b{};
  for (int r = 0; r < 4; ++r) b[r] = c[1][r] + u * (2.0 * c[2][r] + u * 3.0 * c[3][r]);
  return b;
}

std::array<double, 4> betaBasisD2(const BetaShape& shape, double u) {
  const Coefficients c = coefficients(shape);
  std::array<double, 4> b{};
  for (int r = 0; r < 4; ++r) b[r] = 2.0 * c[2][r] + u * 6.0 * c[3][r];
  return b;
}

KnotGrid::KnotGrid(int rows, int cols, std::vector<Vec3> knots)
    : rows_(rows), cols_(cols), knots_(std::move(knots)) {
  if (rows < 4 || cols < 4)
    throw std::invalid_argument(
        "a beta-spline surface needs at least 4 x 4 control vertices, got " + std::to_string(rows) +
        " x " + std::to_string(cols));
  if (knots_.size() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols))
    throw std::invalid_argument("knot grid " + std::to_string(rows) + " x " + std::to_string(cols) +
                                " needs " + std::to_string(rows * cols) +
                                " control vertices, got " + std::to_string(knots_.size()));
}

Vec3 curvePoint(const BetaShape& shape, const std::array<Vec3, 4>& v, double u) {
  const auto b = betaBasis(shape, u);
  Vec3 p{};
  for (int r = 0; r < 4; ++r) p = p + v[r] * b[r];
  return p;
}

Vec3 surfacePoint(const BetaShape& shape, const KnotGrid& grid, int pr, int pc, double u,
                  double v) {
  if (pr < 0 || pc < 0 || pr >= grid.patchRows() || pc >= grid.patchCols())
    throw std::out_of_range("patch " + std::to_string(pr) + "," + std::to_string(pc) + " of a " +
                            std::to_string(grid.patchRows()) + " x " +
                            std::to_string(grid.patchCols()) + " patch surface");
  const auto bu = betaBasis(shape, u);
  const auto bv = betaBasis(shape, v);
  Vec3 p{};
  for (int r = 0; r < 4; ++r) {
    Vec3 row{};
    for (int c = 0; c < 4; ++c) row = row + grid.at(pr + r, pc + c) * bu[c];
    p = p + row * bv[r];
  }
  return p;
}

}  // namespace prime::spline
