// The readers of films and bands (docs/films.md) on any bytes: a camera path
// (src/cli/camera_path_file.h: readCameraPath, then the path it makes and the
// camera of some frames) and a render record (src/cli/render_record.h). The
// first byte chooses which. Contract: each returns, or throws io::InputError
// naming the file (the path: also its line for a line's fault); never another
// exception, a crash or a hang. What a path returns keeps its promises: at
// least one key and one frame, and the camera of its first frame is its
// first key (the spline passes through its keys).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "legacy_io/common/error.h"
#include "src/cli/camera_path_file.h"
#include "src/cli/render_record.h"

namespace {

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
  std::abort();
}
void check(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

std::string scratch(const char* name) {
  static const std::string dir = [] {
    char tmpl[] = "/tmp/film_files_fuzz.XXXXXX";
    const char* d = ::mkdtemp(tmpl);
    if (d == nullptr) fail("no scratch directory");
    return std::string(d);
  }();
  return dir + "/" + name;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool path = (data[0] & 1u) == 0;
  const std::string file = scratch(path ? "key.path" : "piece.ppm.render");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    if (path) {
      const prime::cli::CameraPathFile f = prime::cli::readCameraPath(file);
      check(!f.spec.keys.empty(), "a path without keys was returned");
      const prime::CameraPath p = prime::cli::cameraPathOf(f);
      check(p.frames() >= 1, "a path of no frames");
      for (const int k : {1, p.frames() / 2, p.frames() - 1}) (void)p.camera(k, 8, 8);
      if (!f.spec.keys.front().frame || *f.spec.keys.front().frame == 0.0)
        check(p.camera(0, 8, 8).eye == f.spec.keys.front().eye,
              "frame 0 of a path whose first key is at frame 0 is not that key");
    } else {
      const std::string picture = scratch("piece.ppm");
      (void)prime::cli::readRecord(picture);
      (void)prime::cli::recordMatches(picture, "0123456789abcdef");
    }
  } catch (const prime::io::InputError& e) {
    check(std::string(e.what()).find(path ? "key.path" : "piece.ppm.render") != std::string::npos,
          std::string("the message does not name the file: ") + e.what());
  }
  return 0;
}
