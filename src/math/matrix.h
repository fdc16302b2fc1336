// 4x4 row-vector matrices (a point is a row vector times the matrix; row 3
// holds the translation): identity, product and the point and direction
// transforms, each summed in index order (as PRIME's Matrix module does, so
// its databases come out bit-identical). PRIME's Transfrm module and its
// Inverse (K42) are in src/prime/math/listing_matrix.h.
#pragma once
#include <array>

#include "src/math/vec.h"

namespace prime {

using Matrix4 = std::array<std::array<double, 4>, 4>;

Matrix4 identity4();

// MatrixMul(a, b): a = a * b.
void matrixMul(Matrix4& a, const Matrix4& b);

// PointMatrixMul (E29): newP[i] = m[3][i] + sum_j p[j]*m[j][i].
Vec3 pointMatrixMul(const Vec3& p, const Matrix4& m);
// VectorMatrixMul: no translation row.
Vec3 vectorMatrixMul(const Vec3& v, const Matrix4& m);

}  // namespace prime
