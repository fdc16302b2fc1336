// A free camera steered by hand (`prime walk`): the eye looks at a target
// point from a distance, turned by yaw about the world's up (+y) and pitch
// above the horizon, both in degrees. Orbiting turns the whole camera (eye
// and target) rigidly about a pivot, by default the target itself; a pivot
// elsewhere (the centre of the scene's objects) stays on the same pixel of
// the picture however far the camera turns, so the scene stays in view.
// Panning moves the target, the eye and the pivot in the picture's plane;
// dollying scales the distance. No system's quirk.
//
// yaw 0, pitch 0 puts the eye on the target's -z side looking down +z (the
// listing's view); positive yaw swings the eye towards +x, positive pitch
// raises it.
#pragma once
#include "src/geom/free_camera.h"

namespace prime {

struct OrbitView {
  Vec3 target{0, 0, 0};
  Vec3 pivot{0, 0, 0};  // what orbit() turns about
  double distance = 1.0;
  double yaw = 0.0, pitch = 0.0;  // degrees; pitch kept within +-89
  double fovY = 40.0;
  int width = 640, height = 480;

  // The orbit that reproduces `camera`'s eye, look-at, fov and size (its up
  // is taken as +y), turning about its look-at point.
  static OrbitView from(const FreeCameraSettings& camera);
  // The same, turning about `pivot`.
  static OrbitView from(const FreeCameraSettings& camera, const Vec3& pivot);
  FreeCameraSettings camera() const;
  Vec3 eye() const;

  // Turns the camera about the pivot: yaw about the world's up through it,
  // pitch about the picture's horizontal through it (kept within +-89).
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
