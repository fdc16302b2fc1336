#include "src/cli/camera_flags.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "legacy_io/common/charconv.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/text_reader.h"

namespace prime::cli {

namespace {

// A camera file is a few lines; a megabyte is thousands of cameras.
constexpr std::uint64_t kCameraFileCap = 1u << 20;

// What each flag takes, for the command line and the file alike.
struct FlagShape {
  const char* name;
  int count;
  bool integer;
};
constexpr FlagShape kShapes[] = {{"--eye", 3, false},
                                 {"--look-at", 3, false},
                                 {"--up", 3, false},
                                 {"--fov", 1, false},
                                 {"--size", 2, true}};

// Checks and stores one flag's values; returns what is wrong, or "".
std::string store(CameraFlags& f, const FlagShape& shape, const std::vector<std::string>& words) {
  std::vector<double> v;
  for (const std::string& w : words) {
    if (shape.integer) {
      const auto n = exactInt(w);
      if (!n || *n < 1 || *n > 32767) return "a whole number of pixels, 1 .. 32767";
      v.push_back(*n);
    } else {
      const auto n = exactNumber(w);
      if (!n) return "a finite decimal number";
      v.push_back(*n);
    }
  }
  const std::string name = shape.name;
  if (name == "--eye") f.eye = v;
  if (name == "--look-at") f.lookAt = v;
  if (name == "--up") f.up = v;
  if (name == "--fov") {
    if (!(v[0] > 0.0 && v[0] < 180.0)) return "degrees, more than 0 and less than 180";
    f.fov = v[0];
  }
  if (name == "--size") f.size = {static_cast<int>(v[0]), static_cast<int>(v[1])};
  return "";
}

void addFlag(CLI::App* cmd, CameraFlags& flags, const FlagShape& shape, const std::string& help) {
  cmd->add_option_function<std::vector<std::string>>(
         shape.name,
         [&flags, shape](const std::vector<std::string>& words) {
           const std::string wrong = store(flags, shape, words);
           if (!wrong.empty()) {
             std::string got;
             for (const std::string& w : words) got += (got.empty() ? "" : " ") + w;
             throw CLI::ValidationError(shape.name, "expected " + wrong + "; got " + got);
           }
         },
         help)
      ->expected(shape.count)
      ->allow_extra_args(false)
      ->type_name(shape.count == 3   ? "X Y Z"
                  : shape.count == 2 ? "W H"
                                     : "DEG");
}

Vec3 vec(const std::vector<double>& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

// The number `text` names, read exactly (std::from_chars: the nearest double,
// not through a long double as CLI11 reads); nullopt for anything else,
// infinities and NaN included.
std::optional<double> exactNumber(std::string_view text) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  double v = 0.0;
  const auto r = io::fromChars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

std::optional<int> exactInt(std::string_view text) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  int v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
  return v;
}

std::string numberText(double v) {
  char buf[64];
  const auto r = io::toChars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

void addEyeFlag(CLI::App* cmd, CameraFlags& flags, const std::string& help) {
  addFlag(cmd, flags, kShapes[0], help);
}

void addCameraFlags(CLI::App* cmd, CameraFlags& flags, const std::string& what, bool eye) {
  const std::string keeps = " (default: " + what + ")";
  if (eye) addFlag(cmd, flags, kShapes[0], "Camera: the eye's position" + keeps);
  addFlag(cmd, flags, kShapes[1], "Camera: the point looked at" + keeps);
  addFlag(cmd, flags, kShapes[2], "Camera: the up direction" + keeps);
  addFlag(cmd, flags, kShapes[3], "Camera: the vertical field of view, the full angle" + keeps);
  addFlag(cmd, flags, kShapes[4], "Camera: the picture's size, square pixels" + keeps);
  cmd->add_option("--camera", flags.file,
                  "Camera: the last camera of a camera file (the C key of a window appends to "
                  "one); flags given as well win")
      ->type_name("FILE");
}

std::string textToAppendTo(const std::string& path, std::uint64_t cap, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return "";
  // Read as this run's own output, not as an input (which no output of the
  // run may replace: the second C of a window would be refused).
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(cap) + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (!in.eof() && !in)
    throw io::InputError(io::InputLocation{path}, "cannot read " + what + " to append to it");
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > cap)
    throw io::InputError(io::InputLocation{path}, "file size",
                         "at most " + std::to_string(cap) + " bytes for " + what,
                         "more: not appending to it");
  if (!text.empty() && text.back() != '\n') text += '\n';
  return text;
}

CameraLine splitCameraLine(const std::string& line) {
  CameraLine out;
  for (std::size_t i = 0; i < line.size();) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    out.words.push_back(line.substr(i, j - i));
    out.columns.push_back(static_cast<int>(i) + 1);
    i = j;
  }
  return out;
}

std::vector<std::pair<int, CameraLine>> cameraFileLines(const std::string& text) {
  std::vector<std::pair<int, CameraLine>> lines;
  int lineNo = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++lineNo;
    std::string line = text.substr(start, end - start);
    start = end + 1;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    CameraLine words = splitCameraLine(line);
    if (!words.words.empty()) lines.emplace_back(lineNo, std::move(words));
  }
  return lines;
}

CameraFlags parseCameraFlags(const CameraLine& line, const std::string& file, int lineNo,
                             std::size_t first) {
  const std::vector<std::string>& words = line.words;
  CameraFlags cam;
  for (std::size_t w = first; w < words.size();) {
    io::InputLocation where{file, lineNo, std::nullopt, line.columns[w], static_cast<int>(w) + 1};
    const FlagShape* shape = nullptr;
    for (const FlagShape& s : kShapes)
      if (words[w] == s.name) shape = &s;
    if (shape == nullptr)
      throw io::InputError(where, "flag", "one of --eye, --look-at, --up, --fov, --size",
                           io::quotedWord(words[w], 40));
    std::vector<std::string> values;
    for (int k = 1; k <= shape->count; ++k) {
      if (w + static_cast<std::size_t>(k) >= words.size())
        throw io::InputError(where, shape->name, std::to_string(shape->count) + " values after it",
                             std::to_string(k - 1));
      values.push_back(words[w + static_cast<std::size_t>(k)]);
    }
    const std::string wrong = store(cam, *shape, values);
    if (!wrong.empty()) {
      std::string got;
      for (const std::string& v : values) got += (got.empty() ? "" : " ") + v;
      throw io::InputError(where, shape->name, wrong, io::quotedWord(got, 80));
    }
    w += static_cast<std::size_t>(shape->count) + 1;
  }
  return cam;
}

CameraFlags withCameraFile(const CameraFlags& flags) {
  if (flags.file.empty()) return flags;
  io::InputFileOptions options;
  options.maxBytes = kCameraFileCap;
  options.what = "a camera file";
  const std::string text = io::normalizeLineBreaks(io::readInputText(flags.file, options));
  // The last camera line.
  CameraFlags fromFile;
  int cameraLine = 0;
  for (const auto& entry : cameraFileLines(text)) {
    const int lineNo = entry.first;
    const CameraLine& words = entry.second;
    fromFile = parseCameraFlags(words, flags.file, lineNo, 0);
    cameraLine = lineNo;
  }
  if (cameraLine == 0)
    throw io::InputError(io::InputLocation{flags.file}, "camera", "a line of camera flags",
                         "no camera (only comments or blank lines)");
  CameraFlags out = flags;
  if (out.eye.empty()) out.eye = fromFile.eye;
  if (out.lookAt.empty()) out.lookAt = fromFile.lookAt;
  if (out.up.empty()) out.up = fromFile.up;
  if (!(out.fov > 0.0)) out.fov = fromFile.fov;
  if (out.size.empty()) out.size = fromFile.size;
  return out;
}

FreeCameraSettings applyCameraFlags(const CameraFlags& flags, const FreeCameraSettings& own) {
  FreeCameraSettings c = own;
  if (!flags.eye.empty()) c.eye = vec(flags.eye);
  if (!flags.lookAt.empty()) c.lookAt = vec(flags.lookAt);
  if (!flags.up.empty()) c.up = vec(flags.up);
  if (flags.fov > 0.0) c.fovY = flags.fov;
  if (!flags.size.empty()) {
    c.width = flags.size[0];
    c.height = flags.size[1];
  }
  try {
    const FreeCamera check(c);  // refuses what cannot be a camera, naming the part
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("camera", e.what());
  }
  return c;
}

std::string cameraFlagsText(const FreeCameraSettings& c, bool size) {
  auto v3 = [](const Vec3& v) {
    return numberText(v[0]) + " " + numberText(v[1]) + " " + numberText(v[2]);
  };
  return "--eye " + v3(c.eye) + " --look-at " + v3(c.lookAt) + " --up " + v3(c.up) + " --fov " +
         numberText(c.fovY) +
         (size ? " --size " + std::to_string(c.width) + " " + std::to_string(c.height) : "");
}

void appendCamera(const std::string& path, const FreeCameraSettings& camera,
                  const std::string& comment) {
  std::string text = textToAppendTo(path, kCameraFileCap, "a camera file");
  if (!comment.empty()) text += "# " + comment + "\n";
  text += cameraFlagsText(camera) + "\n";
  io::OutputFile out(path);
  out.write(text);
  out.commit();
}

void cameraKey(const std::optional<FreeCameraSettings>& camera, const std::string& comment,
               const std::string& file, const std::string& withoutCamera) {
  if (!camera) {
    std::fprintf(stderr, "prime: camera: %s\n", withoutCamera.c_str());
    return;
  }
  std::printf("%s\n", cameraFlagsText(*camera).c_str());
  std::fflush(stdout);
  try {
    appendCamera(file, *camera, comment);
    std::fprintf(stderr, "prime: camera appended to %s (--camera %s renders this frame)\n",
                 file.c_str(), file.c_str());
  } catch (const std::exception& err) {
    std::fprintf(stderr, "prime: camera not saved: %s\n", err.what());
  }
}

}  // namespace prime::cli
