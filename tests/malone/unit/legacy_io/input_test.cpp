// The reader of Malone's numeric input language (legacy_io/malone/input.h):
// the document's own scene of section 1.2 field by field, every doc-*.mal
// example, and one located error per error class (file, line, column, token
// number, field, expected and found).
#include "legacy_io/malone/input.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace prime::malone {
namespace {

using ::testing::HasSubstr;

const std::string kScenes = MALONE_SCENES;
// A valid viewer, appended where a test needs a complete scene.
const std::string kViewer = "102 0 0 5 0 0 0 1 0 0 0 1 0 8 8\n";
const std::string kSurface = "100 1 1 1 0 1 1 0 1";

// Reads `text` as "t.mal" and returns the error (fails the test if none).
io::InputError readError(const std::string& text, const ReadOptions& options = {}) {
  try {
    readScene(text, "t.mal", options);
  } catch (const io::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError for: " << text;
  return io::InputError({}, "none");
}

// The location and the three parts of a message, all checked at once.
void expectError(const io::InputError& e, int line, int column, std::optional<int> token,
                 const std::string& field, const std::string& expected, const std::string& found) {
  SCOPED_TRACE(e.what());
  EXPECT_EQ(e.where().file, "t.mal");
  EXPECT_EQ(e.where().line, line);
  EXPECT_EQ(e.where().column, column);
  EXPECT_EQ(e.where().token, token);
  EXPECT_EQ(e.field(), field);
  EXPECT_THAT(e.expected(), HasSubstr(expected));
  EXPECT_EQ(e.found(), found);
  // The message itself names all of it.
  std::string place = "t.mal:" + std::to_string(line) + ":" + std::to_string(column);
  if (token) place += " (token " + std::to_string(*token) + ")";
  EXPECT_THAT(std::string(e.what()), HasSubstr(place + ": " + field + ": expected "));
  EXPECT_THAT(std::string(e.what()), HasSubstr(", found " + found));
}

TEST(MaloneInput, DocumentSceneEveryField) {
  // Section 1.2 [L111-134], verbatim in scenes/malone/doc-scene.mal.
  const SceneFile f = readSceneFile(kScenes + "/doc-scene.mal");
  EXPECT_EQ(f.viewers, 1);
  EXPECT_EQ(f.viewer.eye, (Vec3{0, 2, 3}));
  EXPECT_EQ(f.viewer.lookAt, (Vec3{0, 0, 0}));
  EXPECT_EQ(f.viewer.x, (Vec3{1, 0, 0}));
  EXPECT_EQ(f.viewer.y, (Vec3{0, 1, 0}));
  EXPECT_EQ(f.viewer.xRes, 256);
  EXPECT_EQ(f.viewer.yRes, 256);
  EXPECT_EQ(f.viewer.where.line, 1);  // the 102

  ASSERT_EQ(f.lights.size(), 1u);
  EXPECT_EQ(f.lights[0].id, ObjectId::PointLight);
  EXPECT_EQ(f.lights[0].position, (Vec3{-2, 5, 2}));
  EXPECT_EQ(f.lights[0].rgb, (Vec3{1, 1, 1}));
  EXPECT_EQ(f.lights[0].where.line, 7);
  EXPECT_EQ(f.lights[0].where.token, 16);  // after 102 and its 14 numbers

  ASSERT_EQ(f.primitives.size(), 1u);
  const PrimitiveRecord& p = f.primitives[0];
  EXPECT_EQ(p.id, ObjectId::Plane);
  EXPECT_EQ(p.numbers, (std::vector<double>{0, 0, 1, 0}));  // D, then the normal
  EXPECT_EQ(p.objectNumber, 3);
  EXPECT_EQ(p.where.line, 10);
  EXPECT_EQ(p.where.column, 1);
  EXPECT_EQ(p.where.token, 23);  // 16 + 1 + 6

  ASSERT_EQ(f.surfaces.size(), 1u);
  ASSERT_EQ(p.surface, 0);
  const SurfaceRecord& s = f.surfaces[0];
  EXPECT_EQ(s.colour, (Vec3{1, 1, 1}));
  EXPECT_EQ(s.ks, 0.0);
  EXPECT_EQ(s.ke, 30.0);
  EXPECT_EQ(s.kd, 1.0);
  EXPECT_EQ(s.kt, 0.0);
  EXPECT_EQ(s.index, 0.0);
  EXPECT_EQ(s.where.line, 13);
  EXPECT_TRUE(f.ambients.empty());
}

TEST(MaloneInput, EveryDocumentExampleReads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("doc-", 0) != 0 || entry.path().extension() != ".mal") continue;
    SCOPED_TRACE(name);
    ++count;
    SceneFile f;
    EXPECT_NO_THROW(f = readSceneFile(entry.path().string()));
    EXPECT_EQ(f.viewers, 1);
    EXPECT_GE(f.primitives.size(), 1u);
  }
  EXPECT_EQ(count, 10);  // scene, sphere, plane, disk, annulus, triangle, parallelogram,
                         // ellipsoid (affine), cone, cylinder
}

TEST(MaloneInput, DocumentExamplesFieldOrder) {
  // The cone of [L562-569]: alpha, start, finish, apex, axis.
  SceneFile f = readSceneFile(kScenes + "/doc-cone.mal");
  EXPECT_EQ(f.primitives[0].id, ObjectId::Cone);
  EXPECT_EQ(f.primitives[0].numbers, (std::vector<double>{0.9, 0, 2, 0, 2, 0, 0, -5, 0}));
  // The ellipsoid of [L508-520]: O X Y Z and the embedded sphere (radius, centre).
  f = readSceneFile(kScenes + "/doc-ellipsoid.mal");
  const PrimitiveRecord& a = f.primitives[0];
  EXPECT_EQ(a.id, ObjectId::Affine);
  EXPECT_EQ(a.numbers, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 2}));
  ASSERT_TRUE(a.inner);
  EXPECT_EQ(a.inner->id, ObjectId::Sphere);
  EXPECT_EQ(a.inner->numbers, (std::vector<double>{0.5, 0, 0.5, 0}));
  // The annulus of [L418-424]: centre, normal, radius, r_in.
  f = readSceneFile(kScenes + "/doc-annulus.mal");
  EXPECT_EQ(f.primitives[0].numbers, (std::vector<double>{1, 1, 1, 4, 3, -1, 4, 0.23}));
}

TEST(MaloneInputErrors, UnknownId) {
  // Line 2, after two blanks: column 3, the 16th token (the viewer has 15).
  expectError(readError(kViewer + "  99 1 2 3\n"), 2, 3, 16,
              "object ID (a primitive, light, viewer or 106)", "a known ID", "unknown ID '99'");
}

TEST(MaloneInputErrors, EndOfFileInsideAnObject) {
  // The sphere starts at line 2 column 1 (token 16); after radius and two
  // centre numbers the file ends at line 4 column 4: the centre's z was next.
  const io::InputError e = readError(kViewer + "1\n0.5\n0 0");
  expectError(e, 4, 4, std::nullopt, "sphere, field centre z",
              "(the sphere that starts at t.mal:2:1 (token 16) is not complete)", "end of file");
  // Inside a surface: the object that was next is named.
  expectError(readError(kViewer + "1 1 0 0 0\n100 1 1"), 3, 8, std::nullopt,
              "surface, field colour blue", "the surface that starts at t.mal:3:1 (token 21)",
              "end of file");
  // The primitive's surface slot itself missing.
  expectError(readError(kViewer + "1 1 0 0 0"), 2, 10, std::nullopt, "sphere (its surface)",
              "a surface: 100 and its 8 numbers, or 107", "end of file");
}

TEST(MaloneInputErrors, NonNumericToken) {
  expectError(readError(kViewer + "1 abc 0 0 0 " + kSurface), 2, 3, 17, "sphere, field radius",
              "a number", "'abc'");
  // A number glued to text is not a number either.
  expectError(readError(kViewer + "1 1 0 0 0.5.5 " + kSurface), 2, 9, 20, "sphere, field centre z",
              "a number", "'0.5.5'");
}

TEST(MaloneInputErrors, NonIntegralId) {
  expectError(readError("1.5 1 0 0 0 " + kSurface), 1, 1, 1,
              "object ID (a primitive, light, viewer or 106)", "an integral ID", "'1.5'");
}

TEST(MaloneInputErrors, SurfaceAtTopLevel) {
  expectError(readError(kViewer + kSurface), 2, 1, 16, "object ID", "a surface is read only after",
              "100 (a surface on its own)");
}

TEST(MaloneInputErrors, UseDefaultBeforeAnySet) {
  // Tokens: 15 viewer, then 1 1 0 0 0 (16-20), 107 is token 21 at column 11.
  expectError(readError(kViewer + "1 1 0 0 0 107"), 2, 11, 21, "sphere (its surface)",
              "none has been set yet", "107");
}

TEST(MaloneInput, UseDefaultBindsTheSurfaceCurrentAtReadTime) {
  const SceneFile f = readScene(kViewer +
                                    "106 100 0.1 0.2 0.3 0 1 1 0 1\n"
                                    "1 1 0 0 0 107\n"
                                    "106 100 0.7 0.8 0.9 0 1 1 0 1\n"
                                    "1 2 0 0 0 107\n",
                                "t.mal");
  ASSERT_EQ(f.primitives.size(), 2u);
  ASSERT_EQ(f.surfaces.size(), 2u);
  // The first sphere keeps the first default although a later 106 set another.
  EXPECT_EQ(f.surfaces[f.primitives[0].surface].colour, (Vec3{0.1, 0.2, 0.3}));
  EXPECT_EQ(f.surfaces[f.primitives[1].surface].colour, (Vec3{0.7, 0.8, 0.9}));
  // 107 itself is no object at top level.
  expectError(readError(kViewer + "107"), 2, 1, 16, "object ID",
              "107 stands only where a primitive's surface goes", "107");
}

TEST(MaloneInputErrors, NonFiniteNumbers) {
  expectError(readError(kViewer + "1 nan 0 0 0 " + kSurface), 2, 3, 17, "sphere, field radius",
              "a finite number", "'nan'");
  expectError(readError(kViewer + "1 1 inf 0 0 " + kSurface), 2, 5, 18, "sphere, field centre x",
              "a finite number", "'inf'");
  expectError(readError(kViewer + "1 1 0 -INFINITY 0 " + kSurface), 2, 7, 19,
              "sphere, field centre y", "a finite number", "'-INFINITY'");
  // 1e309 overflows a double: out of range, not "not finite".
  expectError(readError(kViewer + "1 1e309 0 0 0 " + kSurface), 2, 3, 17, "sphere, field radius",
              "a number within the range of a double", "'1e309' (out of range)");
  // An underflow to a denormal or zero is a number like any other.
  EXPECT_NO_THROW(readScene(kViewer + "1 1 1e-320 1e-400 0 " + kSurface, "t.mal"));
}

TEST(MaloneInputErrors, AbsurdResolution) {
  // X_RES is token 14 of the viewer, column 29 of "102 0 0 5 0 0 0 1 0 0 0 1 0 8 8";
  // Y_RES token 15, column 31.
  expectError(readError("102 0 0 5 0 0 0 1 0 0 0 1 0 0 8\n"), 1, 29, 14, "viewer, field X_RES",
              "an integer from 1 to 16384", "'0'");
  expectError(readError("102 0 0 5 0 0 0 1 0 0 0 1 0 8 100000\n"), 1, 31, 15, "viewer, field Y_RES",
              "an integer from 1 to 16384", "'100000'");
  expectError(readError("102 0 0 5 0 0 0 1 0 0 0 1 0 8.5 8\n"), 1, 29, 14, "viewer, field X_RES",
              "an integer from 1 to 16384", "'8.5'");
}

TEST(MaloneInputErrors, NoViewer) {
  const io::InputError e = readError("1 1 0 0 0 " + kSurface + "\n");
  expectError(e, 2, 1, std::nullopt, "viewer", "a viewer (102 eye look-at x y X_RES Y_RES)",
              "end of file without one");
}

TEST(MaloneInputErrors, CommentsOnlyWhenAsked) {
  const std::string text = "# the viewer\n" + kViewer + "1 1 0 0 0 # a sphere\n" + kSurface;
  // Strict (the original): '#' is a token that is not a number.
  expectError(readError(text), 1, 1, 1, "object ID (a primitive, light, viewer or 106)", "a number",
              "'#'");
  ReadOptions options;
  options.comments = true;
  const SceneFile f = readScene(text, "t.mal", options);
  ASSERT_EQ(f.primitives.size(), 1u);
  EXPECT_EQ(f.primitives[0].numbers, (std::vector<double>{1, 0, 0, 0}));
  EXPECT_EQ(f.primitives[0].where.line, 3);
  EXPECT_EQ(f.primitives[0].where.token, 16);  // comments are not tokens
  // A comment glued to a number ends it.
  EXPECT_NO_THROW(readScene(kViewer + "1 1 0 0 0#x\n" + kSurface, "t.mal", options));
}

TEST(MaloneInput, AffineEmbedsOnlyAPrimitive) {
  expectError(readError(kViewer + "7 0 0 0 1 0 0 0 1 0 0 0 1 101 0 0 0 1 1 1"), 2, 27, 29,
              "affine, embedded primitive ID", "a primitive ID (1-11)", "101 (point light)");
}

TEST(MaloneInput, LooksLikeMalone) {
  EXPECT_TRUE(looksLikeMalone("  102 0 2 3"));
  EXPECT_TRUE(looksLikeMalone("# c\n102"));
  EXPECT_FALSE(looksLikeMalone("P6\n"));
  EXPECT_FALSE(looksLikeMalone("1.5 2"));
  EXPECT_FALSE(looksLikeMalone(""));
  // A binary file whose first word starts with a NUL (a CGL RLE picture named
  // by `-o pic.rle scene.cgl`) is no number: strtod stopped at the NUL.
  EXPECT_FALSE(looksLikeMalone(std::string("\0\x01\x02 x", 5)));
  EXPECT_FALSE(looksLikeMalone(std::string("12\0", 3)));
}

}  // namespace
}  // namespace prime::malone
