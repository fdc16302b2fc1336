// loadScene on a scene directory of binary databases (prim/PrimFile,
// obj/List, obj/O<n>, map/Map<n>_?.map) and light/light.txt, written from the
// fuzz input (fuzz_support.h: split at "%%prime:<path>" lines). It must load,
// with every index the renderer follows checked, or throw an InputError.
#include "src/prime/scene/scene_loader.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz::ScratchScene scratch;
  scratch.fill(fuzz::splitScene(data, size));
  try {
    const Scene scene = loadScene(io::SceneDir(scratch.root()));
    // What the renderer relies on (scene.h): every index inside its table.
    const int prims = static_cast<int>(scene.prims.size());
    for (const auto& obj : scene.objects) {
      const int n = static_cast<int>(obj.entries.size());
      fuzz::check(n > 0, "object without entries loaded");
      fuzz::check(obj.boundPrim == -1 || (obj.boundPrim >= 0 && obj.boundPrim < prims),
                  "bound out of range");
      for (const auto& e : obj.entries) {
        if (e.op == 'P') {
          fuzz::check(e.l >= 0 && e.l < prims, "primitive index out of range loaded");
          const ScenePrim& p = scene.prims[e.l];
          for (int s = 0; s < io::surfaceCount(p.type); ++s)
            for (int side = 0; side < 2; ++side)
              fuzz::check(scene.map(p.map[s][side]) != nullptr,
                          "primitive names a map that is not loaded");
        } else {
          fuzz::check(e.l >= 0 && e.l < n && e.r >= 0 && e.r < n,
                      "child index out of range loaded");
        }
      }
    }
    for (const auto& m : scene.maps)
      for (const auto& ch : m.channel)
        fuzz::check(
            ch.size() == static_cast<std::size_t>(m.uScale) * static_cast<std::size_t>(m.vScale),
            "texel count is not uScale*vScale");
  } catch (const io::InputError& e) {
    fuzz::check(std::string(e.what()).find(": ") != std::string::npos, "message without a place");
  }
  return 0;
}
