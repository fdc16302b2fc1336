// Where the window puts the picture, as pure functions of sizes (no SDL, no
// window): the zoom clamped to the display, the size of a window that shows
// the picture, the picture's place in a window of any size (fullscreen, or
// resized by the user), and the pace at which finished rows are shown.
// ScreenWindow (screen_window.cpp) and LiveRender (src/cli/live_render.cpp)
// use them; tests/core/window checks them.
#pragma once
#include <algorithm>
#include <cmath>

#include "palette/rect.h"
#include "palette/window/window_module.h"

namespace prime::display {

// Integer: the largest whole factor that fits, centred, black borders (every
// picture pixel is k x k window pixels). Aspect: the largest size of the
// picture's aspect that fits, nearest neighbour (G23).
enum class ScaleMode { Integer, Aspect };

struct Size {
  int w = 0, h = 0;
  bool operator==(const Size&) const = default;
};

inline constexpr int kMaxZoom = 8;

// The largest zoom, at most `zoom` and at least 1, whose window (picture x
// zoom) fits a display of `display` (usable bounds; 0 x 0 means unknown:
// only 1..kMaxZoom applies). The result is 1 even when 1 does not fit.
inline int clampZoomToDisplay(int zoom, Size picture, Size display) {
  zoom = std::clamp(zoom, 1, kMaxZoom);
  if (display.w <= 0 || display.h <= 0) return zoom;
  while (zoom > 1 && (static_cast<long long>(picture.w) * zoom > display.w ||
                      static_cast<long long>(picture.h) * zoom > display.h))
    --zoom;
  return zoom;
}

// The picture's rectangle in a window of `window` pixels (G23). Integer mode
// falls back to aspect when even factor 1 does not fit (the window is smaller
// than the picture): the picture shrinks rather than being cut.
inline Rect fitPicture(Size picture, Size window, ScaleMode mode) {
  if (picture.w <= 0 || picture.h <= 0 || window.w <= 0 || window.h <= 0) return {};
  const int k = std::min(window.w / picture.w, window.h / picture.h);
  int w, h;
  if (mode == ScaleMode::Integer && k >= 1) {
    w = picture.w * k;
    h = picture.h * k;
  } else if (static_cast<long long>(window.w) * picture.h <=
             static_cast<long long>(window.h) * picture.w) {
    // The width limits: full width, the height in proportion (rounded).
    w = window.w;
    h = static_cast<int>((static_cast<long long>(picture.h) * window.w + picture.w / 2) /
                         picture.w);
  } else {
    h = window.h;
    w = static_cast<int>((static_cast<long long>(picture.w) * window.h + picture.h / 2) /
                         picture.h);
  }
  w = std::clamp(w, 1, window.w);
  h = std::clamp(h, 1, window.h);
  return {(window.w - w) / 2, (window.h - h) / 2, w, h};
}

// The window for a picture at a zoom on a display: picture x zoom with the
// zoom clamped to the display; when even zoom 1 does not fit, the picture's
// aspect-correct fit in the display.
inline Size windowSizeFor(Size picture, int zoom, Size display) {
  const int z = clampZoomToDisplay(zoom, picture, display);
  const Size zoomed{picture.w * z, picture.h * z};
  if (display.w <= 0 || display.h <= 0 || (zoomed.w <= display.w && zoomed.h <= display.h))
    return zoomed;
  const Rect r = fitPicture(picture, display, ScaleMode::Aspect);
  return {r.w, r.h};
}

// Nearest neighbour: the first window pixel (relative to the fitted
// rectangle, of `fitted` pixels) that shows picture pixel `p` of `picture`;
// window pixel d shows picture pixel floor(d * picture / fitted), so picture
// pixels [a, b) cover window pixels [firstShowing(a), firstShowing(b)).
inline int firstShowing(int p, int picture, int fitted) {
  const long long n = static_cast<long long>(p) * fitted;
  return static_cast<int>((n + picture - 1) / picture);
}

// --pace: finished rows are shown no faster than `rowsPerSecond` (G24). The
// shown count grows by rate x elapsed time but never past the rows done, and
// time spent waiting for the render earns no credit: after a stall the rows
// still come at the pace, not in a burst. Time is whatever the caller's clock
// says, in seconds, so a test can fake it.
class RowPacer {
 public:
  // Call with the rows done so far, the time now, and the rate (which may
  // change between calls: `--pace 1991` re-estimates it as rays come in).
  // Returns the rows to show.
  int advance(int rowsDone, double now, double rowsPerSecond) {
    if (!started_) {
      started_ = true;
      last_ = now;
    }
    const double elapsed = std::max(0.0, now - last_);
    last_ = std::max(last_, now);
    shown_ =
        std::min(static_cast<double>(rowsDone), shown_ + std::max(0.0, rowsPerSecond) * elapsed);
    shown_ = std::max(shown_, 0.0);
    return static_cast<int>(std::floor(shown_));
  }
  int shown() const { return static_cast<int>(std::floor(shown_)); }

 private:
  bool started_ = false;
  double last_ = 0.0;
  double shown_ = 0.0;
};

// The pace's own clock and its keys: Space pauses and resumes, ] and [
// double and halve the speed (x1/64 .. x4096). Time is the caller's, in
// seconds, so a test can fake it.
class PaceClock {
 public:
  // The pace's time after `wallSeconds` more of the caller's: nothing while
  // paused, `speed()` times as much otherwise.
  double advance(double wallSeconds) {
    if (!paused_) now_ += std::max(0.0, wallSeconds) * speed_;
    return now_;
  }
  // True when `key` is one of the pace's (and it took effect).
  bool onKey(module::Key key) {
    switch (key) {
      case module::Key::Pause:
        paused_ = !paused_;
        return true;
      case module::Key::Faster:
        speed_ = std::min(speed_ * 2.0, 4096.0);
        return true;
      case module::Key::Slower:
        speed_ = std::max(speed_ / 2.0, 1.0 / 64.0);
        return true;
      default:
        return false;
    }
  }
  bool paused() const { return paused_; }
  double speed() const { return speed_; }
  double now() const { return now_; }

 private:
  bool paused_ = false;
  double speed_ = 1.0;
  double now_ = 0.0;
};

}  // namespace prime::display
