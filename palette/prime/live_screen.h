// The emulated 8514/A screen as a window shows it (a LiveFrame): a Screen of
// palette indices shared between the thread that draws (the renderer's
// callbacks, a graph-file replay) and the window's thread, which takes only
// the rectangle that changed since it last looked, through the current
// palette's DAC table and a 6-to-8-bit conversion. Batching comes for free:
// however many rows are drawn between two looks, the window converts and
// sends them once, and only the columns the picture covers (349 of the 1024
// for the listing's image). P cycles the palettes, D the DAC conversions.
#pragma once
#include <algorithm>
#include <array>
#include <mutex>
#include <span>
#include <vector>

#include "palette/prime/dac.h"
#include "palette/prime/export.h"
#include "palette/prime/palettes.h"
#include "palette/prime/screen.h"
#include "palette/window/live_frame.h"

namespace prime::display {

class LiveScreen : public LiveFrame {
 public:
  // `palettes`: what P cycles through, the first shown first (the listing's
  // palette when empty).
  LiveScreen(int width, int height, std::vector<Palette> palettes = {}, DacTo8 dac = kDefaultDacTo8)
      : screen_(width, height), palettes_(std::move(palettes)), dac_(dac) {
    if (palettes_.empty()) palettes_.push_back(*findBuiltinPalette("listing"));
    rebuildLut();
  }

  int width() const override { return screen_.width(); }
  int height() const override { return screen_.height(); }

  // Any thread: PutPixel one graph-file row at `at` (drawGraphRow).
  void drawRow(Placement at, int row, std::span<const std::int16_t> values) {
    std::lock_guard lock(mutex_);
    drawGraphRow(screen_, at, row, values);
    const Rect changed =
        intersect(screen_.bounds(), {at.left, at.top + row, static_cast<int>(values.size()), 1});
    if (!changed.empty()) dirty_.mark(changed);
  }
  // Any thread: draw anything (lines, pixels); the whole screen counts as
  // changed.
  template <class F>
  void draw(F&& f) {
    std::lock_guard lock(mutex_);
    f(screen_);
    dirty_.mark(screen_.bounds());
  }
  void markAllDirty() override {
    std::lock_guard lock(mutex_);
    dirty_.mark(screen_.bounds());
  }
  // If anything changed since the last call, calls f(screen, rect) with the
  // bounding rectangle of the changes, under the lock, and returns true.
  template <class F>
  bool takeDirty(F&& f) {
    std::lock_guard lock(mutex_);
    const Rect r = dirty_.take();
    if (r.empty()) return false;
    f(static_cast<const Screen&>(screen_), r);
    return true;
  }
  // The window's side: the changed indices through the palette's DAC.
  Rect takeDirty(std::vector<std::uint32_t>& pixels) override {
    Rect changed;
    takeDirty([&](const Screen& s, Rect r) {
      changed = r;
      pixels.resize(static_cast<std::size_t>(r.w) * r.h);
      for (int y = 0; y < r.h; ++y) {
        const auto src = s.row(r.y + y);
        for (int x = 0; x < r.w; ++x)
          pixels[static_cast<std::size_t>(y) * r.w + x] =
              lut_[src[static_cast<std::size_t>(r.x + x)]];
      }
    });
    return changed;
  }
  bool dirty() const override {
    std::lock_guard lock(mutex_);
    return dirty_.any();
  }

  bool onKey(module::Key key) override {
    {
      std::lock_guard lock(mutex_);
      if (key == module::Key::Palette) {
        paletteIndex_ = (paletteIndex_ + 1) % palettes_.size();
      } else if (key == module::Key::Dac) {
        dac_ = dac_ == DacTo8::Round       ? DacTo8::Replicate
               : dac_ == DacTo8::Replicate ? DacTo8::Truncate
                                           : DacTo8::Round;
      } else {
        return false;
      }
      rebuildLutLocked();
    }
    markAllDirty();
    return true;
  }
  std::string describe() const override {
    std::lock_guard lock(mutex_);
    return "palette " + palettes_[paletteIndex_].name + " (DAC " + std::string(dacTo8Name(dac_)) +
           ")";
  }
  bool indexed(IndexedImage8& out) const override {
    std::lock_guard lock(mutex_);
    out.width = screen_.width();
    out.height = screen_.height();
    out.indices.assign(screen_.pixels().begin(), screen_.pixels().end());
    out.palette = pngPalette(present(palettes_[paletteIndex_].dac, dac_));
    return true;
  }
  bool paletteChart(Image8& out) const override;
  std::string pixelAbout(int x, int y) const override;
  Palette palette() const {
    std::lock_guard lock(mutex_);
    return palettes_[paletteIndex_];
  }
  DacTo8 dac() const {
    std::lock_guard lock(mutex_);
    return dac_;
  }

 private:
  void rebuildLut() {
    std::lock_guard lock(mutex_);
    rebuildLutLocked();
  }
  void rebuildLutLocked() {
    const Rgb8Table colours = present(palettes_[paletteIndex_].dac, dac_);
    for (std::size_t i = 0; i < 256; ++i)
      lut_[i] = static_cast<std::uint32_t>(colours[i].r) << 16 |
                static_cast<std::uint32_t>(colours[i].g) << 8 | colours[i].b;
  }
  mutable std::mutex mutex_;
  Screen screen_;
  std::vector<Palette> palettes_;
  std::size_t paletteIndex_ = 0;
  DacTo8 dac_;
  std::array<std::uint32_t, 256> lut_ = {};
  DirtyRegion dirty_;  // the changed rectangle
};

}  // namespace prime::display
