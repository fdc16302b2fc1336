// A file written in full or not at all, for every output of every system.
//   - The temporary is created beside the target with mkstemp: a fresh,
//     unpredictable name opened with O_EXCL, so a symbolic link or file
//     planted at any name is never followed and never overwritten.
//   - A target that exists and is neither a regular file nor a symbolic link
//     (a directory, a device such as /dev/null, a FIFO, a socket) is refused
//     before anything is written: renaming over it would replace the device
//     node, and opening a FIFO would block.
//   - commit() flushes, closes and renames the temporary over the target (a
//     symbolic link at the target is replaced, never written through); an
//     uncommitted temporary is removed when the OutputFile goes, on every
//     exit path.
//   - Every failure names the path and the system's reason (errno).
#pragma once
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>

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
  // Flushes, closes and renames the temporary over the target.
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temporary() const { return temp_; }

 private:
  [[noreturn]] void fail(const std::string& what, int error);
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

// Throws InputError (naming `path`) unless `path` may be written as an
// output: missing, a regular file, or a symbolic link; and its directory
// exists. For checks before a long render.
void checkOutputPath(const std::string& path);

}  // namespace prime::io
