// A probed pixel's ray tree drawn over the picture, for every system
// (`prime probe SCENE --pixel X Y --overlay OUT.png`): each ray a segment
// from its origin to its hit (or out of the picture when it misses),
// projected into the frame by the system's camera and coloured by kind,
// hits marked with a square, the probed pixel outlined, the picture under
// it dimmed. Nothing here knows a system: each gives its segments and its
// camera as a linear map from picture coordinates to ray directions.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "palette/png_image.h"
#include "src/math/vec.h"

namespace prime {

// A camera whose ray for the picture point (a, b) has the direction
// toFirst + a * across + b * down from `eye`; the picture coordinates of
// that point are (a + offsetX, b + offsetY), pixel (c, r) covering
// [c, c + 1) x [r, r + 1). (A camera through pixel centres has offset 0.5,
// one through top-left corners 0.)
struct PictureProjection {
  Vec3 eye{}, toFirst{}, across{}, down{};
  double offsetX = 0.5, offsetY = 0.5;
  // The picture point of `p` and its depth along the ray's direction
  // (s in p - eye = s (toFirst + a across + b down)); nullopt when the three
  // directions are degenerate. s <= 0: behind the eye.
  struct Point {
    double x = 0, y = 0, s = 0;
  };
  std::optional<Point> project(const Vec3& p) const;
};

enum class OverlayKind { Primary, Reflected, Transmitted, Shadow };

struct OverlaySegment {
  Vec3 from{}, to{};
  OverlayKind kind = OverlayKind::Primary;
  bool hit = false;  // `to` is a hit (marked); else the ray left the scene
};

// "primary", "reflected", "transmitted", "shadow" (and PRIME's names).
std::optional<OverlayKind> overlayKind(std::string_view name);

// The colour of each kind on the overlay (RGB).
std::array<std::uint8_t, 3> overlayColour(OverlayKind kind);

// Draws the segments over `picture` (dimmed to half), clipped at the eye
// and to the picture, and outlines pixel (column, row). `under`, if given,
// draws onto the dimmed picture before the rays (the probe's text panel: a
// ray may cross the text, the text never hides a ray).
Image8 drawRayOverlay(const Image8& picture, std::span<const OverlaySegment> segments,
                      const PictureProjection& camera, int column, int row,
                      const std::function<void(Image8&)>& under = {});

// The picture-space points of a segment as drawn (after clipping at the
// eye), for tests: nullopt when nothing of it is in front of the eye.
std::optional<std::array<PictureProjection::Point, 2>> projectSegment(
    const PictureProjection& camera, const OverlaySegment& segment);

}  // namespace prime
