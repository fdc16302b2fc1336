// Malone's scene after reading (section 1.1: "a list of primitives, their
// surfaces and types ... lights ... the viewer"), with each object's read-
// time precalculation done once (r^2, unit normals, the inverted affine
// matrix, the triangle's dot products) and every geometric check made with
// the object's place in the file.
#pragma once
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "legacy_io/malone/input.h"
#include "src/geom/free_camera.h"
#include "src/math/rgb.h"
#include "src/math/vec.h"

namespace prime::malone {

// A 3x3 matrix, rows.
using Mat3 = std::array<Vec3, 3>;

struct Primitive {
  ObjectId id = ObjectId::Sphere;
  // Sphere: c, r2. Plane: n (unit), D. Disk/annulus: c, n (unit), D, r2, rIn2.
  // Triangle/parallelogram: c = v0, a, b, n (unit), D, aa, ab, bb, det.
  // Cone: c = apex, axis (raw), u (unit axis), axis2 = |axis|^2, alpha,
  //   alpha2, lo, hi (range in axis lengths). Cylinder: c, axis, u, axis2,
  //   r2, lo, hi. Torus: c, u (unit axis), R, r.
  // Polygon: n (unit), D, vertices [first, first + count) of
  //   Scene::polygonVertices, dropped axis.
  // Affine: c = O, affine (index into Scene::affines).
  Vec3 c{}, n{}, a{}, b{}, axis{}, u{};
  double D = 0, r2 = 0, rIn2 = 0, aa = 0, ab = 0, bb = 0, det = 0;
  double axis2 = 0, alpha = 0, alpha2 = 0, lo = 0, hi = 0, R = 0, r = 0;
  int first = 0, count = 0, dropAxis = 0;
  int affine = -1;
  int surface = -1;                     // index into Scene::surfaces (top-level primitives)
  int objectNumber = 0;                 // its place among the file's objects, for messages
  int line = 0, column = 0, token = 0;  // where its ID stands in the file
};

// The affine primitive's matrices (kept apart: a mesh of a million triangles
// should not carry them).
struct Affine {
  Mat3 m{};        // M = (X Y Z)^-1: world -> local
  Mat3 mT{};       // M^T, for normals
  Mat3 mInv{};     // (X Y Z): local -> world, for boxes
  int inner = -1;  // index into Scene::embedded
};

struct Surface {
  Rgb kd{};  // k_d times the colour: the diffuse spectrum
  Rgb colour{};
  double diffuse = 0;  // k_d itself (the POV-Ray export's finish)
  double ks = 0, ke = 0, kt = 0, index = 1;
};

// One light sample: a point, a spectrum, and whether the r^-2 law applies.
struct LightSample {
  Vec3 position{};
  Rgb rgb{};
  bool inverseSquare = true;
  int light = 0;  // which light of the file (for the probe)
};

struct Viewer {
  Vec3 eye{}, lookAt{}, x{}, y{};
  int xRes = 0, yRes = 0;
};

struct Scene {
  std::vector<Primitive> primitives;  // top level, in file order
  std::vector<Primitive> embedded;    // the primitives inside affine ones
  std::vector<Affine> affines;
  std::vector<Vec3> polygonVertices;
  std::vector<Surface> surfaces;
  std::vector<LightSample> lights;  // every sample of every light, in file order
  int lightCount = 0;               // lights in the file
  Rgb ambient{};                    // the sum of the ambient lights
  bool hasAmbient = false;
  Viewer viewer;
  std::string name;  // the file, for titles and messages

  io::InputLocation where(const Primitive& p) const {
    return {name, p.line, std::nullopt, p.column, p.token};
  }
};

// The most samples the sampled lights (105) of one scene may have together.
// Each sample is a light of its own, with a shadow ray from every shaded
// point; the reader caps one light at 100000, and 16 KB of text could
// otherwise ask for 60 million (3 GB).
inline constexpr long kMaxLightSamples = 1'000'000;

// Builds the scene; throws io::InputError naming the object whose numbers
// make no primitive (a zero normal or axis, a degenerate triangle, polygon
// or parallelogram, a singular affine matrix, a refractive index <= 0 on a
// transparent surface, a viewer looking at its own eye) and the light whose
// samples would not be finite or would take the scene past
// kMaxLightSamples.
Scene buildScene(const SceneFile& file, const std::string& name);

// The viewer as a free camera (src/geom/free_camera.h): eye, look-at, up
// along y, the vertical field of view 2 atan |y| (y spans half the picture's
// height at distance 1), X_RES x Y_RES. It is the viewer exactly when x, y
// and the view are perpendicular and |x| / |y| = X_RES / Y_RES, as the
// cameras of this port's scenes are; otherwise the nearest such camera.
FreeCameraSettings freeCamera(const Viewer& viewer);
// The viewer of a free camera: x = right tan(fov/2) W/H, y = up tan(fov/2),
// right and up as FreeCamera makes them. Malone's own sampling stays (MAL-Q23:
// the ray through a pixel's corner, not its centre).
Viewer viewerOf(const FreeCameraSettings& camera);

// The deterministic sample positions of a sampled (spherical) light: a
// Fibonacci lattice of `count` points on the sphere (MAL-D3).
std::vector<Vec3> sphereSamples(const Vec3& centre, double radius, int count);

}  // namespace prime::malone
