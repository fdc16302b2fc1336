#include "legacy_io/common/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "legacy_io/common/error.h"

namespace prime::io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw InputError({path, std::nullopt, std::nullopt}, why);
}

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

void checkOutputPath(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode))
      refuse(path, "cannot be written: it is " + kindOf(st.st_mode) +
                       " (prime writes outputs only as regular files)");
  } else if (errno != ENOENT) {
    refuse(path, std::string("cannot be written: ") + std::strerror(errno));
  }
  const fs::path dir = fs::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty() && !fs::is_directory(dir, ec))
    refuse(path, "cannot be written: the directory " + dir.string() + " does not exist");
}

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  checkOutputPath(path_);
  // mkstemp: a name nobody can predict, created with O_CREAT | O_EXCL.
  std::string pattern = path_ + ".prime-tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail("cannot create a temporary beside it", errno);
  temp_ = name.data();
  // mkstemp makes the file 0600; outputs are ordinary files (0666 & ~umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  file_ = ::fdopen(fd, "wb");
  if (file_ == nullptr) {
    const int error = errno;
    ::close(fd);
    fail("cannot write", error);
  }
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
}

void OutputFile::fail(const std::string& what, int error) {
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
  if (!temp_.empty()) {
    ::unlink(temp_.c_str());
    temp_.clear();
  }
  refuse(path_, what + ": " + std::strerror(error));
}

void OutputFile::write(std::span<const std::uint8_t> bytes) {
  errno = 0;
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    fail("write failed", errno != 0 ? errno : EIO);
}

void OutputFile::write(std::string_view text) {
  write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void OutputFile::commit() {
  errno = 0;
  if (std::fflush(file_) != 0) fail("write failed", errno != 0 ? errno : EIO);
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0) fail("write failed", errno != 0 ? errno : EIO);
  // The target may have changed kind while we wrote: check again.
  checkOutputPath(path_);
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail("cannot be replaced", errno);
  committed_ = true;
}

}  // namespace prime::io
