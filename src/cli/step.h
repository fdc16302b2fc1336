// What a command is doing, for the message of a failure nobody foresaw (out
// of memory, a library's exception): "prime: out of memory while rendering
// scenes/malone/glass.mal" instead of a bare "std::bad_alloc".
//   Step step("rendering " + file);   // for as long as the step lasts
// The main thread's steps only: a worker's exception reaches the main thread
// inside the step that started the workers.
#pragma once
#include <string>
#include <vector>

namespace prime::cli {

class Step {
 public:
  explicit Step(std::string what) { steps().push_back(std::move(what)); }
  ~Step() { steps().pop_back(); }
  Step(const Step&) = delete;
  Step& operator=(const Step&) = delete;
  // The innermost step, or "" outside every step.
  static std::string current() { return steps().empty() ? std::string() : steps().back(); }

 private:
  static std::vector<std::string>& steps() {
    static std::vector<std::string> s;
    return s;
  }
};

}  // namespace prime::cli
