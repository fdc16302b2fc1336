// A child process for end-to-end tests that must run something in the
// background (a window, an X server) and talk to it while it runs: fork/exec
// with extra environment variables, its stdout and stderr collected through
// pipes, waiting for a line with a timeout, signals, and exit status.
#pragma once
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace prime::test {

class ChildProcess {
 public:
  // Starts argv[0] (looked up in PATH) with `env` added to (or, for an empty
  // value, removed from) this process's environment. Throws on failure.
  // `cwd`: the child's working directory ("" = the test's).
  ChildProcess(const std::vector<std::string>& argv,
               const std::map<std::string, std::string>& env = {}, const std::string& cwd = "") {
    int out[2], err[2];
    if (pipe(out) != 0 || pipe(err) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the test (an X server, a window)
      dup2(out[1], 1);
      dup2(err[1], 2);
      close(out[0]);
      close(out[1]);
      close(err[0]);
      close(err[1]);
      for (const auto& [k, v] : env) {
        if (v.empty())
          unsetenv(k.c_str());
        else
          setenv(k.c_str(), v.c_str(), 1);
      }
      if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(126);
      std::vector<char*> args;
      for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      execvp(args[0], args.data());
      _exit(127);
    }
    close(out[1]);
    close(err[1]);
    outFd_ = out[0];
    errFd_ = err[0];
    fcntl(outFd_, F_SETFL, O_NONBLOCK);
    fcntl(errFd_, F_SETFL, O_NONBLOCK);
  }
  ~ChildProcess() {
    if (!exited_) {
      kill(pid_, SIGKILL);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
    close(outFd_);
    close(errFd_);
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  const std::string& out() const { return out_; }
  const std::string& err() const { return err_; }

  // Reads what the child wrote, for up to `ms` milliseconds or until `pred`
  // holds for (stdout, stderr). Returns whether it held.
  template <class Pred>
  bool readUntil(Pred pred, int ms) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
    for (;;) {
      drain();
      if (pred(out_, err_)) return true;
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          end - std::chrono::steady_clock::now());
      if (left.count() <= 0 || (outClosed_ && errClosed_)) return pred(out_, err_);
      pollfd fds[2] = {{outFd_, POLLIN, 0}, {errFd_, POLLIN, 0}};
      poll(fds, 2, static_cast<int>(std::min<long long>(left.count(), 50)));
    }
  }
  bool waitForErr(const std::string& text, int ms) {
    return readUntil(
        [&](const std::string&, const std::string& e) { return e.find(text) != std::string::npos; },
        ms);
  }

  // The exit status (128 + signal if killed), or nullopt if it is still
  // running after `ms` milliseconds.
  std::optional<int> wait(int ms) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
    for (;;) {
      drain();
      int status = 0;
      const pid_t r = waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        exited_ = true;
        readUntil([](const std::string&, const std::string&) { return false; }, 200);
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
      if (std::chrono::steady_clock::now() >= end) return std::nullopt;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  void signal(int sig) { kill(pid_, sig); }

 private:
  void drain() {
    char buf[4096];
    for (;;) {
      const ssize_t n = read(outFd_, buf, sizeof buf);
      if (n > 0) {
        out_.append(buf, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0) outClosed_ = true;
      break;
    }
    for (;;) {
      const ssize_t n = read(errFd_, buf, sizeof buf);
      if (n > 0) {
        err_.append(buf, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0) errClosed_ = true;
      break;
    }
  }

  pid_t pid_ = -1;
  int outFd_ = -1, errFd_ = -1;
  bool exited_ = false, outClosed_ = false, errClosed_ = false;
  std::string out_, err_;
};

}  // namespace prime::test
