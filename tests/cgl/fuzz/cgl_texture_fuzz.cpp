// The CGL package's texture maps (section 10) as a scene loads them
// (src/cgl/scene.h, buildScene): a scene-description file whose textured
// surfaces name RLE maps (legacy_io/cgl/frame.h) by a path relative to the
// scene, by base name in the scene's directory or its textures/, or `last`.
// One fuzz input is a whole scene directory: the scene file, then files
// introduced by marker lines
//     %%cgl:<name>\n<content>
// where <name> is a plain file name or textures/<plain name>; the content runs
// up to the next marker. They are written to a scratch directory (in memory
// where there is one) and read with readSceneFile and buildScene. Contract:
// they return, or throw prime::io::InputError naming a file and a line (the
// scene: a surface's texture not found, `last` first) or a byte offset (a
// map). What is built keeps its promises: every map is 512 x 512 texels of
// finite samples (negative ones are allowed: section 10 does not clip them);
// every textured surface has a map in range, every untextured one none; a
// map is loaded once, however many surfaces name it.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "legacy_io/common/error.h"
#include "src/cgl/scene.h"

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}
void check(bool ok, const char* what) {
  if (!ok) fail(what);
}

constexpr std::string_view kMarker = "%%cgl:";
constexpr std::size_t kMaxFiles = 8;

bool plainName(std::string_view n) {
  if (n.empty() || n.size() > 40 || n == "." || n == "..") return false;
  for (char c : n)
    if (c == '/' || c == '\0') return false;
  return true;
}

bool filePath(std::string_view n) {
  constexpr std::string_view sub = "textures/";
  if (n.substr(0, sub.size()) == sub) return plainName(n.substr(sub.size()));
  return plainName(n) && n != "scene.cgl" && n != "textures";
}

// One scratch directory per fuzzing process, refilled for every input.
std::filesystem::path scratch() {
  namespace fs = std::filesystem;
  static const fs::path root = [] {
    std::error_code ec;
    const fs::path shm = "/dev/shm";
    const fs::path base = fs::is_directory(shm, ec) && ::access(shm.c_str(), W_OK) == 0
                              ? shm
                              : fs::temp_directory_path();
    return base / ("prime-fuzz-cgl-texture-" + std::to_string(::getpid()));
  }();
  static const struct Cleanup {
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(root, ec);
    }
  } cleanup;
  return root;
}

void write(const std::filesystem::path& path, std::string_view content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace prime;
  using namespace prime::cgl;
  namespace fs = std::filesystem;
  if (size > 200000) return 0;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  const fs::path root = scratch();
  fs::remove_all(root);
  fs::create_directories(root / "textures");
  std::size_t at = in.find(kMarker);
  write(root / "scene.cgl", in.substr(0, at));
  for (std::size_t files = 0; at != std::string_view::npos && files < kMaxFiles; ++files) {
    const std::size_t nameStart = at + kMarker.size();
    const std::size_t eol = in.find('\n', nameStart);
    if (eol == std::string_view::npos) break;
    const std::size_t next = in.find(kMarker, eol + 1);
    const std::size_t end = next == std::string_view::npos ? in.size() : next;
    const std::string_view name = in.substr(nameStart, eol - nameStart);
    if (filePath(name)) write(root / std::string(name), in.substr(eol + 1, end - eol - 1));
    at = next;
  }
  const std::string scenePath = (root / "scene.cgl").string();
  try {
    const cgl::SceneFile file = readSceneFile(scenePath);
    BuildOptions options;
    options.maxObjects = 20000;  // the geometry is not what is fuzzed here
    const Scene scene = buildScene(file, options);
    check(scene.surfaces.size() == file.surfaces.size(), "surface count");
    check(scene.textures.size() <= kMaxFiles, "a map loaded twice");
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
      const int t = scene.surfaces[i].texture;
      if (file.surfaces[i].textured)
        check(t >= 0 && static_cast<std::size_t>(t) < scene.textures.size(), "a map out of range");
      else
        check(t == -1, "a map on an untextured surface");
    }
    for (const Texture& tex : scene.textures) {
      check(tex.texels.size() == 512u * 512u, "a map of the wrong size");
      for (const auto& texel : tex.texels)
        for (double v : texel) check(std::isfinite(v), "a non-finite texel sample");
    }
  } catch (const io::InputError& e) {
    const std::string msg = e.what();
    check(!e.where().file.empty(), "an error without a file");
    check(msg.rfind(e.where().file, 0) == 0, "a message that does not start with the file");
    check(e.where().line.has_value() || e.where().byte.has_value(),
          "an error without a line or a byte offset");
    if (e.where().file == scenePath)
      check(e.where().line.has_value(), "a scene error without a line");
    else
      check(e.where().byte.has_value(), "a map error without a byte offset");
  }
  return 0;
}
