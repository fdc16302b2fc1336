// Runs the `prime` executable under test (PRIME_EXE) with a command line and
// collects its exit status and output (stdout and stderr together).
#pragma once
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace prime::test {

struct CommandResult {
  int status;
  std::string output;  // stdout and stderr
};

// `cwd`: the directory it runs in ("" = the test's).
inline CommandResult runPrime(const std::string& args, const std::string& cwd = "") {
  std::string out;
  const std::string in = cwd.empty() ? "" : "cd '" + cwd + "' && ";
  FILE* p = popen((in + std::string(PRIME_EXE) + " " + args + " 2>&1").c_str(), "r");
  std::array<char, 4096> buf;
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
  const int status = pclose(p);
  // A run that did not exit (killed by a signal, should the shell hand it the
  // process) is never status 0: the shell's 128 + signal, or -1.
  if (WIFEXITED(status)) return {WEXITSTATUS(status), out};
  return {WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1, out};
}

}  // namespace prime::test
