// What the B-spline surfaces' four files share (spline_surface.cpp,
// spline_tree.cpp, spline_intersect.cpp): the knot interval, the cubic basis
// and its derivative, the four-wide vector type of the evaluation and the box
// test, and the AVX2 clones (CGL-D172). Private to src/cgl.
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "src/cgl/spline.h"

namespace prime::cgl::spline_detail {

constexpr double kInf = std::numeric_limits<double>::infinity();

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The knot interval i of u (clamped to -1 .. last) and the local parameter.
// (Forced inline, as basisWeights() below: GCC's own choice changes with the
// size of a file, and out of line they cost Newton's evaluation 3 % more
// instructions, 6-9 % more time on the spline figures.)
[[gnu::always_inline]] inline int interval(double u, int last, double& local) {
  int i = static_cast<int>(std::floor(u));
  i = std::clamp(i, -1, last);
  local = u - i;
  return i;
}

// CGL-D172: the evaluation and the box test on GCC/Clang vector types, four
// doubles wide (x, y, z and a zero pad for a point; four boxes for a
// packet). Each lane gets the same IEEE operations in the same order as the
// scalar code (the build has -ffp-contract=off: no fused multiply-add), so
// the same doubles. On x86-64 GCC the hot functions are also compiled for
// AVX2 (`target_clones`, chosen once at load time by the CPU); the baseline
// clone runs the same vectors as SSE2 pairs, with the same results.
using V4 = double __attribute__((vector_size(32)));
// (V4 is loaded into a reference, not returned: a 32-byte vector return
// would change the ABI of the baseline clone.)
[[gnu::always_inline]] inline void load4(V4& v, const double* p) {
  std::memcpy(&v, p, sizeof v);
}

[[gnu::always_inline]] inline void basisWeights(double u, double w[4], double dw[4]) {
  const double u2 = u * u, u3 = u2 * u, t = 1.0 - u;
  w[0] = t * t * t / 6.0;                              // b_3: 1 - 3u + 3u^2 - u^3
  w[1] = (4.0 - 6.0 * u2 + 3.0 * u3) / 6.0;            // b_2
  w[2] = (1.0 + 3.0 * u + 3.0 * u2 - 3.0 * u3) / 6.0;  // b_1
  w[3] = u3 / 6.0;                                     // b_0
  dw[0] = -t * t / 2.0;
  dw[1] = (-12.0 * u + 9.0 * u2) / 6.0;
  dw[2] = (3.0 + 6.0 * u - 9.0 * u2) / 6.0;
  dw[3] = u2 / 2.0;
}

// The refined knots a of one direction whose parameter lies in `range`
// (spline_tree.cpp builds the tree over them; spline_intersect.cpp's dense
// reference walks them).
std::vector<int> knotsInRange(int m, int divisions, ParamRange range);

}  // namespace prime::cgl::spline_detail

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define PRIME_SPLINE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PRIME_SPLINE_CLONES
#endif
