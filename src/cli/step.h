// What a command is doing, for the message of a failure nobody foresaw (out
// of memory, a library's exception): "prime: out of memory while rendering
// scenes/malone/glass.mal" instead of a bare "std::bad_alloc".
//   Step step("rendering " + file);   // for as long as the step lasts
// The main thread's steps only: a worker's exception reaches the main thread
// inside the step that started the workers.
#pragma once
#include <exception>
#include <string>
#include <vector>

namespace prime::cli {

class Step {
 public:
  explicit Step(std::string what) : exceptions_(std::uncaught_exceptions()) {
    steps().push_back(std::move(what));
  }
  // A step left by an exception is remembered (the innermost one): main()
  // catches it after every step has gone.
  ~Step() {
    if (std::uncaught_exceptions() > exceptions_ && failed().empty()) failed() = steps().back();
    steps().pop_back();
  }
  Step(const Step&) = delete;
  Step& operator=(const Step&) = delete;
  // The step an exception ended, else the innermost step, or "" outside every step.
  static std::string current() {
    if (!failed().empty()) return failed();
    return steps().empty() ? std::string() : steps().back();
  }

 private:
  static std::vector<std::string>& steps() {
    static std::vector<std::string> s;
    return s;
  }
  static std::string& failed() {
    static std::string f;
    return f;
  }
  int exceptions_;
};

}  // namespace prime::cli
