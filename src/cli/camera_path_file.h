// Camera path files (docs/user-guide.md, "Camera paths"): plain text, one
// directive or key per line, `#` starts a comment, blank lines are skipped.
//
//   frames 240     how many frames the path lasts (0 .. 239); optional
//   fps 30         frames a second, for key times written as 2.5s and for
//                  `prime film` (default 30)
//   loop           the path closes: after the last key comes the first
//   size 1024 768  the pictures' size when --size is not given; optional
//   key 0 --eye X Y Z --look-at X Y Z --up X Y Z --fov DEG
//   key 2.5s --eye ...      a key at a time (2.5 s = frame 75 at 30 fps)
//   key --eye ...           a key placed by the path's length
//   --eye ...               the same (a camera file's line is a key)
//
// A key gives the camera flags of src/cli/camera_flags.h; a flag it leaves
// out takes the previous key's value (the first key's: the look-at point at
// the origin, up +y, a field of view of 40 degrees). So a camera file the C
// key of a window wrote is a path, each camera a key. The camera of each
// frame is src/geom/camera_path.h's.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "src/geom/camera_path.h"

namespace prime::cli {

struct CameraPathFile {
  std::string name;  // as the command line named it
  CameraPathSpec spec;
  double fps = 30.0;
  std::optional<std::array<int, 2>> size;  // `size W H`, else the keys' --size
  std::vector<int> keyLines;               // the line each key is written on
};

// Throws io::InputError naming the file, line, column and word.
CameraPathFile readCameraPath(const std::string& path);
// The path built from the file: io::InputError naming the file for a path
// that cannot be (key frames that do not increase, ...).
CameraPath cameraPathOf(const CameraPathFile& file);

// Where `prime walk`'s K key keeps a scene's path: DIR/camera.path for a
// scene directory, SCENE.path beside a scene file (in place of its extension).
std::string defaultPathFile(const std::string& scene);

// Appends `camera` as a key placed by length, creating the file with a
// header (`# comment`, fps 30) if it does not exist; written anew through
// io::OutputFile. Throws io::InputError naming the file.
void appendPathKey(const std::string& path, const FreeCameraSettings& camera,
                   const std::string& comment);

// A path that orbits `turns` times about the vertical (+y) line through
// `centre`, from `start`, in `frames` frames (a loop when turns is whole),
// with 24 keys a turn; `comment` heads it.
std::string orbitPathText(const FreeCameraSettings& start, const Vec3& centre, int frames,
                          int turns, const std::string& comment);

// A frame or row range as --frames and --rows take it: "A-B" (inclusive), or
// "A" alone; "A-" runs to `last`. Throws CLI::ValidationError naming `flag`.
struct Range {
  int first = 0, last = 0;
  int count() const { return last - first + 1; }
};
Range parseRange(const std::string& text, const std::string& flag, int last);

}  // namespace prime::cli
