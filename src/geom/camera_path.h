// A camera path: keyframes of a free camera (src/geom/free_camera.h) and the
// camera of any frame between them, for films (`prime trace --camera-path`).
// No system's quirk lives here.
//
// Interpolation (docs/user-guide.md, "Camera paths"): one uniform
// Catmull-Rom spline through the keys' eye, look-at point, up vector and
// field of view together (a cubic Hermite curve per segment whose tangent at
// a key is half the difference of its neighbours; an open path's end keys
// take the one-sided difference; a loop wraps around). Speed is constant
// along the path: a key without a frame of its own is placed by the path's
// length, and between two keys that have frames the frames are spaced
// evenly by length, measured as the mean of the eye's and the look-at
// point's distances along the curve (so a camera that only turns moves at
// constant speed too). The camera of frame k is a pure function of the path
// and k: additions, multiplications and square roots in a fixed order,
// nothing that depends on the machine, the thread or an earlier frame.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/geom/free_camera.h"

namespace prime {

struct CameraKey {
  Vec3 eye{0, 0, 0}, lookAt{0, 0, 1}, up{0, 1, 0};
  double fovY = 40.0;
  std::optional<double> frame;  // the frame this key is at (fractional: a time); none: by length
};

struct CameraPathSpec {
  std::vector<CameraKey> keys;  // at least one
  // How many frames the path lasts (frames 0 .. frames-1); none: the last
  // key's frame + 1, else 60 frames a segment (2 s at 30 frames a second).
  std::optional<int> frames;
  bool loop = false;  // the path closes: after the last key comes the first again
};

// A fault of one key (its frame): which key, from 0, for a reader that
// knows where the key is written.
struct CameraKeyError : std::invalid_argument {
  CameraKeyError(int k, const std::string& what) : std::invalid_argument(what), key(k) {}
  int key;
};

class CameraPath {
 public:
  // Throws std::invalid_argument saying what is wrong (no key; fewer than 1
  // frame), CameraKeyError for a key's frame that does not increase or is past
  // the path's end.
  explicit CameraPath(CameraPathSpec spec);

  int frames() const { return frames_; }
  // The frame each key is at, after placing those the spec left open.
  const std::vector<double>& keyFrames() const { return keyFrames_; }
  // Frame k's camera (k in 0 .. frames-1; others are clamped), at the
  // given picture size.
  FreeCameraSettings camera(int k, int width, int height) const;

 private:
  CameraKey at(int segment, double u) const;  // u in [0, 1]
  double lengthAt(int segment, double u) const;
  int segments() const;

  CameraPathSpec spec_;
  int frames_ = 1;
  std::vector<double> keyFrames_;  // per key, and the loop's closing point last
  std::vector<double> table_;      // the length from key 0 at kSamples points a segment
};

}  // namespace prime
