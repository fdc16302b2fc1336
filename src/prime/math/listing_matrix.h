// The listing's Transfrm module and Inverse (Matrix module), performed in
// exactly the listing's order of floating-point operations so that the
// databases `prime model` writes come out bit-identical: Scale (K1),
// Translate, Rotate with Roundoff'ed sines and cosines (K3), Transform (K2)
// and Gauss-Jordan without pivoting (K42).
#pragma once
#include "src/math/matrix.h"

namespace prime {

// Inverse(c, b): Gauss-Jordan without pivoting (K42); a zero pivot is repaired
// by adding a later row. Returns false when some pivot stays zero (singular):
// the listing then silently produced garbage; callers turn that into an error.
bool inverse(const Matrix4& c, Matrix4& b);

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
