#include "src/prime/render/camera.h"

#include <stdexcept>
#include <string>

namespace prime {

// SetScrCoordsX/Y: (int)(normalised * (getmax + 1)).
static int scr(double normalised, int size) {
  return static_cast<int>(normalised * static_cast<double>(size));
}

ListingCamera::ListingCamera(const CameraSettings& s) : s_(s) {
  left_ = scr(s.xMin, s.screenWidth);
  top_ = scr(s.yMin, s.screenHeight);
  numPixAcross_ = scr(s.xMax, s.screenWidth) - left_;
  numPixDown_ = scr(s.yMax, s.screenHeight) - top_;
  if (numPixAcross_ <= 0 || numPixDown_ <= 0 || numPixAcross_ > 32767 || numPixDown_ > 32767)
    throw std::invalid_argument("viewport " + std::to_string(s.xMin) + "," +
                                std::to_string(s.yMin) + " .. " + std::to_string(s.xMax) + "," +
                                std::to_string(s.yMax) + " on a " + std::to_string(s.screenWidth) +
                                "x" + std::to_string(s.screenHeight) + " screen gives " +
                                std::to_string(numPixAcross_) + " x " +
                                std::to_string(numPixDown_) + " pixel steps; need at least 1 x 1");
  Vec3 stepAcross{}, stepDown{};
  for (int i = 0; i < 3; ++i) {
    stepAcross[i] = (s.windowRight[i] - s.windowLeft[i]) / static_cast<double>(numPixAcross_);
    stepDown[i] = (-s.windowLeft[i] / static_cast<double>(numPixDown_));  // K23
  }
  stepAcross_ = stepAcross;
  stepDown_ = stepDown;
  across_.assign(columns(), Vec3{});
  down_.assign(rows(), Vec3{});
  for (int j = 1; j < columns(); ++j)
    for (int k = 0; k < 3; ++k) across_[j][k] = across_[j - 1][k] + stepAcross[k];
  for (int i = 1; i < rows(); ++i)
    for (int k = 0; k < 3; ++k) down_[i][k] = down_[i - 1][k] + stepDown[k];
}

Ray ListingCamera::primaryRay(int row, int column) const {
  Ray ray;
  ray.o = s_.eye;
  for (int k = 0; k < 3; ++k) {
    const double curPt = s_.windowLeft[k] + across_[column][k] + down_[row][k];
    ray.d[k] = curPt - ray.o[k];  // MakeVector(xO, curPt)
  }
  return ray;
}

Ray ListingCamera::sampleRay(int row, int column, double fx, double fy) const {
  Ray ray = primaryRay(row, column);
  if (fx != 0.0 || fy != 0.0)
    for (int k = 0; k < 3; ++k) ray.d[k] += fx * stepAcross_[k] + fy * stepDown_[k];
  return ray;
}

}  // namespace prime
