#include "src/cli/film.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "legacy_io/common/digest.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/run_inputs.h"
#include "src/cli/camera_flags.h"
#include "src/cli/option_values.h"
#include "src/cli/render_record.h"

namespace prime::cli {

namespace {

// Flags that change no pixel of any output: the outputs' names, threads,
// the window, messages, and films' and bands' own.
bool pixelFree(const CLI::Option* o) {
  static const char* const names[] = {"--out",          "--ppm",         "--rle",
                                      "--raw",          "--png",         "--true-color-png",
                                      "--png-8514",     "--threads",     "--quiet",
                                      "--timings",      "--no-window",   "--zoom",
                                      "--fullscreen",   "--scale",       "--no-wait",
                                      "--pace",         "--camera-path", "--frames",
                                      "--rows",         "--help",        "--model",
                                      "--png-upscaled", "--upscale-fit"};
  for (const std::string& n : o->get_lnames())
    for (const char* x : names)
      if (n == std::string(x).substr(2)) return true;
  return !o->nonpositional();  // the scene: its files' bytes count, not its name
}

// Every setting given that changes pixels, as text (`--jitter=4` lines,
// in the command's order of options: the same for any order given).
std::string pixelSettings(const CLI::App* cmd) {
  std::string text;
  for (const CLI::Option* o : cmd->get_options()) {
    if (o->count() == 0 || pixelFree(o)) continue;
    text += o->get_name();
    // A flag as it is given (--frame-listing-window), an option with its values.
    if (o->get_type_size() != 0)
      for (const std::string& r : o->results()) text += " " + r;
    text += "\n";
  }
  return text;
}

int runFilm(const CLI::App* cmd, TraceFlags& flags, const TraceFactory& make,
            const std::string& system) {
  if (flags.camera == nullptr)
    throw CLI::ValidationError("--camera-path", system + " has no free camera to move");
  CameraFlags& cam = *flags.camera;
  if (!cam.eye.empty() || !cam.lookAt.empty() || !cam.up.empty() || cam.fov > 0.0 ||
      !cam.file.empty())
    throw CLI::ValidationError("--camera-path",
                               "the path gives every frame's camera: --eye, --look-at, --up, "
                               "--fov and --camera cannot be given with it (--size can)");
  const CameraPathFile file = readCameraPath(flags.cameraPath);
  const CameraPath path = cameraPathOf(file);
  const Range range =
      parseRange(flags.frames.empty() ? "0-" : flags.frames, "--frames", path.frames() - 1);
  // The outputs, each a pattern of the frame number.
  std::vector<std::string*> names = {&flags.png, &flags.trueColourPng, &flags.png8514};
  names.insert(names.end(), flags.ownOutputs.begin(), flags.ownOutputs.end());
  // One frame may name its files as they are (a job of a band of frame K).
  std::vector<std::string> patterns;
  for (std::string* n : names) {
    if (!n->empty() && (range.count() > 1 || n->find('%') != std::string::npos))
      checkFramePattern(*n);
    patterns.push_back(*n);
  }
  const CameraFlags original = cam;
  std::vector<bool> onceOriginal;
  for (bool* b : flags.firstFrameOnly) onceOriginal.push_back(*b);
  const LiveOptions live = flags.live;
  flags.live.noWindow = true;  // a film renders headless: no window a frame
  if (!live.noWindow) flags.live.headlessBecause = "--camera-path: a film renders headless";
  flags.live.noWait = true;
  if (cam.size.empty() && file.size) cam.size = {(*file.size)[0], (*file.size)[1]};
  auto restore = [&] {
    for (std::size_t i = 0; i < names.size(); ++i) *names[i] = patterns[i];
    cam = original;
    flags.live = live;
    for (std::size_t i = 0; i < onceOriginal.size(); ++i)
      *flags.firstFrameOnly[i] = onceOriginal[i];
  };
  RecordContext record;
  record.system = system;
  record.settings = pixelSettings(cmd);
  record.notInputs = {flags.cameraPath};
  const int n = range.count();
  int rendered = 0, skipped = 0;
  double renderSeconds = 0;
  const auto start = std::chrono::steady_clock::now();
  try {
    for (int k = range.first; k <= range.last; ++k) {
      for (std::size_t i = 0; i < names.size(); ++i)
        if (!patterns[i].empty()) *names[i] = frameName(patterns[i], k);
      const FreeCameraSettings c = path.camera(k, 1, 1);
      cam.eye = {c.eye[0], c.eye[1], c.eye[2]};
      cam.lookAt = {c.lookAt[0], c.lookAt[1], c.lookAt[2]};
      cam.up = {c.up[0], c.up[1], c.up[2]};
      cam.fov = c.fovY;
      const std::unique_ptr<TraceJob> job = make();
      if (k == range.first && range.count() > 1 && job->writesWithoutOutputs() &&
          !flags.ownOutputs.empty() && flags.ownOutputs[0]->empty())
        throw CLI::ValidationError("--frames", "needs --out PATTERN (frame%04d): " + system +
                                                   " writes its picture for every frame");
      record.frame = k;
      record.camera = cameraFlagsText(c, false);
      if (!cam.size.empty())  // the path's size when --size is not given
        record.camera +=
            " --size " + std::to_string(cam.size[0]) + " " + std::to_string(cam.size[1]);
      bool wasDone = false;
      const auto t0 = std::chrono::steady_clock::now();
      const int rc = runTrace(*job, flags, &record, &wasDone);
      const double took =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (rc != 0) {
        std::cerr << "prime: trace: film stopped at frame " << k << ": frames " << range.first
                  << "-" << (k - 1) << " are done; the same command resumes\n";
        restore();
        return rc;
      }
      for (bool* b : flags.firstFrameOnly) *b = false;  // done by the first frame
      const int done = k - range.first + 1;
      if (wasDone) {
        ++skipped;
      } else {
        ++rendered;
        renderSeconds += took;
      }
      if (!flags.quiet) {
        const double eta = rendered > 0 ? renderSeconds / rendered * (n - done) : 0.0;
        const std::string what =
            wasDone ? "done already, skipped" : "rendered in " + durationText(took);
        std::fprintf(stderr, "prime: frame %d (%d of %d): %s; ETA %s\n", k, done, n, what.c_str(),
                     durationText(eta).c_str());
      }
    }
  } catch (...) {
    restore();
    throw;
  }
  restore();
  if (!flags.quiet)
    std::printf("frames %d-%d of %s: %d rendered, %d done already (skipped), in %s\n", range.first,
                range.last, file.name.c_str(), rendered, skipped,
                durationText(
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())
                    .c_str());
  return 0;
}

}  // namespace

void addPathVerb(CLI::App& app, Action& action, const System& system) {
  auto* cmd = app.add_subcommand(
      "path",
      "Write a camera path for a film of a scene of any system: --orbit FRAMES turns the "
      "camera about the scene's centre (the walk's K key adds keys to a path by hand)");
  auto flags = std::make_shared<WalkFlags>();  // what the system's walk part reads
  auto frames = std::make_shared<int>(0);
  auto turns = std::make_shared<int>(1);
  auto out = std::make_shared<std::string>();
  addFormatOption(cmd, "scene");
  cmd->add_option("--orbit", *frames,
                  "Frames of one orbit about the vertical line through the scene's centre, from "
                  "the scene's camera (or the camera flags')")
      ->required()
      ->check(CLI::Range(1, 5'184'000));
  cmd->add_option("--turns", *turns, "Whole turns in those frames (default 1)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--pivot", flags->pivot,
                  "The point the camera turns about (default: the centre of the scene's objects)")
      ->expected(3)
      ->allow_extra_args(false);
  cmd->add_option("-o,--out", *out,
                  "The path file to write (default: DIR/camera.path, or beside a scene file its "
                  "name with .path for its extension; the default is never replaced unless "
                  "named here)")
      ->check(outputName());
  if (system.walk == nullptr) {
    cmd->callback([&action, title = std::string(system.title)] {
      action = [title] {
        std::fprintf(stderr, "prime: path: %s has no free camera (prime path --help)\n",
                     title.c_str());
        return 2;
      };
    });
    return;
  }
  const WalkFactory make = system.walk(cmd, flags);
  cmd->footer(systemFooter(system, "path"));
  cmd->callback([flags, make, frames, turns, out, &action] {
    action = [flags, make, frames, turns, out] {
      const WalkJob job = make();
      const Vec3 centre = flags->pivot.size() == 3
                              ? Vec3{flags->pivot[0], flags->pivot[1], flags->pivot[2]}
                              : job.centre;
      const std::string file = out->empty() ? defaultPathFile(job.name) : *out;
      io::checkOutputPath(file);
      // The default file is where the walk's K key records keys by hand:
      // replaced only when -o names it.
      std::error_code ec;
      if (out->empty() && std::filesystem::exists(file, ec))
        throw io::InputError({file, std::nullopt, std::nullopt},
                             "the scene's camera path exists (the walk's K key may have recorded "
                             "keys there): -o " +
                                 file + " replaces it, -o FILE writes another");
      const std::string text =
          orbitPathText(job.camera, centre, *frames, *turns,
                        "prime path " + job.name + " --orbit " + std::to_string(*frames));
      io::OutputFile o(file);
      o.write(text);
      o.commit();
      std::printf("wrote %s (%d frames, %d keys)\n", file.c_str(), *frames, 24 * *turns);
      return 0;
    };
  });
}

void addFilmOptions(CLI::App* cmd, TraceFlags& flags) {
  cmd->add_option("--camera-path", flags.cameraPath,
                  "Render the frames of a camera path (a file of keyframes; prime path --orbit "
                  "writes one, walk's K adds to one): outputs are patterns (frame%04d.png)")
      ->type_name("FILE");
  cmd->add_option("--frames", flags.frames,
                  "With --camera-path: the frames to render, FIRST-LAST (from 0; default: all); "
                  "frames already done are skipped")
      ->type_name("FIRST-LAST");
  cmd->add_option("--rows", flags.rows,
                  "Render only these rows of the picture (from the top, FIRST-LAST) into a piece "
                  "that prime stitch joins")
      ->type_name("FIRST-LAST");
}

int runFilmOrTrace(const CLI::App* cmd, TraceFlags& flags, const TraceFactory& make,
                   const std::string& system) {
  if (!flags.cameraPath.empty()) return runFilm(cmd, flags, make, system);
  if (!flags.frames.empty())
    throw CLI::ValidationError("--frames", "needs --camera-path FILE: the frames of which path");
  RecordContext record;
  record.system = system;
  record.settings = pixelSettings(cmd);
  const std::unique_ptr<TraceJob> job = make();
  if (flags.rows.empty()) return runTrace(*job, flags, &record);
  const LiveOptions live = flags.live;
  flags.live.noWindow = true;  // a piece renders headless
  if (!live.noWindow) flags.live.headlessBecause = "--rows: a band renders headless";
  flags.live.noWait = true;
  const int rc = runTrace(*job, flags, &record);
  flags.live = live;
  return rc;
}

std::string renderDigest(const RecordContext& record) {
  const std::string text = std::string("prime ") + PRIME_VERSION + "\nsystem " + record.system +
                           "\nsettings\n" + record.settings + "camera " + record.camera +
                           "\ninputs " + io::hex16(io::inputsDigest(record.notInputs)) + "\n";
  return io::hex16(io::xxh3(text));
}

namespace {

// The camera as given (flags, or a camera file's last line, or both), as
// flags: the same text for the same camera however it was given.
std::string givenCameraText(const CameraFlags& given) {
  const CameraFlags c = withCameraFile(given);
  std::string text;
  auto add = [&](const char* name, const std::vector<double>& v) {
    if (v.empty()) return;
    text += std::string(text.empty() ? "" : " ") + name;
    for (double x : v) text += " " + numberText(x);
  };
  add("--eye", c.eye);
  add("--look-at", c.lookAt);
  add("--up", c.up);
  if (c.fov > 0.0) add("--fov", {c.fov});
  if (!c.size.empty())
    text += std::string(text.empty() ? "" : " ") + "--size " + std::to_string(c.size[0]) + " " +
            std::to_string(c.size[1]);
  return text;
}

bool cameraSetting(const std::string& line) {
  for (const char* flag : {"--eye ", "--look-at ", "--up ", "--fov ", "--size ", "--camera "})
    if (line.rfind(flag, 0) == 0) return true;
  return false;
}

}  // namespace

std::string sceneNameOf(std::string scene) {
  while (scene.size() > 1 && scene.back() == '/') scene.pop_back();
  const std::size_t slash = scene.find_last_of('/');
  return slash == std::string::npos ? scene : scene.substr(slash + 1);
}

PngMeta provenanceOf(const TraceJob& job, const RecordContext& record, const CameraFlags* camera) {
  PngMeta meta;
  meta.aspectX = meta.aspectY = 1;  // every system's pixels are shown square
  auto add = [&](std::string key, std::string text) {
    meta.text.push_back({std::move(key), std::move(text)});
  };
  add("Software", std::string("prime ") + PRIME_VERSION);
  std::string title = record.system;
  for (const System& s : systems())
    if (record.system == s.name) title = s.title;
  add("System", title);
  add("Scene", sceneNameOf(job.scene()));
  std::vector<std::string> notScene = record.notInputs;
  if (camera != nullptr && !camera->file.empty()) notScene.push_back(camera->file);
  add("Scene digest",
      "xxh3 " + io::hex16(io::inputsDigest(notScene)) + " (of the bytes of every scene file read)");
  for (PngText& t : job.describe()) meta.text.push_back(std::move(t));
  // The settings one a line, the camera's apart (as the camera it is).
  std::string settings, line;
  for (char c : record.settings) {
    if (c != '\n') {
      line += c;
      continue;
    }
    if (!cameraSetting(line + " ")) settings += (settings.empty() ? "" : " ") + line;
    line.clear();
  }
  add("Settings", settings.empty() ? "(the defaults)" : settings);
  const std::string given =
      record.camera.empty() && camera != nullptr && camera->given() ? givenCameraText(*camera) : "";
  if (!record.camera.empty() || !given.empty())
    add("Camera", record.camera.empty() ? given : record.camera);
  if (record.frame) add("Frame", std::to_string(*record.frame));
  return meta;
}

bool outputsDone(const TraceJob& job, const std::string& render) {
  int named = 0;
  for (const TraceJob::Output& o : job.outputs()) {
    if (o.path.empty() || o.flag.rfind("--", 0) != 0) continue;
    ++named;
    if (!recordMatches(o.path, render)) return false;
  }
  return named > 0;
}

void writeRecords(const TraceJob& job, const std::vector<std::string>& written,
                  const std::string& render, const RecordContext& record, Range band) {
  for (const TraceJob::Output& o : job.outputs()) {
    if (o.path.empty() || o.flag.rfind("--", 0) != 0) continue;
    if (std::find(written.begin(), written.end(), o.path) == written.end()) continue;
    RenderRecord r;
    r.render = render;
    r.system = record.system;
    r.output = o.flag;
    r.frame = record.frame;
    r.firstRow = band.first;
    r.lastRow = band.last;
    r.rows = job.pictureRows();
    const TraceJob::FileRows f = job.fileRows(o.flag, band.first, band.last);
    r.fileFirstRow = f.first;
    r.fileLastRow = f.last;
    r.fileRows = f.rows;
    writeRecord(o.path, r);
  }
}

void checkFramePattern(const std::string& pattern) {
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < pattern.size() && pattern[j] >= '0' && pattern[j] <= '9') ++j;
    if (j >= pattern.size() || pattern[j] != 'd' || j - i - 1 > 2)
      throw CLI::ValidationError("--frames",
                                 "an output pattern takes the frame number as %d or "
                                 "%04d (zero-padded) and %% for a percent sign; got " +
                                     pattern);
    ++conversions;
    i = j;
  }
  if (conversions != 1)
    throw CLI::ValidationError(
        "--frames",
        "each output needs one %04d for the frame number, or every frame would "
        "replace the last; got " +
            pattern);
}

std::string frameName(const std::string& pattern, int frame) {
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      out += pattern[i];
      continue;
    }
    if (pattern[i + 1] == '%') {
      out += '%';
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    int width = 0;
    while (pattern[j] >= '0' && pattern[j] <= '9') width = width * 10 + (pattern[j++] - '0');
    std::string digits = std::to_string(frame);
    if (static_cast<int>(digits.size()) < width)
      digits.insert(0, static_cast<std::size_t>(width) - digits.size(), '0');
    out += digits;
    i = j;
  }
  return out;
}

}  // namespace prime::cli
