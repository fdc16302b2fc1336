// A file written in full or not at all, for every output of every system.
//   - The temporary is created beside the target with mkstemp: a fresh,
//     unpredictable name opened with O_EXCL, so a symbolic link or file
//     planted at any name is never followed and never overwritten. Its name,
//     TARGET.prime-tmp.<pid>.XXXXXX, says which process made it.
//   - A target that exists and is neither a regular file nor a symbolic link
//     (a directory, a device such as /dev/null, a FIFO, a socket) is refused
//     before anything is written: renaming over it would replace the device
//     node, and opening a FIFO would block. So is a target that is an input of
//     the run (run_inputs.h), and a target whose directory does not exist.
//   - Every whole MiB written is handed to the disk at once (write-behind:
//     sync_file_range on Linux), so that the sync at the end of a long
//     stream of writes, such as a graph file written while its render runs,
//     waits for the last MiB only.
//   - commit() flushes, syncs, closes and renames the temporary over the
//     target (a symbolic link at the target is replaced, never written
//     through); an uncommitted temporary is removed when the OutputFile goes,
//     on every exit path: exceptions, and SIGINT, SIGTERM, SIGHUP and SIGQUIT
//     (a handler removes the live temporaries, then dies of the signal as it
//     would have). A SIGKILL cannot be caught: the next OutputFile for the
//     same target removes the temporaries whose process is gone.
//   - Every failure names the path and the system's reason (errno) of the
//     step that failed, never that of a cleanup after it.
#pragma once
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace prime::io {

class OutputFile {
 public:
  // Checks the target and creates the temporary; throws InputError.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // The temporary as a stdio stream (for libraries such as libpng).
  std::FILE* stream() { return file_; }
  void write(std::span<const std::uint8_t> bytes);
  void write(std::string_view text);
  // Flushes, syncs, closes and renames the temporary over the target.
  void commit();

  // For a writer that switches many files at once (PRIME's `prime model`,
  // M19): finish() flushes, syncs and closes the temporary and keeps it;
  // release() then hands it over (no longer removed by the destructor or a
  // signal): the caller renames it, or leaves it to a later recovery.
  void finish();
  std::string release();

  const std::string& path() const { return path_; }
  const std::string& temporary() const { return temp_; }

 private:
  [[noreturn]] void fail(const std::string& what, int error);
  void dropTemporary();
  void writeBehind();
  std::string path_, temp_;
  std::unique_ptr<char[]> buffer_;  // stdio's, for file_: outlives it
  std::FILE* file_ = nullptr;
  bool committed_ = false;
  int slot_ = -1;                               // in the signal handler's list of live temporaries
  std::uint64_t written_ = 0, handedOver_ = 0;  // bytes written; bytes handed to the disk
};

// Several files that belong together (a POV-Ray scene and its texture
// PNGs), written all or none: each goes to its own temporary, and commit()
// first syncs every one (a full disk fails there, and every temporary is
// removed), then renames them all into place.
class OutputSet {
 public:
  OutputFile& add(std::string path) {
    files_.push_back(std::make_unique<OutputFile>(std::move(path)));
    return *files_.back();
  }
  void commit() {
    for (auto& f : files_) f->finish();
    for (auto& f : files_) f->commit();
  }

 private:
  std::vector<std::unique_ptr<OutputFile>> files_;
};

// Throws InputError (naming `path`) unless `path` may be written as an
// output: missing, a regular file, or a symbolic link; not an input of the
// run; and its directory exists. For checks before a long render.
void checkOutputPath(const std::string& path);

// One output of a run: the flag that names it ("--png", or what the file is)
// and its path.
struct NamedOutput {
  std::string flag;
  std::string path;
};
// checkOutputPath for each non-empty path, and throws InputError when two
// name one file (the same path, another spelling of it, a link to it): the
// second would replace the first.
void checkOutputs(const std::vector<NamedOutput>& outputs);

// The infix of every temporary: TARGET + kTempInfix + "<pid>.XXXXXX".
inline constexpr std::string_view kTempInfix = ".prime-tmp.";
// Removes the temporaries TARGET.prime-tmp.<pid>.* of `target` whose process
// no longer runs (a run killed by SIGKILL, a crash). Returns how many.
int removeStaleTemporaries(const std::string& target);
// The same for every file of directory `dir`.
int removeStaleTemporariesIn(const std::string& dir);

}  // namespace prime::io
