#include "src/math/matrix.h"

namespace prime {

Matrix4 identity4() {
  Matrix4 m{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m[i][j] = (i == j) ? 1.0 : 0.0;
  return m;
}

void matrixMul(Matrix4& a, const Matrix4& b) {
  Matrix4 c{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      c[i][j] = 0.0;
      for (int k = 0; k < 4; ++k) c[i][j] += a[i][k] * b[k][j];
    }
  a = c;
}

Vec3 pointMatrixMul(const Vec3& p, const Matrix4& m) {
  Vec3 r{};
  for (int i = 0; i < 3; ++i) {
    r[i] = m[3][i];
    for (int j = 0; j < 3; ++j) r[i] += p[j] * m[j][i];
  }
  return r;
}

Vec3 vectorMatrixMul(const Vec3& v, const Matrix4& m) {
  Vec3 r{};
  for (int i = 0; i < 3; ++i) {
    r[i] = 0.0;
    for (int j = 0; j < 3; ++j) r[i] += v[j] * m[j][i];
  }
  return r;
}

}  // namespace prime
