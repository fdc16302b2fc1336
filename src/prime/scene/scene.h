// The in-memory scene: everything RayTrace.c re-read from files for every ray,
// loaded once and checked once, then shared read-only by all render threads.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "legacy_io/prime/records.h"
#include "legacy_io/prime/text_inputs.h"
#include "src/math/matrix.h"
#include "src/prime/geom/csg_1991.h"

namespace prime {

struct ScenePrim {
  // Checked by loadScene for every primitive an object uses (a leaf or a
  // bound). A record no object uses keeps its place (primitive numbers are
  // positions in PrimFile) but is never traced; if its type byte is not a
  // type letter it is loaded as a Sphere.
  io::PrimType type = io::PrimType::Sphere;
  Matrix4 transform{}, inverse{};
  std::array<std::array<int, 2>, io::kMaxSurface> map{};  // [surface][Out/In] map numbers
  int priority = 0;
};

struct SceneObject {
  int number = 0;                 // n of obj/O<n>
  std::vector<CsgEntry> entries;  // entry 0 is the CSG root (opcode, l, r)
  int boundPrim = -1;             // primitive number of the bounding volume, or -1
  io::Hue hue;
};

struct SceneTexture {
  int uScale = 0, vScale = 0;
  std::array<std::vector<double>, 3> channel;  // R, G, B texels, index u + uScale*v
  bool constant = false;                       // every texel equal in each channel
};

struct Scene {
  std::string name;                  // for titles and messages
  std::vector<ScenePrim> prims;      // by primitive number (PrimFile order)
  std::vector<SceneObject> objects;  // in obj/List order (GetObj)
  std::vector<SceneTexture> maps;    // by map number; uScale == 0 where absent
  Vec3 ambient{};                    // IA
  std::vector<io::LightSource> lights;
  Vec3 background{};  // InitBackground: black

  const SceneTexture* map(int number) const {
    return number >= 0 && number < static_cast<int>(maps.size()) && maps[number].uScale > 0
               ? &maps[number]
               : nullptr;
  }
};

}  // namespace prime
