// A Screen shared between the thread that draws (the renderer's callbacks, a
// graph-file replay) and the window's thread, which redraws only the
// rectangle that changed since it last looked. Batching comes for free:
// however many rows are drawn between two looks, the window converts and
// sends them once, and only the columns the picture covers (349 of the
// 1024 for the listing's image).
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
    const Rect changed =
        intersect(screen_.bounds(), {at.left, at.top + row, static_cast<int>(values.size()), 1});
    if (!changed.empty()) markLocked(changed);
  }
  // Any thread: draw anything (lines, pixels); the whole screen counts as
  // changed.
  template <class F>
  void draw(F&& f) {
    std::lock_guard lock(mutex_);
    f(screen_);
    markLocked(screen_.bounds());
  }
  void markAllDirty() {
    std::lock_guard lock(mutex_);
    markLocked(screen_.bounds());
  }
  // The window's thread: if anything changed since the last call, calls
  // f(screen, rect) with the bounding rectangle of the changes, under the
  // lock, and returns true.
  template <class F>
  bool takeDirty(F&& f) {
    std::lock_guard lock(mutex_);
    if (x1_ <= x0_ || y1_ <= y0_) return false;
    f(static_cast<const Screen&>(screen_), Rect{x0_, y0_, x1_ - x0_, y1_ - y0_});
    x0_ = y0_ = INT_MAX;
    x1_ = y1_ = INT_MIN;
    return true;
  }
  bool dirty() const {
    std::lock_guard lock(mutex_);
    return x0_ < x1_ && y0_ < y1_;
  }

 private:
  void markLocked(const Rect& r) {
    x0_ = std::min(x0_, r.x);
    y0_ = std::min(y0_, r.y);
    x1_ = std::max(x1_, r.x + r.w);
    y1_ = std::max(y1_, r.y + r.h);
  }
  mutable std::mutex mutex_;
  Screen screen_;
  int x0_ = INT_MAX, y0_ = INT_MAX, x1_ = INT_MIN, y1_ = INT_MIN;  // the changed rectangle
};

}  // namespace prime::display
