// The message of the InputError a piece of code throws, or "(no error)": for
// tests that check what a reader or writer tells the user.
#pragma once
#include <functional>
#include <string>

#include "legacy_io/common/error.h"

namespace prime::test {

inline std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace prime::test
