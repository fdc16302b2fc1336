#include "src/cli/camera_path_file.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/text_reader.h"
#include "src/cli/camera_flags.h"
#include "src/geom/orbit_view.h"

namespace prime::cli {

namespace {

// A path of 1,800 frames has a few hundred keys at most; a megabyte is
// thousands of them.
constexpr std::uint64_t kPathFileCap = 1u << 20;
// A path longer than this many frames is a mistake (a day at 60 frames a second).
constexpr int kMaxFrames = 5'184'000;

Vec3 keyVec(const std::vector<double>& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

CameraPathFile readCameraPath(const std::string& path) {
  io::InputFileOptions options;
  options.maxBytes = kPathFileCap;
  options.what = "a camera path";
  const std::string text = io::normalizeLineBreaks(io::readInputText(path, options));
  CameraPathFile out;
  out.name = path;
  struct Pending {
    CameraKey key;
    std::optional<double> seconds;  // a key written as a time
  };
  std::vector<Pending> keys;
  CameraKey previous;  // what a key's missing flags take
  std::optional<std::array<int, 2>> keySize;
  for (const auto& entry : cameraFileLines(text)) {
    const int lineNo = entry.first;
    const CameraLine& words = entry.second;
    const std::string& head = words.words[0];
    auto where = [&](std::size_t w) {
      return io::InputLocation{path, lineNo, std::nullopt, words.columns[w],
                               static_cast<int>(w) + 1};
    };
    auto arguments = [&](std::size_t count, const std::string& what) {
      if (words.words.size() != count + 1)
        throw io::InputError(where(0), head, what,
                             std::to_string(words.words.size() - 1) + " values");
    };
    if (head == "frames") {
      arguments(1, "one whole number of frames, 1 .. " + std::to_string(kMaxFrames));
      const auto n = exactInt(words.words[1]);
      if (!n || *n < 1 || *n > kMaxFrames)
        throw io::InputError(where(1), "frames",
                             "a whole number of frames, 1 .. " + std::to_string(kMaxFrames),
                             io::quotedWord(words.words[1], 40));
      out.spec.frames = *n;
    } else if (head == "fps") {
      arguments(1, "one number of frames a second");
      const auto v = exactNumber(words.words[1]);
      if (!v || !(*v > 0.0) || *v > 1000.0)
        throw io::InputError(where(1), "fps", "frames a second, more than 0 and at most 1000",
                             io::quotedWord(words.words[1], 40));
      out.fps = *v;
    } else if (head == "loop") {
      arguments(0, "no value");
      out.spec.loop = true;
    } else if (head == "size") {
      arguments(2, "a width and a height in pixels");
      std::array<int, 2> wh{};
      for (int k = 0; k < 2; ++k) {
        const auto n = exactInt(words.words[static_cast<std::size_t>(k) + 1]);
        if (!n || *n < 1 || *n > 32767)
          throw io::InputError(where(static_cast<std::size_t>(k) + 1), "size",
                               "a whole number of pixels, 1 .. 32767",
                               io::quotedWord(words.words[static_cast<std::size_t>(k) + 1], 40));
        wh[static_cast<std::size_t>(k)] = *n;
      }
      out.size = wh;
    } else if (head == "key" || head.rfind("--", 0) == 0) {
      std::size_t first = head == "key" ? 1 : 0;
      Pending p;
      if (head == "key" && words.words.size() > 1 && words.words[1].rfind("--", 0) != 0) {
        std::string when = words.words[1];
        const bool seconds = !when.empty() && when.back() == 's';
        if (seconds) when.pop_back();
        const auto v = exactNumber(when);
        if (!v || *v < 0.0)
          throw io::InputError(where(1), "key",
                               "a frame (120) or a time in seconds (4s), not negative",
                               io::quotedWord(words.words[1], 40));
        if (seconds)
          p.seconds = *v;
        else
          p.key.frame = *v;
        first = 2;
      }
      const CameraFlags flags = parseCameraFlags(words, path, lineNo, first);
      CameraKey& k = p.key;
      k.eye = flags.eye.empty() ? previous.eye : keyVec(flags.eye);
      k.lookAt = flags.lookAt.empty() ? previous.lookAt : keyVec(flags.lookAt);
      k.up = flags.up.empty() ? previous.up : keyVec(flags.up);
      k.fovY = flags.fov > 0.0 ? flags.fov : previous.fovY;
      if (!flags.size.empty()) {
        const std::array<int, 2> wh{flags.size[0], flags.size[1]};
        if (keySize && *keySize != wh)
          throw io::InputError(where(0), "--size",
                               "the size every earlier key gave, " + std::to_string((*keySize)[0]) +
                                   " x " + std::to_string((*keySize)[1]) + " (a film has one size)",
                               std::to_string(wh[0]) + " x " + std::to_string(wh[1]));
        keySize = wh;
      }
      try {
        FreeCameraSettings check;
        check.eye = k.eye;
        check.lookAt = k.lookAt;
        check.up = k.up;
        check.fovY = k.fovY;
        const FreeCamera camera(check);
      } catch (const std::invalid_argument& e) {
        throw io::InputError(where(0), "key", "a camera", e.what());
      }
      previous = k;
      previous.frame.reset();
      keys.push_back(p);
      out.keyLines.push_back(lineNo);
    } else {
      throw io::InputError(where(0), "directive",
                           "one of frames, fps, loop, size, key, or a key's --eye ...",
                           io::quotedWord(head, 40));
    }
  }
  if (keys.empty())
    throw io::InputError(io::InputLocation{path}, "key", "at least one key (key --eye X Y Z ...)",
                         "none");
  for (Pending& p : keys) {
    if (p.seconds) p.key.frame = *p.seconds * out.fps;
    out.spec.keys.push_back(p.key);
  }
  if (!out.size) out.size = keySize;
  return out;
}

CameraPath cameraPathOf(const CameraPathFile& file) {
  try {
    return CameraPath(file.spec);
  } catch (const CameraKeyError& e) {
    // A loop's closing point is its first key again.
    const std::size_t k = static_cast<std::size_t>(e.key) < file.keyLines.size()
                              ? static_cast<std::size_t>(e.key)
                              : 0;
    io::InputLocation at{file.name};
    if (k < file.keyLines.size()) at.line = file.keyLines[k];
    throw io::InputError(at, e.what());
  } catch (const std::invalid_argument& e) {
    throw io::InputError(io::InputLocation{file.name}, e.what());
  }
}

std::string defaultPathFile(const std::string& scene) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(scene);
  // `.path`, not `.txt`: a PRIME scene takes every .txt of its directory
  // for a text input, and a newer one for databases out of date.
  if (fs::is_directory(p, ec)) return (p / "camera.path").string();
  fs::path beside = p;
  beside.replace_extension(".path");
  return beside.string();
}

void appendPathKey(const std::string& path, const FreeCameraSettings& camera,
                   const std::string& comment) {
  std::string text = textToAppendTo(path, kPathFileCap, "a camera path");
  if (text.empty())
    text =
        "# prime camera path (docs/films.md): one key a line, placed by length; add "
        "`frames N`\n# for its length (default: 60 frames a segment), `key FRAME` or "
        "`key SECONDSs` to time a key\nfps 30\nsize " +
        std::to_string(camera.width) + " " + std::to_string(camera.height) + "\n";
  if (!comment.empty()) text += "# " + comment + "\n";
  text += "key " + cameraFlagsText(camera, false) + "\n";
  io::OutputFile out(path);
  out.write(text);
  out.commit();
}

std::string orbitPathText(const FreeCameraSettings& start, const Vec3& centre, int frames,
                          int turns, const std::string& comment) {
  const int keys = 24 * turns;
  std::string text = "# " + comment + "\n";
  text += "# " + std::to_string(turns) + (turns == 1 ? " turn" : " turns") +
          " about the vertical line through " + numberText(centre[0]) + " " +
          numberText(centre[1]) + " " + numberText(centre[2]) + ", " + std::to_string(keys) +
          " keys\n";
  text += "frames " + std::to_string(frames) + "\nfps 30\nloop\nsize " +
          std::to_string(start.width) + " " + std::to_string(start.height) + "\n";
  for (int j = 0; j < keys; ++j) {
    OrbitView v = OrbitView::from(start, centre);
    v.orbit(360.0 * j / keys, 0.0);
    text += "key " + cameraFlagsText(v.camera(), false) + "\n";
  }
  return text;
}

Range parseRange(const std::string& text, const std::string& flag, int last) {
  Range r;
  const std::size_t dash = text.find('-', 1);
  const std::string a = text.substr(0, dash),
                    b = dash == std::string::npos ? a : text.substr(dash + 1);
  const auto first = exactInt(a);
  const auto second = b.empty() ? std::optional<int>(last) : exactInt(b);
  if (!first || !second)
    throw CLI::ValidationError(flag,
                               "expected FIRST-LAST (whole numbers, e.g. 0-119), FIRST, or "
                               "FIRST- (to the end); got " +
                                   text);
  r.first = *first;
  r.last = *second;
  if (r.first < 0 || r.last < r.first || r.last > last)
    throw CLI::ValidationError(flag, "expected a range within 0-" + std::to_string(last) +
                                         " with FIRST <= LAST; got " + text);
  return r;
}

}  // namespace prime::cli
