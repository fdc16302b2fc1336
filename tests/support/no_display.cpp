// Linked into the end-to-end test binaries: no display for the `prime` they
// run, even in a desktop session (X11 or Wayland), so that a `prime trace`
// never opens a window and waits for Esc. The window tests give their own
// Xvfb server's DISPLAY to the processes they start, explicitly.
#include <cstdlib>

namespace {
const bool kNoDisplay = [] {
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  return true;
}();
}  // namespace
