// Preprocess and the camera (src/cgl/scene.h; Sweeney 1985 sections 1.2, 7,
// 8.2 and Appendix 1): the rotation sign, the order of the object list,
// shared subtrees instantiated per path, super boxes, ignored scale nodes,
// what the port refuses, texture look-up, and the default view.
#include "src/cgl/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>

#include "legacy_io/cgl/frame.h"
#include "tests/cgl/unit/scene_text.h"
#include "tests/support/temp_scene.h"

namespace prime::cgl {
namespace {

using test::emptyScene;
using test::lambert;

const double kDeg = std::numbers::pi / 180.0;

Vec3 rotatedCentre(char axis, double theta, Vec3 centre) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.nodes.push_back(test::rotate(1, 2, 0, axis, theta));
  f.nodes.push_back(test::sphere(2, 0, 1, centre, 0.1));
  f.numbers.root = 1;
  return buildScene(f).objects.at(0).c;
}

TEST(CglPreprocess, RotateIsRightHandedByMinusTheta) {
  // Digest of section 11 (CGL-Q41): rotate x -22 of (0,0,1) is
  // y' = y cos(theta) + z sin(theta) = sin(-22 deg) = -0.374607,
  // z' = -y sin(theta) + z cos(theta) = cos(22 deg) = 0.927184.
  const Vec3 c = rotatedCentre('x', -22.0, {0, 0, 1});
  EXPECT_NEAR(c[0], 0.0, 1e-15);
  EXPECT_NEAR(c[1], -0.374607, 1e-6);
  EXPECT_NEAR(c[2], 0.927184, 1e-6);
  EXPECT_DOUBLE_EQ(c[1], std::sin(-22.0 * kDeg));
  // rotate z 90: the right-handed rotation by -90 takes +x to -y ("clockwise
  // looking down the z axis towards the origin").
  const Vec3 z = rotatedCentre('z', 90.0, {1, 0, 0});
  EXPECT_NEAR(z[0], 0.0, 1e-15);
  EXPECT_NEAR(z[1], -1.0, 1e-15);
  // rotate y 90: by -90 about y, x' = x cos + z sin(-90) takes +z to -x.
  const Vec3 y = rotatedCentre('y', 90.0, {0, 0, 1});
  EXPECT_NEAR(y[0], -1.0, 1e-15);
  EXPECT_NEAR(y[2], 0.0, 1e-15);
}

TEST(CglPreprocess, CheckerboardOrderAndTransforms) {
  BuildOptions options;
  options.textures.emplace_back("checkerboard", test::checkerboardTexture());
  const Scene s = buildScene(test::checkerboardScene(), options);
  // Right pointers first: the sphere (node 4, on the rotate node's right) is
  // processed first and so is last in the list; the polygon (node 3) first.
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].kind, ObjectKind::Polygon);
  EXPECT_EQ(s.objects[0].node, 3);
  EXPECT_EQ(s.objects[1].kind, ObjectKind::Sphere);
  // The sphere hangs on the right pointer: untransformed.
  EXPECT_DOUBLE_EQ(s.objects[1].c[0], 0.3);
  EXPECT_DOUBLE_EQ(s.objects[1].c[1], -0.18);
  EXPECT_DOUBLE_EQ(s.objects[1].r, 0.16);
  // V0 = vertex 4 = (1,0,-1): translated to (1,-0.8,-1), then rotated x -22:
  // y' = -0.8 cos 22 + (-1) sin(-22) = -0.741747 + 0.374607 = -0.367140,
  // z' = -0.8 sin 22 + (-1) cos 22 = -0.299685 - 0.927184 = -1.226869: the
  // far edge is raised, the near edge (z = 1: y' = -1.116353) lowered, so
  // the eye at (0,0,3.5) sees the floor from above.
  const Object& floor = s.objects[0];
  EXPECT_NEAR(floor.v0[0], 1.0, 1e-12);
  EXPECT_NEAR(floor.v0[1], -0.367140, 1e-6);
  EXPECT_NEAR(floor.v0[2], -1.226869, 1e-6);
  // The plane's upward side faces the eye: (eye - V0).up > 0 with up the
  // rotated +y = (0, cos 22, sin 22) (the normal's sign is N_E1 x N_E2's).
  const Vec3 up{0, std::cos(22 * kDeg), std::sin(22 * kDeg)};
  EXPECT_GT(dot(s.camera.eye - floor.v0, up), 0.0);
  EXPECT_NEAR(std::fabs(dot(floor.n, up)), 1.0, 1e-12);
  // Surfaces: the floor textured, the ball opaque; the light normalised.
  EXPECT_EQ(s.surfaces[0].texture, 0);
  EXPECT_TRUE(s.objects[1].opaque);
  EXPECT_NEAR(length(s.lights[0].xyz), 1.0, 1e-15);
  // Ambience: k_a pi I_a; at 380 nm 0.0005 * pi * 50.0.
  EXPECT_DOUBLE_EQ(s.ambient[0], 0.0005 * std::numbers::pi * 50.0);
}

// Appendix 1 section 12's nine cubes as reconstructed (three translations in
// y of three translations in x of a rotation of a scaling of six polygons).
SceneFile nineCubes() {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.vertices = {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, 1, 1},
                {-1, 1, 1},   {-1, -1, 1}, {1, -1, 1}, {1, -1, -1}};
  using test::transform;
  f.nodes.push_back(transform(1, NodeKind::Translate, 4, 2, {0, -0.7, 0}));
  f.nodes.push_back(transform(2, NodeKind::Translate, 4, 3, {0, 0, 0}));
  f.nodes.push_back(transform(3, NodeKind::Translate, 4, 0, {0, 0.7, 0}));
  f.nodes.push_back(transform(4, NodeKind::Translate, 7, 5, {-0.7, 0, 0}));
  f.nodes.push_back(transform(5, NodeKind::Translate, 7, 6, {0, 0, 0}));
  f.nodes.push_back(transform(6, NodeKind::Translate, 7, 0, {0.7, 0, 0}));
  f.nodes.push_back(test::rotate(7, 8, 0, 'x', -22.0));
  f.nodes.push_back(transform(8, NodeKind::Scale, 9, 0, {0.2, 0.2, 0.2}));
  const int faces[6][4] = {{2, 3, 4, 5}, {6, 7, 8, 1}, {1, 8, 3, 2},
                           {5, 4, 7, 6}, {1, 2, 5, 6}, {8, 7, 4, 3}};
  for (int k = 0; k < 6; ++k)
    f.nodes.push_back(test::polygon(9 + k, k < 5 ? 10 + k : 0, 1,
                                    {faces[k][0], faces[k][1], faces[k][2], faces[k][3]}));
  f.numbers.root = 1;
  return f;
}

TEST(CglPreprocess, SharedSubtreesAreInstantiatedPerPath) {
  const Scene s = buildScene(nineCubes());
  // 3 x 3 paths to node 7, six faces each: 54 polygons.
  EXPECT_EQ(s.objects.size(), 54u);
  EXPECT_EQ(s.primitives, 54);
  // Every cube is 0.4 wide (scale 0.2 of a 2-wide cube, rotated about x: x
  // extent unchanged); the x centres are -0.7, 0, +0.7.
  int atLeft = 0;
  for (const Object& o : s.objects) {
    EXPECT_EQ(o.kind, ObjectKind::Polygon);
    EXPECT_LE(o.box.hi[0] - o.box.lo[0], 0.4 + 1e-8);
    if (o.box.lo[0] < -0.85) ++atLeft;  // the cubes at x = -0.7 span -0.9..-0.5
  }
  // Three cubes at x = -0.7, each with five faces reaching x = -0.9 (the
  // sixth, {8,7,4,3}, is the x = +1 face, at -0.5).
  EXPECT_EQ(atLeft, 15);
}

// Issue 37: the walk of the DAG counts every node reached along every path.
// Transform nodes that share the next by both pointers double the paths at
// each level without making an object, which the object limit never saw.
TEST(CglPreprocess, SharedPathsAreCountedAsVisitsAndRefused) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  const int levels = 24;  // 2^24 paths: 33 million visits
  for (int k = 1; k <= levels; ++k) f.nodes.push_back(test::node(k, NodeKind::Dummy, k + 1, k + 1));
  f.nodes.push_back(test::node(levels + 1, NodeKind::Dummy, 0, 0));
  f.numbers.root = 1;
  BuildOptions options;
  options.maxVisits = 1'000'000;
  try {
    buildScene(f, options);
    FAIL() << "2^24 paths were walked";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("at most 1000000 node visits"), std::string::npos)
        << e.what();
  }
}

// A chain of 100,000 nodes: a call per node overflowed the stack at about
// 6,000 (ASan); the walk is a work list now, in the same order.
TEST(CglPreprocess, AChainOfAHundredThousandNodesIsWalked) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  const int n = 100'000;
  for (int k = 1; k < n; ++k) f.nodes.push_back(test::node(k, NodeKind::Dummy, k + 1, 0));
  f.nodes.push_back(test::sphere(n, 0, 1, {0, 0, 0}, 0.5));
  f.numbers.root = 1;
  const Scene s = buildScene(f);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].node, n);
  // As deep in boxes: each box holds the next (flatten is iterative too).
  for (int k = 1; k < n; ++k) f.nodes[static_cast<std::size_t>(k - 1)].kind = NodeKind::Box;
  const Scene boxed = buildScene(f);
  ASSERT_EQ(boxed.objects.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(boxed.objects[0].skip, n);
  EXPECT_EQ(boxed.objects[static_cast<std::size_t>(n - 1)].kind, ObjectKind::Sphere);
}

// The refined meshes of spline nodes add up along every path to them, and
// are sized before each is made (section 6.3.3).
TEST(CglPreprocess, SplineMeshesAddUpAlongEveryPath) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  const int levels = 6;  // 64 paths to the spline
  for (int k = 1; k <= levels; ++k) f.nodes.push_back(test::node(k, NodeKind::Dummy, k + 1, k + 1));
  NodeRecord spline = test::node(levels + 1, NodeKind::Spline, 0, 0);
  spline.surface = 1;
  spline.nu = 4;
  spline.uEnd = EndCondition::Closed;
  spline.nv = 5;
  spline.vEnd = EndCondition::Double;
  spline.divisions = 8;  // (5 x 8 + 3) x (6 x 8 + 3) = 2,193 points, 343 KiB
  spline.overlap = 0.6;
  for (int v = 0; v < 5; ++v)
    for (int u = 0; u < 4; ++u)
      spline.controls.push_back({std::cos(u * std::numbers::pi / 2) * 0.3, 0.2 * v,
                                 std::sin(u * std::numbers::pi / 2) * 0.3});
  f.nodes.push_back(spline);
  f.numbers.root = 1;
  BuildOptions options;
  EXPECT_EQ(buildScene(f, options).splines.size(), 64u);
  options.maxSplineBytes = 10 * 2193 * kSplineBytesPerPoint;  // ten of them
  try {
    buildScene(f, options);
    FAIL() << "64 meshes were made within the room of ten";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().line, 1000 + levels + 1);
    EXPECT_NE(std::string(e.what()).find("4 x 5 vertices at 8 divisions: 43 x 51 points"),
              std::string::npos)
        << e.what();
  }
}

TEST(CglPreprocess, BoxesHoldTheirSubtreeInListOrder) {
  // Root 1 box (down 2, right 4); 2 sphere (right 3); 3 sphere; 4 sphere.
  // Right first: node 4 is processed first (last in the list). Inside the box
  // node 3 is processed before node 2, so the contents read 2, 3.
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.nodes.push_back(test::node(1, NodeKind::Box, 2, 4));
  f.nodes.push_back(test::sphere(2, 3, 1, {0, 0, 0}, 0.5));
  f.nodes.push_back(test::sphere(3, 0, 1, {1, 0, 0}, 0.5));
  f.nodes.push_back(test::sphere(4, 0, 1, {5, 0, 0}, 0.5));
  f.numbers.root = 1;
  const Scene s = buildScene(f);
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.objects[0].kind, ObjectKind::Box);
  EXPECT_EQ(s.objects[0].skip, 3);
  EXPECT_EQ(s.objects[1].node, 2);
  EXPECT_EQ(s.objects[2].node, 3);
  EXPECT_EQ(s.objects[3].node, 4);
  // The box is the union of the two spheres' boxes: x -0.5..1.5, y -0.5..0.5.
  EXPECT_NEAR(s.objects[0].box.lo[0], -0.5, 1e-8);
  EXPECT_NEAR(s.objects[0].box.hi[0], 1.5, 1e-8);
  EXPECT_NEAR(s.objects[0].box.hi[1], 0.5, 1e-8);
  EXPECT_EQ(s.boxes, 1);
  EXPECT_NE(describeObjects(s).find("  1: sphere (node 2)"), std::string::npos);
}

TEST(CglPreprocess, ScaleWithAZeroIsIgnored) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.nodes.push_back(test::transform(1, NodeKind::Scale, 2, 0, {2.0, 0.0, 2.0}));
  f.nodes.push_back(test::sphere(2, 0, 1, {1, 1, 1}, 0.1));
  f.numbers.root = 1;
  const Scene s = buildScene(f);
  EXPECT_DOUBLE_EQ(s.objects.at(0).c[0], 1.0);  // not scaled to 2
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("0.0 component"), std::string::npos);
  // A real scale moves the centre and keeps the radius (section 2.1).
  f.nodes[0].xyz = {2.0, 3.0, 4.0};
  const Scene t = buildScene(f);
  EXPECT_DOUBLE_EQ(t.objects.at(0).c[1], 3.0);
  EXPECT_DOUBLE_EQ(t.objects.at(0).r, 0.1);
}

TEST(CglPreprocess, BuildsWhatPartTwoRendersAndRefusesItsBadNodes) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.nodes.push_back(test::node(1, NodeKind::Fractal, 0, 0));
  f.numbers.root = 1;
  // Fractal nodes are built (src/cgl/fractal.h); divisions outside the
  // reader's 1..10 are refused at the node.
  f.nodes[0].kind = NodeKind::Fractal;
  f.nodes[0].surface = 1;
  EXPECT_THROW(buildScene(f), io::InputError);  // divisions 0
  f.nodes[0].divisions = 2;
  EXPECT_EQ(buildScene(f).fractals.size(), 1u);
  // A spline node is built now (section 6); one without vertices is refused
  // at its line, naming nu.
  f.nodes[0].kind = NodeKind::Spline;
  try {
    buildScene(f);
    FAIL() << "an empty spline node was accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().line, 1001);
    EXPECT_NE(std::string(e.what()).find("nu"), std::string::npos) << e.what();
  }
  // Cook surfaces are rendered (section 9.9, CGL-D42 no longer refuses
  // them): m and the 66 Fresnel vectors are carried into the Surface; a
  // table of another size (which the reader never makes) is refused at the
  // surface's line.
  f.nodes[0] = test::sphere(1, 0, 1, {0, 0, 0}, 1);
  f.surfaces[0].model = ShadingModel::Cook;
  f.surfaces[0].m = 0.3;
  f.surfaces[0].fresnel.assign(kFresnelAngles, test::flat(0.25));
  const Scene s = buildScene(f);
  EXPECT_EQ(s.surfaces[0].model, ShadingModel::Cook);
  EXPECT_DOUBLE_EQ(s.surfaces[0].m, 0.3);
  ASSERT_EQ(s.surfaces[0].fresnel.size(), 66u);
  EXPECT_DOUBLE_EQ(s.surfaces[0].fresnel[65][0], 0.25);
  f.surfaces[0].fresnel.pop_back();
  try {
    buildScene(f);
    FAIL() << "a cook surface with 65 Fresnel vectors was accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().line, 100);
  }
}

TEST(CglPreprocess, RefusesDegenerateGeometry) {
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 0}};
  f.nodes.push_back(test::polygon(1, 0, 1, {1, 2, 3}));  // collinear
  f.numbers.root = 1;
  EXPECT_THROW(buildScene(f), io::InputError);
  f.nodes[0] = test::cylinder(1, 0, 1, 0.5, 1, 4);  // both ends at the origin
  EXPECT_THROW(buildScene(f), io::InputError);
  f.nodes[0] = test::polygon(1, 0, 1, {1, 2});  // not 3 or 4 vertices
  EXPECT_THROW(buildScene(f), io::InputError);
}

TEST(CglPreprocess, TexturesAreLookedUpAndLastReusesOne) {
  SceneFile f = test::checkerboardScene();
  // Missing: the message names the surface's line and every place looked.
  BuildOptions none;
  none.textureDirs = {"/nonexistent-dir"};
  try {
    buildScene(f, none);
    FAIL() << "a missing texture was accepted";
  } catch (const io::InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.where().line, 22);
    EXPECT_NE(m.find("/u/majsweeney/textures/checkerboard"), std::string::npos) << m;
    EXPECT_NE(m.find("/nonexistent-dir/checkerboard.rle"), std::string::npos) << m;
  }
  // `last` shares the previous map.
  SurfaceRecord again = f.surfaces[0];
  again.texture.clear();
  again.textureLast = true;
  f.surfaces.push_back(again);
  BuildOptions options;
  options.textures.emplace_back("checkerboard", test::checkerboardTexture());
  const Scene s = buildScene(f, options);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.surfaces[2].texture, 0);
  // Texels as spectra: only the 450, 550 and 600 nm samples, the top-left
  // texel green (row 0, column 0 of the procedural board).
  const Spectrum green = rgbToSpectrum(Rgb8{test::kGreen[0], test::kGreen[1], test::kGreen[2]},
                                       Phosphors::Electrohome);
  EXPECT_DOUBLE_EQ(s.textures[0].texels[0][1], green[17]);
  // `last` with nothing before it.
  SceneFile g = test::checkerboardScene();
  g.surfaces[0].texture.clear();
  g.surfaces[0].textureLast = true;
  EXPECT_THROW(buildScene(g, options), io::InputError);
}

// CGL-D62: a texture path that leads out of the scene's directory (an
// absolute path, a "..", a symbolic link) is never opened; the base name is
// looked up inside it instead.
TEST(CglPreprocess, TexturesOutsideTheSceneAreNeverOpened) {
  namespace fs = std::filesystem;
  prime::test::TempScene t;
  const fs::path scene = t.path("scene"), outside = t.path("outside");
  fs::create_directories(scene / "textures");
  fs::create_directories(outside);
  writeRleFile((outside / "secret.rle").string(), test::checkerboardTexture());
  SceneFile f = test::checkerboardScene();
  f.path = (scene / "board.cgl").string();
  const auto messageOf = [&](const std::string& texture) {
    f.surfaces[0].texture = texture;
    try {
      buildScene(f, BuildOptions{});
    } catch (const io::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(built)");
  };
  for (const std::string& path :
       std::vector<std::string>{(outside / "secret.rle").string(), "../outside/secret.rle",
                                "textures/../../outside/secret.rle"}) {
    const std::string m = messageOf(path);
    EXPECT_NE(m.find("no file for '" + path + "'"), std::string::npos) << path << ": " << m;
    EXPECT_NE(m.find("(built)"), 0u) << path << " was opened";
  }
  EXPECT_NE(messageOf("/etc/passwd").find("leads outside the scene's directory"),
            std::string::npos);
  // A symbolic link inside the scene to a map outside it.
  fs::create_symlink(outside / "secret.rle", scene / "textures" / "linked.rle");
  EXPECT_NE(messageOf("textures/linked.rle").find("symbolic link"), std::string::npos);
  // The base name of a lost absolute path, found in the scene's textures/.
  writeRleFile((scene / "textures" / "secret.rle").string(), test::checkerboardTexture());
  EXPECT_EQ(messageOf((outside / "secret.rle").string()), "(built)");
  EXPECT_EQ(messageOf("/u/majsweeney/textures/secret"), "(built)");
  // A copy whose names changed case: each place looked in named once, and
  // the file that differs only in case pointed out.
  writeRleFile((scene / "textures" / "Checker.RLE").string(), test::checkerboardTexture());
  const std::string m = messageOf("textures/checker.rle");
  const std::string place = (scene / "textures" / "checker.rle").string();
  EXPECT_NE(m.find(place), std::string::npos) << m;
  EXPECT_EQ(m.find(place + ","), m.rfind(place + ",")) << "named twice: " << m;
  EXPECT_NE(m.find((scene / "textures" / "Checker.RLE").string() + " differs only in case"),
            std::string::npos)
      << m;
}

// Found by the cgl_texture fuzzer: every textured surface loaded its map
// anew (6 MB of texels each), so a 17 KB scene naming one 6 KB map on 200
// surfaces took 1.2 GB. A map is loaded once per file, whichever way a
// surface names it, and once per supplied map.
TEST(CglPreprocess, AMapNamedByManySurfacesIsLoadedOnce) {
  namespace fs = std::filesystem;
  prime::test::TempScene t;
  const fs::path scene = t.path("scene");
  fs::create_directories(scene / "textures");
  writeRleFile((scene / "textures" / "board.rle").string(), test::checkerboardTexture());
  writeRleFile((scene / "other.rle").string(), test::checkerboardTexture());
  SceneFile f = test::checkerboardScene();
  f.path = (scene / "board.cgl").string();
  f.surfaces.resize(1);
  f.surfaces[0].texture = "textures/board.rle";
  for (const char* name : {"/u/majsweeney/textures/board", "board", "./textures/board.rle",
                           "other.rle", "textures/board.rle"}) {
    SurfaceRecord again = f.surfaces[0];
    again.texture = name;
    f.surfaces.push_back(again);
  }
  const Scene s = buildScene(f);
  ASSERT_EQ(s.textures.size(), 2u);
  for (int k : {0, 1, 2, 3, 5}) EXPECT_EQ(s.surfaces[static_cast<std::size_t>(k)].texture, 0);
  EXPECT_EQ(s.surfaces[4].texture, 1);
  EXPECT_EQ(s.textures[1].path, (scene / "other.rle").string());
  // Supplied maps too.
  BuildOptions options;
  options.textures.emplace_back("checkerboard", test::checkerboardTexture());
  SceneFile g = test::checkerboardScene();
  g.surfaces.push_back(g.surfaces[0]);
  EXPECT_EQ(buildScene(g, options).textures.size(), 1u);
}

TEST(CglCamera, DefaultView) {
  const Scene s = buildScene(emptyScene());
  const Camera& c = s.camera;
  // up x sight = (0,1,0) x (0,0,-1) = (-1,0,0): screen-right is world -x.
  EXPECT_DOUBLE_EQ(c.right[0], -1.0);
  EXPECT_DOUBLE_EQ(c.up[1], 1.0);
  // The centre (256, 256): D = dist * sight = (0,0,-2.5), normalised.
  const Ray centre = c.primaryRay(256, 256);
  EXPECT_DOUBLE_EQ(centre.d[2], -1.0);
  EXPECT_DOUBLE_EQ(centre.o[2], 3.5);
  // (384, 256): D = (0,0,-2.5) + 128 (2/512) (-1,0,0) = (-0.5, 0, -2.5),
  // normalised: -0.5/sqrt(6.5) = -0.196116.
  const Ray right = c.primaryRay(384, 256);
  EXPECT_NEAR(right.d[0], -0.5 / std::sqrt(6.5), 1e-15);
  EXPECT_NEAR(right.d[2], -2.5 / std::sqrt(6.5), 1e-15);
  // (256, 0), the bottom: D = (0, -1, -2.5).
  EXPECT_LT(c.primaryRay(256, 0).d[1], 0.0);
}

TEST(CglCamera, RadiusPointOneSphereSpans37Pixels) {
  // Half-width on the screen: 2.5 tan(asin(0.1/3.5)) = 0.071487, or 18.30
  // pixels of 2/512: the corners x = 238..274 are inside, 37 pixels (the
  // document's "about 100 pixels" does not fit its own defaults).
  SceneFile f = emptyScene();
  f.surfaces.push_back(lambert(1, 1));
  f.nodes.push_back(test::sphere(1, 0, 1, {0, 0, 0}, 0.1));
  f.numbers.root = 1;
  const Scene s = buildScene(f);
  int first = -1, count = 0;
  for (int x = 0; x < 512; ++x) {
    double t = 0;
    if (hitSphere(s.objects[0], s.camera.primaryRay(x, 256), 0.0, 1e10, t)) {
      if (first < 0) first = x;
      ++count;
    }
  }
  EXPECT_EQ(count, 37);
  EXPECT_EQ(first, 238);
}

}  // namespace
}  // namespace prime::cgl
