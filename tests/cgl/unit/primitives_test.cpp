// The CGL object nodes (src/cgl/primitives.h; Sweeney 1985 sections 2-4 and
// 7): intersections, normals and texture indices, each expectation worked
// out by hand in the comment beside it.
#include "src/cgl/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "src/cgl/scene.h"
#include "tests/cgl/unit/scene_text.h"

namespace prime::cgl {
namespace {

using test::emptyScene;
using test::lambert;

// One object from a one-node scene.
Object only(SceneFile f) {
  f.numbers.root = 1;
  const Scene s = buildScene(f);
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0);
}

Object unitSphere() {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.nodes.push_back(test::sphere(1, 0, 1, {0, 0, 0}, 1.0));
  return only(f);
}

// A cylinder from (0,0,0) to `b`, radius 1.
Object cylinderTo(Vec3 b) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.vertices = {{0, 0, 0}, b};
  f.nodes.push_back(test::cylinder(1, 0, 1, 1.0, 1, 2));
  return only(f);
}

Object polygonOf(std::vector<Vec3> vertices, std::vector<int> order) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.vertices = std::move(vertices);
  f.nodes.push_back(test::polygon(1, 0, 1, std::move(order)));
  return only(f);
}

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(CglSphere, NearRootThenFarRootThenMiss) {
  const Object s = unitSphere();
  double t = 0;
  // O = (0,0,5), D = (0,0,-1): L = (0,0,5), a = 1, b = -10, c = 25 - 1 = 24,
  // disc = 100 - 96 = 4, t = (10 - 2)/2 = 4.
  ASSERT_TRUE(hitSphere(s, {{0, 0, 5}, {0, 0, -1}}, 0.0, kInf, t));
  EXPECT_DOUBLE_EQ(t, 4.0);
  const Vec3 n = normalAt(s, {0, 0, 1}, 0);
  EXPECT_DOUBLE_EQ(n[2], 1.0);
  // From the centre along +x: b = 0, c = -1, disc = 4; (0 - 2)/2 = -1 <= 0,
  // so the far root (0 + 2)/2 = 1.
  ASSERT_TRUE(hitSphere(s, {{0, 0, 0}, {1, 0, 0}}, 0.0, kInf, t));
  EXPECT_DOUBLE_EQ(t, 1.0);
  // O = (0,2,5): c = 4 + 25 - 1 = 28, disc = 100 - 112 < 0.
  EXPECT_FALSE(hitSphere(s, {{0, 2, 5}, {0, 0, -1}}, 0.0, kInf, t));
  // Behind the ray: O = (0,0,-5), D = (0,0,-1): roots -6 and -4.
  EXPECT_FALSE(hitSphere(s, {{0, 0, -5}, {0, 0, -1}}, 0.0, kInf, t));
  // Not nearer than the current t_min (4 is not < 4).
  EXPECT_FALSE(hitSphere(s, {{0, 0, 5}, {0, 0, -1}}, 0.0, 4.0, t));
}

TEST(CglSphere, TextureAxesGiveTheIndices) {
  const Object s = unitSphere();  // axes x y
  double u = 0, v = 0;
  // N = (0.6, 0.8, 0): u = (0.6 + 1)/2 = 0.8, v = (0.8 + 1)/2 = 0.9;
  // u_i = int(512 * 0.8) = int(409.6) = 409, v_i = int(460.8) = 460.
  textureUv(s, {0.6, 0.8, 0}, {0.6, 0.8, 0}, 0, u, v);
  EXPECT_DOUBLE_EQ(u, 0.8);
  EXPECT_DOUBLE_EQ(v, 0.9);
  EXPECT_EQ(textureIndex(u, 1.0), 409);
  EXPECT_EQ(textureIndex(v, 1.0), 460);
  // umod 2: int(819.2) = 819, mod 512 = 307.
  EXPECT_EQ(textureIndex(u, 2.0), 307);
}

TEST(CglCylinder, HitWithTheMinusRSquaredReading) {
  // A = 0, B = (0,0,2): P = (0,0,2), P.P = 4. O = (0,5,1), D = (0,-1,0):
  // alpha = D.P/P.P = 0, beta = (O-A).P/P.P = 2/4 = 0.5, L = O - beta P =
  // (0,5,0), Omega = D; a = 1, b = -10, c = 25 - 1 = 24 -> t = (10 - 2)/2 = 4,
  // u_i = 0.5. With the printed "+ r^2" c would be 26 and disc = 100 - 104 < 0:
  // a miss (CGL-E40).
  const Object c = cylinderTo({0, 0, 2});
  double t = 0, axial = 0;
  ASSERT_TRUE(hitCylinder(c, {{0, 5, 1}, {0, -1, 0}}, 0.0, kInf, t, axial));
  EXPECT_DOUBLE_EQ(t, 4.0);
  EXPECT_DOUBLE_EQ(axial, 0.5);
  const Vec3 n = normalAt(c, {0, 1, 1}, axial);  // I - (A + 0.5 P) = (0,1,0)
  EXPECT_DOUBLE_EQ(n[1], 1.0);
  // Beyond the end: O = (0,5,3) meets the infinite cylinder at u_i = 1.5.
  EXPECT_FALSE(hitCylinder(c, {{0, 5, 3}, {0, -1, 0}}, 0.0, kInf, t, axial));
}

TEST(CglCylinder, OnlyTheChosenRootIsRangeChecked) {
  // O = (0,1.5,3.5), D = (0,-1,-1): points (0, 1.5 - t, 3.5 - t). alpha =
  // -2/4 = -0.5, beta = 7/4 = 1.75; L = (0,1.5,0), Omega = (0,-1,0): a = 1,
  // b = -3, c = 1.25, disc = 4, roots 0.5 (u_i = 1.5, past the open end) and
  // 2.5 (u_i = 0.5, on the cylinder). As printed only the chosen near root is
  // checked, so the ray misses (CGL-Q46) although its far root is a real hit.
  const Object c = cylinderTo({0, 0, 2});
  double t = 0, axial = 0;
  EXPECT_FALSE(hitCylinder(c, {{0, 1.5, 3.5}, {0, -1, -1}}, 0.0, kInf, t, axial));
  // The same line started past the near root (t = 1 along it) finds the far one.
  ASSERT_TRUE(hitCylinder(c, {{0, 0.5, 2.5}, {0, -1, -1}}, 0.0, kInf, t, axial));
  EXPECT_DOUBLE_EQ(t, 1.5);
  EXPECT_DOUBLE_EQ(axial, 0.5);
}

TEST(CglCylinder, TextureAxisAndIndices) {
  // P = (0,0,2) is parallel to z: A1 = P x (0,1,0) = (-2,0,0), normalised
  // (-1,0,0). Hit from +x: O = (5,0,0.5), D = (-1,0,0) meets (1,0,0.5):
  // N = (1,0,0), v = (N.A1 + 1)/2 = 0, u = u_i = 0.25 -> u_i = 128, v_i = 0.
  const Object c = cylinderTo({0, 0, 2});
  EXPECT_DOUBLE_EQ(c.a1[0], -1.0);
  double t = 0, axial = 0, u = 0, v = 0;
  ASSERT_TRUE(hitCylinder(c, {{5, 0, 0.5}, {-1, 0, 0}}, 0.0, kInf, t, axial));
  const Vec3 p{1, 0, 0.5};
  textureUv(c, p, normalAt(c, p, axial), axial, u, v);
  EXPECT_DOUBLE_EQ(u, 0.25);
  EXPECT_DOUBLE_EQ(v, 0.0);
  EXPECT_EQ(textureIndex(u, 1.0), 128);
  EXPECT_EQ(textureIndex(v, 1.0), 0);
  // P = (2,0,0): A1 = P x (0,0,1) = (0,-2,0) -> (0,-1,0).
  const Object x = cylinderTo({2, 0, 0});
  EXPECT_DOUBLE_EQ(x.a1[1], -1.0);
}

TEST(CglPolygon, TriangleEdgesByPermutingThePoints) {
  // V0 = 0, V1 = (1,0,0), V2 = (0,1,0). Edge 1: E1 = (1,0,0), E2 = (0,1,0),
  // alpha = 0, N_E1 = (0,1,0), d1 = 0. Edge 2 (V1 -> V2, towards V0): E1 =
  // (-1,1,0), E2 = (-1,0,0), alpha = 1/2, N_E2 = (-0.5,-0.5,0), d2 = -0.5.
  // Edge 3 (V2 -> V0, towards V1): E1 = (0,-1,0), E2 = (1,-1,0), alpha = 1,
  // N_E3 = (1,0,0), d3 = 0. N = N_E1 x N_E2 = (0,0,0.5) -> (0,0,1).
  const Object p = polygonOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {1, 2, 3});
  ASSERT_EQ(p.edges, 3);
  EXPECT_DOUBLE_EQ(p.en[1][0], -0.5);
  EXPECT_DOUBLE_EQ(p.d[1], -0.5);
  EXPECT_DOUBLE_EQ(p.en[2][0], 1.0);
  EXPECT_DOUBLE_EQ(p.n[2], 1.0);
  double t = 0;
  ASSERT_TRUE(hitPolygon(p, {{0.25, 0.25, 1}, {0, 0, -1}}, 0.0, kInf, t));
  EXPECT_DOUBLE_EQ(t, 1.0);
  // (0.6, 0.6): I.N_E2 - d2 = -0.6 + 0.5 = -0.1 < 0, outside the hypotenuse.
  EXPECT_FALSE(hitPolygon(p, {{0.6, 0.6, 1}, {0, 0, -1}}, 0.0, kInf, t));
  // Parallel to the plane, and behind the ray.
  EXPECT_FALSE(hitPolygon(p, {{0.25, 0.25, 1}, {1, 0, 0}}, 0.0, kInf, t));
  EXPECT_FALSE(hitPolygon(p, {{0.25, 0.25, 1}, {0, 0, 1}}, 0.0, kInf, t));
  // Texture: u = (I - V0).E1/|E1|^2 = x, v = (I - V0).N_E1/|N_E1|^2 = y, both
  // over [0,1] at the vertices: at (0.25,0.25) u_i = 128; umod 2 -> 256;
  // vmod 3 -> int(384) = 384.
  double u = 0, v = 0;
  textureUv(p, {0.25, 0.25, 0}, p.n, 0, u, v);
  EXPECT_DOUBLE_EQ(u, 0.25);
  EXPECT_DOUBLE_EQ(v, 0.25);
  EXPECT_EQ(textureIndex(u, 2.0), 256);
  EXPECT_EQ(textureIndex(v, 3.0), 384);
}

TEST(CglPolygon, RectangleHasAFourthEdge) {
  // Figure 59's floor, vertices 4 3 2 1: V0 = (1,0,-1), V1 = (1,0,1), V2 =
  // (-1,0,1), V3 = (-1,0,-1). N_E1 = (-2,0,0) (x <= 1), N_E2 = (0,0,-2)
  // (z <= 1), N_E3 = (2,0,0) (x >= -1), and the fourth edge V3 -> V0 seen
  // from V1: E1 = (2,0,0), E2 = (2,0,2), alpha = 1, N_E4 = (0,0,2), d4 = -2
  // (z >= -1). N = N_E1 x N_E2 = (0,-4,0) -> (0,-1,0).
  const Object r = polygonOf(test::floorVertices(), {4, 3, 2, 1});
  ASSERT_EQ(r.edges, 4);
  EXPECT_DOUBLE_EQ(r.en[3][2], 2.0);
  EXPECT_DOUBLE_EQ(r.d[3], -2.0);
  EXPECT_DOUBLE_EQ(r.n[1], -1.0);
  double t = 0;
  // (-0.5, -0.5) is outside the triangle V0 V1 V2 but inside the rectangle.
  EXPECT_TRUE(hitPolygon(r, {{-0.5, 1, -0.5}, {0, -1, 0}}, 0.0, kInf, t));
  EXPECT_DOUBLE_EQ(t, 1.0);
  // z = -1.5 passes the first three edges and fails only the fourth.
  EXPECT_FALSE(hitPolygon(r, {{0.5, 1, -1.5}, {0, -1, 0}}, 0.0, kInf, t));
  // Texture: u = (z + 1)/2, v = (1 - x)/2; at (0.5, 0, -0.5): u = v = 0.25,
  // u_i = v_i = 128.
  double u = 0, v = 0;
  textureUv(r, {0.5, 0, -0.5}, r.n, 0, u, v);
  EXPECT_DOUBLE_EQ(u, 0.25);
  EXPECT_DOUBLE_EQ(v, 0.25);
  EXPECT_EQ(textureIndex(u, 1.0), 128);
}

TEST(CglTextureIndex, TruncatesAndWraps) {
  EXPECT_EQ(textureIndex(1.0, 1.0), 0);      // 512 mod 512
  EXPECT_EQ(textureIndex(0.999, 1.0), 511);  // int(511.488)
  EXPECT_EQ(textureIndex(0.0, 5.0), 0);
  EXPECT_EQ(textureIndex(0.75, 3.0), 128);        // int(1152) mod 512 = 128
  EXPECT_EQ(textureIndex(-3.2 / 512, 1.0), 509);  // int(-3.2) = -3, folded (CGL-Q50)
}

TEST(CglBox, EntryAheadInsideAndMisses) {
  Object box;
  box.kind = ObjectKind::Box;
  box.box.add(Vec3{-1, -1, -1});
  box.box.add(Vec3{1, 1, 1});
  EXPECT_DOUBLE_EQ(boxEntry(box, BoxRay({{0, 0, 5}, {0, 0, -1}})), 4.0);
  EXPECT_DOUBLE_EQ(boxEntry(box, BoxRay({{0, 0, 0}, {0, 0, -1}})), 0.0);  // inside
  EXPECT_EQ(boxEntry(box, BoxRay({{0, 0, 5}, {0, 0, 1}})), kInf);         // behind
  EXPECT_EQ(boxEntry(box, BoxRay({{2, 0, 5}, {0, 0, -1}})), kInf);        // beside
  // Diagonal: O = (3,3,0), D = (-1,-1,0) enters at x = y = 1, t = 2.
  EXPECT_DOUBLE_EQ(boxEntry(box, BoxRay({{3, 3, 0}, {-1, -1, 0}})), 2.0);
}

}  // namespace
}  // namespace prime::cgl
