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

// Issue 37: while a trace held the lock shared, `prime model` said busy
// naming the pid of an earlier model run that had long finished.
TEST(DirLockTest, AReaderIsNotReportedByTheLastWritersPid) {
  TempDir d;
  {
    DirLock earlier(d / "lock", "prime model");
    ASSERT_TRUE(earlier.tryLock(DirLock::Mode::Exclusive));
  }  // finished: its pid goes with it
  DirLock reader(d / "lock", "prime model"), writer(d / "lock", "prime model");
  ASSERT_TRUE(reader.tryLock(DirLock::Mode::Shared));
  EXPECT_FALSE(writer.tryLock(DirLock::Mode::Exclusive));
  EXPECT_EQ(writer.holder(), 0);
  const std::string m = messageOf([&] { writer.busy("scenes/x", "add --wait"); });
  EXPECT_NE(m.find("busy: another prime command is reading or writing scenes/x; add --wait"),
            std::string::npos)
      << m;
}

TEST(DirLockTest, APidWhoseProcessHasGoneIsNoOnes) {
  TempDir d;
  const pid_t child = fork();
  if (child == 0) {
    DirLock l(d / "lock", "w");
    l.tryLock(DirLock::Mode::Exclusive);  // writes its pid
    ::raise(SIGKILL);                     // and cannot take it away
  }
  waitpid(child, nullptr, 0);
  DirLock reader(d / "lock", "w");
  ASSERT_TRUE(reader.tryLock(DirLock::Mode::Shared));
  EXPECT_EQ(reader.holder(), 0);
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
