// The Waterloo CGL package's scene-description file (M. A. J. Sweeney, "The
// Waterloo CGL Ray Tracing Package", University of Waterloo CS-85-35, 1985,
// Appendix 1), read record by record into what the file says, nothing more:
// the numbers of things, the program and display parameters, the vertex
// table, the surface descriptors, the ambience descriptor, the lights and the
// scene-node DAG. Geometry (transforms, boxes, object lists) is the scene's
// (src/cgl/scene.h).
//
// The file is line oriented: a line whose first non-blank character is `*`
// and a blank line are comments; the counts of the first record say how many
// records of each section follow; text after a record's required fields is
// ignored. The strict reader refuses anything else with a located message
// (file, line, field, what was expected, what was found). With
// ReadOptions::lenient the reader also accepts the document's own OCR-damaged
// copies and records every repair it made (SceneFile::repairs), so the tool can
// say what it changed (docs/cgl/scene-format.md).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "legacy_io/common/error.h"
#include "src/math/vec.h"

namespace prime::cgl {

// A colour-vector: reflectance or intensity from 380 to 700 nm every 10 nm
// (section 9.1), written in a file as 3 lines of 10 numbers and one of 3.
inline constexpr int kSpectrumSamples = 33;
using Spectrum = std::array<double, kSpectrumSamples>;
// Cook-Torrance Fresnel table: 66 colour-vectors, angles 0 to 90 degrees.
inline constexpr int kFresnelAngles = 66;

// The first record: seven integers.
struct NumbersOfThings {
  int programParameters = 0, displayParameters = 0, vertices = 0, surfaces = 0, lights = 0,
      nodes = 0, root = 0;
  io::InputLocation where;
};

// Program parameters (Appendix 1 section 5, Table 8), with the table's
// defaults. `given` flags say which the file set (the CLI's overrides and the
// parameter report use them).
struct ProgramParameters {
  std::string output;  // "" = no output named (the frame buffer)
  int yhigh = 511, ylow = 0, xleft = 0, xright = 511;
  int depth = 0;
  bool shadows = false;
  int memory = 4;                          // Mbytes; a figure, not a limit, in the port
  double brightness = 0.0;                 // -Dbackground's user procedure (not built; see docs)
  std::array<int, 3> background{0, 0, 0};  // red green blue, 0-255
  bool quiet = false;
  double aathreshold = 40.0;
  int aalevel = 2;  // 1, 2, 4 or 8; 0 = no anti-aliasing (one ray per pixel)
  struct Given {
    bool output = false, yhigh = false, ylow = false, xleft = false, xright = false, depth = false,
         shadows = false, memory = false, brightness = false, background = false, quiet = false,
         aathreshold = false, aalevel = false;
  } given;
};

// Display parameters (section 6), with the document's defaults. `sight` is
// the viewing direction: a `sight towards P` record is stored as P - eye, the
// eye as set so far (the manual: "the eye point should be set before the
// sight direction").
struct DisplayParameters {
  Vec3 eye{0.0, 0.0, 3.5};
  Vec3 sight{0.0, 0.0, -3.5};
  Vec3 up{0.0, 1.0, 0.0};
  double dist = 2.5;
  double viewportHeight = 2.0, viewportWidth = 2.0;
};

enum class ShadingModel { Lambert, Phong, Cook };

struct SurfaceRecord {
  ShadingModel model = ShadingModel::Lambert;
  bool textured = false;
  double reflect = 0.0, refract = 0.0, index = 0.0;  // k_r, k_t, n
  double diffuse = 0.0;                              // k_d
  double specular = 0.0, exponent = 0.0;             // Phong k_s, e; Cook k_s (m below)
  double m = 0.0;                                    // Cook: rms facet slope
  Spectrum colour{};                                 // D_lambda (Cook: normal reflectance)
  // Textured Lambert/Phong: the RLE image file as written (`last` = the
  // previous textured surface's texture), and the repeat counts.
  // For `last`, texture is the earlier surface's path (resolved by the
  // reader) and textureLast is true.
  std::string texture;
  bool textureLast = false;
  io::InputLocation textureWhere;  // where the pathname is written (for `last`: the earlier one)
  double umod = 1.0, vmod = 1.0;
  std::vector<Spectrum> fresnel;  // Cook: kFresnelAngles vectors, 0 degrees first
  io::InputLocation where;        // the header line
};

struct AmbienceRecord {
  double ka = 0.0;
  Spectrum colour{};  // I_a lambda
  io::InputLocation where;
};

enum class LightKind { Infinity, InScene };

struct LightRecord {
  LightKind kind = LightKind::Infinity;
  Vec3 xyz{};  // infinity: direction to the light; inscene: its position
  double dw = 0.0;
  Spectrum colour{};
  io::InputLocation where;
};

enum class NodeKind {
  Translate,
  Scale,
  Rotate,
  Sphere,
  Cylinder,
  Polygon,
  Fractal,
  Spline,
  Box,
  Dummy
};
enum class EndCondition { Single, Double, Triple, Closed };

struct NodeRecord {
  int number = 0;  // 1-based, consecutive
  NodeKind kind = NodeKind::Dummy;
  int down = 0, right = 0;                      // node numbers, 0 = NIL
  int surface = 0;                              // primitives: 1-based surface descriptor
  Vec3 xyz{};                                   // translate / scale: x y z; sphere: centre
  char axis = 'x';                              // rotate: 'x', 'y' or 'z'
  double theta = 0.0;                           // rotate: degrees
  double radius = 0.0;                          // sphere, cylinder
  char textureAxis1 = 'x', textureAxis2 = 'y';  // sphere
  std::vector<int> vertices;  // cylinder: 2, polygon: n (1-based vertex table indices)
  // fractal
  int divisions = 0;  // fractal and spline
  double h = 0.0, offset = 0.0;
  std::int64_t seed = 0;
  bool constrained = true;
  // spline: nv groups of nu control vertices (row v, column u: controls[v * nu + u])
  int nu = 0, nv = 0;
  EndCondition uEnd = EndCondition::Single, vEnd = EndCondition::Single;
  double overlap = 0.0;
  std::vector<Vec3> controls;
  // A scale node with a 0.0 component: the manual's "warning, node ignored"
  // (Appendix 1 section 13). The reader keeps the node (its down and right
  // links still count) and records a warning; the builder treats it as the
  // identity, as a dummy node.
  bool ignored = false;
  io::InputLocation where;  // the node's header line
};

// What the lenient reader changed, and where ("line 12: read 'l' as '1'").
struct Repair {
  io::InputLocation where;
  std::string what;
};

struct SceneFile {
  std::string path;  // as given (texture paths are relative to its directory)
  NumbersOfThings numbers;
  ProgramParameters program;
  DisplayParameters display;
  std::vector<Vec3> vertices;           // vertex n is vertices[n - 1]
  std::vector<SurfaceRecord> surfaces;  // surface n is surfaces[n - 1]
  AmbienceRecord ambience;
  std::vector<LightRecord> lights;
  std::vector<NodeRecord> nodes;  // node n is nodes[n - 1]
  std::vector<Repair> repairs;    // lenient only; empty when strict
  // Non-fatal messages, strict or lenient: a value outside the range the
  // manual advises (a "typical" range), a scale node ignored, a parameter
  // given twice, a node the root cannot reach (docs/cgl/scene-format.md).
  std::vector<Repair> warnings;
};

struct ReadOptions {
  // Accept the document's OCR-damaged examples, recording each repair.
  bool lenient = false;
};

// Reads a whole scene file from `text`; `display` names it in messages.
// Checks the grammar and the table references (surface, vertex and node
// numbers exist, node numbers consecutive from 1, the root exists, the DAG
// has no cycle; shared subtrees are allowed). Throws io::InputError.
SceneFile readScene(const std::string& text, const std::string& display,
                    const ReadOptions& options = {});
// The same from a file (a regular file of at most 64 MiB).
SceneFile readSceneFile(const std::string& path, const ReadOptions& options = {});

// True when `text` (the first few kilobytes of a file) reads like a CGL scene
// file rather than a Malone number stream: a `*` comment line first, or a
// keyword of the format (depth, eye, lambert, phong, cook, infinity, sphere,
// ...) on one of its first lines.
bool looksLikeCgl(const std::string& text);

}  // namespace prime::cgl
