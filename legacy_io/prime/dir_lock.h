// An advisory lock (flock) on a lock file, so that two writers of the same
// files never run at once (PRIME's `prime model`, M20). The holder of the
// exclusive lock writes its pid into the file, for the "busy" message of the
// next one, and takes it away when it lets go. The lock goes with the process: a killed holder
// never leaves a stale lock behind (the kernel drops it), only the file, which is harmless.
#pragma once
#include <string>

namespace prime::io {

class DirLock {
 public:
  enum class Mode { Exclusive, Shared };
  // Throws InputError if the lock file cannot be opened or created.
  DirLock(std::string lockFile, std::string what);
  ~DirLock();
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;

  // Without waiting: false if another process holds a conflicting lock.
  bool tryLock(Mode mode);
  // Waits for it.
  void lock(Mode mode);
  void unlock();
  // The pid written by the current exclusive holder (0 if unknown: none
  // written, the lock held shared by readers, or a process that has gone).
  long holder() const;
  // "another <what> (pid N) is writing", or, without a pid, "another prime
  // command is reading or writing": followed by the directory.
  std::string holderText() const;
  // "busy: " + holderText() + " <dir>; <hint>".
  [[noreturn]] void busy(const std::string& dir, const std::string& hint) const;

 private:
  void clearPid();
  std::string file_, what_;
  int fd_ = -1;
  bool exclusive_ = false;  // held exclusive by this process: its pid is in the file
};

}  // namespace prime::io
