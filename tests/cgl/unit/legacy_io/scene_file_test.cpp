// The CGL scene-description file reader (legacy_io/cgl/scene_file.h; Sweeney,
// "The Waterloo CGL Ray Tracing Package", 1985, Appendix 1): a complete scene
// read field by field, one located error per error class of every section,
// the document's two damaged copies of the checkerboard scene (strict
// refusal, lenient reading with its list of repairs), the 9-cubes DAG with
// shared subtrees, a deep chain, and looksLikeCgl.
#include "legacy_io/cgl/scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace prime::cgl {
namespace {

using ::testing::HasSubstr;

const std::string kScenes = CGL_SCENES;

// A colour-vector of 33 equal samples in the manual's layout (10, 10, 10, 3).
std::string flat(double v) {
  std::ostringstream s;
  for (int k = 0; k < 33; ++k) s << v << (k == 9 || k == 19 || k == 29 || k == 32 ? "\n" : " ");
  return s.str();
}
// Samples 1..33 as k / 100 (sample k is k/100), in the manual's layout.
std::string ramp() {
  std::ostringstream s;
  for (int k = 1; k <= 33; ++k)
    s << k / 100.0 << (k == 10 || k == 20 || k == 30 || k == 33 ? "\n" : " ");
  return s.str();
}

// A scene assembled from its sections; the counts of the first record are
// computed from the parts, each part one record (possibly several lines).
struct Parts {
  std::vector<std::string> program = {"1 depth 3"};
  std::vector<std::string> display = {"1 eye 0.0 0.0 3.5"};
  std::vector<std::string> vertices = {"1 -1 0 -1", "2 -1 0 1", "3 1 0 1", "4 1 0 -1"};
  std::vector<std::string> surfaces = {"1 lambert normal 0.0 0.0 0.0\n7.0\n" + flat(0.5)};
  std::string ambience = "0.00050\n" + flat(50.0);
  std::vector<std::string> lights = {"1 infinity 1.0 1.0 1.0 0.0006\n" + flat(100.0)};
  std::vector<std::string> nodes = {"1 polygon 00 00 1 4 1 2 3 4"};
  int root = 1;
  std::string text() const {
    std::ostringstream s;
    s << "* a test scene\n"
      << program.size() << " " << display.size() << " " << vertices.size() << " " << surfaces.size()
      << " " << lights.size() << " " << nodes.size() << " " << root << "\n";
    for (const auto* section : {&program, &display, &vertices, &surfaces})
      for (const auto& r : *section) s << r << (r.ends_with("\n") ? "" : "\n");
    s << ambience;
    for (const auto* section : {&lights, &nodes})
      for (const auto& r : *section) s << r << (r.ends_with("\n") ? "" : "\n");
    return s.str();
  }
};

// The 1-based line of `text` holding `needle` (which must be on one line).
int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

io::InputError readError(const std::string& text, const ReadOptions& options = {}) {
  try {
    readScene(text, "t.cgl", options);
  } catch (const io::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return io::InputError({}, "none");
}

// The file, line, field, expected and found of an error, and the message
// naming all of them.
void expectError(const io::InputError& e, int line, const std::string& field,
                 const std::string& expected, const std::string& found) {
  SCOPED_TRACE(e.what());
  EXPECT_EQ(e.where().file, "t.cgl");
  EXPECT_EQ(e.where().line, line);
  EXPECT_THAT(e.field(), HasSubstr(field));
  EXPECT_THAT(e.expected(), HasSubstr(expected));
  EXPECT_THAT(e.found(), HasSubstr(found));
  EXPECT_THAT(std::string(e.what()), HasSubstr("t.cgl:" + std::to_string(line)));
  EXPECT_THAT(std::string(e.what()), HasSubstr(": expected "));
}

// The first repair (or warning) mentioning `what`, on `line`.
bool hasNote(const std::vector<Repair>& notes, int line, const std::string& what) {
  for (const auto& r : notes)
    if (r.where.line == line && r.what.find(what) != std::string::npos) return true;
  return false;
}
std::string listed(const std::vector<Repair>& notes) {
  std::string s;
  for (const auto& r : notes) s += io::describe(r.where) + ": " + r.what + "\n";
  return s;
}

// ---------------------------------------------------------------------------
// A complete scene, every field.

std::string cookSurface(int n) {
  std::string s = std::to_string(n) + " cook normal 0.8 0.0 0.0\n0.0\n" + ramp() + "1.0 0.3\n";
  for (int a = 0; a < kFresnelAngles; ++a) s += flat(a / 100.0);
  return s;
}

TEST(CglSceneFile, CompleteSceneEveryField) {
  Parts p;
  p.program = {"1 output /tmp/out.rle",
               "2 yhigh 286",
               "3 ylow 02",
               "4 xleft 31",
               "5 xright 480",
               "6 depth 3",
               "7 shadows",
               "8 memory 6",
               "9 brightness 0.8",
               "10 background 10 20 255 ignored",
               "11 quiet",
               "12 aathreshold 40.0",
               "13 aalevel 4"};
  // Counts of parameters need not be consecutive ("restrictions are relaxed").
  p.display = {"1 eye 1.0 2.0 3.0", "7 sight towards 0.0 0.0 0.0", "3 up 0.0 0.0 1.0", "3 dist 2.0",
               "9 viewport 1.5 2.5"};
  p.surfaces = {"1 lambert normal 0.0 0.0 0.0\n7.0\n" + ramp(),
                "2 lambert textured 0.1 0.0 1.0\n5.0\n/u/majsweeney/textures/checkerboard 1 2\n",
                "3 phong normal 0.6 0.0 0.0\n7.0 3.0 25.0 trailing words\n" + flat(1.2),
                "4 phong textured 0.0 0.8 1.2\n7.0 1.0 15.0\nlast 2.0 0.5\n", cookSurface(5)};
  p.lights = {"1 infinity 0.6 1.0 0.6 0.0006\n" + flat(100.0),
              "2 inscene +0.1 -0.0 .5 0.001\n" + ramp()};
  p.nodes = {"1 rotate 02 00 x -22.0",
             "2 translate 03 00 0.0 -0.8 0.0",
             "3 scale 04 00 0.5 0.5 0.5",
             "4 box 05 00",
             "5 sphere 00 06 3 0.3 -0.18 0.0 0.16 z x",
             "6 cylinder 00 07 1 0.15 1 2",
             "7 polygon 00 08 2 3 4 3 2",
             "8 fractal 00 09 1 5 1.3 0.5 9772 free",
             "9 dummy 00 10 4 24 24 26 27",
             "10 spline 00 00 4 2 single 3 closed 2 0.5\n1 0 0 0\n2 1 0 0\n1 0 1 0\n2 1 1 0\n"
             "1 0 2 0\n2 1 2 0"};
  const std::string text = p.text();
  const SceneFile f = readScene(text, "t.cgl");
  EXPECT_EQ(f.path, "t.cgl");
  EXPECT_TRUE(f.repairs.empty()) << listed(f.repairs);
  EXPECT_EQ(f.numbers.programParameters, 13);
  EXPECT_EQ(f.numbers.displayParameters, 5);
  EXPECT_EQ(f.numbers.vertices, 4);
  EXPECT_EQ(f.numbers.surfaces, 5);
  EXPECT_EQ(f.numbers.lights, 2);
  EXPECT_EQ(f.numbers.nodes, 10);
  EXPECT_EQ(f.numbers.root, 1);
  EXPECT_EQ(f.numbers.where.line, 2);

  const auto& g = f.program;
  EXPECT_EQ(g.output, "/tmp/out.rle");
  EXPECT_EQ(g.yhigh, 286);
  EXPECT_EQ(g.ylow, 2);  // "02": leading zeros are digits
  EXPECT_EQ(g.xleft, 31);
  EXPECT_EQ(g.xright, 480);
  EXPECT_EQ(g.depth, 3);
  EXPECT_TRUE(g.shadows);
  EXPECT_EQ(g.memory, 6);
  EXPECT_EQ(g.brightness, 0.8);
  EXPECT_EQ(g.background, (std::array<int, 3>{10, 20, 255}));
  EXPECT_TRUE(g.quiet);
  EXPECT_EQ(g.aathreshold, 40.0);
  EXPECT_EQ(g.aalevel, 4);
  EXPECT_TRUE(g.given.output && g.given.yhigh && g.given.ylow && g.given.xleft && g.given.xright &&
              g.given.depth && g.given.shadows && g.given.memory && g.given.brightness &&
              g.given.background && g.given.quiet && g.given.aathreshold && g.given.aalevel);
  // brightness and background together: read, with a warning (CGL-Q14).
  EXPECT_TRUE(hasNote(f.warnings, 2, "both brightness and background")) << listed(f.warnings);

  const auto& d = f.display;
  EXPECT_EQ(d.eye, (Vec3{1, 2, 3}));
  EXPECT_EQ(d.sight, (Vec3{-1, -2, -3}));  // towards the origin: origin - eye
  EXPECT_EQ(d.up, (Vec3{0, 0, 1}));
  EXPECT_EQ(d.dist, 2.0);
  EXPECT_EQ(d.viewportHeight, 1.5);
  EXPECT_EQ(d.viewportWidth, 2.5);

  ASSERT_EQ(f.vertices.size(), 4u);
  EXPECT_EQ(f.vertices[1], (Vec3{-1, 0, 1}));

  ASSERT_EQ(f.surfaces.size(), 5u);
  const auto& s1 = f.surfaces[0];
  EXPECT_EQ(s1.model, ShadingModel::Lambert);
  EXPECT_FALSE(s1.textured);
  EXPECT_EQ(s1.diffuse, 7.0);
  EXPECT_EQ(s1.colour[0], 0.01);
  EXPECT_EQ(s1.colour[32], 0.33);
  EXPECT_EQ(s1.where.line, lineOf(text, "1 lambert normal"));
  const auto& s2 = f.surfaces[1];
  EXPECT_TRUE(s2.textured);
  EXPECT_EQ(s2.reflect, 0.1);
  EXPECT_EQ(s2.index, 1.0);
  EXPECT_EQ(s2.diffuse, 5.0);
  EXPECT_EQ(s2.texture, "/u/majsweeney/textures/checkerboard");
  EXPECT_FALSE(s2.textureLast);
  EXPECT_EQ(s2.umod, 1.0);
  EXPECT_EQ(s2.vmod, 2.0);
  const auto& s3 = f.surfaces[2];
  EXPECT_EQ(s3.model, ShadingModel::Phong);
  EXPECT_EQ(s3.reflect, 0.6);
  EXPECT_EQ(s3.diffuse, 7.0);
  EXPECT_EQ(s3.specular, 3.0);
  EXPECT_EQ(s3.exponent, 25.0);
  EXPECT_EQ(s3.colour[17], 1.2);  // above 1: allowed (the manual's own phong red has 1.2)
  const auto& s4 = f.surfaces[3];
  EXPECT_TRUE(s4.textured);
  EXPECT_EQ(s4.refract, 0.8);
  EXPECT_EQ(s4.index, 1.2);
  EXPECT_EQ(s4.texture, "/u/majsweeney/textures/checkerboard");  // `last`, resolved
  EXPECT_TRUE(s4.textureLast);
  EXPECT_EQ(s4.umod, 2.0);
  EXPECT_EQ(s4.vmod, 0.5);
  const auto& s5 = f.surfaces[4];
  EXPECT_EQ(s5.model, ShadingModel::Cook);
  EXPECT_EQ(s5.reflect, 0.8);
  EXPECT_EQ(s5.diffuse, 0.0);
  EXPECT_EQ(s5.colour[4], 0.05);
  EXPECT_EQ(s5.specular, 1.0);
  EXPECT_EQ(s5.m, 0.3);
  ASSERT_EQ(s5.fresnel.size(), 66u);
  EXPECT_EQ(s5.fresnel[0][0], 0.0);
  EXPECT_EQ(s5.fresnel[65][32], 0.65);

  EXPECT_EQ(f.ambience.ka, 0.0005);
  EXPECT_EQ(f.ambience.colour[20], 50.0);

  ASSERT_EQ(f.lights.size(), 2u);
  EXPECT_EQ(f.lights[0].kind, LightKind::Infinity);
  EXPECT_EQ(f.lights[0].xyz, (Vec3{0.6, 1.0, 0.6}));
  EXPECT_EQ(f.lights[0].dw, 0.0006);
  EXPECT_EQ(f.lights[0].colour[32], 100.0);
  EXPECT_EQ(f.lights[1].kind, LightKind::InScene);
  EXPECT_EQ(f.lights[1].xyz, (Vec3{0.1, 0.0, 0.5}));  // "+0.1 -0.0 .5"
  EXPECT_TRUE(std::signbit(f.lights[1].xyz[1]));
  EXPECT_EQ(f.lights[1].colour[9], 0.1);

  ASSERT_EQ(f.nodes.size(), 10u);
  const auto& n = f.nodes;
  EXPECT_EQ(n[0].kind, NodeKind::Rotate);
  EXPECT_EQ(n[0].down, 2);
  EXPECT_EQ(n[0].right, 0);
  EXPECT_EQ(n[0].axis, 'x');
  EXPECT_EQ(n[0].theta, -22.0);
  EXPECT_EQ(n[1].kind, NodeKind::Translate);
  EXPECT_EQ(n[1].xyz, (Vec3{0.0, -0.8, 0.0}));
  EXPECT_EQ(n[2].kind, NodeKind::Scale);
  EXPECT_FALSE(n[2].ignored);
  EXPECT_EQ(n[3].kind, NodeKind::Box);
  EXPECT_EQ(n[3].down, 5);
  EXPECT_EQ(n[4].kind, NodeKind::Sphere);
  EXPECT_EQ(n[4].surface, 3);
  EXPECT_EQ(n[4].xyz, (Vec3{0.3, -0.18, 0.0}));
  EXPECT_EQ(n[4].radius, 0.16);
  EXPECT_EQ(n[4].textureAxis1, 'z');
  EXPECT_EQ(n[4].textureAxis2, 'x');
  EXPECT_EQ(n[4].right, 6);
  EXPECT_EQ(n[5].kind, NodeKind::Cylinder);
  EXPECT_EQ(n[5].radius, 0.15);
  EXPECT_EQ(n[5].vertices, (std::vector<int>{1, 2}));
  EXPECT_EQ(n[6].kind, NodeKind::Polygon);
  EXPECT_EQ(n[6].surface, 2);
  EXPECT_EQ(n[6].vertices, (std::vector<int>{4, 3, 2}));
  EXPECT_EQ(n[7].kind, NodeKind::Fractal);
  EXPECT_EQ(n[7].divisions, 5);
  EXPECT_EQ(n[7].h, 1.3);
  EXPECT_EQ(n[7].offset, 0.5);
  EXPECT_EQ(n[7].seed, 9772);
  EXPECT_FALSE(n[7].constrained);
  EXPECT_EQ(n[8].kind, NodeKind::Dummy);  // "4 24 24 26 27" after down/right: ignored
  EXPECT_EQ(n[8].right, 10);
  EXPECT_EQ(n[9].kind, NodeKind::Spline);
  EXPECT_EQ(n[9].surface, 4);
  EXPECT_EQ(n[9].nu, 2);
  EXPECT_EQ(n[9].uEnd, EndCondition::Single);
  EXPECT_EQ(n[9].nv, 3);
  EXPECT_EQ(n[9].vEnd, EndCondition::Closed);
  EXPECT_EQ(n[9].divisions, 2);
  EXPECT_EQ(n[9].overlap, 0.5);
  ASSERT_EQ(n[9].controls.size(), 6u);
  EXPECT_EQ(n[9].controls[3], (Vec3{1, 1, 0}));  // row v = 1, column u = 1
  EXPECT_EQ(n[9].where.line, lineOf(text, "10 spline"));
  EXPECT_EQ(n[9].number, 10);
}

TEST(CglSceneFile, DocumentSplineTube) {
  // Appendix 1 section 13's spline node, verbatim: the u count restarts at 1
  // in each of the 5 groups of 4 (CGL-Q6).
  Parts p;
  p.nodes = {
      "1 spline 00 00 1 4 closed 5 double 8 0.6\n"
      "1 -0.2 0.8 -0.2\n2 -0.2 0.8 0.2\n3 0.2 0.8 0.2\n4 0.2 0.8 -0.2\n"
      "1 -0.3 0.6 -0.3\n2 -0.3 0.6 0.3\n3 0.3 0.6 0.3\n4 0.3 0.6 -0.3\n"
      "1 -0.4 0.4 -0.4\n2 -0.4 0.4 0.4\n3 0.4 0.4 0.4\n4 0.4 0.4 -0.4\n"
      "1 -0.3 0.2 -0.3\n2 -0.3 0.2 0.3\n3 0.3 0.2 0.3\n4 0.3 0.2 -0.3\n"
      "1 -0.2 0.0 -0.2\n2 -0.2 0.0 0.2\n3 0.2 0.0 0.2\n4 0.2 0.0 -0.2\n"};
  const SceneFile f = readScene(p.text(), "t.cgl");
  const auto& s = f.nodes[0];
  EXPECT_EQ(s.nu, 4);
  EXPECT_EQ(s.uEnd, EndCondition::Closed);
  EXPECT_EQ(s.nv, 5);
  EXPECT_EQ(s.vEnd, EndCondition::Double);
  EXPECT_EQ(s.divisions, 8);
  EXPECT_EQ(s.overlap, 0.6);
  ASSERT_EQ(s.controls.size(), 20u);
  EXPECT_EQ(s.controls[2 * 4 + 2], (Vec3{0.4, 0.4, 0.4}));  // group 3, vertex 3
  // A running count (5 for the first vertex of group 2) is refused.
  std::string text = p.text();
  const auto at = text.find("1 -0.3 0.6 -0.3");
  text.replace(at, 1, "5");
  expectError(readError(text), lineOf(text, "5 -0.3 0.6 -0.3"),
              "control vertex 1 of group 2 of 5, field count", "the u count 1 (it restarts", "'5'");
}

TEST(CglSceneFile, DocumentCookCopperShape) {
  // Appendix 1 section 8's copper surface (the two printed Fresnel vectors,
  // then 64 more) without the OCR's bullets, blank lines and $..$ wrappers.
  const std::string normal =
      "0.0223 0.0242 0.0261 0.0280 0.0302 0.0337 0.0372 0.0407 0.0446 0.0497\n"
      "0.0547 0.0602 0.0653 0.0700 0.0748 0.0796 0.0844 0.0955 0.1066 0.1311\n"
      "0.1560 0.1757 0.1958 0.2044 0.2133 0.2174 0.2219 0.2263 0.2308 0.2330\n"
      "0.2355 0.2381 0.2403\n";
  const std::string fresnel =
      "0.0700 0.0760 0.0820 0.0880 0.0950 0.1060 0.1170 0.1280 0.1400 0.1560\n"
      "0.1720 0.1890 0.2050 0.2200 0.2350 0.2500 0.2650 0.3000 0.3350 0.4120\n"
      "0.4900 0.5520 0.6150 0.6420 0.6700 0.6830 0.6970 0.7110 0.7250 0.7320\n"
      "0.7400 0.7480 0.7550\n";
  std::string s =
      "* surface reflective copper\n1 cook normal 0.8 0.0 0.0\n0.0\n"
      "* normal reflectance vs wavelength\n" +
      normal + "1.0 0.3\n* fresnel reflectance vs wavelength & angle\n";
  for (int a = 0; a < 66; ++a) s += fresnel;
  Parts p;
  p.surfaces = {s};
  const SceneFile f = readScene(p.text(), "t.cgl");
  const auto& c = f.surfaces[0];
  EXPECT_EQ(c.colour[0], 0.0223);
  EXPECT_EQ(c.colour[32], 0.2403);
  EXPECT_EQ(c.specular, 1.0);
  EXPECT_EQ(c.m, 0.3);
  ASSERT_EQ(c.fresnel.size(), 66u);
  EXPECT_EQ(c.fresnel[1][32], 0.7550);
  // 65 Fresnel vectors: the 66th runs into the ambience's k_a and fails.
  Parts q;
  q.surfaces = {s.substr(0, s.size() - fresnel.size())};
  const std::string text = q.text();
  const auto e = readError(text);
  EXPECT_THAT(e.field(), HasSubstr("fresnel colour-vector 66 of 66"));
}

// ---------------------------------------------------------------------------
// Errors, section by section: location, field, expected, found.

TEST(CglSceneFile, NumbersOfThingsErrors) {
  expectError(readError("* c\n5 2 4 2 1 4\n"), 2, "DAG-root-node", "a scene-node number",
              "end of line");
  expectError(readError("1 2 x 4 5 6 7\n"), 1, "number-of-vertices", "a count 0 or more", "'x'");
  expectError(readError("0 0 0 0 0 0 0\n"), 1, "number-of-scene-nodes", "at least its root", "'0'");
  expectError(readError("0 0 0 0 0 2 3\n"), 1, "DAG-root-node", "1-2", "'3'");
  expectError(readError("* only a comment\n"), 1, "numbers-of-things", "a record", "end of file");
}

TEST(CglSceneFile, ProgramParameterErrors) {
  Parts p;
  p.program = {"1 detph 3"};
  std::string t = p.text();
  auto e = readError(t);
  expectError(e, 3, "program parameter 1 of 1, field keyword", "one of output, yhigh", "'detph'");
  EXPECT_THAT(e.expected(), HasSubstr("aathreshold or aalevel"));
  p.program = {"1 depth 11"};
  expectError(readError(p.text()), 3, "field depth", "0-10", "'11'");
  p.program = {"1 depth"};
  expectError(readError(p.text()), 3, "field depth", "0-10", "end of line");
  p.program = {"1 xleft 512"};
  expectError(readError(p.text()), 3, "field xleft", "0-511", "'512'");
  p.program = {"1 ylow -1"};
  expectError(readError(p.text()), 3, "field ylow", "0-511", "'-1'");
  p.program = {"1 memory 0"};
  expectError(readError(p.text()), 3, "field memory", "1 or more", "'0'");
  p.program = {"1 aalevel 3"};
  expectError(readError(p.text()), 3, "field aalevel", "one of 0, 1, 2, 4 or 8", "'3'");
  p.program = {"1 aathreshold 0.0"};
  expectError(readError(p.text()), 3, "field aathreshold", "above 0.0", "'0.0'");
  p.program = {"1 brightness 1.5"};
  expectError(readError(p.text()), 3, "field brightness", "0.0-1.0", "'1.5'");
  p.program = {"1 background 0 256 0"};
  expectError(readError(p.text()), 3, "field green", "0-255", "'256'");
  p.program = {"1 depth 2.5"};
  expectError(readError(p.text()), 3, "field depth", "0-10", "'2.5'");
  // A display record where a program parameter is due: the counts are wrong.
  p.program = {"1 eye 0 0 3"};
  e = readError(p.text());
  EXPECT_THAT(e.found(), HasSubstr("a record of another section"));
  // Advice and repeats are warnings (CGL-Q2, CGL-Q3, CGL-Q4).
  p.program = {"1 aathreshold 2.0", "2 memory 32", "3 depth 2", "4 depth 4"};
  const SceneFile f = readScene(p.text(), "t.cgl");
  EXPECT_EQ(f.program.aathreshold, 2.0);
  EXPECT_EQ(f.program.depth, 4);
  EXPECT_TRUE(hasNote(f.warnings, 3, "outside Table 8's 5.0-100.0")) << listed(f.warnings);
  EXPECT_TRUE(hasNote(f.warnings, 4, "above Table 8's 1-24")) << listed(f.warnings);
  EXPECT_TRUE(hasNote(f.warnings, 6, "'depth' given again")) << listed(f.warnings);
}

TEST(CglSceneFile, DisplayParameterErrors) {
  Parts p;
  p.display = {"1 eye 0.0 0.0"};
  expectError(readError(p.text()), 4, "display parameter 1 of 1, field eye z", "a real number",
              "end of line");
  p.display = {"1 sight at 0 0 0"};
  expectError(readError(p.text()), 4, "field direction|towards", "direction or towards", "'at'");
  p.display = {"1 sight towards 0.0 0.0 3.5"};  // the default eye
  expectError(readError(p.text()), 4, "field sight", "other than (0, 0, 0)", "the eye point");
  p.display = {"1 up 0 0 0"};
  expectError(readError(p.text()), 4, "field up", "other than (0, 0, 0)", "(0, 0, 0)");
  p.display = {"1 dist 0.0"};
  expectError(readError(p.text()), 4, "field dist", "above 0.0", "'0.0'");
  p.display = {"1 viewport 2.0 -2.0"};
  expectError(readError(p.text()), 4, "field width", "above 0.0", "'-2.0'");
  p.display = {"1 focus 2.0"};
  expectError(readError(p.text()), 4, "field keyword", "eye, sight, up, dist or viewport",
              "'focus'");
  // The eye set after `sight towards`: the sight keeps the earlier eye (CGL-Q5).
  p.display = {"1 sight towards 0 0 0", "2 eye 0 0 10"};
  const SceneFile f = readScene(p.text(), "t.cgl");
  EXPECT_EQ(f.display.sight, (Vec3{0, 0, -3.5}));
  EXPECT_EQ(f.display.eye, (Vec3{0, 0, 10}));
  EXPECT_TRUE(hasNote(f.warnings, 5, "eye is set after 'sight towards' (line 4)"))
      << listed(f.warnings);
}

TEST(CglSceneFile, NumberSyntax) {
  Parts p;
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"nan", "'nan'"},
      {"inf", "'inf'"},
      {"0x1p3", "'0x1p3'"},
      {"1.0.0", "'1.0.0'"},
      {"1e", "'1e'"},
      {"abc", "'abc'"},
      {"1e999", "out of range"},
      {"+", "a sign apart from its number"}};
  for (const auto& [word, found] : bad) {
    p.vertices = {"1 -1 0 -1", "2 -1 " + word + " 1", "3 1 0 1", "4 1 0 -1"};
    expectError(readError(p.text()), 6, "vertex 2, field y", "a real number", found);
  }
  p.vertices = {"1 +0.0 -0.0 .5", "2 5. -.25 1e-3", "3 1E2 0 1e-400", "4 1 0 -1"};
  const SceneFile f = readScene(p.text(), "t.cgl");
  EXPECT_EQ(f.vertices[0], (Vec3{0.0, 0.0, 0.5}));
  EXPECT_TRUE(std::signbit(f.vertices[0][1]));
  EXPECT_EQ(f.vertices[1], (Vec3{5.0, -0.25, 0.001}));
  EXPECT_EQ(f.vertices[2], (Vec3{100.0, 0.0, 0.0}));  // an underflow reads as 0
}

TEST(CglSceneFile, VertexErrors) {
  Parts p;
  p.vertices = {"1 0 0 0", "3 0 0 1", "3 1 0 1", "4 1 0 -1"};
  expectError(readError(p.text()), 6, "vertex 2, field count", "the vertex number 2", "'3'");
  p.vertices = {"1 0 0 0", "2 0 0", "3 1 0 1", "4 1 0 -1"};
  expectError(readError(p.text()), 6, "vertex 2, field z", "a real number", "end of line");
  p.vertices = {"1 0 0 0", "vertices", "2 0 0 1"};
  expectError(readError(p.text()), 6, "vertex 2", "a record",
              "--lenient reads a bare 'vertices' line as a comment");
  p.vertices = {"1 0 0 0", "* vertices\n2 0 0 1", "3 1 0 1", "4 1 0 -1"};
  EXPECT_NO_THROW(readScene(p.text(), "t.cgl"));
}

TEST(CglSceneFile, SurfaceErrors) {
  Parts p;
  p.surfaces = {"1 lambert normal 0.0 0.0 0.0\n7.0\n" + flat(0.5),
                "3 lambert normal 0.0 0.0 0.0\n7.0\n" + flat(0.5)};
  std::string t = p.text();
  expectError(readError(t), lineOf(t, "3 lambert"), "surface 2 (lambert normal), field count",
              "the surface number 2", "'3'");
  p.surfaces = {"l lambert normal 0.0 0.0 0.0\n7.0\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "l lambert"), "surface 1, field count",
              "'1 (lambert|phong|cook)", "the letter l for the digit 1? --lenient reads it as 1");
  EXPECT_EQ(readScene(t, "t.cgl", ReadOptions{true}).surfaces.size(), 1u);
  p.surfaces = {"1 gouraud normal 0.0 0.0 0.0\n7.0\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "gouraud"), "field model", "lambert, phong or cook",
              "'gouraud'");
  p.surfaces = {"1 cook textured 0.0 0.0 0.0\n0.0\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "cook"), "field textured|normal", "no textured Cook form",
              "'textured'");
  p.surfaces = {"1 phong normal -0.1 0.0 0.0\n7.0 1 20\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "phong"), "field reflect", "0.0-1.0", "'-0.1'");
  p.surfaces = {"1 phong normal 0.0 1.5 1.0\n7.0 1 20\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "phong"), "field refract", "0.0-1.0", "'1.5'");
  p.surfaces = {"1 phong normal 0.0 0.5\n7.0 1 20\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "phong"), "field index", "present even if unused",
              "end of line");
  p.surfaces = {"1 phong normal 0.0 0.5 0.0\n7.0 1 20\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "phong"), "field index", "transparent", "0");
  p.surfaces = {"1 phong normal 0.0 0.0 0.0\n7.0 1\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "7.0 1"), "surface 1 (phong normal), field exponent",
              "a real number", "end of line");
  p.surfaces = {"1 lambert normal 0.0 0.0 0.0\n-7.0\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "-7.0"), "field diffuse", "0.0 or more", "'-7.0'");
  p.surfaces = {"1 lambert textured 0.0 0.0 0.0\n7.0\nlast 1 1\n"};
  t = p.text();
  expectError(readError(t), lineOf(t, "last"), "field pathname|last", "an earlier textured surface",
              "'last'");
  p.surfaces = {"1 lambert textured 0.0 0.0 0.0\n7.0\n/tex 0 1\n"};
  t = p.text();
  expectError(readError(t), lineOf(t, "/tex"), "field umod", "above 0.0", "'0'");
  p.surfaces = {"1 lambert textured 0.0 0.0 0.0\n/tex 1 1\n"};
  t = p.text();
  expectError(readError(t), lineOf(t, "/tex"), "field diffuse", "0.0 or more",
              "Figure 2 omits this line; --lenient assumes 7.0");
  // A colour-vector: 10, 10, 10 and 3 to a line; negative samples refused.
  std::string v = flat(0.5);
  v.replace(v.find("0.5\n"), 3, "0.5 junk");  // row 1: text after 10 numbers is ignored
  p.surfaces = {"1 lambert normal 0.0 0.0 0.0\n7.0\n" + v};
  EXPECT_NO_THROW(readScene(p.text(), "t.cgl"));
  p.surfaces = {"1 lambert normal 0.0 0.0 0.0\n7.0\n0.5 0.5 0.5\n" + flat(0.5)};
  t = p.text();
  expectError(readError(t), lineOf(t, "0.5 0.5 0.5\n"), "colour-vector sample 4 (410 nm)",
              "33 numbers, written 10, 10, 10 and 3",
              "end of line after 3 numbers (--lenient pads");
  p.surfaces = {"1 lambert normal 0.0 0.0 0.0\n7.0\n-0.5 " + flat(0.5).substr(4)};
  t = p.text();
  expectError(readError(t), lineOf(t, "-0.5 "), "colour-vector sample 1", "0.0 or more", "'-0.5'");
  // Advice is a warning (CGL-Q3): Phong exponent 5 outside 10-100.
  p.surfaces = {"1 phong normal 0.0 0.0 0.0\n7.0 1.0 5.0\n" + flat(0.5)};
  const SceneFile f = readScene(p.text(), "t.cgl");
  EXPECT_TRUE(hasNote(f.warnings, lineOf(p.text(), "7.0 1.0 5.0"), "exponent 5 is outside"))
      << listed(f.warnings);
}

TEST(CglSceneFile, AmbienceAndLightErrors) {
  Parts p;
  p.ambience = "-0.1\n" + flat(50.0);
  std::string t = p.text();
  expectError(readError(t), lineOf(t, "-0.1"), "ambience descriptor, field k_a", "0.0 or more",
              "'-0.1'");
  p = Parts();
  p.lights = {"1 infinity 0.0 0.0 0.0 0.0006\n" + flat(100.0)};
  t = p.text();
  expectError(readError(t), lineOf(t, "infinity"), "light 1 (infinity), field x y z",
              "other than (0, 0, 0)", "(0, 0, 0)");
  p.lights = {"1 inscene 0.0 0.0 0.0 0.0006\n" + flat(100.0)};  // a light at the origin: fine
  EXPECT_NO_THROW(readScene(p.text(), "t.cgl"));
  p.lights = {"1 spot 1 1 1 0.0006\n" + flat(100.0)};
  t = p.text();
  expectError(readError(t), lineOf(t, "spot"), "field infinity|inscene", "infinity or inscene",
              "'spot'");
  p.lights = {"2 infinity 1 1 1 0.0006\n" + flat(100.0)};
  t = p.text();
  expectError(readError(t), lineOf(t, "2 infinity"), "light 1 (infinity), field count",
              "the light number 1", "'2'");
  p.lights = {"1 infinity 1 1 1 -0.0006\n" + flat(100.0)};
  t = p.text();
  expectError(readError(t), lineOf(t, "infinity"), "field dw", "0.0 or more", "'-0.0006'");
}

TEST(CglSceneFile, NodeErrors) {
  Parts p;
  auto nodeError = [&](const std::vector<std::string>& nodes, const std::string& lineText,
                       const std::string& field, const std::string& expected,
                       const std::string& found) {
    p.nodes = nodes;
    const std::string t = p.text();
    expectError(readError(t), lineOf(t, lineText), field, expected, found);
  };
  nodeError({"1 polygon 00 00 1 5 1 2 3 4 1"}, "1 polygon", "scene node 1 (polygon), field n",
            "3 or 4", "'5'");
  nodeError({"1 polygon 00 00 3 4 1 2 3 4"}, "1 polygon", "field surface-index",
            "a surface number 1-1", "'3'");
  nodeError({"1 polygon 00 00 1 4 1 2 3 9"}, "1 polygon", "field v4", "a vertex number 1-4", "'9'");
  nodeError({"1 cylinder 00 00 1 0.1 2 2"}, "1 cylinder", "field v2", "other than v1", "'2'");
  nodeError({"1 sphere 00 00 1 0 0 0 -1 x y"}, "1 sphere", "field radius", "above 0.0", "'-1'");
  nodeError({"1 sphere 00 00 1 0 0 0 1 x w"}, "1 sphere", "field texture axis 2", "x, y or z",
            "'w'");
  nodeError({"1 sphere 00 00 1 0 0 0 1 y y"}, "1 sphere", "field texture axis 2",
            "other than texture axis 1", "'y'");
  nodeError({"1 rotate 02 00 w 10", "2 dummy 00 00"}, "1 rotate", "field axis", "x, y or z", "'w'");
  nodeError({"1 translate 03 00 0 0 0", "2 dummy 00 00"}, "1 translate", "field down",
            "a scene-node number 0-2", "'03'");
  nodeError({"1 translate 02 00 0 0 0", "3 dummy 00 00"}, "3 dummy",
            "scene node 2 (dummy), field count", "the node number 2", "'3'");
  nodeError({"1 transform 00 00"}, "1 transform", "field keyword",
            "translate, scale, rotate, sphere, cylinder, polygon, fractal, spline, box or dummy",
            "'transform'");
  nodeError({"1 fractal 00 00 1 0 1.3 0.5 9772 constrained"}, "1 fractal", "field divisions",
            "1-10", "'0'");
  nodeError({"1 fractal 00 00 1 5 1.3 0.5 9772 loose"}, "1 fractal", "field constrained|free",
            "constrained or free", "'loose'");
  nodeError({"1 spline 00 00 1 4 open 5 double 8 0.6"}, "1 spline", "field u end condition",
            "single, double, triple or closed", "'open'");
  nodeError({"1 translate 00 00 0.0 -0.8"}, "1 translate", "field z", "a real number",
            "end of line");
  // A polygon whose header is short and continued on the next line: strict
  // refuses and says where the fields might be.
  nodeError({"1 polygon 00 00 1\n   4 1 2 3 4"}, "1 polygon", "field n", "3 or 4",
            "end of line (the fields may continue on line");
  // Lines after the last node.
  p.nodes = {"1 polygon 00 00 1 4 1 2 3 4"};
  const std::string t = p.text() + "2 dummy 00 00\n";  // the first record counts 1 node
  expectError(readError(t), lineOf(t, "2 dummy"), "end of the scene", "end of file",
              "'2 dummy 00 00'");
}

TEST(CglSceneFile, ScaleWithZeroIsIgnoredWithAWarning) {
  Parts p;
  p.nodes = {"1 scale 02 00 1.0 0.0 1.0", "2 polygon 00 00 1 4 1 2 3 4"};
  const std::string t = p.text();
  const SceneFile f = readScene(t, "t.cgl");
  EXPECT_TRUE(f.nodes[0].ignored);
  EXPECT_FALSE(f.nodes[1].ignored);
  EXPECT_TRUE(hasNote(f.warnings, lineOf(t, "1 scale"), "warning, node ignored"))
      << listed(f.warnings);
}

TEST(CglSceneFile, CyclesAreRefusedSharedSubtreesAreNot) {
  Parts p;
  p.nodes = {"1 translate 02 00 0 0 0", "2 rotate 03 00 x 10", "3 box 01 00"};
  std::string t = p.text();
  auto e = readError(t);
  expectError(e, lineOf(t, "3 box"), "scene node 3, field down", "does not lead back",
              "1, closing the cycle 1 -> 2 -> 3 -> 1");
  p.nodes = {"1 translate 00 01 0 0 0"};  // its own right neighbour
  t = p.text();
  expectError(readError(t), lineOf(t, "1 translate"), "scene node 1, field right", "a DAG",
              "closing the cycle 1 -> 1");
  // A diamond: 1 -> 2 and 1 -> 3 (right of 2), both down to 4.
  p.nodes = {"1 box 02 00", "2 translate 04 03 0 0 0", "3 translate 04 00 1 0 0",
             "4 polygon 00 00 1 4 1 2 3 4"};
  const SceneFile f = readScene(p.text(), "t.cgl");
  EXPECT_EQ(f.nodes[1].down, 4);
  EXPECT_EQ(f.nodes[2].down, 4);
  EXPECT_TRUE(f.warnings.empty()) << listed(f.warnings);
  // A node the root cannot reach is a warning (CGL-Q10).
  p.nodes = {"1 polygon 00 00 1 4 1 2 3 4", "2 dummy 00 00"};
  const SceneFile g = readScene(p.text(), "t.cgl");
  EXPECT_TRUE(hasNote(g.warnings, lineOf(p.text(), "2 dummy"), "not reachable from the root"))
      << listed(g.warnings);
}

TEST(CglSceneFile, NineCubesSharesSubtrees) {
  // Appendix 1 section 13's 9 cubes, as reconstructed (the printed listing
  // is scrambled): three translations in y of three in x of a rotation of a
  // scaling of six polygons. Nodes 4 and 7 are each reached three times. The
  // document gives no vertices; these are the corners the faces name
  // ({2,3,4,5} and {6,7,8,1} opposite).
  const std::string reconstructed =
      "1 translate 04 02  +0.0 -0.7 +0.0\n"
      "2 translate 04 03  +0.0 +0.0 +0.0\n"
      "3 translate 04 00  +0.0 +0.7 +0.0\n"
      "4 translate 07 05  -0.7 +0.0 +0.0\n"
      "5 translate 07 06  +0.0 +0.0 +0.0\n"
      "6 translate 07 00  +0.7 +0.0 +0.0\n"
      "7 rotate 08 00     x -22.0\n"
      "8 scale 09 00      0.2 0.2 0.2\n"
      "9 polygon 00 10 1 4 2 3 4 5\n"
      "10 polygon 00 11 1 4 6 7 8 1\n"
      "11 polygon 00 12 1 4 1 8 3 2\n"
      "12 polygon 00 13 1 4 5 4 7 6\n"
      "13 polygon 00 14 1 4 1 2 5 6\n"
      "14 polygon 00 00 1 4 8 7 4 3\n";
  Parts p;
  p.vertices = {"1 -1 -1 1", "2 -1 -1 -1", "3 1 -1 -1", "4 1 1 -1",
                "5 -1 1 -1", "6 -1 1 1",   "7 1 1 1",   "8 1 -1 1"};
  p.nodes = {reconstructed};
  std::string t = p.text();
  t.replace(t.find("1 1 8 1 1 1 1"), 13, "1 1 8 1 1 14 1");
  const SceneFile f = readScene(t, "t.cgl");
  ASSERT_EQ(f.nodes.size(), 14u);
  EXPECT_TRUE(f.warnings.empty()) << listed(f.warnings);
  int parentsOf4 = 0, parentsOf7 = 0;
  for (const auto& n : f.nodes) {
    parentsOf4 += (n.down == 4) + (n.right == 4);
    parentsOf7 += (n.down == 7) + (n.right == 7);
  }
  EXPECT_EQ(parentsOf4, 3);
  EXPECT_EQ(parentsOf7, 3);
  EXPECT_EQ(f.nodes[3].xyz, (Vec3{-0.7, 0, 0}));
  EXPECT_EQ(f.nodes[7].kind, NodeKind::Scale);
  EXPECT_EQ(f.nodes[13].vertices, (std::vector<int>{8, 7, 4, 3}));

  // The listing as printed [Appendix 1 section 13], parameters apart from
  // their headers: the lenient reader's continuation lines and its lines
  // printed before a header (CGL-E7, CGL-E8) give the reconstruction.
  const std::string printed =
      "+0.0 -0.7 +0.0\n"
      "1 translate 04 02\n"
      "2 translate 04 03\n"
      "                   +0.0 +0.0 +0.0\n"
      "                   +0.0 +0.7 +0.0\n"
      "3 translate 04 00\n"
      "4 translate 07 05\n"
      "                   -0.7 + 0.0 + 0.0\n"
      "5 translate 07 06\n"
      "                   +0.0 +0.0 +0.0\n"
      "                   +0.7 +0.0 +0.0\n"
      "6 translate 07 00\n"
      "7 rotate 08 00\n"
      "                   x -22.0\n"
      "           09 00\n"
      "                   0.2 0.2 0.2\n"
      "8 scale\n";
  std::string u = t.substr(0, t.find("1 translate 04 02")) + printed +
                  reconstructed.substr(reconstructed.find("9 polygon"));
  EXPECT_THROW(readScene(u, "t.cgl"), io::InputError);
  const SceneFile g = readScene(u, "t.cgl", ReadOptions{true});
  ASSERT_EQ(g.nodes.size(), 14u);
  for (std::size_t k = 0; k < 14; ++k) {
    SCOPED_TRACE(k + 1);
    EXPECT_EQ(g.nodes[k].kind, f.nodes[k].kind);
    EXPECT_EQ(g.nodes[k].down, f.nodes[k].down);
    EXPECT_EQ(g.nodes[k].right, f.nodes[k].right);
    EXPECT_EQ(g.nodes[k].xyz, f.nodes[k].xyz);
    EXPECT_EQ(g.nodes[k].theta, f.nodes[k].theta);
  }
}

TEST(CglSceneFile, DeepChainReadsWithoutRecursion) {
  // 100000 translate nodes, each down to the next: the DAG walk is iterative.
  constexpr int kNodes = 100000;
  Parts p;
  p.nodes.clear();
  for (int k = 1; k < kNodes; ++k)
    p.nodes.push_back(std::to_string(k) + " translate " + std::to_string(k + 1) + " 00 0 0 0.001");
  p.nodes.push_back(std::to_string(kNodes) + " polygon 00 00 1 4 1 2 3 4");
  const SceneFile f = readScene(p.text(), "t.cgl");
  ASSERT_EQ(f.nodes.size(), static_cast<std::size_t>(kNodes));
  EXPECT_EQ(f.nodes.back().kind, NodeKind::Polygon);
  // and a cycle at its far end is still found.
  std::string t = p.text();
  t.replace(t.rfind("polygon 00 00"), 13, "translate 01 00 0 0 0 ");
  const auto e = readError(t);
  EXPECT_THAT(e.found(), HasSubstr("closing the cycle 1 -> 2 -> 3 -> 4 -> 5 -> ... (99991 more) "
                                   "-> 99997 -> 99998 -> 99999 -> 100000 -> 1"));
}

TEST(CglSceneFile, SizeLimit) {
  const std::string big((std::size_t{64} << 20) + 1, '*');
  const auto e = readError(big);
  EXPECT_THAT(std::string(e.what()), HasSubstr("t.cgl:1: larger than 64 MiB"));
  EXPECT_THROW(readSceneFile(kScenes + "/no-such-file.cgl"), io::InputError);
}

// ---------------------------------------------------------------------------
// The document's copies of the checkerboard scene.

// What both copies say, as the lenient reader reads them (section 1.3's
// English reading of the scene, and Figure 59 field by field).
void expectCheckerboard(const SceneFile& f) {
  EXPECT_EQ(f.numbers.programParameters, 5);
  EXPECT_EQ(f.numbers.nodes, 4);
  EXPECT_EQ(f.program.depth, 3);
  EXPECT_TRUE(f.program.shadows);
  EXPECT_EQ(f.program.xleft, 31);
  EXPECT_EQ(f.program.xright, 480);
  EXPECT_EQ(f.program.yhigh, 286);
  EXPECT_EQ(f.display.eye, (Vec3{0.0, 0.0, 3.5}));
  EXPECT_EQ(f.display.sight, (Vec3{0.0, 0.0, -3.5}));
  ASSERT_EQ(f.vertices.size(), 4u);
  EXPECT_EQ(f.vertices[2], (Vec3{1.0, 0.0, 1.0}));
  ASSERT_EQ(f.surfaces.size(), 2u);
  EXPECT_EQ(f.surfaces[0].model, ShadingModel::Lambert);
  EXPECT_TRUE(f.surfaces[0].textured);
  EXPECT_EQ(f.surfaces[0].diffuse, 7.0);
  EXPECT_EQ(f.surfaces[0].texture, "/u/majsweeney/textures/checkerboard");
  EXPECT_EQ(f.surfaces[0].umod, 1.0);
  EXPECT_EQ(f.surfaces[1].model, ShadingModel::Phong);
  EXPECT_EQ(f.surfaces[1].reflect, 1.0);
  EXPECT_EQ(f.surfaces[1].specular, 2.5);
  EXPECT_EQ(f.surfaces[1].exponent, 25.0);
  for (double v : f.surfaces[1].colour) EXPECT_EQ(v, 0.06);  // "dark gray" (CGL-E2)
  EXPECT_EQ(f.ambience.ka, 0.0005);
  EXPECT_EQ(f.ambience.colour[0], 50.0);   // CIE D6500, 380 nm
  EXPECT_EQ(f.ambience.colour[32], 71.6);  // 700 nm
  ASSERT_EQ(f.lights.size(), 1u);
  EXPECT_EQ(f.lights[0].xyz, (Vec3{0.6, 1.0, 0.6}));
  EXPECT_EQ(f.lights[0].dw, 0.0006);
  EXPECT_EQ(f.lights[0].colour[10], 115.9);
  ASSERT_EQ(f.nodes.size(), 4u);
  EXPECT_EQ(f.nodes[0].kind, NodeKind::Rotate);
  EXPECT_EQ(f.nodes[0].down, 2);
  EXPECT_EQ(f.nodes[0].right, 4);
  EXPECT_EQ(f.nodes[0].axis, 'x');
  EXPECT_EQ(f.nodes[0].theta, -22.0);
  EXPECT_EQ(f.nodes[1].kind, NodeKind::Translate);
  EXPECT_EQ(f.nodes[1].xyz, (Vec3{0.0, -0.8, 0.0}));
  EXPECT_EQ(f.nodes[2].kind, NodeKind::Polygon);
  EXPECT_EQ(f.nodes[2].surface, 1);
  EXPECT_EQ(f.nodes[2].vertices, (std::vector<int>{4, 3, 2, 1}));
  EXPECT_EQ(f.nodes[3].kind, NodeKind::Sphere);
  EXPECT_EQ(f.nodes[3].surface, 2);
  EXPECT_EQ(f.nodes[3].xyz, (Vec3{0.3, -0.18, 0.0}));
  EXPECT_EQ(f.nodes[3].radius, 0.16);
  EXPECT_EQ(f.nodes[3].textureAxis1, 'x');
  EXPECT_EQ(f.nodes[3].textureAxis2, 'y');
}

TEST(CglSceneFile, Figure59StrictRefusesWithAHint) {
  const std::string path = kScenes + "/doc-figure59.cgl";
  try {
    readSceneFile(path);
    FAIL() << "Figure 59 read strictly";
  } catch (const io::InputError& e) {
    // Line 20 of the file is the bare word `vertices` (8 header lines + 12).
    EXPECT_EQ(e.where().file, path);
    EXPECT_EQ(e.where().line, 20);
    EXPECT_EQ(e.field(), "vertex 1");
    EXPECT_THAT(e.found(), HasSubstr("'vertices'"));
    EXPECT_THAT(e.found(), HasSubstr("--lenient"));
  }
}

TEST(CglSceneFile, Figure59LenientRepairs) {
  const SceneFile f = readSceneFile(kScenes + "/doc-figure59.cgl", ReadOptions{true});
  expectCheckerboard(f);
  const auto& r = f.repairs;
  SCOPED_TRACE(listed(r));
  EXPECT_TRUE(hasNote(r, 20, "bare word 'vertices'"));
  EXPECT_TRUE(hasNote(r, 26, "read the letter 'l' of the count 'l' as the digit 1"));
  EXPECT_TRUE(hasNote(r, 32,
                      "surface 2 (phong normal): colour-vector of 3 numbers, not 33; "
                      "padded: the last value (0.06) repeated"));
  EXPECT_TRUE(hasNote(r, 33, "as the comment mark '*'"));
  EXPECT_TRUE(hasNote(r, 47, "continued scene node 1 (rotate) (header on line 46"));
  EXPECT_TRUE(hasNote(r, 49, "continued scene node 2 (translate)"));
  EXPECT_TRUE(hasNote(r, 51, "continued scene node 3 (polygon)"));
  EXPECT_TRUE(hasNote(r, 53, "continued scene node 4 (sphere)"));
  EXPECT_EQ(r.size(), 8u);
  for (const auto& x : r) EXPECT_EQ(x.where.file, kScenes + "/doc-figure59.cgl");
}

TEST(CglSceneFile, Figure2StrictRefusesLenientReadsTheSameScene) {
  const std::string path = kScenes + "/doc-figure2.cgl";
  try {
    readSceneFile(path);
    FAIL() << "Figure 2 read strictly";
  } catch (const io::InputError& e) {
    // Line 9: the '•' of the first comment.
    EXPECT_EQ(e.where().line, 9);
    EXPECT_THAT(e.found(), HasSubstr("--lenient also reads"));
  }
  const SceneFile f = readSceneFile(path, ReadOptions{true});
  expectCheckerboard(f);
  const auto& r = f.repairs;
  SCOPED_TRACE(listed(r));
  EXPECT_TRUE(hasNote(r, 9, "as the comment mark '*'"));
  EXPECT_TRUE(hasNote(r, 11, "as the comment mark '*'"));
  EXPECT_TRUE(hasNote(r, 20, "bare word 'vertices'"));
  EXPECT_TRUE(hasNote(r, 23, "joined 3 lone signs to the number after each: '3 +1.0 -0.0 +1.0'"));
  EXPECT_TRUE(hasNote(r, 26, "as the digit 1"));
  EXPECT_TRUE(hasNote(r, 27, "no diffuse line before the texture line; diffuse 7.0 assumed"));
  EXPECT_TRUE(hasNote(r, 31, "colour-vector of 3 numbers"));
  EXPECT_TRUE(hasNote(r, 46, "continued scene node 1 (rotate) (header on line 45"));
  // `0.0 -0.8 0.0` is printed after node 1's parameters, before node 2's header.
  EXPECT_TRUE(hasNote(r, 47, "printed before the header of scene node 2 (translate) (line 48)"));
  EXPECT_TRUE(hasNote(r, 50, "continued scene node 3 (polygon)"));
  EXPECT_TRUE(hasNote(r, 52, "continued scene node 4 (sphere)"));
  EXPECT_EQ(r.size(), 11u);
}

TEST(CglSceneFile, LenientPhongRedLostSampleInTheFirstRow) {
  // Appendix 1 section 8's "reflective phong red": 32 numbers, the first row
  // 9. The lenient reader repeats that row's last value at its end (CGL-E3),
  // keeping rows 2-4 where the printed layout puts them.
  Parts p;
  p.surfaces = {
      "\\* surface: reflective phong red\n"
      "1 phong normal 0.6 0.0 0.0\n"
      "7.0 3.0 25.0\n"
      "0.0127 0.0095 0.0064 0.0032 0.0000 0.0000 0.0000 0.0000 0.0000\n"
      "0.0000 0.0000 0.0000 0.0000 0.0000 0.0000 0.0000 0.0127 0.0159 0.0286\n"
      "0.0477 0.0637 0.0987 0.1273 0.1592 0.1910 0.2228 1.2000 1.2000 1.2000\n"
      "1.2000 1.2000 1.2000\n"};
  const std::string t = p.text();
  EXPECT_THROW(readScene(t, "t.cgl"), io::InputError);
  const SceneFile f = readScene(t, "t.cgl", ReadOptions{true});
  const Spectrum& c = f.surfaces[0].colour;
  EXPECT_EQ(c[0], 0.0127);
  EXPECT_EQ(c[9], 0.0);      // the inserted sample
  EXPECT_EQ(c[16], 0.0);     // row 2, 7th: 540 nm
  EXPECT_EQ(c[17], 0.0127);  // row 2, 8th: 550 nm
  EXPECT_EQ(c[20], 0.0477);  // row 3 starts at 580 nm
  EXPECT_EQ(c[32], 1.2);
  EXPECT_TRUE(hasNote(f.repairs, lineOf(t, "0.0127 0.0095"),
                      "row 1 has 9 of 10 numbers: its last value repeated at its end"))
      << listed(f.repairs);
  EXPECT_TRUE(hasNote(f.repairs, lineOf(t, "\\* surface"), "'\\*' as the comment mark"));
}

TEST(CglSceneFile, LenientFindsTheAmbienceBeforeLinesOfTheFirstNode) {
  // No lights, a 3-number grey in the last surface, and the first node's
  // parameters printed before its header: the ambience is the one-number
  // line nearest the first node with 33 numbers after it (CGL-E10).
  Parts p;
  p.surfaces = {"1 lambert normal 0.0 0.0 0.0\n7.0\n0.06 0.06 0.06\n"};
  p.lights.clear();
  p.nodes = {"+0.0 -0.7 +0.0\n1 translate 02 00\n2 polygon 00 00 1 4 1 2 3 4"};
  std::string t = p.text();
  t.replace(t.find("1 1 4 1 0 1 1"), 13, "1 1 4 1 0 2 1");
  const SceneFile f = readScene(t, "t.cgl", ReadOptions{true});
  for (double v : f.surfaces[0].colour) EXPECT_EQ(v, 0.06);
  EXPECT_EQ(f.ambience.ka, 0.0005);
  EXPECT_EQ(f.ambience.colour[32], 50.0);
  EXPECT_EQ(f.nodes[0].xyz, (Vec3{0.0, -0.7, 0.0}));
  EXPECT_TRUE(hasNote(f.repairs, lineOf(t, "+0.0 -0.7"),
                      "printed before the header of scene "
                      "node 1 (translate)"))
      << listed(f.repairs);
}

TEST(CglSceneFile, LenientStillRefusesWhatItCannotRepair) {
  Parts p;
  p.nodes = {"1 polygon 00 00 1 5 1 2 3 4 1"};
  const std::string t = p.text();
  expectError(readError(t, ReadOptions{true}), lineOf(t, "1 polygon"), "field n", "3 or 4", "'5'");
  // A parameter line that no header takes.
  p.nodes = {"1 polygon 00 00 1 4 1 2 3 4\n0.0 1.0 2.0"};
  const std::string u = p.text();
  expectError(readError(u, ReadOptions{true}), lineOf(u, "0.0 1.0 2.0"), "end of the scene",
              "end of file", "'0.0 1.0 2.0'");
}

TEST(CglSceneFile, FormatDocumentExampleReads) {
  // docs/cgl/scene-format.md ends with "A complete small scene": it reads
  // strictly, without warnings, and says what the page says it does.
  std::ifstream in(kScenes + "/../../docs/cgl/scene-format.md", std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string doc = s.str();
  const auto at = doc.find("```\n", doc.find("## A complete small scene")) + 4;
  const std::string text = doc.substr(at, doc.find("```", at) - at);
  const SceneFile f = readScene(text, "doc.cgl");
  EXPECT_TRUE(f.warnings.empty()) << listed(f.warnings);
  EXPECT_EQ(f.nodes.size(), 3u);
  EXPECT_EQ(f.nodes[0].right, 3);
  EXPECT_EQ(f.surfaces[1].reflect, 1.0);
  EXPECT_TRUE(looksLikeCgl(text));
}

// ---------------------------------------------------------------------------

TEST(CglSceneFile, LooksLikeCgl) {
  int malone = 0;
  for (const auto& e : std::filesystem::directory_iterator(kScenes + "/../malone")) {
    if (e.path().extension() != ".mal") continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_FALSE(looksLikeCgl(s.str().substr(0, 8192))) << e.path();
    ++malone;
  }
  EXPECT_GT(malone, 5);
  for (const char* name : {"doc-figure59.cgl", "doc-figure2.cgl"}) {
    std::ifstream in(kScenes + "/" + name, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_TRUE(looksLikeCgl(s.str())) << name;
  }
  Parts p;
  std::string t = p.text();
  EXPECT_TRUE(looksLikeCgl(t));
  EXPECT_TRUE(looksLikeCgl(t.substr(t.find('\n') + 1)));  // no comment: `1 depth 3`
  EXPECT_TRUE(looksLikeCgl("\xE2\x80\xA2 scene\n5 2 4 2 1 4 1\n"));
  EXPECT_FALSE(looksLikeCgl("102 0 0 5 0 0 0 1 0 0 0 1 0 8 8\n1 1 0 0 0\n"));
  EXPECT_FALSE(looksLikeCgl("GIF89a\x01\x02 garbage words here\n"));
  EXPECT_FALSE(looksLikeCgl(""));
}

}  // namespace
}  // namespace prime::cgl
