#include "src/prime/math/listing_matrix.h"

#include <cmath>

#include "src/prime/math/listing_math.h"

namespace prime {

bool inverse(const Matrix4& c, Matrix4& b) {
  Matrix4 a = c;
  b = identity4();
  bool singular = false;
  for (int row = 0; row < 4; ++row) {
    if (a[row][row] != 1.0) {
      if (a[row][row] != 0.0) {
        const double d = 1.0 / a[row][row];
        for (int i = 0; i < 4; ++i) {
          a[row][i] *= d;
          b[row][i] *= d;
        }
      } else {
        // The listing adds the first later row with a non-zero entry in this
        // column, scaled by 1/a[i][row]; it does not re-normalise the pivot.
        bool found = false;
        for (int i = row + 1; !found && i < 4; ++i) {
          if (a[i][row] != 0) {
            found = true;
            const double d = 1.0 / a[i][row];
            for (int j = 0; j < 4; ++j) {
              a[row][j] += d * a[i][j];
              b[row][j] += d * b[i][j];
            }
          }
        }
        if (!found) singular = true;
      }
    }
    for (int i = row + 1; i < 4; ++i) {
      if (a[i][row] != 0.0) {
        const double d = -a[i][row];
        for (int j = 0; j < 4; ++j) {
          a[i][j] += d * a[row][j];
          b[i][j] += d * b[row][j];
        }
      }
    }
    for (int i = row - 1; i >= 0; --i) {
      if (a[i][row] != 0.0) {
        const double d = -a[i][row];
        for (int j = 0; j < 4; ++j) {
          a[i][j] += d * a[row][j];
          b[i][j] += d * b[row][j];
        }
      }
    }
  }
  // After elimination `a` should be the identity; anything else (a zero or
  // non-finite pivot) means the input was singular or not finite.
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (!std::isfinite(b[i][j])) singular = true;
  return !singular;
}

void scale(Matrix4& m, const Vec3& s) {
  for (int i = 0; i < 3; ++i) m[i][i] *= s[i];
}

void translate(Matrix4& m, const Vec3& t) {
  for (int i = 0; i < 3; ++i) m[3][i] += t[i];
}

void rotateX(Matrix4& m, double rX) {
  const double c = roundoff(cosDeg(rX)), s = roundoff(sinDeg(rX));
  for (int i = 0; i < 4; ++i) {
    const double tmp = m[i][Y];
    m[i][Y] = (tmp * c) - (m[i][Z] * s);
    m[i][Z] = (m[i][Z] * c) + (tmp * s);
  }
}

void rotateY(Matrix4& m, double rY) {
  const double c = roundoff(cosDeg(rY)), s = roundoff(sinDeg(rY));
  for (int i = 0; i < 4; ++i) {
    const double tmp = m[i][X];
    m[i][X] = (tmp * c) + (m[i][Z] * s);
    m[i][Z] = (m[i][Z] * c) - (tmp * s);
  }
}

void rotateZ(Matrix4& m, double rZ) {
  const double c = roundoff(cosDeg(rZ)), s = roundoff(sinDeg(rZ));
  for (int i = 0; i < 4; ++i) {
    const double tmp = m[i][X];
    m[i][X] = (tmp * c) - (m[i][Y] * s);
    m[i][Y] = (m[i][Y] * c) + (tmp * s);
  }
}

void rotate(Matrix4& m, double rX, double rY, double rZ) {
  rotateX(m, rX);
  rotateY(m, rY);
  rotateZ(m, rZ);
}

void transform(Matrix4& m, const Vec3& s, const Vec3& t, const Vec3& pivot, const Vec3& r) {
  Vec3 tmpPivot{};
  for (int i = 0; i < 3; ++i) {
    tmpPivot[i] = pivot[i];
    tmpPivot[i] *= -s[i];
  }
  scale(m, s);
  translate(m, tmpPivot);
  rotate(m, r[X], r[Y], r[Z]);
  translate(m, t);
}

}  // namespace prime
