// Test helpers: a Malone scene from text, with a viewer and a plain surface
// added where the test does not care about them.
#pragma once
#include <cmath>
#include <string>

#include "legacy_io/malone/input.h"
#include "src/malone/primitives.h"
#include "src/malone/scene.h"

namespace prime::malone::test {

// A plain white diffuse surface.
inline const std::string kSurface = " 100 1 1 1 0 1 1 0 1\n";
// A viewer at (0, 0, 10) looking at the origin, 8 x 8.
inline const std::string kViewer = "102 0 0 10 0 0 0 1 0 0 0 1 0 8 8\n";

// `objects` (primitives with their surfaces, lights ...) plus the viewer.
inline Scene sceneOf(const std::string& objects) {
  return buildScene(readScene(kViewer + objects, "test.mal"), "test.mal");
}

inline Vec3 unitVec(const Vec3& v) {
  return v * (1.0 / std::sqrt(dot(v, v)));
}

inline MRay rayOf(const Vec3& o, const Vec3& d, double length = kInfinite) {
  return MRay{o, unitVec(d), length};
}

}  // namespace prime::malone::test
