// A Screen shared between the thread that draws (the renderer's callbacks, a
// graph-file replay) and the window's thread, which redraws only the rows
// that changed since it last looked. Batching comes for free: however many
// rows are drawn between two looks, the window converts and sends them once.
#pragma once
#include <algorithm>
#include <climits>
#include <mutex>
#include <span>

#include "palette/screen.h"

namespace prime::display {

class LiveScreen {
 public:
  LiveScreen(int width, int height) : screen_(width, height) {}

  int width() const { return screen_.width(); }
  int height() const { return screen_.height(); }

  // Any thread: PutPixel one graph-file row at `at` (drawGraphRow).
  void drawRow(Placement at, int row, std::span<const std::int16_t> values) {
    std::lock_guard lock(mutex_);
    drawGraphRow(screen_, at, row, values);
    const long long y = static_cast<long long>(at.top) + row;
    if (y >= 0 && y < screen_.height()) markLocked(static_cast<int>(y), static_cast<int>(y) + 1);
  }
  // Any thread: draw anything (lines, pixels); every row counts as changed.
  template <class F>
  void draw(F&& f) {
    std::lock_guard lock(mutex_);
    f(screen_);
    markLocked(0, screen_.height());
  }
  void markAllDirty() {
    std::lock_guard lock(mutex_);
    markLocked(0, screen_.height());
  }
  // The window's thread: if rows changed since the last call, calls
  // f(screen, top, bottom) with the changed band [top, bottom) under the lock
  // and returns true.
  template <class F>
  bool takeDirty(F&& f) {
    std::lock_guard lock(mutex_);
    if (dirtyTop_ >= dirtyBottom_) return false;
    f(static_cast<const Screen&>(screen_), dirtyTop_, dirtyBottom_);
    dirtyTop_ = INT_MAX;
    dirtyBottom_ = INT_MIN;
    return true;
  }
  bool dirty() const {
    std::lock_guard lock(mutex_);
    return dirtyTop_ < dirtyBottom_;
  }

 private:
  void markLocked(int top, int bottom) {
    dirtyTop_ = std::min(dirtyTop_, top);
    dirtyBottom_ = std::max(dirtyBottom_, bottom);
  }
  mutable std::mutex mutex_;
  Screen screen_;
  int dirtyTop_ = INT_MAX, dirtyBottom_ = INT_MIN;
};

}  // namespace prime::display
