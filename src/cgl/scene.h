// The Waterloo CGL package's preprocessed scene (M. A. J. Sweeney, "The
// Waterloo CGL Ray Tracing Package", University of Waterloo CS-85-35, 1985,
// sections 1.2, 2-4, 7, 8.2, 9 and Appendix 1): what Preprocess makes of a
// scene file. The DAG is walked from the root with cumulative transforms
// (each applying to its node's down subtree only), right pointers before
// down pointers, every primitive becoming an object node prepended to the
// object list (the first processed is the last member), a `box` node holding
// the objects of its down subtree as its contents. Shared subtrees are
// instantiated once per path. The camera (Figure 40), the surfaces (with
// their texture maps turned into spectra once, here), the lights and the
// ambience are made ready for the tracer.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "legacy_io/cgl/frame.h"
#include "legacy_io/cgl/scene_file.h"
#include "src/cgl/colour.h"
#include "src/cgl/fractal.h"
#include "src/cgl/primitives.h"
#include "src/cgl/spline.h"
#include "src/geom/free_camera.h"
#include "src/geom/ray.h"
#include "src/render/picture_buffer.h"

namespace prime::cgl {

// The virtual screen of Figure 40: a primary ray from the viewpoint V has
// the direction S + (x - 256) X + (y - 256) Y, normalised (section 8.2),
// S = dist * sight, X = (width/512) * right, Y = (height/512) * up', right =
// normalise(up x sight) (Appendix 1 section 6), up' = up orthogonalised
// against the sight and normalised (CGL-Q40).
struct Camera {
  Vec3 eye{};
  Vec3 sight{}, right{}, up{};  // unit vectors
  Vec3 start{}, xpath{}, ypath{};
  // Through the screen point (x, y) (pixel corners are integers; y = 0 is
  // the bottom scanline).
  Ray primaryRay(double x, double y) const;
};

// The camera of display parameters (section 8.2, Appendix 1 section 6);
// throws io::InputError naming `path` for a sight of zero or an up vector
// along it.
Camera cameraOf(const DisplayParameters& display, const std::string& path);

// The display parameters as a free camera (src/geom/free_camera.h, CGL-D61):
// eye, eye + sight, up, the vertical field of view of the whole screen
// (2 atan(viewport height / 2 dist)), 512 x 512.
FreeCameraSettings freeCamera(const DisplayParameters& display);
// The display parameters of a free camera whose height H scanlines span its
// field of view: eye, sight = look-at - eye, up, dist 1, a square viewport of
// 512 * 2 tan(fov/2) / H (CGL-D61).
DisplayParameters displayOf(const FreeCameraSettings& camera);

// A texture map's texels as spectra: section 10 sets only the 450, 550 and
// 600 nm samples (indices 7, 17, 22), so those three are kept per texel.
struct Texture {
  static constexpr std::array<int, 3> kSamples{7, 17, 22};
  std::string path;  // where it was found
  // 512 * 512 texels, index row * 512 + column, row 0 the top of the image
  // (6 MB: in whole huge pages where the system grants them, LargeBuffer).
  LargeBuffer<std::array<double, 3>> texels;
};

struct Surface {
  ShadingModel model = ShadingModel::Lambert;
  double kr = 0, kt = 0, index = 0, kd = 0, ks = 0, e = 0;
  Spectrum colour{};  // D_lambda (untextured)
  int texture = -1;   // index into Scene::textures, -1 untextured
  double umod = 1, vmod = 1;
  int number = 0;  // 1-based, as in the file
  // Cook (section 9.9): the rms facet slope m (ks is k_s, colour D_lambda)
  // and the 66 Fresnel colour-vectors, 0 degrees first (src/cgl/cook.h).
  double m = 0;
  std::vector<Spectrum> fresnel;
};

struct Light {
  bool inScene = false;
  Vec3 xyz{};              // infinity: the unit direction to the light; inscene: its position
  Spectrum intensity{};    // I_lambda
  Spectrum intensityDw{};  // I_lambda dw
  double dw = 0;
};

struct Scene {
  std::string path;
  Camera camera;
  // The object list, flattened: a box is followed by its contents (up to
  // Object::skip); the tracer walks it in order.
  std::vector<Object> objects;
  std::vector<Surface> surfaces;
  std::vector<Texture> textures;
  std::vector<Light> lights;
  // Fractal surfaces (section 5): Object::fractal indexes this.
  std::vector<FractalSurface> fractals;
  std::vector<SplineSurface> splines;  // B-spline surfaces (Object::spline), section 6
  Spectrum ambient{};                  // k_a pi I_a lambda (section 9.6: "one colour-vector")
  std::vector<std::string> warnings;   // ignored scale nodes (Appendix 1 section 9)
  int primitives = 0, boxes = 0;       // counts of object nodes by kind
};

struct BuildOptions {
  // Directories searched for texture maps by their base name (`checkerboard`
  // or `checkerboard.rle`), after the scene file's own directory.
  std::vector<std::string> textureDirs;
  // Texture maps supplied by the caller (the tool's procedural stand-ins for
  // the document's lost /u/majsweeney/textures files), by base name; they
  // are looked up before any file (CGL-D41).
  std::vector<std::pair<std::string, Frame>> textures;
  // Used to turn texels into spectra (section 10).
  Phosphors phosphors = Phosphors::Electrohome;
  // Refuse DAGs that instantiate more object nodes than this (shared
  // subtrees multiply).
  long maxObjects = 4'000'000;
  // Refuse DAGs whose walk reaches more nodes than this, counting a node once
  // for every path to it: transform nodes shared by two parents double the
  // paths at each level, and cost the walk without making an object.
  long maxVisits = 16'000'000;
  // Refuse spline nodes whose refined meshes (section 6.3.3: (nu + 1) x
  // divisions + 3 points a direction) and box trees would take more than this
  // in all, at kSplineBytesPerPoint: checked before each is made.
  std::uint64_t maxSplineBytes = std::uint64_t{2} << 30;
  // `--profile modern`: spline surfaces are intersected by the modern
  // intersector (CGL-D180, buildModernCells), not the document's walk.
  bool modernSplines = false;
};

// What a refined spline point costs at the peak of building it, with its
// share of the box tree, for maxSplineBytes (measured: the peak resident
// memory of `prime export-pov`, which builds and renders nothing, for splines
// of 20 x 20 and 30 x 30 vertices at 64 divisions, 1.8 and 3.9 million
// points: 356 and 371 bytes a point).
inline constexpr std::uint64_t kSplineBytesPerPoint = 370;

// Preprocess. Throws io::InputError (located at the node, surface or light
// line) for what the port cannot render: spline nodes (part 2 of the
// port), a textured fractal whose texture frame fails (section 5.3),
// degenerate polygons and cylinders, polygons
// other than triangles and rectangles, a missing texture (naming every place
// looked).
Scene buildScene(const SceneFile& file, const BuildOptions& options = {});

// The object list, which the program printed for inspection (Appendix 1,
// scene nodes): one line per object node, a box's contents indented.
std::string describeObjects(const Scene& scene);

}  // namespace prime::cgl
