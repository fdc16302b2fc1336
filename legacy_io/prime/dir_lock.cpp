#include "legacy_io/prime/dir_lock.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "legacy_io/common/error.h"

namespace prime::io {

DirLock::DirLock(std::string lockFile, std::string what)
    : file_(std::move(lockFile)), what_(std::move(what)) {
  // O_NOFOLLOW: a symbolic link planted at the lock's name is not followed.
  fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0666);
  if (fd_ < 0) {
    const int e = errno;
    throw InputError({file_, std::nullopt, std::nullopt},
                     "cannot open the lock file: " + std::string(std::strerror(e)));
  }
}

DirLock::~DirLock() {
  if (fd_ < 0) return;
  clearPid();
  ::close(fd_);  // drops the lock
}

// The exclusive holder takes its pid away before it lets go: a reader that
// later holds the lock shared must not be reported by an old writer's pid.
void DirLock::clearPid() {
  if (exclusive_ && ::ftruncate(fd_, 0) != 0) {
    // Only a message would be wrong: holder() checks that the pid still runs.
  }
  exclusive_ = false;
}

bool DirLock::tryLock(Mode mode) {
  for (;;) {
    if (::flock(fd_, (mode == Mode::Exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB) == 0) break;
    if (errno == EINTR) continue;
    if (errno == EWOULDBLOCK) return false;
    throw InputError({file_, std::nullopt, std::nullopt},
                     "cannot lock: " + std::string(std::strerror(errno)));
  }
  exclusive_ = mode == Mode::Exclusive;
  if (mode == Mode::Exclusive) {
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
      // Only the busy message of another run would miss the pid.
    }
  }
  return true;
}

void DirLock::lock(Mode mode) {
  while (::flock(fd_, mode == Mode::Exclusive ? LOCK_EX : LOCK_SH) != 0)
    if (errno != EINTR)
      throw InputError({file_, std::nullopt, std::nullopt},
                       "cannot lock: " + std::string(std::strerror(errno)));
  if (mode == Mode::Exclusive)
    tryLock(mode);  // held already: writes the pid
  else
    clearPid();  // converted from exclusive
}

void DirLock::unlock() {
  clearPid();
  ::flock(fd_, LOCK_UN);
}

long DirLock::holder() const {
  char buf[32] = {};
  const ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
  if (n <= 0) return 0;
  const long pid = std::strtol(buf, nullptr, 10);
  // A pid left by a writer that was killed (SIGKILL cannot clear it) is no one's.
  if (pid <= 0 || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)) return 0;
  return pid;
}

std::string DirLock::holderText() const {
  const long pid = holder();
  return pid > 0 ? "another " + what_ + " (pid " + std::to_string(pid) + ") is writing"
                 : "another prime command is reading or writing";
}

void DirLock::busy(const std::string& dir, const std::string& hint) const {
  throw InputError({dir, std::nullopt, std::nullopt},
                   "busy: " + holderText() + " " + dir + (hint.empty() ? "" : "; " + hint));
}

}  // namespace prime::io
