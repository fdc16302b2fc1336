// Colour Plate 1 (thesis section 5.10): "a wireframe of a beta-spline surface
// ... both skew and tension are set to 1 at every knot. There are 64 control
// knots contained in an 8 by 8 matrix." The listing holds no code for it, so
// this draws the surface our way, onto the emulated 8514/A screen
// (palette/prime/screen.h: putpixel and line, clipped to 1024 x 768), seen through
// the same camera and window as the ray-traced plates (src/prime/render/camera.h).
//
// The knot file (scenes/prime/plate1/knots.txt) is plain whitespace-separated
// numbers, like the listing's text inputs:
//   rows cols          control vertices per column and per row (>= 4 each)
//   beta1 beta2        bias ("skew") and tension, the same at every knot
//   x y z              rows * cols control vertices, row by row
#pragma once
#include <string>

#include "legacy_io/prime/graph_file.h"
#include "palette/prime/screen.h"
#include "src/prime/plate1/beta_spline.h"
#include "src/prime/render/camera.h"

namespace prime::spline {

struct KnotFile {
  BetaShape shape;
  KnotGrid grid;
};

// Reads a knot file; errors name the file, line and field (io::InputError).
KnotFile readKnotFile(const std::string& path, const std::string& display);

struct WireframeOptions {
  CameraSettings camera;     // the listing's eye, window and viewport unless changed
  int curvesPerPatch = 4;    // iso-parametric curves per patch and direction
  int segmentsPerPatch = 8;  // straight pieces per patch along each curve
  bool net = false;          // also draw the control polygon
  // Palette indices (InitPalette's fixed entries, K17): 5 yellow, 2 red, 7
  // lavender. The screen starts cleared to 0 (black).
  int uColour = 5;  // curves of constant v (along the rows)
  int vColour = 2;  // curves of constant u (down the columns)
  int netColour = 7;
};

// Where a world point lands on the screen: the eye ray through it meets the
// window plane at windowLeft + a*stepAcross + b*stepDown (the camera's own
// steps, K23 included); the pixel is (left + a, top + b), unrounded. False for
// a point not in front of the eye.
class Projection {
 public:
  explicit Projection(const CameraSettings& camera);
  bool project(const Vec3& p, double& x, double& y) const;
  const ListingCamera& camera() const { return camera_; }

 private:
  ListingCamera camera_;
  Vec3 stepAcross_{}, stepDown_{};
};

struct Plate1Picture {
  Screen screen;        // the whole emulated screen, lines drawn
  io::GraphFile graph;  // the camera's viewport of it, as RayTrace.c would write it (K21, K22)
  int lines = 0;        // line() calls made
};

Plate1Picture drawPlate1(const KnotFile& knots, const WireframeOptions& options);

}  // namespace prime::spline
