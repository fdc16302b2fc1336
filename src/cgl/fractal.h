// The Waterloo CGL package's fractal surfaces (M. A. J. Sweeney, "The
// Waterloo CGL Ray Tracing Package", University of Waterloo CS-85-35, 1985,
// section 5): the Fournier-Fussell-Carpenter subdivision of the standard
// triangle (-1, 0, 1), (1, 0, 1), (0, 0, -1), each new midpoint's y
// perturbed by s 2^(-h l) G with G read from a 201 x 201 matrix of Gaussian
// numbers indexed by the midpoint's x and z ("external consistency"), the
// terminal facets put through the current transformation ("internal
// consistency"), the tree of rectilinear bounding boxes (4 children per
// node, fully instantiated), Kajiya's traversal with the active list sorted
// by distance (section 5.5), facet intersection by Cramer's rule (section
// 5.6) and the texture indices of section 5.7.
//
// A surface is a pure function of its node and transformation: the random
// generator (SplitMix64 and Marsaglia's polar method) and the few
// transcendental functions it needs (log, exp2) are written out here in +,
// -, *, / and sqrt, which IEEE 754 rounds the same on every machine
// (CGL-D120). The choices the document leaves open are CGL-Q120 to CGL-Q127
// (docs/cgl/deviations.md).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "src/geom/aabb.h"
#include "src/geom/ray.h"
#include "src/math/matrix.h"
#include "src/math/vec.h"
#include "src/render/picture_buffer.h"

namespace prime::cgl {

// CGL-D120: the port's documented generator. SplitMix64 (Steele, Lea and
// Flood 2014) on the node's seed; uniform numbers in (-1, 1) from the top 53
// bits; Marsaglia's polar method for pairs of unit Gaussians, both of each
// pair used in turn.
class FractalRandom {
 public:
  explicit FractalRandom(std::int64_t seed) : state_(static_cast<std::uint64_t>(seed)) {}
  std::uint64_t next();  // SplitMix64
  double uniform();      // in [-1, 1)
  double gaussian();     // zero mean, unit variance

 private:
  std::uint64_t state_;
  bool haveSpare_ = false;
  double spare_ = 0.0;
};

// ln x for x > 0 and 2^x, in +, -, *, / only (frexp and ldexp are exact):
// the same bits on every IEEE machine, unlike a C library's log and pow.
double portableLog(double x);
double portableExp2(double x);

inline constexpr int kFractalMatrixSize = 201;
// CGL-Q121: the scale factor s of s 2^(-h l) G (not given by the document).
inline constexpr double kFractalScale = 0.5;

// The 201 x 201 matrix of section 5.2: entry [i * 201 + k] for x index i and
// z index k, filled in that order from FractalRandom(seed).gaussian(), with
// `offset` added to every entry (section 5.1: it "effectively becomes the
// mean").
std::vector<double> fractalMatrix(std::int64_t seed, double offset);
// CGL-Q122: x (or z) in [-1, 1] -> the nearest of 0..200, round(100 (x + 1)).
int fractalIndex(double coordinate);

struct FractalParams {
  int divisions = 1;  // 0 gives the plain triangle (the reader takes 1..10)
  double h = 0.9;
  double offset = 0.0;
  std::int64_t seed = 0;
  bool constrained = true;
  double scale = kFractalScale;
};

// A leaf's facet F(u, v) = A + u U + v V, 0 <= u <= 1, 0 <= v <= u (section
// 5.2): corners A, A + U, A + U + V.
struct FractalFacet {
  Vec3 a{}, u{}, v{};
};

// The preprocessed surface. The tree is complete (every internal node has 4
// children, every leaf is at depth `divisions`), so it is stored in level
// order without pointers: node i's children are 4i + 1 .. 4i + 4, and the
// leaves are the last 4^divisions nodes, leaf k holding facets[k].
struct FractalSurface {
  int divisions = 0;
  // (In whole huge pages where the system grants them: LargeBufferAllocator,
  // src/render/picture_buffer.h; 142 MB at 10 divisions.)
  LargeBuffer<Aabb> boxes;           // every node's box, padded (see fractal.cpp)
  LargeBuffer<FractalFacet> facets;  // in leaf order
  std::size_t firstLeaf = 0;         // boxes index of leaf 0
  // The texture frame of section 5.3 (the transformed standard triangle's
  // V0, E1 = V1 - V0, N_E1 = E2 - alpha E1) and the (u, v) extents over every
  // facet vertex; `textureFrame` false when the x and z equations have no
  // solution (the triangle seen edge-on from +y).
  Vec3 v0{}, e1{}, ne1{};
  double umin = 0, umax = 0, vmin = 0, vmax = 0;
  bool textureFrame = false;
  // The active list's preallocated length (see hitFractal).
  std::size_t activeCapacity = 0;

  std::size_t bytes() const;  // the memory the surface holds (compare Table 1)
  const Aabb& root() const { return boxes.front(); }
};

// Section 5.2: subdivides, perturbs, transforms (p' = p m, row vectors) and
// builds the tree and the texture frame.
FractalSurface buildFractal(const FractalParams& params, const Matrix4& m);

// The work done by hitFractal, for the statistics.
struct FractalWork {
  std::uint64_t boxes = 0, facets = 0;  // box and facet tests
  std::uint64_t activeMax = 0;          // the longest active list met
  std::uint64_t activeGrowths = 0;      // times the preallocated list was outgrown
  FractalWork& operator+=(const FractalWork& o);
};

// Section 5.6: O + tD = A + uU + vV by Cramer's rule (the triple products),
// accepted when 0 <= u <= 1, 0 <= v <= u and tMin < t < tMax.
bool hitFacet(const FractalFacet& f, const Ray& ray, double tMin, double tMax, double& t);

// Section 5.5, Kajiya's algorithm: the active list holds nodes with the
// distance at which the ray enters their boxes, sorted; the nearest is taken
// off, an internal node's children whose boxes the ray meets (nearer than
// the best facet hit so far) are sorted in, a leaf's facet is intersected;
// success when the best facet hit is nearer than the first node left.
// On a hit in (tMin, tMax) sets t and the facet index. The list is a
// per-thread buffer reserved to FractalSurface::activeCapacity on a thread's
// first use: nothing is allocated per ray unless a list outgrows it
// (counted in FractalWork::activeGrowths; none in the port's scenes and
// tests).
bool hitFractal(const FractalSurface& f, const BoxRay& ray, double tMin, double tMax, double& t,
                int& facet, FractalWork& work);
// Every facet tested in turn: the reference for the traversal's tests.
bool hitFractalBruteForce(const FractalSurface& f, const Ray& ray, double tMin, double tMax,
                          double& t, int& facet);

// Section 5.6: N = U x V, normalised (CGL-Q124).
Vec3 facetNormal(const FractalSurface& f, int facet);

// Section 5.7: I_x = V0x + u E1x + v N_E1x, I_z = V0z + u E1z + v N_E1z
// solved, then (u - umin)/(umax - umin), (v - vmin)/(vmax - vmin).
void fractalTextureUv(const Vec3& v0, const Vec3& e1, const Vec3& ne1, double umin, double umax,
                      double vmin, double vmax, const Vec3& point, double& u, double& v);

// The same (u, v) as affine functions of the world point, u = au.P + bu, v =
// av.P + bv (for the POV-Ray export's image_map matrix).
void fractalUvMap(const Vec3& v0, const Vec3& e1, const Vec3& ne1, double umin, double umax,
                  double vmin, double vmax, Vec3& au, double& bu, Vec3& av, double& bv);

// The surface as a POV-Ray 3.7 `mesh2` of its facets in leaf order, facet k
// the vertices 3k, 3k + 1, 3k + 2 = A, A + U, A + U + V (CGL-D121): the
// corners the port intersects.
std::string povFractalMesh(const FractalSurface& f);

}  // namespace prime::cgl
