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
//
// A free camera (src/geom/free_camera.h: look-at, up, field of view, any size
// with square pixels) replaces the listing's when CameraSettings::free is set
// (T30, T31); PrimeCamera is the one the renderer, probe and trace use.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "src/geom/free_camera.h"
#include "src/geom/ray.h"

namespace prime {

struct CameraSettings {
  Vec3 eye{500.0, 500.0, -1500.0};
  Vec3 windowLeft{0.0, 1000.0, 0.0};                       // WLX, WLY, WLZ
  Vec3 windowRight{1000.0, 1000.0, 0.0};                   // WRX, WRY, WRZ
  double xMin = 0.66, yMin = 0.0, xMax = 1.0, yMax = 1.0;  // AssignScrPts
  int screenWidth = 1024, screenHeight = 768;              // getmaxx()+1, getmaxy()+1
  // Set: the free camera's rays for every profile instead of the listing's
  // eye and window (T31); the listing fields above are then unused, and the
  // picture is its own screen (width x height at 0, 0).
  std::optional<FreeCameraSettings> free;
};

// A camera's primary rays as one linear map: the direction of pixel
// (row, column) is toFirst + column * stepAcross + row * stepDown (the
// listing's accumulated steps agree to rounding), from `eye`.
struct LinearView {
  Vec3 eye{}, toFirst{}, stepAcross{}, stepDown{};
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
  // eye, WL - eye, the steps across and down (K23) as the constructor computed them.
  LinearView linearView() const;

 private:
  CameraSettings s_;
  int left_ = 0, top_ = 0, numPixAcross_ = 0, numPixDown_ = 0;
  std::vector<Vec3> across_, down_;
  Vec3 stepAcross_{}, stepDown_{};  // curAcross after j steps, curDown after i steps
};

// The listing's camera, or the free one when settings.free is set: what
// every PRIME render samples. The free camera's picture is its own screen
// (screenX(c) == c); its graph file header is (width - 1) x (height - 1),
// inclusive like the listing's (T32).
class PrimeCamera {
 public:
  // Throws std::invalid_argument as ListingCamera or FreeCamera does.
  explicit PrimeCamera(const CameraSettings& s);

  bool isFree() const { return free_.has_value(); }
  int columns() const { return free_ ? free_->columns() : listing_->columns(); }
  int rows() const { return free_ ? free_->rows() : listing_->rows(); }
  int numPixAcross() const { return columns() - 1; }
  int numPixDown() const { return rows() - 1; }
  int screenWidth() const { return free_ ? free_->columns() : settings_.screenWidth; }
  int screenHeight() const { return free_ ? free_->rows() : settings_.screenHeight; }
  int screenX(int column) const { return free_ ? column : listing_->screenX(column); }
  int screenY(int row) const { return free_ ? row : listing_->screenY(row); }
  Ray primaryRay(int row, int column) const {
    return free_ ? free_->primaryRay(row, column) : listing_->primaryRay(row, column);
  }
  Ray sampleRay(int row, int column, double fx, double fy) const {
    return free_ ? free_->sampleRay(row, column, fx, fy) : listing_->sampleRay(row, column, fx, fy);
  }
  LinearView linearView() const;
  const CameraSettings& settings() const { return settings_; }

 private:
  CameraSettings settings_;
  std::optional<ListingCamera> listing_;
  std::optional<FreeCamera> free_;
};

// The listing's world window as its rays see it: top-left WL, top-right WR,
// and the bottom the K23 step down implies (bottom-left at WL - WL = the
// origin, bottom-right at WR - WL).
std::array<Vec3, 4> listingWindowCorners(const CameraSettings& s);

// A free camera that frames the listing's world window from the listing's
// eye (T33): look-at the window's centre, up +y, the smallest vertical field
// of view that shows all four corners at width x height, square pixels.
FreeCameraSettings framedListingWindow(const CameraSettings& s, int width, int height);

}  // namespace prime
