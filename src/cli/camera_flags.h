// The free camera's flags, with one meaning for every system (docs/user-
// guide.md, "Cameras"): --eye X Y Z, --look-at X Y Z, --up X Y Z, --fov DEG
// (the vertical field of view, the full angle) and --size W H (square
// pixels), and --camera FILE, a file holding the same flags as text. The
// geometry is src/geom/free_camera.h's; each system keeps its own way of
// sampling a pixel. A system's own camera stays its default: a flag that is
// not given keeps that part of it.
//
// A camera file is plain text: one camera per line, written as the flags
// above (`--eye 500 500 -1500 --look-at 500 500 0 --up 0 1 0 --fov 36.87
// --size 512 512`); `#` starts a comment; blank lines are skipped. The key C
// of every window appends the camera it shows, so the last line is the
// newest: --camera FILE takes the last camera in the file. Numbers are
// written in the shortest form that reads back to the same double, so a
// camera written by C renders the very frame it was written from.
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "src/geom/free_camera.h"

namespace prime::cli {

struct CameraFlags {
  std::vector<double> eye, lookAt, up;
  double fov = 0.0;  // 0: not given
  std::vector<int> size;
  std::string file;  // --camera FILE
  // Whether any of the five, or a camera file, was given.
  bool given() const {
    return !eye.empty() || !lookAt.empty() || !up.empty() || fov > 0.0 || !size.empty() ||
           !file.empty();
  }
  // Whether a flag that makes a free camera was given (PRIME's --eye alone
  // moves the listing's eye: src/cli/prime/camera_options.h).
  bool freeGiven() const { return !lookAt.empty() || !up.empty() || fov > 0.0 || !size.empty(); }
};

// Adds --look-at, --up, --fov, --size and --camera to `cmd`, and --eye unless
// `eye` is false (PRIME adds its own --eye, which also moves the listing's
// eye). `what` names the system's own camera in the help ("the scene's viewer").
void addCameraFlags(CLI::App* cmd, CameraFlags& flags, const std::string& what, bool eye = true);
// --eye alone, with the system's own help text.
void addEyeFlag(CLI::App* cmd, CameraFlags& flags, const std::string& help);

// A camera file's line (after its comment is cut) split into words, with
// each word's column (1-based), and the camera flags among its words from
// `first` on. Throws io::InputError naming `file`, the line, the column and
// the word for anything that is not a camera flag with its values.
struct CameraLine {
  std::vector<std::string> words;
  std::vector<int> columns;
};
CameraLine splitCameraLine(const std::string& line);
// Every line of a camera file's text (line breaks normalized) that holds a
// word once its comment is cut, with its number (1-based).
std::vector<std::pair<int, CameraLine>> cameraFileLines(const std::string& text);
CameraFlags parseCameraFlags(const CameraLine& line, const std::string& file, int lineNo,
                             std::size_t first);

// The flags with --camera FILE's values filled in where the command line
// gave none (the command line's win). Throws io::InputError naming the file,
// line and word for anything that is not a camera.
CameraFlags withCameraFile(const CameraFlags& flags);

// The camera the flags (after withCameraFile) make of a system's own
// camera `own`: each flag given replaces its part; a size without --fov
// keeps the vertical field of view. Throws CLI::ValidationError for what
// cannot be a camera (the look-at point at the eye, ...), naming the flag.
FreeCameraSettings applyCameraFlags(const CameraFlags& flags, const FreeCameraSettings& own);

// The camera as the five flags (four without `size`), each number in the
// shortest text that reads back to the same double.
std::string cameraFlagsText(const FreeCameraSettings& camera, bool size = true);

// The number `text` names, read exactly (std::from_chars: the nearest
// double); nullopt for anything else, infinities and NaN included. And the
// shortest text that reads back to the same double.
std::optional<double> exactNumber(std::string_view text);
std::optional<int> exactInt(std::string_view text);
std::string numberText(double v);

// What a file holds that a window appends to (a camera file, a camera
// path): its text, ending in a line break, or "" when it does not exist;
// read as an output of the run (not recorded as an input). Throws
// io::InputError naming the file when it is larger than `cap`.
std::string textToAppendTo(const std::string& path, std::uint64_t cap, const std::string& what);

// Appends `camera` (after a `# comment` line, if any) to the camera file
// `path`, writing the whole file anew (io::OutputFile: all or nothing).
// Throws io::InputError naming the file.
void appendCamera(const std::string& path, const FreeCameraSettings& camera,
                  const std::string& comment);

// The C key of a window: prints the camera as flags on stdout and appends it
// (after `# comment`) to `file`, saying so on stderr; a failure to write is
// said, not thrown (the window stays). Without a camera (the system's own,
// which no flag reproduces, or needs none) it says how to get the frame.
void cameraKey(const std::optional<FreeCameraSettings>& camera, const std::string& comment,
               const std::string& file, const std::string& withoutCamera);

// The name the windows' C key appends to (the current directory, beside the
// screenshots): prime-cameras.txt.
inline constexpr const char* kDefaultCameraFile = "prime-cameras.txt";

}  // namespace prime::cli
