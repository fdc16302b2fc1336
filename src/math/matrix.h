// 4x4 row-vector matrices and the listing's matrix operations (Matrix and
// Transfrm modules), each performed in exactly the listing's order of
// floating-point operations so that databases come out bit-identical.
#pragma once
#include <array>

#include "src/math/vec.h"

namespace prime {

using Matrix4 = std::array<std::array<double, 4>, 4>;

Matrix4 identity4();

// MatrixMul(a, b): a = a * b.
void matrixMul(Matrix4& a, const Matrix4& b);

// Inverse(c, b): Gauss-Jordan without pivoting (K42); a zero pivot is repaired
// by adding a later row. Returns false when some pivot stays zero (singular):
// the listing then silently produced garbage; callers turn that into an error.
bool inverse(const Matrix4& c, Matrix4& b);

// PointMatrixMul (E29): newP[i] = m[3][i] + sum_j p[j]*m[j][i].
Vec3 pointMatrixMul(const Vec3& p, const Matrix4& m);
// VectorMatrixMul: no translation row.
Vec3 vectorMatrixMul(const Vec3& v, const Matrix4& m);

// Scale (K1): multiplies only the diagonal m[i][i], i = X..Z.
void scale(Matrix4& m, const Vec3& s);
// Translate: adds t to row 3.
void translate(Matrix4& m, const Vec3& t);
// RotateX/Y/Z with Roundoff'ed sines and cosines (K3); Rotate = X, then Y, then Z.
void rotateX(Matrix4& m, double degrees);
void rotateY(Matrix4& m, double degrees);
void rotateZ(Matrix4& m, double degrees);
void rotate(Matrix4& m, double rX, double rY, double rZ);

// Transform (K2): Scale(s), Translate(-pivot*s), Rotate(r), Translate(t),
// applied to the matrix as it is (identity for AddPrim/AddBound, an existing
// transform for TransferObj).
void transform(Matrix4& m, const Vec3& s, const Vec3& t, const Vec3& pivot, const Vec3& r);

}  // namespace prime
