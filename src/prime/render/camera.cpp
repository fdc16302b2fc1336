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

LinearView ListingCamera::linearView() const {
  return {s_.eye, s_.windowLeft - s_.eye, stepAcross_, stepDown_};
}

PrimeCamera::PrimeCamera(const CameraSettings& s) : settings_(s) {
  if (s.free)
    free_.emplace(*s.free);
  else
    listing_.emplace(s);
}

LinearView PrimeCamera::linearView() const {
  if (!free_) return listing_->linearView();
  return {free_->settings().eye, free_->toFirst(), free_->stepAcross(), free_->stepDown()};
}

std::array<Vec3, 4> listingWindowCorners(const CameraSettings& s) {
  return {s.windowLeft, s.windowRight, Vec3{0.0, 0.0, 0.0}, s.windowRight - s.windowLeft};
}

FreeCameraSettings framedListingWindow(const CameraSettings& s, int width, int height) {
  const std::array<Vec3, 4> c = listingWindowCorners(s);
  FreeCameraSettings f;
  f.eye = s.eye;
  f.lookAt = (c[0] + c[1] + c[2] + c[3]) * 0.25;
  f.up = {0.0, 1.0, 0.0};
  f.width = width;
  f.height = height;
  f.fovY = fitFovY(f.eye, f.lookAt, f.up, width, height, c);
  return f;
}

}  // namespace prime
