// A true-colour picture as a window shows it (a LiveFrame): rows of
// XRGB8888 set by the render's thread, taken by the window's thread. For the
// systems that render true colour (Malone, CGL); each converts its colours
// to bytes its own way before a row is set.
#pragma once
#include <algorithm>
#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

#include "palette/window/live_frame.h"

namespace prime::display {

class LiveRgbFrame : public LiveFrame {
 public:
  // The pixels are allocated when first needed (a row set, or a window
  // taking them): a headless render never touches them, and on a small
  // render the page faults of a frame nobody sees are a measurable share.
  LiveRgbFrame(int width, int height) : width_(width), height_(height) {}

  int width() const override { return width_; }
  int height() const override { return height_; }

  // Any thread: row `row` is `xrgb` (width values, 0x00RRGGBB).
  void setRow(int row, std::span<const std::uint32_t> xrgb) {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= height_) return;
    allocate();
    std::copy_n(xrgb.begin(), std::min<std::size_t>(xrgb.size(), width_),
                pixels_.begin() + static_cast<std::ptrdiff_t>(row) * width_);
    dirty_.mark({0, row, width_, 1});
  }

  Rect takeDirty(std::vector<std::uint32_t>& pixels) override {
    std::lock_guard lock(mutex_);
    const Rect r = dirty_.take();
    if (r.empty()) return {};
    allocate();
    pixels.resize(static_cast<std::size_t>(r.w) * r.h);
    for (int y = 0; y < r.h; ++y)
      std::copy_n(pixels_.begin() + static_cast<std::ptrdiff_t>(r.y + y) * width_ + r.x, r.w,
                  pixels.begin() + static_cast<std::ptrdiff_t>(y) * r.w);
    return r;
  }
  void markAllDirty() override {
    std::lock_guard lock(mutex_);
    dirty_.mark({0, 0, width_, height_});
  }
  bool dirty() const override {
    std::lock_guard lock(mutex_);
    return dirty_.any();
  }
  std::string describe() const override { return "true colour"; }

 private:
  // Under mutex_: black until rows are set.
  void allocate() {
    if (pixels_.empty()) pixels_.assign(static_cast<std::size_t>(width_) * height_, 0u);
  }

  mutable std::mutex mutex_;
  int width_, height_;
  std::vector<std::uint32_t> pixels_;
  DirtyRegion dirty_;
};

}  // namespace prime::display
