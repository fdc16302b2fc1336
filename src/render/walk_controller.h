// What the keys and the mouse of `prime walk` do to the view, apart from any
// window (so it can be tested with synthetic input): the orbiting camera,
// the light positions, the profile and the view mode. Every change bumps
// generation(), which the window compares with the frame it shows to
// abandon it and render again (T39).
#pragma once
#include <cstdint>
#include <vector>

#include "src/geom/orbit_view.h"

namespace prime {

class WalkController {
 public:
  // The step sizes (T40): a key orbits 5 degrees or pans 16 pixels, a
  // dolly step scales the distance by 0.9 (in) or 1 / 0.9 (out), a dragged
  // pixel orbits 0.4 degrees; a light moves 16 pixels' worth at the target's
  // distance per key, or a tenth of the camera's distance per dolly step.
  static constexpr double kOrbitStep = 5.0, kPanStep = 16.0, kDollyStep = 0.9, kDragDegrees = 0.4;

  WalkController(const OrbitView& start, std::vector<Vec3> lights, int profiles);

  // Arrows: orbit (or, with a light selected, move it right/up in the picture).
  void arrows(int dx, int dy);
  // Shift + arrows: pan (or move the light, as arrows).
  void panArrows(int dx, int dy);
  // W / + / wheel up: steps > 0 closer; S / - / wheel down: farther. A
  // selected light moves along the view instead.
  void dolly(int steps);
  // A drag of (dx, dy) pixels (right, down) with the left (orbit) or right
  // (pan) button; with a light selected, either moves the light with the mouse.
  void drag(bool leftButton, int dx, int dy);
  void reset();              // Home / R: the starting view and lights
  void selectLight(int n);   // 1..lights: that light; 0 the camera
  void cycleSelection();     // L: camera, light 1, light 2, ..., camera
  void nextProfile();        // F
  void togglePaletteView();  // V: true colour or the 8514/A palette

  std::uint64_t generation() const { return generation_; }
  const OrbitView& view() const { return view_; }
  const std::vector<Vec3>& lights() const { return lights_; }
  int selectedLight() const { return selected_; }  // 0: none (the camera moves)
  int profile() const { return profile_; }
  bool paletteView() const { return paletteView_; }

 private:
  void moveLight(double dxPixels, double dyPixels, double forward);
  void changed() { ++generation_; }
  OrbitView start_, view_;
  std::vector<Vec3> startLights_, lights_;
  int profiles_, profile_ = 0, selected_ = 0;
  bool paletteView_ = false;
  std::uint64_t generation_ = 1;
};

}  // namespace prime
