// PRIME's directory lock (legacy_io/prime/dir_lock.h, docs/prime/deviations.md M20):
// one `prime model` writes a scene's databases at a time, readers share.
#include "legacy_io/prime/dir_lock.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/support/error_message.h"
#include "tests/support/temp_dir.h"

namespace prime::io {
namespace {

using test::messageOf;
using test::TempDir;

TEST(DirLockTest, TheSecondWriterIsBusyAndNamesTheFirst) {
  TempDir d;
  // flock locks belong to open files: two DirLocks in one process conflict
  // as two processes would.
  DirLock first(d / "lock", "prime model"), second(d / "lock", "prime model");
  ASSERT_TRUE(first.tryLock(DirLock::Mode::Exclusive));
  EXPECT_FALSE(second.tryLock(DirLock::Mode::Exclusive));
  EXPECT_FALSE(second.tryLock(DirLock::Mode::Shared));
  EXPECT_EQ(second.holder(), getpid());
  const std::string m = messageOf([&] { second.busy("scenes/x", "add --wait"); });
  EXPECT_NE(m.find("busy: another prime model (pid " + std::to_string(getpid()) +
                   ") is writing scenes/x; add --wait"),
            std::string::npos)
      << m;
  first.unlock();
  EXPECT_TRUE(second.tryLock(DirLock::Mode::Exclusive));
}

TEST(DirLockTest, ReadersShareAndExcludeTheWriter) {
  TempDir d;
  DirLock a(d / "lock", "w"), b(d / "lock", "w"), c(d / "lock", "w");
  EXPECT_TRUE(a.tryLock(DirLock::Mode::Shared));
  EXPECT_TRUE(b.tryLock(DirLock::Mode::Shared));
  EXPECT_FALSE(c.tryLock(DirLock::Mode::Exclusive));
}

TEST(DirLockTest, AKilledHolderLeavesNoLock) {
  TempDir d;
  const pid_t child = fork();
  if (child == 0) {
    DirLock l(d / "lock", "w");
    l.tryLock(DirLock::Mode::Exclusive);
    ::raise(SIGKILL);
  }
  waitpid(child, nullptr, 0);
  DirLock l(d / "lock", "w");
  EXPECT_TRUE(l.tryLock(DirLock::Mode::Exclusive));
}

}  // namespace
}  // namespace prime::io
