// The window as `prime` sees it: zoom, keys, the converted picture and
// screenshots; what the picture is and its own keys belong to the LiveFrame. The SDL calls are in a
// module, libprime_window_sdl.so (sdl_window_module.cpp, interface in window_module.h), loaded with
// dlopen() when the first window opens, so that a headless `prime` never loads libSDL2 and its
// libraries.
#include "palette/window/screen_window.h"

#ifndef __EMSCRIPTEN__
#include <dlfcn.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>

#include "palette/png_image.h"
#include "palette/window/window_module.h"

#ifndef PRIME_WINDOW_MODULE_NAME
#define PRIME_WINDOW_MODULE_NAME "libprime_window_sdl.so"
#endif

namespace prime::display {

std::optional<std::string> headlessReason(bool noWindowFlag) {
  if (noWindowFlag) return "--no-window";
#ifdef __EMSCRIPTEN__
  // The web build: the page's canvas is the display (web_window_module.cpp).
  if (!prime_window_web_available()) return "no canvas: under node there is no page to draw in";
  return std::nullopt;
#endif
  auto set = [](const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != '\0';
  };
  if (!set("DISPLAY") && !set("WAYLAND_DISPLAY")) return "no DISPLAY";
  return std::nullopt;
}

namespace {

namespace fs = std::filesystem;
using OpenWindow = decltype(&prime_window_sdl_open);

constexpr int kMaxWindowSide = 16384;

// The zoom a window may have before the display is known: 1..kMaxZoom and
// within what X11 allows.
int clampZoom(int zoom, int w, int h) {
  return clampZoomToDisplay(zoom, {w, h}, {kMaxWindowSide, kMaxWindowSide});
}

#ifdef __EMSCRIPTEN__
// The web build links its module in: the page's canvas (web_window_module.cpp).
OpenWindow loadModule() {
  return &prime_window_sdl_open;
}
#else
std::string dlerrorText() {
  const char* e = dlerror();
  return e != nullptr ? e : "unknown error";
}

// The module's factory. Loaded once and never unloaded: SDL keeps threads,
// signal handlers and libraries (libdbus among them) for the life of the
// process, as it did when `prime` linked it.
OpenWindow loadModule() {
  static std::mutex mutex;
  static OpenWindow factory = nullptr;
  std::lock_guard lock(mutex);
  if (factory != nullptr) return factory;

  const std::string name = PRIME_WINDOW_MODULE_NAME;
  std::string where;  // what was loaded, for messages
  void* handle = nullptr;
  const char* override = std::getenv("PRIME_WINDOW_MODULE");
  if (override != nullptr && *override != '\0') {
    // A path, or a plain name for the library path.
    where = override;
    handle = dlopen(override, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
      throw WindowError("cannot load the window module " + where +
                        " (PRIME_WINDOW_MODULE): " + dlerrorText());
  } else {
    // Next to the executable (the build tree), or in ../lib/prime/ from it
    // (where `cmake --install` puts it, whatever the prefix); failing that,
    // by name from the library path.
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    fs::path beside = ec ? fs::path() : self.parent_path() / name;
    if (!beside.empty() && !fs::exists(beside, ec)) {
      const fs::path installed = self.parent_path() / ".." / "lib" / "prime" / name;
      if (fs::exists(installed, ec)) beside = installed.lexically_normal();
    }
    if (!beside.empty() && fs::exists(beside, ec)) {
      where = beside.string();
      handle = dlopen(where.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (handle == nullptr)
        throw WindowError("cannot load the window module " + where + ": " + dlerrorText());
    } else {
      where = name;
      handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (handle == nullptr)
        throw WindowError("cannot load the window module " +
                          (beside.empty() ? std::string() : beside.string() + " (not there) or ") +
                          name + " from the library path: " + dlerrorText());
    }
  }
  dlerror();
  void* symbol = dlsym(handle, "prime_window_sdl_open");
  if (symbol == nullptr) {
    const std::string why = dlerrorText();
    dlclose(handle);
    throw WindowError("the window module " + where +
                      " is not PRIME's (no prime_window_sdl_open): " + why);
  }
  factory = reinterpret_cast<OpenWindow>(symbol);
  return factory;
}
#endif

}  // namespace

struct ScreenWindow::Impl {
  LiveFrame& screen;
  WindowConfig config;
  int zoom;
  std::string status;
  // The picture as the frame last gave it, unscaled, XRGB8888: what --pace
  // holds back and what a new window size is scaled from.
  std::vector<std::uint32_t> latest;
  // A drawing shown instead of `latest` (a probed pixel's ray tree), the
  // picture's size; empty: none. It goes when the frame changes.
  std::vector<std::uint32_t> overlay;
  DirtyRegion unshown;  // the part of `latest` not yet in `frame`
  int rowLimit = INT_MAX;
  // The window's pixels as sent to the display: XRGB8888 (0x00RRGGBB),
  // frameWidth pixels a row, the picture at `fit`, black around it. Declared
  // before `window`, which shows it.
  std::vector<std::uint32_t> frame;
  int frameWidth = 0, frameHeight = 0;
  Rect fit;
  std::vector<int> sourceColumn;  // the picture column each column of `fit` shows
  std::unique_ptr<module::WindowBackend> window;
  std::vector<std::uint32_t> changedPixels;  // the frame's changed rectangle, unzoomed
  Size display;                              // usable bounds, 0 x 0 if unknown
  bool fullscreen = false;
  bool exposed = false;
  bool quit = false;
  std::string title;
  std::string hover;        // what the pointer is over (the frame's pixelAbout)
  bool chartShown = false;  // the T key's palette chart is the overlay
  std::function<bool(const module::Event&)> inputHandler;

  Size picture() const { return {screen.width(), screen.height()}; }

  Impl(LiveFrame& s, WindowConfig c) : screen(s), config(std::move(c)) {
    zoom = clampZoom(config.zoom, screen.width(), screen.height());
    if (config.paced) rowLimit = 0;
    latest.assign(static_cast<std::size_t>(screen.width()) * screen.height(), 0);
    const OpenWindow openWindow = loadModule();
    char why[1024] = "";
    window.reset(openWindow(module::kInterfaceVersion, screen.width() * zoom,
                            screen.height() * zoom, why, sizeof why));
    if (window == nullptr) throw WindowError(why);
    // The zoom within the display (G23), before the window is shown.
    if (int w = 0, h = 0; window->usableBounds(w, h)) display = {w, h};
    const int fitting = clampZoomToDisplay(zoom, picture(), display);
    if (fitting != zoom)
      std::cerr << "prime: --zoom " << zoom << " reduced to " << fitting
                << ": the window must fit the display (" << display.w << " x " << display.h
                << ")\n";
    zoom = fitting;
    const Size size = windowSizeFor(picture(), zoom, display);
    window->resize(size.w, size.h);
    rebuildFrame(size);
    screen.markAllDirty();
    window->show();
    if (config.fullscreen) setFullscreen(true);
    updateTitle();
  }

  // A frame of `size` pixels (the window's), the picture fitted in it.
  void rebuildFrame(Size size) {
    size.w = std::max(size.w, 1);
    size.h = std::max(size.h, 1);
    frameWidth = size.w;
    frameHeight = size.h;
    fit = fitPicture(picture(), size, config.scale);
    try {
      frame.assign(static_cast<std::size_t>(frameWidth) * frameHeight, 0);
      sourceColumn.resize(static_cast<std::size_t>(fit.w));
    } catch (const std::bad_alloc&) {
      throw WindowError("no memory for the window's picture (" + std::to_string(frameWidth) +
                        " x " + std::to_string(frameHeight) + ")");
    }
    for (int d = 0; d < fit.w; ++d)
      sourceColumn[static_cast<std::size_t>(d)] =
          static_cast<int>(static_cast<long long>(d) * screen.width() / fit.w);
    if (!window->setFrame(frame.data(), frameWidth, frameHeight,
                          frameWidth * static_cast<int>(sizeof(std::uint32_t))))
      throw WindowError(window->error());
    // Everything the display had is shown again from `latest`.
    unshown.mark({0, 0, screen.width(), screen.height()});
  }

  // The window's size changed (the user, the window manager, fullscreen):
  // the picture is fitted again.
  void followWindowSize() {
    int w = 0, h = 0;
    window->size(w, h);
    if (w > 0 && h > 0 && (w != frameWidth || h != frameHeight)) {
      rebuildFrame({w, h});
      updateTitle();
    }
  }

  void setFullscreen(bool on) {
    fullscreen = on;
    window->setFullscreen(on);
    followWindowSize();
    updateTitle();
  }

  void updateTitle() {
    std::string t = "PRIME";
    if (!config.caption.empty()) t += " - " + config.caption;
    if (const std::string about = screen.describe(); !about.empty()) t += " - " + about;
    if (fullscreen)
      t += " - fullscreen";
    else if (fit.w != screen.width() * zoom || fit.h != screen.height() * zoom)
      t += " - fitted";
    else if (zoom != 1)
      t += " - zoom " + std::to_string(zoom) + "x";
    if (!status.empty()) t += " - " + status;
    if (!hover.empty()) t += " - " + hover;
    if (t != title) {
      title = t;
      window->setTitle(title.c_str());
    }
  }

  // Scales picture rectangle `r` of `latest` into `frame`; returns the
  // window rectangle it covers.
  Rect scaleIntoFrame(const Rect& r) {
    const int pw = screen.width(), ph = screen.height();
    const int x0 = firstShowing(r.x, pw, fit.w), x1 = firstShowing(r.x + r.w, pw, fit.w);
    const int y0 = firstShowing(r.y, ph, fit.h), y1 = firstShowing(r.y + r.h, ph, fit.h);
    int previous = -1;
    for (int dy = y0; dy < y1; ++dy) {
      const int sy = static_cast<int>(static_cast<long long>(dy) * ph / fit.h);
      std::uint32_t* out = frame.data() + static_cast<std::size_t>(fit.y + dy) * frameWidth + fit.x;
      if (sy == previous) {
        std::copy_n(out - frameWidth + x0, x1 - x0, out + x0);
        continue;
      }
      previous = sy;
      const std::uint32_t* src =
          (overlay.empty() ? latest : overlay).data() + static_cast<std::size_t>(sy) * pw;
      for (int dx = x0; dx < x1; ++dx) out[dx] = src[sourceColumn[static_cast<std::size_t>(dx)]];
    }
    return {fit.x + x0, fit.y + y0, x1 - x0, y1 - y0};
  }

  // Takes the frame's changes into `latest`, scales what may be shown (rows
  // above the limit) into `frame` and sends it to the display.
  void refresh(bool everything) {
    if (!window->ready()) return;  // not mapped yet: the changes wait for EXPOSED
    const Rect changed = screen.takeDirty(changedPixels);
    if (!changed.empty()) {
      for (int y = 0; y < changed.h; ++y)
        std::copy_n(
            changedPixels.data() + static_cast<std::size_t>(y) * changed.w, changed.w,
            latest.data() + static_cast<std::size_t>(changed.y + y) * screen.width() + changed.x);
      unshown.mark(changed);
      if (!overlay.empty()) {
        overlay.clear();
        chartShown = false;
        unshown.mark({0, 0, screen.width(), screen.height()});
      }
    }
    Rect sent;
    if (unshown.any()) {
      const Rect r = unshown.take();
      const int limit = std::clamp(rowLimit, 0, screen.height());
      const Rect now = intersect(r, {0, 0, screen.width(), limit});
      const Rect later = intersect(r, {0, limit, screen.width(), screen.height() - limit});
      if (!later.empty()) unshown.mark(later);
      if (!now.empty()) sent = scaleIntoFrame(now);
    }
    if (everything)
      window->present(0, 0, frameWidth, frameHeight);
    else if (!sent.empty())
      window->present(sent.x, sent.y, sent.w, sent.h);
  }

  void setZoom(int z) {
    z = clampZoomToDisplay(clampZoom(z, screen.width(), screen.height()), picture(), display);
    if (fullscreen) setFullscreen(false);
    zoom = z;
    const Size size = windowSizeFor(picture(), zoom, display);
    if (size.w == frameWidth && size.h == frameHeight) return updateTitle();
    window->resize(size.w, size.h);
    rebuildFrame(size);
    updateTitle();
  }

  void onKey(const module::Event& e) {
    using module::Key;
    if (e.letter == 't') {  // the palette chart, and back
      Image8 chart;
      if (chartShown) {
        overlay.clear();
        chartShown = false;
        unshown.mark({0, 0, screen.width(), screen.height()});
      } else if (screen.paletteChart(chart)) {
        setOverlay(chart);
        chartShown = true;
      }
      return;
    }
    switch (e.key) {
      case Key::Escape:
        quit = true;
        return;
      case Key::ZoomIn:
        setZoom(zoom + 1);
        return;
      case Key::ZoomOut:
        setZoom(zoom - 1);
        return;
      case Key::Palette:
      case Key::Dac:
        if (screen.onKey(e.key)) updateTitle();
        return;
      case Key::Screenshot:
        try {
          std::cerr << "prime: screenshot " + saveScreenshot() + "\n";
        } catch (const std::exception& ex) {
          std::cerr << "prime: screenshot failed: " << ex.what() << "\n";
        }
        return;
      case Key::Digit:
        setZoom(e.digit);
        return;
      case Key::Fullscreen:
        setFullscreen(!fullscreen);
        return;
      case Key::Other:
      case Key::Left:
      case Key::Right:
      case Key::Up:
      case Key::Down:
      case Key::Home:
      case Key::Zero:
      case Key::Pause:  // the pace's (src/cli/live_render.cpp), through the input handler
      case Key::Faster:
      case Key::Slower:
        return;
    }
  }

  void handle(const module::Event& e, bool& everything) {
    if (inputHandler && e.type != module::Event::Type::Quit &&
        e.type != module::Event::Type::Redraw && inputHandler(e))
      return;
    switch (e.type) {
      case module::Event::Type::Quit:
        quit = true;
        break;
      case module::Event::Type::Key:
        onKey(e);
        break;
      case module::Event::Type::Redraw:
        exposed = exposed || e.exposed;
        everything = true;
        followWindowSize();
        break;
      case module::Event::Type::MouseMotion: {
        std::string about;
        if (!fit.empty() && e.x >= fit.x && e.y >= fit.y && e.x < fit.x + fit.w &&
            e.y < fit.y + fit.h)
          about = screen.pixelAbout(
              static_cast<int>(static_cast<long long>(e.x - fit.x) * screen.width() / fit.w),
              static_cast<int>(static_cast<long long>(e.y - fit.y) * screen.height() / fit.h));
        if (about != hover) {
          hover = about;
          updateTitle();
        }
        break;
      }
      case module::Event::Type::Other:
      case module::Event::Type::MouseButton:
      case module::Event::Type::Wheel:
        break;
    }
  }

  // Polls in small sleeps rather than waiting inside SDL
  // (SDL_WaitEventTimeout): that one lets SDL wake a waiting window by sending
  // it an X event from a second connection, which can reach the server after
  // the window is gone and then kills the process (BadWindow) on exit.
  bool poll(int timeoutMs) {
    using Clock = std::chrono::steady_clock;
    bool everything = false;
    const Clock::time_point end = Clock::now() + std::chrono::milliseconds(std::max(0, timeoutMs));
    for (;;) {
      bool any = false;
      module::Event e;
      while (window->nextEvent(e)) {
        handle(e, everything);
        any = true;
      }
      const Clock::time_point now = Clock::now();
      if (any || quit || now >= end) break;
      std::this_thread::sleep_for(
          std::min<Clock::duration>(std::chrono::milliseconds(5), end - now));
    }
    refresh(everything);
    return quit;
  }

  // A drawing shown over the picture, the picture's size, until cleared.
  void setOverlay(const Image8& drawing) {
    if (drawing.width != screen.width() || drawing.height != screen.height())
      throw WindowError("an overlay of " + std::to_string(drawing.width) + " x " +
                        std::to_string(drawing.height) + " on a picture of " +
                        std::to_string(screen.width()) + " x " + std::to_string(screen.height()));
    overlay.resize(latest.size());
    for (std::size_t i = 0; i < overlay.size(); ++i)
      overlay[i] = static_cast<std::uint32_t>(drawing.rgb[3 * i]) << 16 |
                   static_cast<std::uint32_t>(drawing.rgb[3 * i + 1]) << 8 | drawing.rgb[3 * i + 2];
    unshown.mark({0, 0, screen.width(), screen.height()});
  }

  // The S key: the frame at its own size (an 8514/A screen as its 256
  // indices and palette, an indexed PNG; else its colours), not the window's
  // scaled pixels; prime-screenshot-N.png, the first N not taken.
  std::string saveScreenshot() {
    fs::path path;
    for (int n = 1;; ++n) {
      path = fs::path(config.screenshotDir) / ("prime-screenshot-" + std::to_string(n) + ".png");
      if (!fs::exists(path)) break;
    }
    PngMeta meta = config.screenshot;
    meta.aspectX = meta.aspectY = 1;
    if (const std::string d = screen.describe(); !d.empty()) meta.text.push_back({"Display", d});
    // A drawing over the picture (a pixel's rays, the palette chart) is
    // saved as shown, in its colours, and so is a paced replay's screen (the
    // rows not shown yet are the window's black); else the screen as its
    // indices.
    const int shownRows = std::clamp(rowLimit, 0, screen.height());
    IndexedImage8 indexed;
    if (overlay.empty() && shownRows == screen.height() && screen.indexed(indexed)) {
      writeIndexedPng(path.string(), indexed, meta);
      return path.string();
    }
    const std::vector<std::uint32_t>& shown = overlay.empty() ? latest : overlay;
    Image8 img;
    img.width = screen.width();
    img.height = screen.height();
    img.rgb.assign(shown.size() * 3, 0);
    const std::size_t limit = static_cast<std::size_t>(shownRows) * screen.width();
    for (std::size_t i = 0; i < std::min(shown.size(), limit); ++i) {
      img.rgb[3 * i] = static_cast<std::uint8_t>(shown[i] >> 16);
      img.rgb[3 * i + 1] = static_cast<std::uint8_t>(shown[i] >> 8);
      img.rgb[3 * i + 2] = static_cast<std::uint8_t>(shown[i]);
    }
    writePng(path.string(), img, meta);
    return path.string();
  }
};

ScreenWindow::ScreenWindow(LiveFrame& screen, WindowConfig config)
    : impl_(std::make_unique<Impl>(screen, std::move(config))) {}

ScreenWindow::~ScreenWindow() = default;

bool ScreenWindow::poll(int timeoutMs) {
  return impl_->poll(timeoutMs);
}

void ScreenWindow::setInputHandler(std::function<bool(const module::Event&)> handler) {
  impl_->inputHandler = std::move(handler);
}

void ScreenWindow::setStatus(const std::string& status) {
  impl_->status = status;
  impl_->updateTitle();
}

bool ScreenWindow::upToDate() const {
  return impl_->exposed && !impl_->screen.dirty();
}

std::optional<std::array<int, 2>> ScreenWindow::pictureAt(int x, int y) const {
  const Impl& w = *impl_;
  if (w.fit.empty() || x < w.fit.x || y < w.fit.y || x >= w.fit.x + w.fit.w ||
      y >= w.fit.y + w.fit.h)
    return std::nullopt;
  return std::array<int, 2>{
      static_cast<int>(static_cast<long long>(x - w.fit.x) * w.screen.width() / w.fit.w),
      static_cast<int>(static_cast<long long>(y - w.fit.y) * w.screen.height() / w.fit.h)};
}

Image8 ScreenWindow::picture() const {
  const Impl& w = *impl_;
  Image8 img{w.screen.width(), w.screen.height(), {}};
  img.rgb.resize(w.latest.size() * 3);
  for (std::size_t i = 0; i < w.latest.size(); ++i) {
    img.rgb[3 * i] = static_cast<std::uint8_t>(w.latest[i] >> 16);
    img.rgb[3 * i + 1] = static_cast<std::uint8_t>(w.latest[i] >> 8);
    img.rgb[3 * i + 2] = static_cast<std::uint8_t>(w.latest[i]);
  }
  return img;
}

void ScreenWindow::showOverlay(const Image8& drawing) {
  impl_->setOverlay(drawing);
  impl_->chartShown = false;
}

void ScreenWindow::clearOverlay() {
  Impl& w = *impl_;
  if (w.overlay.empty()) return;
  w.overlay.clear();
  w.chartShown = false;
  w.unshown.mark({0, 0, w.screen.width(), w.screen.height()});
}

bool ScreenWindow::overlayShown() const {
  return !impl_->overlay.empty();
}

unsigned long ScreenWindow::nativeId() const {
  return impl_->window->nativeId();
}

int ScreenWindow::zoom() const {
  return impl_->zoom;
}

void ScreenWindow::setRowLimit(int rows) {
  impl_->rowLimit = rows;
}
std::string ScreenWindow::saveScreenshot() {
  return impl_->saveScreenshot();
}

}  // namespace prime::display
