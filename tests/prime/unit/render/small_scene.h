// A small in-memory scene for render tests: one 2 x 2 map (map 1), a grey
// ambient, one white light up and to the left, a dark blue background.
// prim() adds a primitive scaled, turned (10, 20, 0) degrees and moved;
// object() an object made of primitives.
#pragma once
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "src/prime/math/listing_matrix.h"
#include "src/prime/render/hall_1991.h"
#include "src/prime/scene/scene.h"

namespace prime::test {

struct SmallScene {
  Scene scene;

  SmallScene() {
    SceneTexture map;
    map.uScale = map.vScale = 2;
    for (auto& c : map.channel) c = {0.1, 0.5, 0.9, 0.3};
    scene.maps = {SceneTexture{}, map};
    scene.ambient = {0.2, 0.2, 0.2};
    scene.background = {0.05, 0.1, 0.15};
    scene.lights = {{{500, 1500, -1000}, {0.8, 0.8, 0.8}}};
  }

  int prim(char type, const Vec3& scale, const Vec3& at) {
    ScenePrim p;
    p.type = io::primType(type).value();
    p.transform = identity4();
    transform(p.transform, scale, at, {0, 0, 0}, {10, 20, 0});
    EXPECT_TRUE(inverse(p.transform, p.inverse));
    for (auto& m : p.map) m = {1, 1};
    scene.prims.push_back(p);
    return static_cast<int>(scene.prims.size()) - 1;
  }

  // Appends an object numbered in list order: opaque (kDT = 1), kDR and fDR
  // as given, kRH = kTH = 3, indx 1.5; `entries` is its CSG tree.
  void object(double kDR, const Rgb& fDR, std::vector<CsgEntry> entries) {
    SceneObject o;
    o.number = static_cast<int>(scene.objects.size()) + 1;
    o.hue = {kDR, 1.0, {fDR[0], fDR[1], fDR[2]}, 0.999, 3, 3, 1.5};
    o.entries = std::move(entries);
    scene.objects.push_back(o);
  }
  // A one-primitive object.
  void object(double kDR, const Rgb& fDR, int prim) { object(kDR, fDR, {CsgEntry{'P', prim, 0}}); }
};

// One reddish sphere of radius 200 at (500, 500, 200), in the listing's
// default view: the scene of the free-camera and walk tests.
inline Scene sphereScene() {
  SmallScene small;
  const int p = small.prim('S', {200, 200, 200}, {500, 500, 200});
  small.object(0.6, {0.9, 0.3, 0.2}, p);
  return small.scene;
}

}  // namespace prime::test
