// The fixed camera and image window of RayTrace.c (lines 7059-7140) and the
// Coords module (3110-3216), every constant overridable:
//   eye (SourceX/Y/Z)       500, 500, -1500
//   world window            top-left WL = (0,1000,0), top-right WR = (1000,1000,0);
//                           the bottom is implied: wStepDown = -WL / numPixDown (K23)
//   AssignScrPts(0.66, 0.0, 1.0, 1.0) on a 1024 x 768 screen -> columns 675..1024,
//                           rows 0..768, both loops inclusive (K21): 350 x 769 rays,
//                           and the graph file header says 349 x 768 (K22).
// The sample points are accumulated by repeated addition exactly as the listing
// steps curAcross/curDown, so every ray is bit-identical to the original's.
#pragma once
#include <vector>

#include "src/geom/ray.h"

namespace prime {

struct CameraSettings {
  Vec3 eye{500.0, 500.0, -1500.0};
  Vec3 windowLeft{0.0, 1000.0, 0.0};                       // WLX, WLY, WLZ
  Vec3 windowRight{1000.0, 1000.0, 0.0};                   // WRX, WRY, WRZ
  double xMin = 0.66, yMin = 0.0, xMax = 1.0, yMax = 1.0;  // AssignScrPts
  int screenWidth = 1024, screenHeight = 768;              // getmaxx()+1, getmaxy()+1
};

class ListingCamera {
 public:
  // Throws std::invalid_argument for a viewport with no pixels.
  explicit ListingCamera(const CameraSettings& s);

  int numPixAcross() const { return numPixAcross_; }  // as written to the header
  int numPixDown() const { return numPixDown_; }
  int columns() const { return numPixAcross_ + 1; }  // inclusive loops
  int rows() const { return numPixDown_ + 1; }
  int screenX(int column) const { return left_ + column; }  // where PutPixel draws
  int screenY(int row) const { return top_ + row; }
  // The primary ray of (row, column): origin at the eye, direction to the
  // window point (MakeVector; CastRay normalises it).
  Ray primaryRay(int row, int column) const;
  // A ray through the pixel's footprint, offset by (fx, fy) pixel steps
  // across and down from the listing's sample point (|fx|, |fy| <= 0.5 for
  // supersampling). sampleRay(r, c, 0, 0) == primaryRay(r, c).
  Ray sampleRay(int row, int column, double fx, double fy) const;
  const CameraSettings& settings() const { return s_; }

 private:
  CameraSettings s_;
  int left_ = 0, top_ = 0, numPixAcross_ = 0, numPixDown_ = 0;
  std::vector<Vec3> across_, down_;
  Vec3 stepAcross_{}, stepDown_{};  // curAcross after j steps, curDown after i steps
};

}  // namespace prime
