// prime export-pov for CGL scenes (src/cgl/pov_export.h): the camera of the
// default view, each primitive's text, the surfaces (opaque, transparent,
// Phong, textured), lights with and without shadows, max_trace_level, and
// that the texture matrix reproduces the tracer's texel for points of a
// textured rectangle and sphere. Scenes are built from records
// (tests/cgl/unit/scene_text.h), not read.
#include "src/cgl/pov_export.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "src/cgl/primitives.h"
#include "tests/cgl/unit/scene_text.h"

namespace prime::cgl {
namespace {

using test::flat;

// One light (infinity, straight up, dw 0.001, D6500), an ambience, one
// surface, and the nodes given (numbers.root = 1).
SceneFile fileWith(const SurfaceRecord& surface, std::vector<NodeRecord> nodes,
                   std::vector<Vec3> vertices = {}) {
  SceneFile f = test::emptyScene();
  f.surfaces.push_back(surface);
  f.vertices = std::move(vertices);
  f.ambience.ka = 0.0005;
  f.ambience.colour = test::d6500();
  f.lights.push_back(test::infinityLight({0, 1, 0}, 0.001, test::d6500()));
  f.nodes = std::move(nodes);
  f.numbers.root = 1;
  return f;
}

PovExport exportOf(const SceneFile& f, const BuildOptions& build = {}) {
  PovExportOptions o;
  o.program = f.program;
  return exportPov(buildScene(f, build), o);
}

// The object statement of the export (the line after "// node ...").
std::string objectLine(const PovExport& e) {
  const auto at = e.pov.find("// node ");
  EXPECT_NE(at, std::string::npos) << e.pov;
  const auto start = e.pov.find('\n', at) + 1;
  return e.pov.substr(start, e.pov.find('\n', start) - start);
}

std::vector<double> numbersIn(const std::string& text) {
  static const std::regex number(R"(-?[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?)");
  std::vector<double> out;
  for (std::sregex_iterator i(text.begin(), text.end(), number), end; i != end; ++i)
    out.push_back(std::stod(i->str()));
  return out;
}

TEST(CglPovExport, CameraOfTheDefaultView) {
  // Appendix 1 section 6's defaults: eye (0, 0, 3.5), sight (0, 0, -3.5), up
  // (0, 1, 0), dist 2.5, viewport 2 x 2. right = up x sight = (-1, 0, 0)
  // (left-handed: screen-right is -x), X = (2/512) right, Y = (2/512) up, S =
  // 2.5 sight. POV-Ray: right = 512 X = (-2, 0, 0), up = (0, 2, 0).
  const Scene s = buildScene(test::emptyScene());
  const PovCamera centre = povCamera(s.camera, false);
  EXPECT_EQ(povVector(centre.location), "<0, 0, 3.5>");
  EXPECT_EQ(povVector(centre.direction), "<0, 0, -2.5>");
  EXPECT_EQ(povVector(centre.right), "<-2, 0, 0>");
  EXPECT_EQ(povVector(centre.up), "<0, 2, 0>");
  // aalevel 0: the corner ray, half a pixel (X/2 + Y/2) back:
  // (0, 0, -2.5) - (-1/512, 0, 0) - (0, 1/512, 0).
  const PovCamera corner = povCamera(s.camera, true);
  EXPECT_EQ(povVector(corner.direction), "<0.001953125, -0.001953125, -2.5>");
  // POV-Ray's ray for column i, row r is direction + ((i + .5)/512 - .5)
  // right + (.5 - (r + .5)/512) up; it must be CGL's ray through (i, 511 - r).
  for (int i : {0, 100, 511})
    for (int r : {0, 300, 511}) {
      const Vec3 d = corner.direction + corner.right * ((i + 0.5) / 512 - 0.5) +
                     corner.up * (0.5 - (r + 0.5) / 512);
      const Ray cgl = s.camera.primaryRay(i, 511 - r);
      const Vec3 dn = normalized(d);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(dn[k], cgl.d[k], 1e-15) << i << " " << r;
    }
  // The export writes them.
  PovExportOptions o;
  o.program.aalevel = 0;
  const PovExport e = exportPov(s, o);
  EXPECT_NE(e.pov.find("location <0, 0, 3.5>\n  direction <0.001953125, -0.001953125, -2.5>\n"
                       "  right <-2, 0, 0>\n  up <0, 2, 0>"),
            std::string::npos)
      << e.pov;
  EXPECT_NE(e.povArgs.find("-A"), std::string::npos);
}

TEST(CglPovExport, Sphere) {
  // A flat reflectance 0.5 is 0.5 in every channel under any light:
  // L(0.5 I)/L(I). k_d 0.8; ambient the constant 1.0.
  const PovExport e =
      exportOf(fileWith(test::lambert(0.8, 0.5), {test::sphere(1, 0, 1, {0.25, -0.5, 1}, 0.3)}));
  EXPECT_EQ(objectLine(e),
            "sphere { <0.25, -0.5, 1>, 0.3 texture { pigment { rgb <0.5, 0.5, 0.5> } "
            "finish { ambient 1 diffuse 0.8 } } }");
  EXPECT_EQ(e.objects, 1);
  EXPECT_EQ(e.mainLight, 0);
}

TEST(CglPovExport, OpenCylinder) {
  const PovExport e = exportOf(fileWith(
      test::lambert(1, 0.5), {test::cylinder(1, 0, 1, 0.25, 1, 2)}, {{0, 0, 0}, {0, 1.5, -2}}));
  EXPECT_EQ(objectLine(e).substr(0, 46), "cylinder { <0, 0, 0>, <0, 1.5, -2>, 0.25 open ");
}

TEST(CglPovExport, RectangleAndTriangleCorners) {
  // The floor of Figure 59 (vertices 1-4), in the order 1 2 3 4: the corners
  // recovered from the edge tests are the vertices.
  const PovExport e = exportOf(fileWith(
      test::lambert(1, 0.5), {test::polygon(1, 0, 1, {1, 2, 3, 4})}, test::floorVertices()));
  const std::string line = objectLine(e);
  ASSERT_EQ(line.rfind("polygon { 5, ", 0), 0u) << line;
  const std::vector<double> n = numbersIn(line.substr(0, line.find("texture")));
  const double expected[] = {5, -1, 0, -1, -1, 0, 1, 1, 0, 1, 1, 0, -1, -1, 0, -1};
  ASSERT_EQ(n.size(), std::size(expected)) << line;
  for (std::size_t i = 0; i < n.size(); ++i) EXPECT_NEAR(n[i], expected[i], 1e-15) << line;

  // A triangle, and a skewed rectangle (a parallelogram): every corner back.
  const std::vector<Vec3> v = {{0, 0, 0}, {2, 0.5, 0}, {2.5, 1.5, 0.25}, {0.5, 1, 0.25}};
  const Scene tri =
      buildScene(fileWith(test::lambert(1, 0.5), {test::polygon(1, 0, 1, {1, 2, 3})}, v));
  // The third corner is solved from the edge tests: equal to the vertex
  // within rounding.
  const std::string t = povGeometry(tri.objects[0]);
  EXPECT_EQ(t.rfind("triangle { <0, 0, 0>, <2, 0.5, 0>, <", 0), 0u) << t;
  const std::vector<double> tn = numbersIn(t);
  ASSERT_EQ(tn.size(), 9u) << t;
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(tn[6 + j], v[2][j], 1e-14) << t;
  const Scene quad =
      buildScene(fileWith(test::lambert(1, 0.5), {test::polygon(1, 0, 1, {1, 2, 3, 4})}, v));
  const auto c = polygonCorners(quad.objects[0]);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(c[k][j], v[k][j], 1e-14) << k;
}

TEST(CglPovExport, TransparentSurface) {
  // k_t 0.75, index 1.5: transmit 0.75; POV-Ray scales diffuse and ambient by
  // 1 - 0.75, so the finish has them times 4 (diffuse 0.5 -> 2); the ior is
  // the index; no_shadow because section 9.3's shadow rays ignore objects
  // that are not opaque. k_r 0.25: reflection.
  const PovExport e = exportOf(fileWith(test::phong(0.5, 0.7, 20, 0.5, 0.25, 0.75, 1.5),
                                        {test::sphere(1, 0, 1, {0, 0, 0}, 1)}));
  EXPECT_EQ(objectLine(e),
            "sphere { <0, 0, 0>, 1 texture { pigment { rgb <0.5, 0.5, 0.5> transmit 0.75 } "
            "finish { ambient 4 diffuse 2 phong 0.7 phong_size 20 reflection { 0.25 } } } "
            "interior { ior 1.5 } no_shadow }");
  // An opaque surface casts shadows.
  const PovExport opaque =
      exportOf(fileWith(test::lambert(1, 0.5), {test::sphere(1, 0, 1, {0, 0, 0}, 1)}));
  EXPECT_EQ(objectLine(opaque).find("no_shadow"), std::string::npos);
}

TEST(CglPovExport, LightsShadowlessWhenShadowsAreOff) {
  SceneFile f = fileWith(test::lambert(1, 0.5), {test::sphere(1, 0, 1, {0, 0, 0}, 1)});
  LightRecord inscene = test::infinityLight({1, 2, 3}, 0.002, test::d6500());
  inscene.kind = LightKind::InScene;
  f.lights.push_back(inscene);
  const PovExport off = exportOf(f);
  EXPECT_EQ(off.lights, 2);
  // The infinity light straight up: a parallel light from far above; the
  // in-scene light a point light at its position.
  EXPECT_NE(off.pov.find("light_source { <0, 1e+07, 0> rgb"), std::string::npos) << off.pov;
  EXPECT_NE(off.pov.find("parallel point_at <0, 0, 0> shadowless }"), std::string::npos);
  EXPECT_NE(off.pov.find("light_source { <1, 2, 3> rgb"), std::string::npos);
  // The in-scene light has dw 0.002 > 0.001: the main light.
  EXPECT_EQ(off.mainLight, 1);
  const auto count = [](const std::string& s, const std::string& w) {
    int n = 0;
    for (auto p = s.find(w); p != std::string::npos; p = s.find(w, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(off.pov, "shadowless"), 2);
  f.program.shadows = true;
  EXPECT_EQ(count(exportOf(f).pov, "shadowless"), 0);
  // The light's colour is L(I dw)/255: D6500 times 0.002 against times 0.001.
  const Rgb a = povRgb(inscene.colour, Phosphors::Electrohome);
  EXPECT_GT(a[1], 0.0);
}

TEST(CglPovExport, MaxTraceLevelIsDepthPlusOne) {
  SceneFile f = fileWith(test::lambert(1, 0.5), {test::sphere(1, 0, 1, {0, 0, 0}, 1)});
  // Figure 41 (CGL-E42): depth 0 traces primary rays only (POV-Ray's level
  // 1); depth 3 three generations more.
  EXPECT_NE(exportOf(f).pov.find("max_trace_level 1 "), std::string::npos);
  f.program.depth = 3;
  EXPECT_NE(exportOf(f).pov.find("max_trace_level 4 "), std::string::npos);
  EXPECT_NE(exportOf(f).pov.find("adc_bailout 0 "), std::string::npos);
}

TEST(CglPovExport, WindowAndAntiAliasingOptions) {
  // Figure 59's window: xleft 31, xright 480, yhigh 286 (ylow 0); aalevel
  // 2, aathreshold 40: +A 40/255 with 3 x 3 samples.
  SceneFile f = test::checkerboardScene();
  BuildOptions b;
  b.textures.emplace_back("checkerboard", test::checkerboardTexture());
  EXPECT_EQ(exportOf(f, b).povArgs,
            "+W512 +H512 +SC0.060546875 +EC0.939453125 +SR0.439453125 +ER1 +A0.1569 +AM1 +R3");
}

TEST(CglPovExport, PigmentUnderTheMainLight) {
  // pigment * L(I) = L(D * I) per channel, for a reflectance that is not flat.
  Spectrum d{};
  for (int k = 0; k < kSpectrumSamples; ++k) d[k] = 0.1 + 0.02 * k;
  const Spectrum light = test::d6500();
  const Rgb p = pigmentUnder(d, light, Phosphors::Electrohome);
  Spectrum lit{};
  for (int k = 0; k < kSpectrumSamples; ++k) lit[k] = d[k] * light[k];
  const Rgb want = povRgb(lit, Phosphors::Electrohome), l = povRgb(light, Phosphors::Electrohome);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k] * l[k], want[k], 1e-12 * std::fabs(want[k]));
  // Reddish: more red than blue.
  EXPECT_GT(p[0], p[2]);
}

// The image_map pixel POV-Ray takes for the world point P under the export's
// matrix: local = M^-1 P, column floor(512 frac(x)), row from the top
// floor(512 (1 - frac(y))) (row 0 at y just below 1).
struct Texel {
  int row, column;
};
Texel povTexel(const std::string& line, const Vec3& p) {
  const auto at = line.find("matrix <");
  EXPECT_NE(at, std::string::npos) << line;
  const std::vector<double> m = numbersIn(line.substr(at, line.find('>', at) - at));
  EXPECT_EQ(m.size(), 12u);
  // P = x row0 + y row1 + z row2 + row3: solve by Cramer.
  const Vec3 r0{m[0], m[1], m[2]}, r1{m[3], m[4], m[5]}, r2{m[6], m[7], m[8]};
  const Vec3 q = p - Vec3{m[9], m[10], m[11]};
  const double det = dot(r0, cross(r1, r2));
  const double x = dot(q, cross(r1, r2)) / det, y = dot(r0, cross(q, r2)) / det;
  const double fx = x - std::floor(x), fy = y - std::floor(y);
  return {static_cast<int>(std::floor(512 * (1 - fy))) % 512,
          static_cast<int>(std::floor(512 * fx))};
}

TEST(CglPovExport, TextureMatrixGivesTheTracersTexel) {
  BuildOptions b;
  b.textures.emplace_back("checkerboard", test::checkerboardTexture());
  SurfaceRecord tex = test::lambert(1.0, 0.0);
  tex.textured = true;
  tex.texture = "checkerboard";
  tex.umod = 2.0;
  tex.vmod = 3.0;
  // A rectangle (Figure 59's floor) and a sphere with axes z, x.
  NodeRecord ball = test::sphere(1, 0, 1, {0.2, 0.1, -0.3}, 0.7);
  ball.textureAxis1 = 'z';
  ball.textureAxis2 = 'x';
  const std::vector<std::pair<std::vector<NodeRecord>, std::vector<Vec3>>> cases = {
      {{test::polygon(1, 0, 1, {1, 2, 3, 4})}, test::floorVertices()}, {{ball}, {}}};
  for (const auto& [nodes, vertices] : cases) {
    const SceneFile f = fileWith(tex, nodes, vertices);
    const Scene s = buildScene(f, b);
    PovExportOptions o;
    const PovExport e = exportPov(s, o);
    ASSERT_EQ(e.images.size(), 1u);
    EXPECT_EQ(e.images[0].file, "scene-texture1.png");
    const std::string line = objectLine(e);
    EXPECT_NE(line.find("image_map { png \"scene-texture1.png\" gamma 1.0 }"), std::string::npos)
        << line;
    const Object& obj = s.objects[0];
    int agree = 0, tried = 0;
    // Points on the surface away from texel edges (checked below).
    for (int i = 0; i < 40; ++i) {
      Vec3 p{};
      if (obj.kind == ObjectKind::Polygon) {
        p = {-0.95 + 0.047 * i, 0.0, 0.9 - 0.043 * i};
      } else {
        const double th = 0.3 + 0.07 * i, ph = 0.2 + 0.13 * i;
        p = obj.c +
            Vec3{std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)} * obj.r;
      }
      const Vec3 n = normalAt(obj, p, 0.0);
      double u = 0, v = 0;
      textureUv(obj, p, n, 0.0, u, v);
      // Skip points within 1e-6 of a texel edge, where rounding decides.
      const double fu = 512 * u * tex.umod, fv = 512 * v * tex.vmod;
      if (std::fabs(fu - std::round(fu)) < 1e-6 || std::fabs(fv - std::round(fv)) < 1e-6) continue;
      ++tried;
      const Texel t = povTexel(line, p);
      if (t.row == textureIndex(u, tex.umod) && t.column == textureIndex(v, tex.vmod))
        ++agree;
      else
        ADD_FAILURE() << "point " << i << ": POV-Ray texel (" << t.row << ", " << t.column
                      << "), CGL (" << textureIndex(u, tex.umod) << ", "
                      << textureIndex(v, tex.vmod) << ")";
    }
    EXPECT_GT(tried, 30);
    EXPECT_EQ(agree, tried);
  }
}

TEST(CglPovExport, TextureImageIsThePigmentOfEachTexel) {
  BuildOptions b;
  b.textures.emplace_back("checkerboard", test::checkerboardTexture());
  SurfaceRecord tex = test::lambert(1.0, 0.0);
  tex.textured = true;
  tex.texture = "checkerboard";
  const Scene s =
      buildScene(fileWith(tex, {test::polygon(1, 0, 1, {1, 2, 3, 4})}, test::floorVertices()), b);
  PovExportOptions o;
  o.textureStem = "floor";
  const PovExport e = exportPov(s, o);
  ASSERT_EQ(e.images.size(), 1u);
  const PovImage& img = e.images[0];
  EXPECT_EQ(img.file, "floor-texture1.png");
  // Texel (0, 0) is green (30, 160, 40) in the stand-in; its pigment under
  // D6500, divided by the image's scale, is the PNG's byte.
  Spectrum d{};
  for (int k = 0; k < 3; ++k) d[Texture::kSamples[k]] = s.textures[0].texels[0][k];
  const Rgb p = pigmentUnder(d, test::d6500(), Phosphors::Electrohome);
  const std::uint32_t w = img.frame.words[0];
  EXPECT_EQ(greenOf(w),
            static_cast<int>(std::lround(std::clamp(p[1] / img.scale, 0.0, 1.0) * 255)));
  EXPECT_GT(greenOf(w), redOf(w));
  EXPECT_GE(img.scale, 1.0);
  // The finish multiplies the scale back.
  EXPECT_NE(objectLine(e).find("finish { ambient " + povNumber(img.scale) + " diffuse " +
                               povNumber(img.scale)),
            std::string::npos)
      << objectLine(e);
}

TEST(CglPovExport, SuperBoxesAreNotWritten) {
  SceneFile f = fileWith(test::lambert(1, 0.5),
                         {test::node(1, NodeKind::Box, 2, 0), test::sphere(2, 3, 1, {0, 0, 0}, 1),
                          test::sphere(3, 0, 1, {2, 0, 0}, 1)});
  const PovExport e = exportOf(f);
  EXPECT_EQ(e.objects, 2);
  EXPECT_EQ(e.boxesOmitted, 1);
  EXPECT_NE(e.pov.find("1 super box(es) not written"), std::string::npos);
}

}  // namespace
}  // namespace prime::cgl
