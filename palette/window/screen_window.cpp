// The window as `prime` sees it: zoom, keys, the converted picture and
// screenshots; what the picture is and its own keys belong to the LiveFrame. The SDL calls are in a
// module, libprime_window_sdl.so (sdl_window_module.cpp, interface in window_module.h), loaded with
// dlopen() when the first window opens, so that a headless `prime` never loads libSDL2 and its
// libraries.
#include "palette/window/screen_window.h"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <chrono>
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

constexpr int kMaxZoom = 8;
constexpr int kMaxWindowSide = 16384;

int clampZoom(int zoom, int w, int h) {
  zoom = std::clamp(zoom, 1, kMaxZoom);
  while (zoom > 1 && (w * zoom > kMaxWindowSide || h * zoom > kMaxWindowSide)) --zoom;
  return zoom;
}

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

}  // namespace

struct ScreenWindow::Impl {
  LiveFrame& screen;
  WindowConfig config;
  int zoom;
  std::string status;
  // The zoomed picture as sent to the display: XRGB8888 (0x00RRGGBB),
  // frameWidth pixels a row. Declared before `window`, which shows it.
  std::vector<std::uint32_t> frame;
  int frameWidth = 0, frameHeight = 0;
  std::unique_ptr<module::WindowBackend> window;
  std::vector<std::uint32_t> changedPixels;  // the frame's changed rectangle, unzoomed
  bool exposed = false;
  bool quit = false;
  std::string title;
  std::function<bool(const module::Event&)> inputHandler;

  Impl(LiveFrame& s, WindowConfig c) : screen(s), config(std::move(c)) {
    zoom = clampZoom(config.zoom, screen.width(), screen.height());
    const OpenWindow openWindow = loadModule();
    char why[1024] = "";
    window.reset(openWindow(module::kInterfaceVersion, screen.width() * zoom,
                            screen.height() * zoom, why, sizeof why));
    if (window == nullptr) throw WindowError(why);
    rebuildFrame();
    updateTitle();
  }

  void rebuildFrame() {
    frameWidth = screen.width() * zoom;
    frameHeight = screen.height() * zoom;
    try {
      frame.assign(static_cast<std::size_t>(frameWidth) * frameHeight, 0);
    } catch (const std::bad_alloc&) {
      throw WindowError("no memory for the window's picture (" + std::to_string(frameWidth) +
                        " x " + std::to_string(frameHeight) + ")");
    }
    if (!window->setFrame(frame.data(), frameWidth, frameHeight,
                          frameWidth * static_cast<int>(sizeof(std::uint32_t))))
      throw WindowError(window->error());
    screen.markAllDirty();
  }

  void updateTitle() {
    std::string t = "PRIME";
    if (!config.caption.empty()) t += " - " + config.caption;
    if (const std::string about = screen.describe(); !about.empty()) t += " - " + about;
    if (zoom != 1) t += " - zoom " + std::to_string(zoom) + "x";
    if (!status.empty()) t += " - " + status;
    if (t != title) {
      title = t;
      window->setTitle(title.c_str());
    }
  }

  // Converts the changed band into `frame` and sends it to the display.
  void refresh(bool everything) {
    if (!window->ready()) return;  // not mapped yet: the changes wait for EXPOSED
    const Rect changed = screen.takeDirty(changedPixels);
    if (!changed.empty()) {
      const Rect& r = changed;
      const auto line = [&](int zy) {
        return frame.data() + static_cast<std::size_t>(zy) * frameWidth + r.x * zoom;
      };
      for (int y = 0; y < r.h; ++y) {
        const std::uint32_t* src = changedPixels.data() + static_cast<std::size_t>(y) * r.w;
        std::uint32_t* out = line((r.y + y) * zoom);
        for (int x = 0; x < r.w; ++x) std::fill_n(out + x * zoom, zoom, src[x]);
        for (int zy = 1; zy < zoom; ++zy) std::copy_n(out, r.w * zoom, line((r.y + y) * zoom + zy));
      }
    }
    if (changed.empty() && !everything) return;
    if (everything)
      window->present(0, 0, frameWidth, frameHeight);
    else
      window->present(changed.x * zoom, changed.y * zoom, changed.w * zoom, changed.h * zoom);
  }

  void setZoom(int z) {
    z = clampZoom(z, screen.width(), screen.height());
    if (z == zoom) return;
    zoom = z;
    window->resize(screen.width() * zoom, screen.height() * zoom);
    rebuildFrame();
    updateTitle();
  }

  void onKey(const module::Event& e) {
    using module::Key;
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
          std::cerr << "prime: screenshot " << saveScreenshot() << "\n";
        } catch (const std::exception& ex) {
          std::cerr << "prime: screenshot failed: " << ex.what() << "\n";
        }
        return;
      case Key::Digit:
        setZoom(e.digit);
        return;
      case Key::Other:
      case Key::Left:
      case Key::Right:
      case Key::Up:
      case Key::Down:
      case Key::Home:
      case Key::Zero:
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
        break;
      case module::Event::Type::Other:
      case module::Event::Type::MouseMotion:
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

  std::string saveScreenshot() {
    fs::path path;
    for (int n = 1;; ++n) {
      path = fs::path(config.screenshotDir) / ("prime-screenshot-" + std::to_string(n) + ".png");
      if (!fs::exists(path)) break;
    }
    Image8 img;
    img.width = frameWidth;
    img.height = frameHeight;
    img.rgb.resize(frame.size() * 3);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      img.rgb[3 * i] = static_cast<std::uint8_t>(frame[i] >> 16);
      img.rgb[3 * i + 1] = static_cast<std::uint8_t>(frame[i] >> 8);
      img.rgb[3 * i + 2] = static_cast<std::uint8_t>(frame[i]);
    }
    writePng(path.string(), img);
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

unsigned long ScreenWindow::nativeId() const {
  return impl_->window->nativeId();
}

int ScreenWindow::zoom() const {
  return impl_->zoom;
}
std::string ScreenWindow::saveScreenshot() {
  return impl_->saveScreenshot();
}

}  // namespace prime::display
