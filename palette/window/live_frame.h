// What a window shows: a picture that render threads draw into while the
// window's thread looks, any system's. PRIME's is the emulated 8514/A screen
// seen through a palette and a DAC (palette/prime/live_screen.h); a system
// that renders true colour gives rows of RGB. The window only ever asks for
// the rectangle that changed, as XRGB8888, and scales it by its zoom.
#pragma once
#include <algorithm>
#include <climits>
#include <cstdint>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "palette/rect.h"
#include "palette/window/window_module.h"

namespace prime::display {

// The bounding rectangle of everything marked since it was last taken: what
// a frame tells the window to redraw. Not locked: the frame's lock guards it.
class DirtyRegion {
 public:
  void mark(const Rect& r) {
    x0_ = std::min(x0_, r.x);
    y0_ = std::min(y0_, r.y);
    x1_ = std::max(x1_, r.x + r.w);
    y1_ = std::max(y1_, r.y + r.h);
  }
  bool any() const { return x0_ < x1_ && y0_ < y1_; }
  // The rectangle (empty if nothing was marked), and nothing marked after.
  Rect take() {
    if (!any()) return {};
    const Rect r{x0_, y0_, x1_ - x0_, y1_ - y0_};
    x0_ = y0_ = INT_MAX;
    x1_ = y1_ = INT_MIN;
    return r;
  }

 private:
  int x0_ = INT_MAX, y0_ = INT_MAX, x1_ = INT_MIN, y1_ = INT_MIN;
};

class LiveFrame {
 public:
  virtual ~LiveFrame() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;

  // The window's thread: if anything changed since the last call, writes the
  // changed rectangle as XRGB8888 (0x00RRGGBB), row by row, w * h values,
  // into `pixels` and returns the rectangle; otherwise returns an empty one.
  virtual Rect takeDirty(std::vector<std::uint32_t>& pixels) = 0;
  // Any thread: the whole frame counts as changed (the window was resized,
  // the frame's colours changed).
  virtual void markAllDirty() = 0;
  // Any thread: something waits to be taken.
  virtual bool dirty() const = 0;

  // Keys that mean something for this frame only (PRIME: P the next palette,
  // D the next DAC conversion). True when the key was used: the window then
  // redraws everything and updates its title.
  virtual bool onKey(module::Key) { return false; }
  // What the window's title says about the frame ("palette listing (DAC
  // round)"), or nothing.
  virtual std::string describe() const { return {}; }
  // Any thread: the whole picture as palette indices and the palette they
  // are shown through, when the frame is one (PRIME's 8514/A screen): what
  // a screenshot keeps. False for a true-colour frame.
  virtual bool indexed(IndexedImage8&) const { return false; }
  // The T key: a chart of the frame's palette, the frame's size (PRIME: the
  // 256 DAC entries with their indices and 6-bit values); false: none.
  virtual bool paletteChart(Image8&) const { return false; }
  // What the pointer is over, for the title ("pixel (x, y): index 123 -> DAC
  // 12 34 56 -> RGB 48 137 226"); empty: nothing to say.
  virtual std::string pixelAbout(int, int) const { return {}; }
};

}  // namespace prime::display
