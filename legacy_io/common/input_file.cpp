#include "legacy_io/common/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>

#include "legacy_io/common/error.h"
#include "legacy_io/common/run_inputs.h"

namespace prime::io {

namespace {

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

template <typename Buffer>
Buffer readWhole(const std::string& path, const InputFileOptions& o) {
  const std::string shown = o.display.empty() ? path : o.display;
  const InputLocation where{shown, std::nullopt, std::nullopt};
  // O_NONBLOCK: opening a FIFO with no writer returns at once (and its type
  // is refused below) instead of waiting for one.
  const Fd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) {
    const int e = errno;
    if (e == ENOENT) throw InputError(where, "no such file (expected " + o.what + ")");
    throw InputError(where, std::string("cannot open ") + o.what + ": " + std::strerror(e));
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0)
    throw InputError(where, std::string("cannot read ") + o.what + ": " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw InputError(where, "is " + kindOf(st.st_mode) + ", not " + o.what);
  noteInput(st.st_dev, st.st_ino, shown);  // no output of this run may replace it
  const auto size = static_cast<std::uint64_t>(st.st_size);
  // The byte named is the first one past the cap.
  const InputLocation past{shown, std::nullopt, o.maxBytes};
  if (size > o.maxBytes)
    throw InputError(past, "file size",
                     "at most " + std::to_string(o.maxBytes) + " bytes for " + o.what,
                     std::to_string(size) + " bytes");
  // Regular files never block; clear O_NONBLOCK anyway for plain reads.
  ::fcntl(fd.get(), F_SETFL, ::fcntl(fd.get(), F_GETFL) & ~O_NONBLOCK);
  Buffer out;
  out.resize(static_cast<std::size_t>(size));
  std::size_t got = 0;
  for (;;) {
    if (got == out.size()) {
      // The file may have grown since fstat: read on, within the cap.
      if (out.size() >= o.maxBytes) {
        char probe;
        const ssize_t n = ::read(fd.get(), &probe, 1);
        if (n > 0)
          throw InputError(past, "file size",
                           "at most " + std::to_string(o.maxBytes) + " bytes for " + o.what,
                           "a file still growing past that");
        break;
      }
      out.resize(std::min<std::uint64_t>(o.maxBytes, out.size() + 65536));
    }
    const ssize_t n = ::read(fd.get(), out.data() + got, out.size() - got);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(where, std::string("cannot read ") + o.what + ": " + std::strerror(errno));
    }
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  out.resize(got);
  if (o.sceneContent) noteInputContent(st.st_dev, st.st_ino, shown, out.data(), out.size());
  return out;
}

}  // namespace

std::vector<std::uint8_t> readInputFile(const std::string& path, const InputFileOptions& options) {
  return readWhole<std::vector<std::uint8_t>>(path, options);
}

namespace {

// The texts of this process a ^Z ended before their last byte: where the ^Z
// is and how many bytes follow it that are not ^Z padding (dosEofNote).
struct CutText {
  std::size_t at = 0, after = 0;
};
std::mutex cutMutex;
std::map<std::string, CutText>& cutTexts() {
  static std::map<std::string, CutText> texts;
  return texts;
}

}  // namespace

std::string readInputText(const std::string& path, const InputFileOptions& options) {
  std::string text = readWhole<std::string>(path, options);
  const std::size_t end = text.find(kDosEof);
  if (end != std::string::npos) {
    std::size_t after = 0;
    for (std::size_t i = end + 1; i < text.size(); ++i) after += text[i] != kDosEof;
    if (after > 0) {
      const std::lock_guard<std::mutex> lock(cutMutex);
      cutTexts()[options.display.empty() ? path : options.display] = {end, after};
    }
    text.resize(end);
  }
  return text;
}

std::string dosEofNote(const InputError& e) {
  if (e.found().find("end of file") == std::string::npos) return "";
  const std::lock_guard<std::mutex> lock(cutMutex);
  const auto it = cutTexts().find(e.where().file);
  if (it == cutTexts().end()) return "";
  const CutText& c = it->second;
  return "the text ends at the ^Z (0x1A) at byte " + std::to_string(c.at) +
         ", as DOS's text mode read it; " + std::to_string(c.after) + " byte" +
         (c.after == 1 ? "" : "s") + " after it are not read (M41)";
}

void endAtDosEof(std::string& text) {
  if (const std::size_t end = text.find(kDosEof); end != std::string::npos) text.resize(end);
}

}  // namespace prime::io
