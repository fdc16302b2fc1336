// A free camera steered by hand (`prime walk`): the eye orbits a target
// point at a distance, by yaw about the world's up (+y) and pitch above the
// horizon, both in degrees; panning moves the target (and the eye with it)
// in the picture's plane; dollying scales the distance. No system's quirk.
//
// yaw 0, pitch 0 puts the eye on the target's -z side looking down +z (the
// listing's view); positive yaw swings the eye towards +x, positive pitch
// raises it.
#pragma once
#include "src/geom/free_camera.h"

namespace prime {

struct OrbitView {
  Vec3 target{0, 0, 0};
  double distance = 1.0;
  double yaw = 0.0, pitch = 0.0;  // degrees; pitch kept within +-89
  double fovY = 40.0;
  int width = 640, height = 480;

  // The orbit that reproduces `camera`'s eye, look-at, fov and size (its up
  // is taken as +y).
  static OrbitView from(const FreeCameraSettings& camera);
  FreeCameraSettings camera() const;
  Vec3 eye() const;

  void orbit(double dYaw, double dPitch);
  // Moves target and eye by (dx, dy) pixels of the picture at the target's
  // distance (right and up), so a dragged point follows the mouse.
  void pan(double dxPixels, double dyPixels);
  // distance *= factor (factor > 0), never below 1e-6 of the original unit.
  void dolly(double factor);
  // The world distance one pixel spans at the target.
  double pixelAtTarget() const;
};

}  // namespace prime
