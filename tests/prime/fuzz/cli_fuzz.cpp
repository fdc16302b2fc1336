// The command line of every subcommand, parsed in-process: the input is the
// arguments after `prime`, separated by NUL bytes (at most 24 of them).
// primeMain (src/cli/main.cpp) runs with parseOnly: CLI11's parsing, the
// routing of trace/probe/bench/export-pov/export/view to a system, the CGL
// call statement's translation, the option checks and the finite-number
// check, everything but the chosen command's action. It must return 0 (a
// valid command line, or --help/--version) or 2 (a usage error, reported
// on one line), and never crash, hang or throw. The dictionary
// (cli.dict) holds every subcommand and option name.
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/prime/fuzz/fuzz_support.h"

int primeMain(int argc, char** argv, bool parseOnly);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> words{"prime"};
  std::string word;
  for (std::size_t i = 0; i < size && words.size() <= 24; ++i) {
    if (data[i] == 0) {
      words.push_back(word);
      word.clear();
    } else {
      word.push_back(static_cast<char>(data[i]));
    }
  }
  if (words.size() <= 24) words.push_back(word);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // Help and error text would flood the fuzzer's log.
  std::ostringstream sink;
  std::streambuf* out = std::cout.rdbuf(sink.rdbuf());
  std::streambuf* err = std::cerr.rdbuf(sink.rdbuf());
  const int status = primeMain(static_cast<int>(words.size()), argv.data(), true);
  std::cout.rdbuf(out);
  std::cerr.rdbuf(err);
  if (status != 0 && status != 2)
    prime::fuzz::fail("exit status " + std::to_string(status) +
                      " from parsing alone: " + sink.str());
  if (status == 2 && sink.str().rfind("prime: ", 0) != 0 &&
      sink.str().find("Run with") == std::string::npos)
    prime::fuzz::fail("a usage error without the prime: prefix: " + sink.str());
  return 0;
}
