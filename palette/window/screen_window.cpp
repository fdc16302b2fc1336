#include "palette/window/screen_window.h"

#include <SDL.h>
#include <SDL_syswm.h>  // after SDL.h; its X11 headers stay in this file

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "palette/png_image.h"

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

constexpr int kMaxZoom = 8;
constexpr int kMaxWindowSide = 16384;

int clampZoom(int zoom, int w, int h) {
  zoom = std::clamp(zoom, 1, kMaxZoom);
  while (zoom > 1 && (w * zoom > kMaxWindowSide || h * zoom > kMaxWindowSide)) --zoom;
  return zoom;
}

}  // namespace

struct ScreenWindow::Impl {
  LiveScreen& screen;
  WindowConfig config;
  std::size_t paletteIndex = 0;
  DacTo8 dac;
  int zoom;
  std::string status;
  SDL_Window* window = nullptr;
  SDL_Surface* frame = nullptr;  // the zoomed picture, XRGB8888
  Uint32 lut[256] = {};
  bool exposed = false;
  bool quit = false;
  std::string title;

  Impl(LiveScreen& s, WindowConfig c) : screen(s), config(std::move(c)), dac(config.dac) {
    if (config.palettes.empty()) config.palettes.push_back(*findBuiltinPalette("listing"));
    zoom = clampZoom(config.zoom, screen.width(), screen.height());
    // SDL prefers an X11 DirectColor visual (for gamma ramps, unused here),
    // whose colours depend on a colormap only a window manager installs; a
    // TrueColor visual shows the pixel values as they are. A user's own
    // setting of the variable wins.
    setenv("SDL_VIDEO_X11_NODIRECTCOLOR", "1", 0);
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
      throw WindowError(std::string("SDL cannot start video: ") + SDL_GetError());
    // The window surface in plain system memory (X11: shared-memory images),
    // not a GPU texture: exact pixels, no GL context (under Xvfb that would
    // be llvmpipe taking CPU from the render), and no re-creation of the
    // window behind our back.
    SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    window = SDL_CreateWindow("PRIME", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                              screen.width() * zoom, screen.height() * zoom, SDL_WINDOW_SHOWN);
    if (window == nullptr) {
      const std::string why = SDL_GetError();
      SDL_Quit();
      throw WindowError("SDL cannot open a window: " + why);
    }
    if (SDL_GetWindowSurface(window) == nullptr) {
      const std::string why = SDL_GetError();
      SDL_DestroyWindow(window);
      SDL_Quit();
      throw WindowError("SDL cannot draw into the window: " + why);
    }
    rebuildFrame();
    updateTitle();
  }

  ~Impl() {
    if (frame != nullptr) SDL_FreeSurface(frame);
    if (window != nullptr) SDL_DestroyWindow(window);
    SDL_Quit();
  }

  const Palette& palette() const { return config.palettes[paletteIndex]; }

  void rebuildLut() {
    const Rgb8Table colours = present(palette().dac, dac);
    for (std::size_t i = 0; i < 256; ++i)
      lut[i] = SDL_MapRGB(frame->format, colours[i].r, colours[i].g, colours[i].b);
  }

  void rebuildFrame() {
    if (frame != nullptr) SDL_FreeSurface(frame);
    frame = SDL_CreateRGBSurfaceWithFormat(0, screen.width() * zoom, screen.height() * zoom, 32,
                                           SDL_PIXELFORMAT_RGB888);
    if (frame == nullptr)
      throw WindowError(std::string("SDL cannot make a surface: ") + SDL_GetError());
    rebuildLut();
    screen.markAllDirty();
  }

  void updateTitle() {
    std::string t = "PRIME";
    if (!config.caption.empty()) t += " - " + config.caption;
    t += " - palette " + palette().name + " (DAC " + std::string(dacTo8Name(dac)) + ")";
    if (zoom != 1) t += " - zoom " + std::to_string(zoom) + "x";
    if (!status.empty()) t += " - " + status;
    if (t != title) {
      title = t;
      SDL_SetWindowTitle(window, title.c_str());
    }
  }

  // Converts the changed band into `frame` and sends it to the display.
  void refresh(bool everything) {
    SDL_Surface* target = SDL_GetWindowSurface(window);
    if (target == nullptr) return;  // not mapped yet: the changes wait for EXPOSED
    Rect changed;
    screen.takeDirty([&](const Screen& s, Rect r) {
      changed = r;
      if (SDL_MUSTLOCK(frame)) SDL_LockSurface(frame);
      auto* base = static_cast<std::uint8_t*>(frame->pixels);
      const auto line = [&](int zy) {
        return reinterpret_cast<Uint32*>(base + static_cast<std::size_t>(zy) * frame->pitch) +
               r.x * zoom;
      };
      for (int y = r.y; y < r.y + r.h; ++y) {
        const auto src = s.row(y);
        Uint32* out = line(y * zoom);
        for (int x = 0; x < r.w; ++x)
          std::fill_n(out + x * zoom, zoom, lut[src[static_cast<std::size_t>(r.x + x)]]);
        for (int zy = 1; zy < zoom; ++zy) std::copy_n(out, r.w * zoom, line(y * zoom + zy));
      }
      if (SDL_MUSTLOCK(frame)) SDL_UnlockSurface(frame);
    });
    if (changed.empty() && !everything) return;
    SDL_Rect r{changed.x * zoom, changed.y * zoom, changed.w * zoom, changed.h * zoom};
    if (everything) r = {0, 0, frame->w, frame->h};
    SDL_BlitSurface(frame, &r, target, &r);
    SDL_UpdateWindowSurfaceRects(window, &r, 1);
  }

  void setZoom(int z) {
    z = clampZoom(z, screen.width(), screen.height());
    if (z == zoom) return;
    zoom = z;
    SDL_SetWindowSize(window, screen.width() * zoom, screen.height() * zoom);
    // Centre it again: without a window manager (Xvfb) SDL keeps a grown
    // window inside the display from where it was, and it comes out smaller.
    SDL_SetWindowPosition(window, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED);
    rebuildFrame();
    updateTitle();
  }

  void onKey(const SDL_Keysym& key) {
    switch (key.sym) {
      case SDLK_ESCAPE:
        quit = true;
        return;
      case SDLK_PLUS:
      case SDLK_EQUALS:
      case SDLK_KP_PLUS:
        setZoom(zoom + 1);
        return;
      case SDLK_MINUS:
      case SDLK_KP_MINUS:
        setZoom(zoom - 1);
        return;
      case SDLK_p:
        paletteIndex = (paletteIndex + 1) % config.palettes.size();
        rebuildLut();
        screen.markAllDirty();
        updateTitle();
        return;
      case SDLK_d:
        dac = dac == DacTo8::Round       ? DacTo8::Replicate
              : dac == DacTo8::Replicate ? DacTo8::Truncate
                                         : DacTo8::Round;
        rebuildLut();
        screen.markAllDirty();
        updateTitle();
        return;
      case SDLK_s:
      case SDLK_F12:
        try {
          std::cerr << "prime: screenshot " << saveScreenshot() << "\n";
        } catch (const std::exception& e) {
          std::cerr << "prime: screenshot failed: " << e.what() << "\n";
        }
        return;
      default:
        if (key.sym >= SDLK_1 && key.sym <= SDLK_8) setZoom(static_cast<int>(key.sym - SDLK_0));
        return;
    }
  }

  void handle(const SDL_Event& e, bool& everything) {
    switch (e.type) {
      case SDL_QUIT:
        quit = true;
        break;
      case SDL_KEYDOWN:
        onKey(e.key.keysym);
        break;
      case SDL_WINDOWEVENT:
        if (e.window.event == SDL_WINDOWEVENT_EXPOSED || e.window.event == SDL_WINDOWEVENT_SHOWN ||
            e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED ||
            e.window.event == SDL_WINDOWEVENT_RESTORED) {
          exposed = exposed || e.window.event == SDL_WINDOWEVENT_EXPOSED;
          everything = true;
        } else if (e.window.event == SDL_WINDOWEVENT_CLOSE) {
          quit = true;
        }
        break;
      default:
        break;
    }
  }

  // Polls in small sleeps rather than SDL_WaitEventTimeout: that one lets SDL
  // wake a waiting window by sending it an X event from a second connection,
  // which can reach the server after the window is gone and then kills the
  // process (BadWindow) on exit.
  bool poll(int timeoutMs) {
    bool everything = false;
    const Uint64 end = SDL_GetTicks64() + static_cast<Uint64>(std::max(0, timeoutMs));
    for (;;) {
      bool any = false;
      SDL_Event e;
      while (SDL_PollEvent(&e) != 0) {
        handle(e, everything);
        any = true;
      }
      const Uint64 now = SDL_GetTicks64();
      if (any || quit || now >= end) break;
      SDL_Delay(static_cast<Uint32>(std::min<Uint64>(5, end - now)));
    }
    refresh(everything);
    return quit;
  }

  std::string saveScreenshot() {
    namespace fs = std::filesystem;
    fs::path path;
    for (int n = 1;; ++n) {
      path = fs::path(config.screenshotDir) / ("prime-screenshot-" + std::to_string(n) + ".png");
      if (!fs::exists(path)) break;
    }
    Image8 img;
    img.width = frame->w;
    img.height = frame->h;
    img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
    if (SDL_ConvertPixels(frame->w, frame->h, frame->format->format, frame->pixels, frame->pitch,
                          SDL_PIXELFORMAT_RGB24, img.rgb.data(), img.width * 3) != 0)
      throw WindowError(std::string("SDL cannot convert the picture: ") + SDL_GetError());
    writePng(path.string(), img);
    return path.string();
  }
};

ScreenWindow::ScreenWindow(LiveScreen& screen, WindowConfig config)
    : impl_(std::make_unique<Impl>(screen, std::move(config))) {}

ScreenWindow::~ScreenWindow() = default;

bool ScreenWindow::poll(int timeoutMs) {
  return impl_->poll(timeoutMs);
}

void ScreenWindow::setStatus(const std::string& status) {
  impl_->status = status;
  impl_->updateTitle();
}

bool ScreenWindow::upToDate() const {
  return impl_->exposed && !impl_->screen.dirty();
}

unsigned long ScreenWindow::nativeId() const {
  SDL_SysWMinfo info;
  SDL_VERSION(&info.version);
  if (SDL_GetWindowWMInfo(impl_->window, &info) != SDL_TRUE) return 0;
#if defined(SDL_VIDEO_DRIVER_X11)
  if (info.subsystem == SDL_SYSWM_X11) return static_cast<unsigned long>(info.info.x11.window);
#endif
  return 0;
}

const Palette& ScreenWindow::palette() const {
  return impl_->palette();
}
DacTo8 ScreenWindow::dac() const {
  return impl_->dac;
}
int ScreenWindow::zoom() const {
  return impl_->zoom;
}
std::string ScreenWindow::saveScreenshot() {
  return impl_->saveScreenshot();
}

}  // namespace prime::display
