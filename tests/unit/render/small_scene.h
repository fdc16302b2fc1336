// A small in-memory scene for render tests: one 2 x 2 map (map 1), a grey
// ambient, one white light up and to the left, a dark blue background.
// prim() adds a primitive scaled, turned (10, 20, 0) degrees and moved.
#pragma once
#include <gtest/gtest.h>

#include "src/scene/scene.h"

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
    p.type = type;
    p.transform = identity4();
    transform(p.transform, scale, at, {0, 0, 0}, {10, 20, 0});
    EXPECT_TRUE(inverse(p.transform, p.inverse));
    for (auto& m : p.map) m = {1, 1};
    scene.prims.push_back(p);
    return static_cast<int>(scene.prims.size()) - 1;
  }
};

}  // namespace prime::test
