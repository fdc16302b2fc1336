// buildScene (src/malone/scene.h): the read-time precalculation of each
// object (unit normals, normalised D, the triangle's dot products, the
// inverted affine matrix, K_d = k_d colour, light samples) and the geometric
// refusals, each located at the object's ID token.
#include "src/malone/scene.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tests/malone/unit/scene_text.h"

namespace prime::malone {
namespace {

using test::sceneOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

io::InputError buildError(const std::string& objects) {
  try {
    sceneOf(objects);
  } catch (const io::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for: " << objects;
  return io::InputError({}, "none");
}

// The object starts line 2, column 1, token 16 (after the 15 viewer tokens).
void expectAtObject(const io::InputError& e, const std::string& field, const std::string& expected,
                    const std::string& foundPrefix) {
  SCOPED_TRACE(e.what());
  EXPECT_EQ(e.where().file, "test.mal");
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.where().column, 1);
  EXPECT_EQ(e.where().token, 16);
  EXPECT_EQ(e.field(), field);
  EXPECT_THAT(e.expected(), HasSubstr(expected));
  EXPECT_THAT(e.found(), StartsWith(foundPrefix));
  EXPECT_THAT(std::string(e.what()),
              StartsWith("test.mal:2:1 (token 16): " + field + ": expected"));
}

TEST(MaloneScene, Surfaces) {
  // K_d = k_d times the colour: 0.5 (0.2, 0.4, 1) = (0.1, 0.2, 0.5).
  const Scene s = sceneOf("1 1 0 0 0 100 0.2 0.4 1 0.3 20 0.5 0.1 1.33\n");
  ASSERT_EQ(s.surfaces.size(), 1u);
  const Surface& f = s.surfaces[0];
  EXPECT_DOUBLE_EQ(f.kd[0], 0.1);
  EXPECT_DOUBLE_EQ(f.kd[1], 0.2);
  EXPECT_DOUBLE_EQ(f.kd[2], 0.5);
  EXPECT_EQ(f.colour, (Rgb{0.2, 0.4, 1}));
  EXPECT_EQ(f.ks, 0.3);
  EXPECT_EQ(f.ke, 20);
  EXPECT_EQ(f.kt, 0.1);
  EXPECT_EQ(f.index, 1.33);
  EXPECT_EQ(s.primitives[0].surface, 0);
}

TEST(MaloneScene, TransparentSurfaceNeedsAnIndex) {
  // k_t > 0 with index 0: refused at the surface's own 100 (token 21, column 11).
  try {
    sceneOf("1 1 0 0 0 100 1 1 1 0 1 1 0.5 0\n");
    ADD_FAILURE();
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 11);
    EXPECT_EQ(e.where().token, 21);
    EXPECT_EQ(e.field(), "surface, index");
    EXPECT_EQ(e.found(), "0");
  }
  // Opaque with index 0 (the document's own scene): fine.
  EXPECT_NO_THROW(sceneOf("1 1 0 0 0 100 1 1 1 0 1 1 0 0\n"));
}

TEST(MaloneScene, PlanarPrecalculation) {
  // Disk: n = (0,3,4)/5, D = n.c = (0 * 1 + 0.6 * 2 + 0.8 * 3) = 3.6.
  const Scene d = sceneOf("3 1 2 3 0 3 4 2" + test::kSurface);
  EXPECT_NEAR(d.primitives[0].n[1], 0.6, 1e-15);
  EXPECT_NEAR(d.primitives[0].n[2], 0.8, 1e-15);
  EXPECT_NEAR(d.primitives[0].D, 3.6, 1e-14);
  EXPECT_EQ(d.primitives[0].r2, 4);
  // Annulus: r_in^2.
  EXPECT_EQ(sceneOf("4 0 0 0 0 0 1 3 2" + test::kSurface).primitives[0].rIn2, 4);
  // Triangle (1,0,0) (0,1,0) (0,0,1): a = (-1,1,0), b = (-1,0,1), a.a = 2, a.b = 1,
  // b.b = 2, det = 4 - 1 = 3; n = (1,1,1)/sqrt 3, D = 1/sqrt 3.
  const Primitive t = sceneOf("5 1 0 0 0 1 0 0 0 1" + test::kSurface).primitives[0];
  EXPECT_EQ(t.aa, 2);
  EXPECT_EQ(t.ab, 1);
  EXPECT_EQ(t.bb, 2);
  EXPECT_EQ(t.det, 3);
  EXPECT_NEAR(t.D, 1 / std::sqrt(3.0), 1e-15);
  // Polygon: Newell normal of the square in the plane x = 2 ordered
  // counter-clockwise about +x; the dropped axis is x (0).
  const Scene p = sceneOf("11 4 2 0 0 2 1 0 2 1 1 2 0 1" + test::kSurface);
  EXPECT_NEAR(p.primitives[0].n[0], 1, 1e-15);
  EXPECT_NEAR(p.primitives[0].D, 2, 1e-15);
  EXPECT_EQ(p.primitives[0].dropAxis, 0);
  EXPECT_EQ(p.primitives[0].count, 4);
  EXPECT_EQ(p.polygonVertices.size(), 4u);
}

TEST(MaloneScene, QuadricPrecalculation) {
  // Cone: alpha^2 = 0.81, |axis|^2 = 25, u = (0,-1,0), range sorted.
  const Primitive c = sceneOf("8 0.9 2 0 0 2 0 0 -5 0" + test::kSurface).primitives[0];
  EXPECT_DOUBLE_EQ(c.alpha2, 0.9 * 0.9);
  EXPECT_EQ(c.axis2, 25);
  EXPECT_EQ(c.u, (Vec3{0, -1, 0}));
  EXPECT_EQ(c.lo, 0);
  EXPECT_EQ(c.hi, 2);
  // Cylinder: r^2.
  EXPECT_EQ(sceneOf("9 0.5 0 10 0 2 0 0 -1 0" + test::kSurface).primitives[0].r2, 0.25);
}

TEST(MaloneScene, AffineInverse) {
  // (X Y Z) with X = (1,0,0), Y = (1,2,0), Z = (0,1,4): M (X Y Z) = I.
  const Scene s = sceneOf("7 1 2 3 1 0 0 1 2 0 0 1 4 1 1 0 0 0" + test::kSurface);
  const Primitive& p = s.primitives[0];
  ASSERT_EQ(p.affine, 0);
  const Affine& a = s.affines[0];
  ASSERT_EQ(a.inner, 0);
  ASSERT_EQ(s.embedded.size(), 1u);
  EXPECT_EQ(s.embedded[0].id, ObjectId::Sphere);
  EXPECT_EQ(p.c, (Vec3{1, 2, 3}));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double mm = 0;
      for (int k = 0; k < 3; ++k) mm += a.m[i][k] * a.mInv[k][j];
      EXPECT_NEAR(mm, i == j ? 1 : 0, 1e-15) << i << j;
      EXPECT_EQ(a.mT[i][j], a.m[j][i]);
    }
  // By hand: the columns' inverse has first row (1, -1/2, 1/8).
  EXPECT_DOUBLE_EQ(a.m[0][0], 1);
  EXPECT_DOUBLE_EQ(a.m[0][1], -0.5);
  EXPECT_DOUBLE_EQ(a.m[0][2], 0.125);
}

TEST(MaloneScene, Lights) {
  const Scene s = sceneOf("1 1 0 0 0" + test::kSurface +
                          "101 1 2 3 4 5 6\n104 0 0 0 1 1 1\n105 4 10 0 0 2 8 8 8\n"
                          "105 1 5 5 5 1 3 3 3\n103 0.1 0.1 0.1\n103 0.2 0.3 0.4\n");
  EXPECT_EQ(s.lightCount, 4);
  ASSERT_EQ(s.lights.size(), 1u + 1 + 4 + 1);
  EXPECT_TRUE(s.lights[0].inverseSquare);   // 101: r^-2
  EXPECT_FALSE(s.lights[1].inverseSquare);  // 104: without
  EXPECT_EQ(s.lights[0].position, (Vec3{1, 2, 3}));
  EXPECT_EQ(s.lights[0].rgb, (Rgb{4, 5, 6}));
  // 105 with 4 samples: each on the sphere of radius 2 about (10,0,0), each
  // carrying I/N = 2, r^-2, light 2 of the file.
  for (int i = 2; i < 6; ++i) {
    const Vec3 w = s.lights[i].position - Vec3{10, 0, 0};
    EXPECT_NEAR(std::sqrt(dot(w, w)), 2, 1e-14);
    EXPECT_EQ(s.lights[i].rgb, (Rgb{2, 2, 2}));
    EXPECT_TRUE(s.lights[i].inverseSquare);
    EXPECT_EQ(s.lights[i].light, 2);
  }
  // One sample: the centre itself.
  EXPECT_EQ(s.lights[6].position, (Vec3{5, 5, 5}));
  EXPECT_EQ(s.lights[6].rgb, (Rgb{3, 3, 3}));
  // Ambient lights add.
  EXPECT_TRUE(s.hasAmbient);
  EXPECT_NEAR(s.ambient[0], 0.3, 1e-15);
  EXPECT_NEAR(s.ambient[1], 0.4, 1e-15);
  EXPECT_NEAR(s.ambient[2], 0.5, 1e-15);
  // The samples are deterministic and spread (Fibonacci): distinct points.
  const auto a = sphereSamples({0, 0, 0}, 1, 16), b = sphereSamples({0, 0, 0}, 1, 16);
  EXPECT_EQ(a, b);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) EXPECT_NE(a[i], a[j]);
}

TEST(MaloneSceneErrors, DegenerateTriangle) {
  // (0,0,0), (1,1,1), (2,2,2): on one line.
  expectAtObject(buildError("5 0 0 0 1 1 1 2 2 2" + test::kSurface), "triangle, vertices",
                 "three points that span a plane",
                 "a degenerate shape: edges (1, 1, 1) and (2, 2, 2)");
  // Two equal vertices.
  expectAtObject(buildError("5 0 0 0 0 0 0 1 0 0" + test::kSurface), "triangle, vertices",
                 "three points that span a plane", "a degenerate shape");
}

TEST(MaloneSceneErrors, DegenerateParallelogram) {
  expectAtObject(buildError("6 0 0 0 1 0 0 -2 0 0" + test::kSurface), "parallelogram, vertices",
                 "three points that span a plane",
                 "a degenerate shape: edges (1, 0, 0) and (-2, 0, 0)");
}

TEST(MaloneSceneErrors, DegeneratePolygon) {
  expectAtObject(buildError("11 3 0 0 0 1 0 0 2 0 0" + test::kSurface), "polygon, vertices",
                 "a polygon that encloses an area", "a degenerate polygon of 3 vertices");
  // A closed zero-area path (out and back) is degenerate too.
  expectAtObject(buildError("11 4 0 0 0 1 1 0 2 2 0 1 1 0" + test::kSurface), "polygon, vertices",
                 "a polygon that encloses an area", "a degenerate polygon of 4 vertices");
}

TEST(MaloneSceneErrors, SingularAffine) {
  expectAtObject(buildError("7 0 0 0 1 0 0 2 0 0 0 0 1 1 1 0 0 0" + test::kSurface),
                 "affine, X, Y, Z", "three independent axes",
                 "a singular matrix: X (1, 0, 0), Y (2, 0, 0), Z (0, 0, 1)");
  // Coplanar axes: Z = X + Y.
  expectAtObject(buildError("7 0 0 0 1 0 0 0 1 0 1 1 0 1 1 0 0 0" + test::kSurface),
                 "affine, X, Y, Z", "three independent axes", "a singular matrix");
}

TEST(MaloneSceneErrors, ZeroVectorsAndRanges) {
  expectAtObject(buildError("2 1 0 0 0" + test::kSurface), "plane, normal", "a non-zero vector",
                 "(0, 0, 0)");
  expectAtObject(buildError("8 0.9 0 2 0 2 0 0 0 0" + test::kSurface), "cone, axis",
                 "a non-zero vector", "(0, 0, 0)");
  expectAtObject(buildError("8 1 0 2 0 2 0 0 -5 0" + test::kSurface), "cone, alpha",
                 "cos(theta) strictly between 0 and 1", "1");
  expectAtObject(buildError("4 0 0 0 0 0 1 1 1" + test::kSurface), "annulus, r_in",
                 "an inner radius from 0 to below the radius 1", "1");
  expectAtObject(buildError("1 0 0 0 0" + test::kSurface), "sphere, radius", "a radius > 0", "0");
  expectAtObject(buildError("10 2 0 0 0 0 0 0 1" + test::kSurface), "torus, r", "a tube radius > 0",
                 "0");
}

TEST(MaloneSceneErrors, ViewerLookingAtItsEye) {
  try {
    buildScene(readScene("102 1 2 3 1 2 3 1 0 0 0 1 0 8 8\n", "v.mal"), "v.mal");
    ADD_FAILURE();
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.where().token, 1);
    EXPECT_EQ(e.field(), "viewer, look-at");
    EXPECT_EQ(e.found(), "(1, 2, 3) (the eye itself)");
  }
}

// Found by the malone_viewer_lights fuzzer: a sampled light whose centre and
// radius are each finite but whose samples are not (1e308 + 1e308 * 0.5
// overflows) gave the tracer lights at infinity.
TEST(MaloneSceneErrors, SampledLightWhoseSamplesOverflow) {
  const io::InputError e = buildError("105 2 1e308 1e308 1e308 1e308 1 1 1\n");
  expectAtObject(e, "sampled light, radius", "a sphere of finite points",
                 "centre (1e+308, 1e+308, 1e+308), radius 1e+308, which puts a sample at");
  // The largest such sphere that stays finite is a light like any other.
  EXPECT_EQ(sceneOf("105 2 0 0 0 1e308 1 1 1\n").lights.size(), 2u);
}

// Found by the malone_viewer_lights fuzzer: 200 sampled lights of 100000
// samples each (6 KB of text) made 20 million light samples (1.1 GB) and
// took seconds before the first pixel. The scene's total is capped, checked
// before a light's samples are made.
TEST(MaloneSceneErrors, TooManyLightSamplesInAScene) {
  std::string lights;
  for (int i = 0; i < 10; ++i) lights += "105 100000 0 5 0 1 1 1 1\n";
  EXPECT_EQ(sceneOf(lights).lights.size(), 1000000u);  // exactly the cap: accepted
  try {
    sceneOf(lights + "101 0 0 0 1 1 1\n105 1 0 5 0 1 1 1 1\n");
    ADD_FAILURE() << "a scene of 1000001 samples of sampled lights was accepted";
  } catch (const io::InputError& e) {
    SCOPED_TRACE(e.what());
    EXPECT_EQ(e.where().line, 13);
    EXPECT_EQ(e.where().token, 1 + 15 + 10 * 9 + 7);
    EXPECT_EQ(e.field(), "sampled light, samples");
    EXPECT_THAT(e.expected(), HasSubstr("at most 1000000 samples of sampled lights in the whole "
                                        "scene (1000000 before this light)"));
    EXPECT_EQ(e.found(), "1 more");
  }
}

}  // namespace
}  // namespace prime::malone
