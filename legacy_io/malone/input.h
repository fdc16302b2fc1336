// Malone's input language (D. Malone, "A description of a simple Ray
// Tracer", Trinity College Dublin, 1995, section 1.2): a stream of numbers
// read as C doubles, whitespace-insensitive; an object is an integral ID and
// its numbers, a primitive is followed by one surface, end of file ends the
// scene. The document gives four IDs (2 plane, 100 surface, 101 light, 102
// viewer); the rest are this port's, fixed once so that every scene file
// written today means one thing (docs/malone/input-language.md, MAL-Q1).
//
// This reader checks the syntax: IDs, counts, integral fields, where a
// surface may stand. Geometric checks (a degenerate triangle, a singular
// affine matrix) are the scene's (src/malone/scene.h), with the same located
// errors: every error names the file, line, column, token number, the object
// and field being read, what was expected and what was found.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "legacy_io/common/error.h"
#include "src/math/vec.h"

namespace prime::malone {

enum class ObjectId : int {
  Sphere = 1,                 // radius, centre
  Plane = 2,                  // D, normal: the plane n.x = D
  Disk = 3,                   // centre, normal, radius
  Annulus = 4,                // centre, normal, radius, r_in
  Triangle = 5,               // v0, v1, v2
  Parallelogram = 6,          // vertex, edge1, edge2
  Affine = 7,                 // O, X, Y, Z, then an embedded primitive (ID and numbers)
  Cone = 8,                   // alpha = cos(theta), start, finish, apex, axis
  Cylinder = 9,               // radius, start, finish, point, axis
  Torus = 10,                 // R, r, centre, axis
  Polygon = 11,               // N, then N vertices
  Surface = 100,              // colour rgb, k_s, k_e, k_d, k_t, refractive index
  PointLight = 101,           // position, rgb: with the r^-2 law
  Viewer = 102,               // eye, look-at, x, y, X_RES, Y_RES
  Ambient = 103,              // rgb
  PointLightNoFalloff = 104,  // position, rgb: without r^-2
  SampledLight = 105,         // samples, centre, radius, rgb: a spherical light
  SetDefaultSurface = 106,    // then a surface
  UseDefaultSurface = 107,    // in a surface slot: the current default surface
};

// The name of an ID ("sphere", "point light"), or nullptr for an unknown one.
const char* objectName(int id);
bool isPrimitive(ObjectId id);

struct SurfaceRecord {
  Vec3 colour{};
  double ks = 0, ke = 0, kd = 0, kt = 0, index = 0;
  io::InputLocation where;
};

// A primitive's numbers in read order (docs/malone/input-language.md gives
// each ID's fields), and for the affine primitive the one it embeds.
struct PrimitiveRecord {
  ObjectId id = ObjectId::Sphere;
  std::vector<double> numbers;
  std::shared_ptr<const PrimitiveRecord> inner;  // Affine only
  int surface = -1;                              // index into SceneFile::surfaces
  int objectNumber = 0;                          // 1-based, in file order (all objects)
  io::InputLocation where;                       // the ID token
};

struct LightRecord {
  ObjectId id = ObjectId::PointLight;  // 101, 104 or 105
  Vec3 position{};                     // 105: the centre
  Vec3 rgb{};
  int samples = 1;      // 105
  double radius = 0.0;  // 105
  io::InputLocation where;
};

struct ViewerRecord {
  Vec3 eye{}, lookAt{}, x{}, y{};
  int xRes = 0, yRes = 0;
  io::InputLocation where;
};

struct SceneFile {
  std::vector<PrimitiveRecord> primitives;
  std::vector<SurfaceRecord> surfaces;
  std::vector<LightRecord> lights;
  std::vector<Vec3> ambients;  // added together
  ViewerRecord viewer;         // the last one read (the scene points to one viewer)
  int viewers = 0;             // how many were read
};

struct ReadOptions {
  // Extension, not the original: `#` starts a comment that runs to the end
  // of the line (MAL-D2).
  bool comments = false;
  // Largest X_RES or Y_RES accepted.
  int maxResolution = 16384;
};

// Reads a whole scene from `text`; `display` names the file in messages.
// Throws io::InputError.
SceneFile readScene(const std::string& text, const std::string& display,
                    const ReadOptions& options = {});
// The same from a file (at most 256 MiB).
SceneFile readSceneFile(const std::string& path, const ReadOptions& options = {});

// True when `text` starts like a Malone scene: its first token (after
// blanks and, with comments, `#` lines) is an integral number.
bool looksLikeMalone(const std::string& text);

}  // namespace prime::malone
