// prime export-pov's library: the structure of the POV-Ray text for a small
// in-memory scene, the matrix and camera values worked out by hand, and the
// texture images.
#include "src/prime/pov/pov_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <regex>
#include <string>

#include "src/prime/math/listing_matrix.h"

namespace prime {
namespace {

Matrix4 placed(Vec3 s, Vec3 t) {
  Matrix4 m = identity4();
  for (int i = 0; i < 3; ++i) {
    m[i][i] = s[i];
    m[3][i] = t[i];
  }
  return m;
}

ScenePrim prim(char type, const Matrix4& m, int map) {
  ScenePrim p;
  p.type = io::primType(type).value();
  p.transform = m;
  inverse(m, p.inverse);
  for (auto& s : p.map) s = {map, map};
  return p;
}

SceneTexture constantMap(double r, double g, double b) {
  SceneTexture t;
  t.uScale = t.vScale = 1;
  t.channel = {std::vector<double>{r}, std::vector<double>{g}, std::vector<double>{b}};
  t.constant = true;
  return t;
}

// Object 1: (box + sphere) - cylinder, opaque. Object 2: a glass sphere.
Scene smallScene() {
  Scene s;
  s.name = "unit";
  s.prims.push_back(prim('B', placed({100, 200, 300}, {10, 20, 30}), 1));  // 0
  s.prims.push_back(prim('S', placed({50, 50, 50}, {500, 500, 0}), 1));    // 1
  s.prims.push_back(prim('C', placed({20, 20, 400}, {60, 60, -100}), 1));  // 2
  s.prims.push_back(prim('S', placed({80, 80, 80}, {700, 300, 100}), 2));  // 3
  for (auto& m : s.prims[2].map) m[io::kIn] = 2;                           // the cut shows map 2
  SceneObject a;
  a.number = 1;
  a.entries = {{'-', 1, 4}, {'+', 2, 3}, {'P', 0, 0}, {'P', 1, 0}, {'P', 2, 0}};
  a.hue.kDR = 1.0;
  a.hue.kDT = 1.0;
  a.hue.fDR = {0.5, 0.5, 0.5};
  s.objects.push_back(a);
  SceneObject b;
  b.number = 2;
  b.entries = {{'P', 3, 0}};
  b.hue.kDR = 0.0;
  b.hue.kDT = 0.0;
  b.hue.tT = 0.999;
  b.hue.kRH = 3;
  b.hue.indx = 1.5;
  s.objects.push_back(b);
  s.maps.resize(3);
  s.maps[1] = constantMap(0.9, 0.2, 0.1);
  SceneTexture checker;  // 2 x 2: texel (u, v) at u + 2v
  checker.uScale = checker.vScale = 2;
  checker.channel = {std::vector<double>{1.0, 0.0, 0.0, 1.0},
                     std::vector<double>{0.0, 0.0, 0.0, 0.0},
                     std::vector<double>{0.0, 1.0, 1.0, 0.0}};
  s.maps[2] = checker;
  s.ambient = {0.2, 0.2, 0.2};
  s.lights.push_back({{500, 1500, -1000}, {0.8, 0.8, 0.8}});
  return s;
}

std::vector<double> numbersIn(const std::string& text) {
  std::vector<double> out;
  const char* p = text.c_str();
  while (*p) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end != p) {
      out.push_back(v);
      p = end;
    } else {
      ++p;
    }
  }
  return out;
}

// The text after `key` up to the end of its line.
std::string lineAfter(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  if (at == std::string::npos) return "";
  const auto end = text.find('\n', at);
  return text.substr(at + key.size(), end - at - key.size());
}

TEST(PovMatrix, RowVectorTransformReadsRowByRow) {
  // p_world = p_local * M with translation in row 3; POV-Ray's matrix takes the
  // first three columns of each row: x' = m00 x + m10 y + m20 z + m30.
  Matrix4 m = identity4();
  m[0] = {0, 1, 0, 0};   // x -> y
  m[1] = {-2, 0, 0, 0};  // y -> -2x
  m[2] = {0, 0, 3, 0};
  m[3] = {7, 8, 9, 1};
  const std::array<double, 12> expect{0, 1, 0, -2, 0, 0, 0, 0, 3, 7, 8, 9};
  EXPECT_EQ(povMatrix(m), expect);
  // (1, 1, 1) goes to (7 - 2, 8 + 1, 9 + 3) both ways.
  const Vec3 p = pointMatrixMul({1, 1, 1}, m);
  const auto v = povMatrix(m);
  EXPECT_EQ(p[0], v[0] + v[3] + v[6] + v[9]);
  EXPECT_EQ(p[1], v[1] + v[4] + v[7] + v[10]);
  EXPECT_EQ(p[2], v[2] + v[5] + v[8] + v[11]);
}

TEST(PovNumber, ShortestRoundTrip) {
  EXPECT_EQ(povNumber(300.0), "300");
  EXPECT_EQ(povNumber(-0.0), "0");
  EXPECT_EQ(povNumber(0.1), "0.1");
  EXPECT_EQ(std::strtod(povNumber(1000.0 * 350 / 349).c_str(), nullptr), 1000.0 * 350 / 349);
}

TEST(PovCamera, ListingDefaultsByHand) {
  // Eye (500, 500, -1500); window (0..1000) x (1000..0) at z = 0 sampled by
  // 350 x 769 rays whose first and last fall on the window's edges, so the
  // image spans 350/349 of the width and 769/768 of the height around the
  // window's centre (500, 500, 0).
  const PovCamera c = povCamera(CameraSettings{});
  EXPECT_EQ(c.width, 350);
  EXPECT_EQ(c.height, 769);
  EXPECT_EQ(c.location, (Vec3{500, 500, -1500}));
  EXPECT_EQ(c.direction, (Vec3{0, 0, 1500}));
  EXPECT_NEAR(c.right[0], 1002.8653295128940, 1e-9);  // 1000 * 350 / 349, pointing +x: not mirrored
  EXPECT_EQ(c.right[1], 0.0);
  EXPECT_EQ(c.right[2], 0.0);
  EXPECT_EQ(c.up[0], 0.0);
  EXPECT_NEAR(c.up[1], 1001.3020833333333, 1e-9);  // 1000 * 769 / 768
  EXPECT_EQ(c.up[2], 0.0);
}

// POV-Ray 3.7's perspective ray for pixel (x, y) (tracepixel.cpp).
Vec3 povRay(const PovCamera& c, int x, int y) {
  const double x0 = (x + 0.5) / c.width - 0.5, y0 = 0.5 - (y + 0.5) / c.height;
  return c.direction + x0 * c.right + y0 * c.up;
}

void expectSameRays(const CameraSettings& s) {
  const ListingCamera listing(s);
  const PovCamera c = povCamera(s);
  ASSERT_EQ(c.width, listing.columns());
  ASSERT_EQ(c.height, listing.rows());
  for (int row : {0, 1, listing.rows() / 2, listing.rows() - 1})
    for (int col : {0, 7, listing.columns() / 3, listing.columns() - 1}) {
      const Vec3 a = listing.primaryRay(row, col).d, b = povRay(c, col, row);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(a[i], b[i], 1e-9 * 2000) << "row " << row << " col " << col;
    }
}

TEST(PovCamera, SameRaysAsTheListing) {
  expectSameRays(CameraSettings{});
  CameraSettings odd;  // a sheared window, another viewport and screen
  odd.eye = {100, 700, -900};
  odd.windowLeft = {-200, 800, 100};
  odd.windowRight = {900, 1100, 300};
  odd.xMin = 0.1;
  odd.xMax = 0.8;
  odd.yMin = 0.2;
  odd.screenWidth = 640;
  odd.screenHeight = 480;
  expectSameRays(odd);
}

TEST(PovExport, GlobalSettingsCameraAndLights) {
  const PovExport e = exportPov(smallScene());
  EXPECT_EQ(e.width, 350);
  EXPECT_EQ(e.height, 769);
  EXPECT_NE(e.pov.find("#version 3.7;"), std::string::npos);
  EXPECT_NE(e.pov.find("max_trace_level 6\n"), std::string::npos);  // MaxDepth 5 + the primary ray
  EXPECT_NE(e.pov.find("adc_bailout 0"), std::string::npos);
  EXPECT_NE(e.pov.find("assumed_gamma 1"), std::string::npos);
  EXPECT_NE(e.pov.find("ambient_light rgb <0.2, 0.2, 0.2>"), std::string::npos);
  EXPECT_EQ(lineAfter(e.pov, "  location "), "<500, 500, -1500>");
  EXPECT_EQ(lineAfter(e.pov, "  direction "), "<0, 0, 1500>");
  const auto right = numbersIn(lineAfter(e.pov, "  right "));
  ASSERT_EQ(right.size(), 3u);
  EXPECT_EQ(right[0], 1000.0 * 350 / 349);
  EXPECT_NE(e.pov.find("light_source { <500, 1500, -1000> color rgb <0.8, 0.8, 0.8> shadowless }"),
            std::string::npos);
  PovExportOptions deeper;
  deeper.maxDepth = 2;
  EXPECT_NE(exportPov(smallScene(), deeper).pov.find("max_trace_level 3\n"), std::string::npos);
}

TEST(PovExport, CsgNestingAndMatrices) {
  const std::string pov = exportPov(smallScene()).pov;
  // Entry 0 '-' (entry 1, entry 4); entry 1 '+' (prim 0, prim 1): opaque, so union.
  const auto diff = pov.find("\ndifference {  // entry 0");
  const auto uni = pov.find("\n  union {  // entry 1");
  const auto box = pov.find("\n    box { <0, 0, 0>, <1, 1, 1>  // entry 2: prim 0");
  const auto sph = pov.find("\n    sphere { <0, 0, 0>, 1  // entry 3: prim 1");
  const auto cyl = pov.find("\n  cylinder { <0, 0, 0>, <0, 0, 1>, 1  // entry 4: prim 2");
  ASSERT_NE(diff, std::string::npos) << pov;
  ASSERT_NE(uni, std::string::npos) << pov;
  ASSERT_NE(box, std::string::npos) << pov;
  ASSERT_NE(sph, std::string::npos) << pov;
  ASSERT_NE(cyl, std::string::npos) << pov;
  EXPECT_LT(diff, uni);
  EXPECT_LT(uni, box);
  EXPECT_LT(box, sph);
  EXPECT_LT(sph, cyl);
  // The union closes (at its own indentation) before the cylinder starts.
  EXPECT_LT(pov.find("\n  }\n", sph), cyl);
  // Scale (100, 200, 300), translation (10, 20, 30), worked out by hand.
  EXPECT_NE(pov.find("      matrix <100, 0, 0, 0, 200, 0, 0, 0, 300, 10, 20, 30>\n", box),
            std::string::npos);
  EXPECT_NE(pov.find("    matrix <20, 0, 0, 0, 20, 0, 0, 0, 400, 60, 60, -100>\n", cyl),
            std::string::npos);
  // The glass sphere: merge is not needed for one primitive, but its interior is there.
  EXPECT_NE(pov.find("sphere { <0, 0, 0>, 1  // entry 0: prim 3"), std::string::npos);
  EXPECT_NE(pov.find("#declare PrimeInterior2 = interior { ior 1.5 fade_distance"),
            std::string::npos);
  EXPECT_EQ(pov.find("PrimeInterior1"), std::string::npos);  // object 1 is opaque (kDT = 1)
}

TEST(PovExport, SeeThroughUnionIsMerge) {
  Scene s = smallScene();
  s.objects[0].hue.kDT = 0.5;
  const std::string pov = exportPov(s).pov;
  EXPECT_NE(pov.find("merge {  // entry 1"), std::string::npos);
  EXPECT_EQ(pov.find("union {"), std::string::npos);
}

TEST(PovExport, SubtractedPrimitiveShowsItsInMap) {
  PovExportOptions o;
  o.imageStem = "unit";
  const std::string pov = exportPov(smallScene(), o).pov;
  const auto cyl = pov.find("cylinder { <0, 0, 0>, <0, 0, 1>, 1  // entry 4");
  ASSERT_NE(cyl, std::string::npos);
  const std::string leaf = pov.substr(cyl, pov.find("\n  }\n", cyl) - cyl);
  // The cut face is the cylinder's inside: the In map (2, an image) as texture,
  // the Out map (1, constant) as interior_texture.
  EXPECT_NE(leaf.find("  texture { pigment { average pigment_map"), std::string::npos) << leaf;
  EXPECT_NE(leaf.find("unit_map2.png\" gamma 1 map_type 2"), std::string::npos) << leaf;
  EXPECT_NE(leaf.find("  interior_texture { pigment { rgbt <"), std::string::npos) << leaf;
}

TEST(PovExport, MapImagesAreWrittenWithRowZeroAtTheBottom) {
  PovExportOptions o;
  o.imageStem = "unit";
  Scene s = smallScene();
  s.prims[3].map[0] = {2, 2};  // the glass sphere gets the 2 x 2 map too
  const PovExport e = exportPov(s, o);
  ASSERT_EQ(e.images.size(), 2u);  // map 2 for the cylinder, and twice side by side for the sphere
  const PovImage& flat = e.images[0];
  EXPECT_EQ(flat.fileName, "unit_map2.png");
  ASSERT_EQ(flat.image.width, 2);
  ASSERT_EQ(flat.image.height, 2);
  // Texel (0, 0) (red) is the bottom-left pixel, texel (1, 0) (blue) bottom-right.
  auto px = [](const Image8& im, int x, int y) {
    const auto* p = &im.rgb[(static_cast<std::size_t>(y) * im.width + x) * 3];
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  EXPECT_EQ(px(flat.image, 0, 1), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(px(flat.image, 1, 1), (std::array<int, 3>{0, 0, 255}));
  EXPECT_EQ(px(flat.image, 0, 0), (std::array<int, 3>{0, 0, 255}));
  const PovImage& sphere = e.images[1];
  EXPECT_EQ(sphere.fileName, "unit_map2_sphere.png");
  ASSERT_EQ(sphere.image.width, 4);
  EXPECT_EQ(px(sphere.image, 2, 1), (std::array<int, 3>{255, 0, 0}));
  EXPECT_NE(e.pov.find("\"unit_map2_sphere.png\" gamma 1 map_type 1"), std::string::npos);
}

TEST(PovExport, BoundingVolumeBecomesBoundedBy) {
  Scene s = smallScene();
  s.prims.push_back(prim('B', placed({900, 900, 900}, {0, 0, -400}), 0));
  s.objects[0].boundPrim = 4;
  const std::string pov = exportPov(s).pov;
  const auto at = pov.find("bounded_by {  // the object's bounding volume, prim 4");
  ASSERT_NE(at, std::string::npos) << pov;
  EXPECT_NE(pov.find("matrix <900, 0, 0, 0, 900, 0, 0, 0, 900, 0, 0, -400>", at),
            std::string::npos);
  EXPECT_LT(at, pov.find("// Object 2"));
}

TEST(PovExport, PyramidIsAClosedSolidThroughItsCorners) {
  Scene s;
  s.prims.push_back(prim('Y', identity4(), 0));
  SceneObject o;
  o.number = 1;
  o.entries = {{'P', 0, 0}};
  s.objects.push_back(o);
  const std::string pov = exportPov(s).pov;
  // Each plane  n . p = d  passes through its face's corners and the apex.
  const std::regex plane(R"(plane \{ <([^>]*)>, ([^ ]+) \})");
  int planes = 0;
  for (auto it = std::sregex_iterator(pov.begin(), pov.end(), plane); it != std::sregex_iterator();
       ++it) {
    const auto n = numbersIn((*it)[1].str());
    const double d = std::strtod((*it)[2].str().c_str(), nullptr);
    ASSERT_EQ(n.size(), 3u);
    int on = 0;
    for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 1}, Vec3{1, 0, 1}, Vec3{0.5, 1, 0.5}}) {
      const double v = n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - d;
      EXPECT_LE(v, 1e-12);  // every corner inside or on
      on += std::abs(v) < 1e-12;
    }
    EXPECT_EQ(on, planes == 0 ? 4 : 3);  // the base holds four corners, a side two and the apex
    ++planes;
  }
  EXPECT_EQ(planes, 5);
}

// M32: a subtree used twice is written once, as a #declare before the
// object, and seen from both sides it gets two declarations (the subtracted
// use shows its inside). Object 1: e1 = (p0 + p1); root = e2 - e1 with e2 =
// (e1 & e1): e1 is used three times (twice by e2, once as a subtracted
// right operand).
TEST(PovExport, SharedSubtreeIsDeclaredOnce) {
  Scene s = smallScene();
  s.objects[0].entries = {{'-', 2, 1}, {'+', 3, 4}, {'&', 1, 1}, {'P', 0, 0}, {'P', 1, 0}};
  const std::string pov = exportPov(s).pov;
  const auto count = [&](const std::string& key) {
    std::size_t n = 0;
    for (auto at = pov.find(key); at != std::string::npos; at = pov.find(key, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("#declare PrimeO1_E1 ="), 1u) << pov;
  EXPECT_EQ(count("#declare PrimeO1_E1_In ="), 1u) << pov;
  EXPECT_EQ(count("object { PrimeO1_E1 }"), 2u) << pov;     // both operands of e2
  EXPECT_EQ(count("object { PrimeO1_E1_In }"), 1u) << pov;  // the subtracted use
  // e1's two leaves are written once per declaration: 2 boxes in all.
  EXPECT_EQ(count("box {"), 2u) << pov;
  // Declared before use.
  EXPECT_LT(pov.find("#declare PrimeO1_E1 ="), pov.find("object { PrimeO1_E1 }"));
}

// M31, M32: 30 nested doublings would be 2^30 leaves written out; a 20,000
// entry chain recursed 20,000 deep and indented quadratically. Both now
// give text linear in the entries, without recursion.
TEST(PovExport, NestedSharingAndDeepChainsStayLinear) {
  Scene s = smallScene();
  std::vector<CsgEntry> doubling;
  for (int i = 0; i < 30; ++i) doubling.push_back({'+', i + 1, i + 1});
  doubling.push_back({'P', 0, 0});
  s.objects[0].entries = doubling;
  const std::string shared = exportPov(s).pov;
  EXPECT_LT(shared.size(), 100000u);
  EXPECT_NE(shared.find("#declare PrimeO1_E29 ="), std::string::npos);

  constexpr int kDepth = 20000;
  std::vector<CsgEntry> chain;
  for (int i = 0; i < kDepth; ++i) chain.push_back({'+', i + 1, kDepth + 1});
  chain.push_back({'P', 0, 0});
  chain.push_back({'P', 1, 0});
  s.objects[0].entries = chain;
  // (p1 is used by every level: a leaf, so it is written each time.)
  const std::string deep = exportPov(s).pov;
  EXPECT_LT(deep.size(), std::size_t{kDepth} * 1000);  // ~ 600 bytes per level
  const auto opens = static_cast<std::size_t>(std::count(deep.begin(), deep.end(), '{'));
  const auto closes = static_cast<std::size_t>(std::count(deep.begin(), deep.end(), '}'));
  EXPECT_EQ(opens, closes);
  EXPECT_NE(deep.find("  // entry 19999"), std::string::npos);
}

}  // namespace
}  // namespace prime
