// prime film OUT FRAME.png... [--fps N] [--loop N]: PNG frames (any
// system's, in the order given) as a film a lecture can play.
//   OUT.gif                   written here (palette/gif_film.h): a frame of
//                             at most 256 colours exactly (PRIME's 8514/A
//                             view holds the screen's own colours), a frame
//                             of more through median cut (palette/quantize)
//   OUT.mp4, .mkv, .webm, .mov  the frames decoded here and piped to the
//                             ffmpeg program as raw RGB24, which writes a
//                             temporary beside OUT, renamed into place
// Every frame must have the first one's size. docs/user-guide.md, "Films".
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "legacy_io/common/charconv.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/run_inputs.h"
#include "palette/gif_film.h"
#include "palette/png_image.h"
#include "palette/quantize/quantize.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"

extern char** environ;

namespace prime::cli {
namespace {

// What each kind of OUT is, by its extension: ffmpeg's muxer and codec
// arguments (yuv420p, which every player plays, needs an even size: odd
// sizes are padded with one black column or row).
struct FilmKind {
  const char* extension;
  const char* muxer;  // nullptr: the GIF, written here
  std::vector<std::string> codec;
};

const std::vector<FilmKind>& filmKinds() {
  static const std::vector<FilmKind> kinds = {
      {".gif", nullptr, {}},
      {".mp4",
       "mp4",
       {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-movflags", "+faststart"}},
      {".mkv", "matroska", {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18"}},
      {".webm", "webm", {"-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p", "-crf", "24", "-b:v", "0"}},
      {".mov",
       "mov",
       {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-movflags", "+faststart"}},
  };
  return kinds;
}

const FilmKind* kindOf(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return nullptr;
  std::string ext = path.substr(dot);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const FilmKind& k : filmKinds())
    if (ext == k.extension) return &k;
  return nullptr;
}

std::string kindList() {
  std::string s;
  for (const FilmKind& k : filmKinds()) s += (s.empty() ? "" : ", ") + std::string(k.extension);
  return s;
}

// The shortest text that reads back as `v` (29.97, 12.5, 30).
std::string shortest(double v) {
  char buf[32];
  const auto r = io::toChars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// A frame, or an error naming it: a file that is no PNG, or not of the
// first frame's size.
Image8 readFrame(const std::string& path, const Image8* first, const std::string& firstPath) {
  Image8 image;
  try {
    image = readPng(path);
  } catch (const io::InputError&) {
    throw;  // a FIFO, a directory, too large: already named and said
  } catch (const std::runtime_error& e) {
    throw io::InputError({path}, std::string("not a PNG that can be read: ") + e.what());
  }
  if (first != nullptr && (image.width != first->width || image.height != first->height))
    throw io::InputError({path}, "frame size",
                         std::to_string(first->width) + " x " + std::to_string(first->height) +
                             " (the size of the first frame, " + firstPath + ")",
                         std::to_string(image.width) + " x " + std::to_string(image.height));
  return image;
}

struct Summary {
  int width = 0, height = 0;
  int quantized = 0;  // GIF frames of more than 256 colours
  int underTwo = 0;   // GIF frames of a delay under 2/100 s
};

// The GIF, frame by frame into a temporary renamed into place at the end.
Summary writeGif(const std::string& out, const std::vector<std::string>& frames, double fps,
                 int loop) {
  io::OutputFile file(out);
  const Image8 first = readFrame(frames[0], nullptr, "");
  Summary s{first.width, first.height, 0};
  GifFilm film(file, first.width, first.height, loop);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Image8 image = k == 0 ? first : readFrame(frames[k], &first, frames[0]);
    std::optional<IndexedFrame> frame = exactIndexed(image);
    if (!frame) {
      // Median cut to 256 entries of 8 bits each, no dithering (dither
      // patterns crawl from frame to frame).
      const quantize::Result r =
          quantize::quantize(image, {quantize::Method::MedianCut, quantize::Dither::None, 256, 8});
      frame = IndexedFrame{image.width, image.height, r.indices, {}};
      for (std::size_t i = 0; i < r.palette.levels.size(); ++i)
        frame->palette.push_back(r.palette.shown(i));
      ++s.quantized;
    }
    const int delay = gifDelay(static_cast<long>(k), fps);
    if (delay < 2) ++s.underTwo;
    film.addFrame(*frame, delay);
  }
  film.close();
  file.commit();
  return s;
}

// `name` as a program on PATH, or "" (an empty or unset PATH finds nothing).
std::string onPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return "";
  const std::string dirs = path;
  for (std::size_t start = 0; start <= dirs.size();) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    if (end > start) {
      const std::string candidate = dirs.substr(start, end - start) + "/" + name;
      struct stat st {};
      if (stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
          access(candidate.c_str(), X_OK) == 0)
        return candidate;
    }
    start = end + 1;
  }
  return "";
}

// A word of a command as a shell would need it to read it back.
std::string shellWord(const std::string& w) {
  if (!w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789-_+=:,./@%") == std::string::npos)
    return w;
  std::string q = "'";
  for (char c : w) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// ffmpeg running with a pipe to its standard input. Gone with the object:
// stdin closed, the process ended (SIGTERM) if it still runs, and waited for.
// SIGPIPE is ignored meanwhile, so that an ffmpeg that ends early makes a
// write fail (EPIPE) instead of killing prime.
class FfmpegPipe {
 public:
  FfmpegPipe(const std::string& program, const std::vector<std::string>& argv) {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &oldPipe_);
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
      throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const int spawned =
        posix_spawn(&pid_, program.c_str(), &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (spawned != 0) {
      ::close(fds[1]);
      pid_ = -1;
      sigaction(SIGPIPE, &oldPipe_, nullptr);
      throw std::runtime_error("cannot run " + program + ": " + std::strerror(spawned));
    }
    stdin_ = fds[1];
  }
  ~FfmpegPipe() {
    if (stdin_ >= 0) ::close(stdin_);
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      int status = 0;
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
    }
    sigaction(SIGPIPE, &oldPipe_, nullptr);
  }
  FfmpegPipe(const FfmpegPipe&) = delete;
  FfmpegPipe& operator=(const FfmpegPipe&) = delete;

  // False when ffmpeg no longer reads (it ended: finish() says how).
  bool write(const std::vector<std::uint8_t>& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(stdin_, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }
  // Closes ffmpeg's input and waits for it: its wait status.
  int finish() {
    ::close(stdin_);
    stdin_ = -1;
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }

 private:
  pid_t pid_ = -1;
  int stdin_ = -1;
  struct sigaction oldPipe_ {};
};

std::string statusText(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "ended by signal " + std::to_string(WTERMSIG(status));
  return "wait status " + std::to_string(status);
}

// A video through ffmpeg: the frames as raw RGB24 on its standard input,
// its output into the temporary of an io::OutputFile (ffmpeg -y writes over
// the empty file), renamed into place when ffmpeg succeeds. Returns false
// (said on stderr, nothing written) when ffmpeg fails.
bool writeVideo(const std::string& out, const FilmKind& kind,
                const std::vector<std::string>& frames, double fps, Summary& s) {
  const std::string ffmpeg = onPath("ffmpeg");
  if (ffmpeg.empty())
    throw io::InputError({out}, "ffmpeg is not installed (apt install ffmpeg), or write " +
                                    out.substr(0, out.rfind('.')) + ".gif natively");
  const Image8 first = readFrame(frames[0], nullptr, "");
  s.width = first.width;
  s.height = first.height;
  io::OutputFile file(out);
  const std::string size = std::to_string(first.width) + "x" + std::to_string(first.height);
  std::vector<std::string> argv = {"ffmpeg", "-hide_banner", "-loglevel",   "error", "-y",
                                   "-f",     "rawvideo",     "-pix_fmt",    "rgb24", "-s",
                                   size,     "-framerate",   shortest(fps), "-i",    "-"};
  argv.insert(argv.end(), kind.codec.begin(), kind.codec.end());
  argv.insert(argv.end(),
              {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-f", kind.muxer, file.temporary()});
  std::string line;
  for (const std::string& a : argv) line += (line.empty() ? "" : " ") + shellWord(a);
  std::cerr << "prime: film: running " << line << "\n";
  FfmpegPipe pipe(ffmpeg, argv);
  bool fed = pipe.write(first.rgb);
  for (std::size_t k = 1; fed && k < frames.size(); ++k)
    fed = pipe.write(readFrame(frames[k], &first, frames[0]).rgb);
  const int status = pipe.finish();
  if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
    std::cerr << "prime: film: ffmpeg failed (" << statusText(status) << "): " << out
              << " not written\n";
    return false;
  }
  if (!fed) {
    std::cerr << "prime: film: ffmpeg ended before it read every frame (" << statusText(status)
              << "): " << out << " not written\n";
    return false;
  }
  file.commit();
  return true;
}

}  // namespace

void addFilmCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "film", "Make a film (GIF, or MP4/MKV/WebM/MOV through ffmpeg) of PNG frames");
  auto out = std::make_shared<std::string>();
  auto frames = std::make_shared<std::vector<std::string>>();
  auto fps = std::make_shared<double>(30.0);
  auto loop = std::make_shared<int>(0);
  cmd->add_option("OUT", *out,
                  "Film to write, by its extension: .gif (written by prime; frames of at most "
                  "256 colours exact), .mp4, .mkv, .webm, .mov (through the ffmpeg program)")
      ->required()
      ->check(outputName());
  cmd->add_option("FRAME", *frames,
                  "PNG frames in the order shown (a shell glob such as frames/f*.png sorts "
                  "them), all of one size")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--fps", *fps, "Frames a second, fractional allowed (29.97); default 30")
      ->check(above(0));
  cmd->add_option("--loop", *loop, "GIF: the loop count (NETSCAPE2.0), 0 (default) = forever")
      ->check(CLI::Range(0, 65535));
  cmd->callback([=, &action] {
    action = [=] {
      const FilmKind* kind = kindOf(*out);
      if (kind == nullptr) {
        const std::size_t dot = out->rfind('.');
        const bool none = dot == std::string::npos || out->find('/', dot) != std::string::npos;
        throw io::InputError({*out}, "film kind", "a name ending in " + kindList(),
                             none ? "no extension" : io::quotedWord(out->substr(dot), 20));
      }
      if (kind->muxer == nullptr && gifDelay(0, *fps) > 65535)
        throw CLI::ValidationError("--fps",
                                   "a GIF frame lasts at most 655.35 s: at least "
                                   "100/65535 = 0.00153 fps, got " +
                                       shortest(*fps));
      if (kind->muxer != nullptr && *loop != 0)
        std::cerr << "prime: film: --loop is for a GIF; a video plays once (the player loops)\n";
      // The frames are inputs before OUT is checked: `film f1.png f1.png` is refused.
      for (const std::string& f : *frames) io::protectInput(f);
      io::checkOutputPath(*out);
      Summary s;
      if (kind->muxer == nullptr) {
        s = writeGif(*out, *frames, *fps, *loop);
      } else if (!writeVideo(*out, *kind, *frames, *fps, s)) {
        return 1;
      }
      if (s.underTwo > 0)
        std::cerr << "prime: film: " << s.underTwo
                  << (s.underTwo == 1 ? " frame lasts" : " frames last") << " less than 2/100 s ("
                  << *fps
                  << " fps is more than GIF's 100 a second can hold evenly), and many players "
                     "show such frames for 1/10 s: 50 fps or fewer plays as written\n";
      if (s.quantized > 0)
        std::cerr << "prime: film: " << s.quantized << " of " << frames->size()
                  << " frames had more than 256 colours: quantized (median cut, no dithering)\n";
      const double seconds = static_cast<double>(frames->size()) / *fps;
      std::printf("wrote %s (%zu frame%s, %d x %d, %s fps, %.2f s)\n", out->c_str(), frames->size(),
                  frames->size() == 1 ? "" : "s", s.width, s.height, shortest(*fps).c_str(),
                  seconds);
      return 0;
    };
  });
}

}  // namespace prime::cli
