#include "legacy_io/common/output_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/common/run_inputs.h"

namespace prime::io {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kWriteBehindBytes = 1u << 20;
constexpr std::size_t kBufferBytes = 1u << 16;

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

// The live temporaries, for the signal handler: chunks of slots that are
// never freed (a handler may walk them at any instant), each slot free (0),
// being filled (1) or holding a temporary's path (2).
struct Slot {
  std::atomic<int> state{0};
  char path[PATH_MAX]{};
};
struct Chunk {
  static constexpr int kSlots = 64;
  Slot slots[kSlots];
  Chunk* next = nullptr;
};
std::atomic<Chunk*> chunks{nullptr};
std::mutex chunkMutex;  // adding a chunk, and installing the handlers (never in a handler)
const int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

extern "C" void removeTemporariesAndDie(int sig) {
  const int saved = errno;
  for (Chunk* c = chunks.load(); c != nullptr; c = c->next)
    for (Slot& s : c->slots)
      if (s.state.load() == 2) ::unlink(s.path);  // async-signal-safe
  errno = saved;
  // Die of the signal, as without the handler (the exit status says which).
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void installHandlers() {
  static bool installed = false;  // under chunkMutex
  if (installed) return;
  installed = true;
  for (int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction sa {};
    sa.sa_handler = removeTemporariesAndDie;
    sigemptyset(&sa.sa_mask);
    for (int other : kSignals) sigaddset(&sa.sa_mask, other);
    ::sigaction(sig, &sa, nullptr);
  }
}

// Returns a slot index (chunk-major), or -1 when the path does not fit.
int registerTemporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (;;) {
    int index = 0;
    for (Chunk* c = chunks.load(); c != nullptr; c = c->next)
      for (Slot& s : c->slots) {
        int expected = 0;
        if (s.state.compare_exchange_strong(expected, 1)) {
          std::memcpy(s.path, path.c_str(), path.size() + 1);
          s.state.store(2);
          return index;
        }
        ++index;
      }
    std::lock_guard lock(chunkMutex);
    installHandlers();
    auto* c = new Chunk;  // never freed: a handler may be reading the list
    c->next = chunks.load();
    chunks.store(c);
  }
}

void unregisterTemporary(int slot) {
  if (slot < 0) return;
  int index = 0;
  for (Chunk* c = chunks.load(); c != nullptr; c = c->next) {
    if (slot < index + Chunk::kSlots) {
      c->slots[slot - index].state.store(0);
      return;
    }
    index += Chunk::kSlots;
  }
}

// TARGETNAME.prime-tmp.<pid>.XXXXXX -> pid, or 0.
pid_t ownerOf(std::string_view name, std::string_view target) {
  if (name.size() <= target.size() + kTempInfix.size() || !name.starts_with(target)) return 0;
  name.remove_prefix(target.size());
  if (!name.starts_with(kTempInfix)) return 0;
  name.remove_prefix(kTempInfix.size());
  long long pid = 0;
  auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), pid);
  if (ec != std::errc() || end == name.data() + name.size() || *end != '.' || pid <= 0) return 0;
  return static_cast<pid_t>(pid);
}

bool processIsGone(pid_t pid) {
  return ::kill(pid, 0) != 0 && errno == ESRCH;
}

int removeStale(const std::string& dir, const std::string& target) {
  DIR* d = ::opendir(dir.empty() ? "." : dir.c_str());
  if (d == nullptr) return 0;
  int removed = 0;
  while (const dirent* e = ::readdir(d)) {
    const std::string_view name = e->d_name;
    const std::size_t infix = name.find(kTempInfix);
    if (infix == std::string_view::npos) continue;
    const std::string_view owner = target.empty() ? name.substr(0, infix) : target;
    const pid_t pid = ownerOf(name, owner);
    if (pid == 0 || pid == ::getpid() || !processIsGone(pid)) continue;
    const std::string path = (dir.empty() ? std::string() : dir + "/") + std::string(name);
    if (::unlink(path.c_str()) == 0) ++removed;
  }
  ::closedir(d);
  return removed;
}

}  // namespace

int removeStaleTemporaries(const std::string& target) {
  const fs::path p(target);
  return removeStale(p.parent_path().string(), p.filename().string());
}

int removeStaleTemporariesIn(const std::string& dir) {
  return removeStale(dir, "");
}

void checkOutputPath(const std::string& path) {
  if (path.empty())
    throw InputError({path, std::nullopt, std::nullopt},
                     "an empty file name cannot be written: name the file to write");
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
  refuseIfInput(path);
}

void checkOutputs(const std::vector<NamedOutput>& outputs) {
  std::vector<std::pair<const NamedOutput*, fs::path>> seen;
  for (const NamedOutput& out : outputs) {
    if (out.path.empty()) continue;
    checkOutputPath(out.path);
    std::error_code ec;
    fs::path where = fs::weakly_canonical(out.path, ec);
    if (ec) where = fs::absolute(out.path);
    for (const auto& [other, at] : seen) {
      std::error_code same;
      if (at == where || fs::equivalent(other->path, out.path, same))
        throw InputError(
            {out.path, std::nullopt, std::nullopt},
            other->flag + " and " + out.flag + " name the same file: each output needs its own");
    }
    seen.emplace_back(&out, where);
  }
}

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  checkOutputPath(path_);
  removeStaleTemporaries(path_);  // of an earlier run that was killed
  // mkstemp: a name nobody can predict, created with O_CREAT | O_EXCL.
  std::string pattern = path_ + std::string(kTempInfix) + std::to_string(::getpid()) + ".XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail("cannot create a temporary beside it", errno);
  temp_ = name.data();
  slot_ = registerTemporary(temp_);
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
  // 64 KiB at a time: a graph file written row by row (2.8 KB at 4x) makes
  // a sixteenth of the system calls stdio's 4 KiB would. (glibc ignores the
  // size unless it is given the buffer.)
  buffer_ = std::make_unique<char[]>(kBufferBytes);
  std::setvbuf(file_, buffer_.get(), _IOFBF, kBufferBytes);
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!committed_) dropTemporary();
}

void OutputFile::dropTemporary() {
  if (!temp_.empty()) ::unlink(temp_.c_str());
  unregisterTemporary(slot_);
  slot_ = -1;
  temp_.clear();
}

void OutputFile::fail(const std::string& what, int error) {
  // The reason is the step's (`error`, taken before any cleanup).
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
  dropTemporary();
  refuse(path_, what + ": " + std::strerror(error));
}

void OutputFile::write(std::span<const std::uint8_t> bytes) {
  errno = 0;
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    fail("write failed", errno != 0 ? errno : EIO);
  written_ += bytes.size();
  if (written_ - handedOver_ >= kWriteBehindBytes) writeBehind();
}

// Starts the disk writes of what was written since the last call, without
// waiting for them: the final fsync then has little left to wait for. Only
// a hint: a failure here is the fsync's to report.
void OutputFile::writeBehind() {
  errno = 0;
  if (std::fflush(file_) != 0) fail("write failed", errno != 0 ? errno : EIO);
#ifdef __linux__
  ::sync_file_range(::fileno(file_), static_cast<off_t>(handedOver_),
                    static_cast<off_t>(written_ - handedOver_), SYNC_FILE_RANGE_WRITE);
#endif
  handedOver_ = written_;
}

void OutputFile::write(std::string_view text) {
  write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void OutputFile::finish() {
  if (file_ == nullptr) return;
  errno = 0;
  if (std::fflush(file_) != 0) fail("write failed", errno != 0 ? errno : EIO);
  // On a full disk the data may only fail here (delayed allocation).
  if (::fsync(::fileno(file_)) != 0 && errno != EINVAL) fail("write failed", errno);
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0) fail("write failed", errno != 0 ? errno : EIO);
}

std::string OutputFile::release() {
  finish();
  unregisterTemporary(slot_);
  slot_ = -1;
  committed_ = true;
  return temp_;
}

void OutputFile::commit() {
  finish();
  // The target may have changed kind while we wrote: check again.
  checkOutputPath(path_);
  if (::rename(temp_.c_str(), path_.c_str()) != 0) fail("cannot be replaced", errno);
  unregisterTemporary(slot_);
  slot_ = -1;
  committed_ = true;
}

}  // namespace prime::io
