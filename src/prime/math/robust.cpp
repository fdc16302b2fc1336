#include "src/prime/math/robust.h"

#include <cmath>

#include "src/prime/math/float_step.h"
#include "src/prime/math/listing_matrix.h"

namespace prime {

Matrix4 accurateInverse(const Matrix4& m) {
  // Affine row-vector matrix: p' = p A + tr. A^-1 by cofactors in long
  // double, one Newton step X <- X (2I - A X) in long double, then the
  // translation row -tr A^-1; every entry rounded to double once.
  using LD = long double;
  LD a[3][3], x[3][3], c[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m[i][j];
  c[0][0] = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  c[0][1] = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  c[0][2] = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  c[1][0] = a[0][2] * a[2][1] - a[0][1] * a[2][2];
  c[1][1] = a[0][0] * a[2][2] - a[0][2] * a[2][0];
  c[1][2] = a[0][1] * a[2][0] - a[0][0] * a[2][1];
  c[2][0] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
  c[2][1] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
  c[2][2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  const LD det = a[0][0] * c[0][0] + a[0][1] * c[0][1] + a[0][2] * c[0][2];
  Matrix4 inv = identity4();
  if (!(det != 0) || !std::isfinite(static_cast<double>(det))) {
    inverse(m, inv);  // degenerate: the database's inverse is all there is
    return inv;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) x[i][j] = c[j][i] / det;
  LD ax[3][3], y[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      ax[i][j] = 0;
      for (int k = 0; k < 3; ++k) ax[i][j] += a[i][k] * x[k][j];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      LD s = 0;  // X (2I - A X)
      for (int k = 0; k < 3; ++k) s += x[i][k] * ((k == j ? 2 : 0) - ax[k][j]);
      y[i][j] = s;
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inv[i][j] = static_cast<double>(y[i][j]);
  for (int j = 0; j < 3; ++j) {
    LD t = 0;
    for (int k = 0; k < 3; ++k) t -= static_cast<LD>(m[3][k]) * y[k][j];
    inv[3][j] = static_cast<double>(t);
  }
  return inv;
}

Vec3 offsetRayOrigin(const Vec3& p, const Vec3& pError, const Vec3& n, const Vec3& w) {
  const double d = dot(Vec3{std::abs(n[0]), std::abs(n[1]), std::abs(n[2])}, pError);
  Vec3 offset = n * d;
  if (dot(w, n) < 0) offset = -offset;
  Vec3 po = p + offset;
  for (int i = 0; i < 3; ++i) {  // round away from p so the offset survives rounding
    if (offset[i] > 0)
      po[i] = stepAway(po[i], true);
    else if (offset[i] < 0)
      po[i] = stepAway(po[i], false);
  }
  return po;
}

}  // namespace prime
