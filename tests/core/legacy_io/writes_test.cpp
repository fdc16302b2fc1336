// Issue 17, part A (docs/prime/deviations.md M19-M23): no output overwrites an
// input of its run; temporaries go on every exit path, signals included, and
// a killed run's are cleaned by the next; failures give the step's errno;
// line breaks the same in every text input. (PRIME's directory lock:
// tests/prime/unit/legacy_io/dir_lock_test.cpp.)
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/run_inputs.h"
#include "legacy_io/common/text_reader.h"
#include "tests/support/error_message.h"
#include "tests/support/temp_dir.h"

namespace prime::io {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

void put(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}
std::string get(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
int filesIn(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}
using test::messageOf;

// A pid that no process has: a child that has exited and been reaped.
pid_t deadPid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

// --- an output that names an input ------------------------------------------

TEST(OutputNamesInput, AnInputReadInTheRunIsNeverReplaced) {
  TempDir d;
  put(d / "scene.txt", "the input");
  const RunInputs run;
  readInputText(d / "scene.txt");
  const std::string m = messageOf([&] { OutputFile out(d / "scene.txt"); });
  EXPECT_NE(m.find(d / "scene.txt"), std::string::npos) << m;
  EXPECT_NE(m.find("is the input"), std::string::npos) << m;
  EXPECT_EQ(get(d / "scene.txt"), "the input");
  EXPECT_EQ(filesIn(d.path()), 1);  // no temporary left either
}

TEST(OutputNamesInput, ByAnotherNameAHardLinkOrASymbolicLink) {
  TempDir d;
  put(d / "in", "x");
  fs::create_directories(d.path() / "sub");
  fs::create_hard_link(d / "in", d / "hard");
  fs::create_symlink(d / "in", d / "soft");
  const RunInputs run;
  readInputFile(d / "in");
  for (const fs::path& out : {d / "sub/../in", d / "hard", d / "soft"})
    EXPECT_NE(messageOf([&] { checkOutputPath(out); }).find("is the input " + (d / "in").string()),
              std::string::npos)
        << out;
  EXPECT_EQ(get(d / "in"), "x");
}

TEST(OutputNamesInput, ProtectedFilesNotReadAreRefusedToo) {
  TempDir d;
  put(d / "Model.txt", "AddObj d1.txt\n");
  const RunInputs run;
  protectInput(d / "Model.txt", "scene/Model.txt");
  EXPECT_NE(messageOf([&] { checkOutputPath(d / "Model.txt"); }).find("scene/Model.txt"),
            std::string::npos);
}

TEST(OutputNamesInput, OtherOutputsAndRunsWithoutAScopeAreUnaffected) {
  TempDir d;
  put(d / "in", "x");
  {
    // Outside a RunInputs scope (a library user, a unit test rewriting its
    // own file) nothing is recorded.
    readInputFile(d / "in");
    OutputFile out(d / "in");
    out.write(std::string_view("y"));
    out.commit();
  }
  EXPECT_EQ(get(d / "in"), "y");
  const RunInputs run;
  readInputFile(d / "in");
  OutputFile fresh(d / "new");  // does not exist yet: cannot be an input
  fresh.write(std::string_view("z"));
  fresh.commit();
  EXPECT_EQ(get(d / "new"), "z");
}

// --- temporaries on every exit path -------------------------------------------

TEST(Temporaries, NameTheirProcess) {
  TempDir d;
  OutputFile out(d / "picture.png");
  EXPECT_EQ(fs::path(out.temporary())
                .filename()
                .string()
                .rfind("picture.png.prime-tmp." + std::to_string(getpid()) + ".", 0),
            0u)
      << out.temporary();
}

TEST(Temporaries, ThoseOfAKilledRunAreRemovedByTheNextAndLiveOnesKept) {
  TempDir d;
  const std::string dead = d / ("g.prime-tmp." + std::to_string(deadPid()) + ".AbC123");
  const std::string live = d / ("g.prime-tmp." + std::to_string(getppid()) + ".XyZ789");
  const std::string other = d / ("h.prime-tmp." + std::to_string(deadPid()) + ".Qq1234");
  for (const auto& p : {dead, live, other}) put(p, "half");
  OutputFile out(d / "g");
  out.write(std::string_view("whole"));
  out.commit();
  EXPECT_FALSE(fs::exists(dead));  // its process is gone
  EXPECT_TRUE(fs::exists(live));   // the parent runs: maybe writing it now
  EXPECT_TRUE(fs::exists(other));  // another target's: left to its own writer
  EXPECT_EQ(removeStaleTemporariesIn(d.path().string()), 1);  // `other`
  EXPECT_FALSE(fs::exists(other));
  EXPECT_EQ(get(d / "g"), "whole");
}

TEST(Temporaries, AreRemovedWhenTheProcessIsKilledBySignal) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
    TempDir d;
    const pid_t child = fork();
    if (child == 0) {
      OutputFile a(d / "a"), b(d / "b");
      a.write(std::string_view("half"));
      ::raise(sig);
      _exit(0);  // not reached: the handler dies of the signal
    }
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << sig;
    EXPECT_EQ(WTERMSIG(status), sig);  // dies of the signal, as without the handler
    EXPECT_EQ(filesIn(d.path()), 0) << "signal " << sig;
  }
}

TEST(Temporaries, AReleasedTemporaryIsKeptThroughASignal) {
  TempDir d;
  const pid_t child = fork();
  if (child == 0) {
    OutputFile a(d / "a");
    a.write(std::string_view("whole"));
    a.release();  // handed over (prime model's journal owns it)
    ::raise(SIGTERM);
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_EQ(filesIn(d.path()), 1);
}

TEST(Temporaries, AFullDiskReportsTheWriteErrorNotACleanup) {
  // RLIMIT_FSIZE stands in for a full disk (EFBIG instead of ENOSPC): the
  // message must carry the write's errno.
  TempDir d;
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t child = fork();
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    setrlimit(RLIMIT_FSIZE, &limit);
    std::string m = messageOf([&] {
      OutputFile out(d / "big");
      out.write(std::string(100000, 'x'));
      out.commit();
    });
    if (::write(fds[1], m.data(), m.size()) < 0) _exit(2);
    _exit(0);
  }
  close(fds[1]);
  std::string m;
  char buf[512];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) m.append(buf, n);
  close(fds[0]);
  waitpid(child, nullptr, 0);
  EXPECT_NE(m.find("write failed: File too large"), std::string::npos) << m;
  EXPECT_EQ(filesIn(d.path()), 0);
}

TEST(Temporaries, AReadOnlyDirectoryReportsPermissionDenied) {
  if (geteuid() == 0) GTEST_SKIP() << "root writes into read-only directories";
  TempDir d;
  fs::permissions(d.path(), fs::perms::owner_read | fs::perms::owner_exec);
  const std::string m = messageOf([&] { OutputFile out(d / "x"); });
  fs::permissions(d.path(), fs::perms::owner_all);
  EXPECT_NE(m.find("Permission denied"), std::string::npos) << m;
}

// --- line breaks ----------------------------------------------------------------

TEST(LineBreaks, CrLfAndLoneCrBecomeLf) {
  EXPECT_EQ(normalizeLineBreaks("a\r\nb\rc\nd"), "a\nb\nc\nd");
  EXPECT_EQ(normalizeLineBreaks("\r\r\n\n\r"), "\n\n\n\n");  // CR, CR LF, LF, CR
  EXPECT_EQ(normalizeLineBreaks("plain\n"), "plain\n");
  EXPECT_EQ(normalizeLineBreaks(""), "");
}

TEST(LineBreaks, TextReaderCountsTheSameLinesWhateverTheBreaks) {
  // The bad word is on line 3 in all three spellings of the file.
  for (const char* nl : {"\n", "\r\n", "\r"}) {
    TextReader in(std::string("1") + nl + "2" + nl + "x" + nl, "f.txt");
    in.number("a");
    in.number("b");
    const std::string m = messageOf([&] { in.number("c"); });
    EXPECT_NE(m.find("f.txt:3:"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace prime::io
