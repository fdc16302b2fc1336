// The CGL scene-description file reader (legacy_io/cgl/scene_file.h) on any
// bytes, strict and lenient: it returns, or throws prime::io::InputError
// naming the file and a line. What it returns keeps its promises: the counts
// of the first record match the tables, every reference (surface, vertex,
// down, right, root) is in range, every number is finite, colour samples are
// 0 or more, a Cook surface has its 66 Fresnel vectors, and a repair is only
// ever reported by the lenient reader. looksLikeCgl never throws.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "legacy_io/cgl/scene_file.h"
#include "legacy_io/common/error.h"

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}
void check(bool ok, const char* what) {
  if (!ok) fail(what);
}
bool finite(const prime::Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}
void spectrum(const prime::cgl::Spectrum& s) {
  for (double v : s) check(std::isfinite(v) && v >= 0.0, "a bad colour sample");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace prime;
  using namespace prime::cgl;
  if (size > 200000) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  (void)looksLikeCgl(text);
  for (const bool lenient : {false, true}) {
    try {
      const SceneFile f = readScene(text, "fuzz.cgl", ReadOptions{lenient});
      const auto& n = f.numbers;
      check(f.vertices.size() == static_cast<std::size_t>(n.vertices), "vertex count");
      check(f.surfaces.size() == static_cast<std::size_t>(n.surfaces), "surface count");
      check(f.lights.size() == static_cast<std::size_t>(n.lights), "light count");
      check(f.nodes.size() == static_cast<std::size_t>(n.nodes), "node count");
      check(n.root >= 1 && n.root <= n.nodes, "root out of range");
      check(lenient || f.repairs.empty(), "a repair by the strict reader");
      check(finite(f.display.eye) && finite(f.display.sight) && finite(f.display.up),
            "a non-finite view");
      for (const auto& v : f.vertices) check(finite(v), "a non-finite vertex");
      for (const auto& s : f.surfaces) {
        if (!s.textured) spectrum(s.colour);
        check(s.fresnel.size() == (s.model == ShadingModel::Cook ? 66u : 0u), "fresnel count");
        for (const auto& v : s.fresnel) spectrum(v);
      }
      spectrum(f.ambience.colour);
      for (const auto& l : f.lights) {
        check(finite(l.xyz), "a non-finite light");
        spectrum(l.colour);
      }
      for (const auto& d : f.nodes) {
        check(d.down >= 0 && d.down <= n.nodes && d.right >= 0 && d.right <= n.nodes,
              "a link out of range");
        check(finite(d.xyz), "a non-finite node");
        if (d.kind == NodeKind::Sphere || d.kind == NodeKind::Cylinder ||
            d.kind == NodeKind::Polygon || d.kind == NodeKind::Fractal ||
            d.kind == NodeKind::Spline)
          check(d.surface >= 1 && d.surface <= n.surfaces, "a surface out of range");
        for (int v : d.vertices) check(v >= 1 && v <= n.vertices, "a vertex out of range");
        if (d.kind == NodeKind::Spline)
          check(
              d.controls.size() == static_cast<std::size_t>(d.nu) * static_cast<std::size_t>(d.nv),
              "spline control count");
      }
    } catch (const io::InputError& e) {
      check(e.where().file == "fuzz.cgl", "an error without the file");
      check(e.where().line.has_value(), "an error without a line");
      check(std::string(e.what()).rfind("fuzz.cgl:", 0) == 0, "a message without file:line");
    }
  }
  return 0;
}
