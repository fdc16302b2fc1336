// Shared by the libFuzzer targets of tests/fuzz.
//
// The contract every reader is fuzzed against: for any bytes it either returns
// or throws prime::io::InputError naming the file and a line (text) or byte
// offset (binary). Anything else (another exception, a crash, a sanitizer
// report, a hang, a huge allocation) is a bug. Exceptions other than
// InputError are simply not caught here: libFuzzer reports them as a crash
// (std::terminate) with the input that caused them.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/prime/scene_dir.h"

namespace prime::fuzz {

// Stops the run with a message: libFuzzer saves the input as a crash.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
  std::abort();
}

inline void check(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

// A binary reader's error must give the file and a byte offset inside (or
// just past) the file.
inline void checkBinaryError(const io::InputError& e, const std::string& file, std::size_t size) {
  const std::string msg = e.what();
  check(msg.rfind(file, 0) == 0, "message does not start with the file name: " + msg);
  check(e.where().byte.has_value(), "binary error without a byte offset: " + msg);
  check(*e.where().byte <= size, "byte offset past the end of the file: " + msg);
}

// A text reader's error must give the file and a line of the text.
inline void checkTextError(const io::InputError& e, const std::string& file,
                           std::string_view text) {
  const std::string msg = e.what();
  check(msg.rfind(file + ":", 0) == 0, "message does not start with \"file:\": " + msg);
  check(e.where().line.has_value(), "text error without a line: " + msg);
  // Lines as the readers count them (M21): LF, CR LF and a lone CR each end one.
  std::size_t lines = 1;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')))
      ++lines;
  check(*e.where().line >= 1 && static_cast<std::size_t>(*e.where().line) <= lines,
        "line outside the text (" + std::to_string(lines) + " lines): " + msg);
}

// ---------------------------------------------------------------------------
// A scene directory in one fuzz input: a sequence of files, each introduced by
// a marker line
//     %%prime:<path>\n<content>
// where <path> is "Model.txt" or "<sub>/<name>" with <sub> one of the scene's
// folders; the content runs up to the next marker (or the end of the input).
// Bytes before the first marker, paths that are not plain scene paths and
// files past kMaxFiles are ignored. make_corpus.py writes seeds this way.
inline constexpr std::string_view kFileMarker = "%%prime:";
inline constexpr std::size_t kMaxFiles = 48;

struct SceneFile {
  std::string path;     // relative to the scene root
  std::string content;  // raw bytes
};

inline bool isScenePath(const std::string& path) {
  static const char* kSubs[] = {"prim/", "bound/", "obj/Copy/", "obj/", "map/", "light/"};
  if (path.size() > 80) return false;
  if (path.find('/') == std::string::npos) return io::isPlainFileName(path);
  for (const char* sub : kSubs) {
    const std::string s(sub);
    if (path.rfind(s, 0) == 0) return io::isPlainFileName(path.substr(s.size()));
  }
  return false;
}

inline std::vector<SceneFile> splitScene(const std::uint8_t* data, std::size_t size) {
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  std::vector<SceneFile> files;
  std::size_t at = in.find(kFileMarker);
  while (at != std::string_view::npos && files.size() < kMaxFiles) {
    const std::size_t nameStart = at + kFileMarker.size();
    const std::size_t eol = in.find('\n', nameStart);
    if (eol == std::string_view::npos) break;
    const std::size_t next = in.find(kFileMarker, eol + 1);
    const std::size_t end = next == std::string_view::npos ? in.size() : next;
    SceneFile f{std::string(in.substr(nameStart, eol - nameStart)),
                std::string(in.substr(eol + 1, end - eol - 1))};
    if (isScenePath(f.path)) files.push_back(std::move(f));
    at = next;
  }
  return files;
}

// One scene directory per fuzzing process, emptied and refilled for every
// input, removed when the process exits normally.
class ScratchScene {
 public:
  // In memory (/dev/shm) where there is one: on a disk, deleting and creating
  // a dozen files per input makes the fuzzer wait on the file system (ext4
  // with discard: ~40 runs/s instead of hundreds).
  ScratchScene() {
    std::error_code ec;
    const std::filesystem::path shm = "/dev/shm";
    const std::filesystem::path base =
        std::filesystem::is_directory(shm, ec) && ::access(shm.c_str(), W_OK) == 0
            ? shm
            : std::filesystem::temp_directory_path();
    root_ = base / ("prime-fuzz-" + std::to_string(::getpid()) + "-" +
                    std::to_string(reinterpret_cast<std::uintptr_t>(this) & 0xffff));
  }
  ~ScratchScene() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  ScratchScene(const ScratchScene&) = delete;
  ScratchScene& operator=(const ScratchScene&) = delete;

  // Empties the directory, recreates the scene folders and writes `files`.
  void fill(const std::vector<SceneFile>& files) {
    std::filesystem::remove_all(root_);
    for (const char* sub : {"prim", "bound", "obj/Copy", "map", "light"})
      std::filesystem::create_directories(root_ / sub);
    for (const auto& f : files) {
      std::ofstream out(root_ / f.path, std::ios::binary | std::ios::trunc);
      out.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
    }
  }
  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

}  // namespace prime::fuzz
