// libprime_window_sdl.so: the SDL2 calls of the window (window_module.h), a
// module that `prime` loads with dlopen() only when a window opens. It draws
// with SDL's window surface (no GPU renderer), copying only the rectangle the
// executable asks for from the executable's own XRGB8888 picture, so what the
// X server shows is exactly the converted indices.
#include <SDL.h>
#include <SDL_syswm.h>  // after SDL.h; its X11 headers stay in this file

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>

#include "palette/window/window_module.h"

namespace {

using prime::display::module::copyError;
using prime::display::module::Event;
using prime::display::module::Key;
using prime::display::module::WindowBackend;

class SdlWindow final : public WindowBackend {
 public:
  // Starts SDL's video and opens the window; nullptr (and SDL shut down
  // again) with the reason in `why` when it cannot.
  static SdlWindow* open(int width, int height, std::string& why) {
    // SDL prefers an X11 DirectColor visual (for gamma ramps, unused here),
    // whose colours depend on a colormap only a window manager installs; a
    // TrueColor visual shows the pixel values as they are. A user's own
    // setting of the variable wins.
    setenv("SDL_VIDEO_X11_NODIRECTCOLOR", "1", 0);
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
      why = std::string("SDL cannot start video: ") + SDL_GetError();
      return nullptr;
    }
    // A DISPLAY that names no X server makes SDL fall back to a driver whose
    // windows nobody can see (offscreen, dummy): a render would then wait
    // for an Esc no one can press. Only a visible window will do.
    const char* driver = SDL_GetCurrentVideoDriver();
    const std::string name = driver != nullptr ? driver : "";
    if (name.empty() || name == "offscreen" || name == "dummy" || name == "evdev") {
      why = "no visible window: SDL's video driver is '" + name +
            "' (does DISPLAY or WAYLAND_DISPLAY name a running display server?)";
      SDL_Quit();
      return nullptr;
    }
    // The window surface in plain system memory (X11: shared-memory images),
    // not a GPU texture: exact pixels, no GL context (under Xvfb that would
    // be llvmpipe taking CPU from the render), and no re-creation of the
    // window behind our back.
    SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    SDL_Window* window = SDL_CreateWindow("PRIME", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                          width, height, SDL_WINDOW_HIDDEN | SDL_WINDOW_RESIZABLE);
    if (window == nullptr) {
      why = std::string("SDL cannot open a window: ") + SDL_GetError();
      SDL_Quit();
      return nullptr;
    }
    if (SDL_GetWindowSurface(window) == nullptr) {
      why = std::string("SDL cannot draw into the window: ") + SDL_GetError();
      SDL_DestroyWindow(window);
      SDL_Quit();
      return nullptr;
    }
    auto* w = new (std::nothrow) SdlWindow(window);
    if (w == nullptr) {
      why = "out of memory";
      SDL_DestroyWindow(window);
      SDL_Quit();
    }
    return w;
  }

  ~SdlWindow() override {
    if (frame_ != nullptr) SDL_FreeSurface(frame_);
    SDL_DestroyWindow(window_);
    SDL_Quit();
  }
  SdlWindow(const SdlWindow&) = delete;
  SdlWindow& operator=(const SdlWindow&) = delete;

  void setTitle(const char* title) override { SDL_SetWindowTitle(window_, title); }

  void resize(int width, int height) override {
    SDL_SetWindowSize(window_, width, height);
    SDL_SetWindowPosition(window_, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED);
  }

  void show() override { SDL_ShowWindow(window_); }

  bool usableBounds(int& width, int& height) override {
    int display = SDL_GetWindowDisplayIndex(window_);
    if (display < 0) display = 0;
    SDL_Rect r;
    if (SDL_GetDisplayUsableBounds(display, &r) != 0 || r.w <= 0 || r.h <= 0) return false;
    width = r.w;
    height = r.h;
    return true;
  }

  // SDL asks the window manager (_NET_WM_STATE_FULLSCREEN); without one (a
  // bare X server such as Xvfb) nothing would happen, and SDL would still
  // report the display's size. So on X11 without a window manager the window
  // is made borderless and placed over the display's bounds by hand (G23).
  void setFullscreen(bool on) override {
    if (on == fullscreen_) return;
    if (on) {
      SDL_GetWindowPosition(window_, &windowed_.x, &windowed_.y);
      SDL_GetWindowSize(window_, &windowed_.w, &windowed_.h);
      int display = SDL_GetWindowDisplayIndex(window_);
      if (display < 0) display = 0;
      SDL_Rect b{0, 0, 0, 0};
      SDL_GetDisplayBounds(display, &b);
      if (haveWindowManager() || b.w <= 0 || b.h <= 0) {
        SDL_SetWindowFullscreen(window_, SDL_WINDOW_FULLSCREEN_DESKTOP);
      } else {
        SDL_SetWindowBordered(window_, SDL_FALSE);
        SDL_SetWindowPosition(window_, b.x, b.y);
        SDL_SetWindowSize(window_, b.w, b.h);
        byHand_ = true;
      }
    } else if (byHand_) {
      SDL_SetWindowBordered(window_, SDL_TRUE);
      SDL_SetWindowSize(window_, windowed_.w, windowed_.h);
      SDL_SetWindowPosition(window_, windowed_.x, windowed_.y);
      byHand_ = false;
    } else {
      SDL_SetWindowFullscreen(window_, 0);
    }
    fullscreen_ = on;
  }

  void size(int& width, int& height) override { SDL_GetWindowSize(window_, &width, &height); }

  bool setFrame(const std::uint32_t* pixels, int width, int height, int pitch) override {
    if (frame_ != nullptr) SDL_FreeSurface(frame_);
    // SDL only reads a surface it blits from; the pointer is not const in
    // its interface.
    frame_ = SDL_CreateRGBSurfaceWithFormatFrom(const_cast<std::uint32_t*>(pixels), width, height,
                                                32, pitch, SDL_PIXELFORMAT_RGB888);
    if (frame_ == nullptr) {
      error_ = std::string("SDL cannot make a surface: ") + SDL_GetError();
      return false;
    }
    return true;
  }

  bool ready() override { return SDL_GetWindowSurface(window_) != nullptr; }

  void present(int x, int y, int width, int height) override {
    SDL_Surface* target = SDL_GetWindowSurface(window_);
    if (target == nullptr || frame_ == nullptr) return;
    SDL_Rect r{x, y, width, height};
    SDL_BlitSurface(frame_, &r, target, &r);
    SDL_UpdateWindowSurfaceRects(window_, &r, 1);
  }

  bool nextEvent(Event& event) override {
    SDL_Event e;
    if (SDL_PollEvent(&e) == 0) return false;
    event = Event{};
    switch (e.type) {
      case SDL_QUIT:
        event.type = Event::Type::Quit;
        break;
      case SDL_KEYDOWN:
        event.type = Event::Type::Key;
        event.key = keyOf(e.key.keysym.sym, event.digit);
        if (e.key.keysym.sym >= SDLK_a && e.key.keysym.sym <= SDLK_z)
          event.letter = static_cast<char>('a' + (e.key.keysym.sym - SDLK_a));
        event.shift = (e.key.keysym.mod & KMOD_SHIFT) != 0;
        break;
      case SDL_MOUSEMOTION:
        event.type = Event::Type::MouseMotion;
        event.x = e.motion.x;
        event.y = e.motion.y;
        event.dx = e.motion.xrel;
        event.dy = e.motion.yrel;
        event.buttons = ((e.motion.state & SDL_BUTTON_LMASK) ? 1u : 0u) |
                        ((e.motion.state & SDL_BUTTON_MMASK) ? 2u : 0u) |
                        ((e.motion.state & SDL_BUTTON_RMASK) ? 4u : 0u);
        break;
      case SDL_MOUSEBUTTONDOWN:
      case SDL_MOUSEBUTTONUP:
        event.type = Event::Type::MouseButton;
        event.x = e.button.x;
        event.y = e.button.y;
        event.button = e.button.button == SDL_BUTTON_LEFT     ? 1
                       : e.button.button == SDL_BUTTON_MIDDLE ? 2
                       : e.button.button == SDL_BUTTON_RIGHT  ? 3
                                                              : 0;
        event.down = e.type == SDL_MOUSEBUTTONDOWN;
        break;
      case SDL_MOUSEWHEEL:
        event.type = Event::Type::Wheel;
        event.wheel = e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y;
        break;
      case SDL_WINDOWEVENT:
        if (e.window.event == SDL_WINDOWEVENT_EXPOSED || e.window.event == SDL_WINDOWEVENT_SHOWN ||
            e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED ||
            e.window.event == SDL_WINDOWEVENT_RESTORED) {
          event.type = Event::Type::Redraw;
          event.exposed = e.window.event == SDL_WINDOWEVENT_EXPOSED;
        } else if (e.window.event == SDL_WINDOWEVENT_CLOSE) {
          event.type = Event::Type::Quit;
        }
        break;
      default:
        break;
    }
    return true;
  }

  // Whether an X11 window manager runs (it owns the WM_Sn selection, ICCCM
  // 4.3); true on any other video driver, which then does it itself.
  bool haveWindowManager() const {
    SDL_SysWMinfo info;
    SDL_VERSION(&info.version);
    if (SDL_GetWindowWMInfo(window_, &info) != SDL_TRUE) return true;
#if defined(SDL_VIDEO_DRIVER_X11)
    if (info.subsystem == SDL_SYSWM_X11) {
      Display* d = info.info.x11.display;
      const std::string name = "WM_S" + std::to_string(DefaultScreen(d));
      return XGetSelectionOwner(d, XInternAtom(d, name.c_str(), False)) != None;
    }
#endif
    return true;
  }

  unsigned long nativeId() const override {
    SDL_SysWMinfo info;
    SDL_VERSION(&info.version);
    if (SDL_GetWindowWMInfo(window_, &info) != SDL_TRUE) return 0;
#if defined(SDL_VIDEO_DRIVER_X11)
    if (info.subsystem == SDL_SYSWM_X11) return static_cast<unsigned long>(info.info.x11.window);
#endif
    return 0;
  }

  const char* error() const override {
    return error_.c_str();
  }

 private:
  explicit SdlWindow(SDL_Window* window) : window_(window) {}

  static Key keyOf(SDL_Keycode sym, int& digit) {
    switch (sym) {
      case SDLK_ESCAPE:
        return Key::Escape;
      case SDLK_PLUS:
      case SDLK_EQUALS:
      case SDLK_KP_PLUS:
        return Key::ZoomIn;
      case SDLK_MINUS:
      case SDLK_KP_MINUS:
        return Key::ZoomOut;
      case SDLK_p:
        return Key::Palette;
      case SDLK_d:
        return Key::Dac;
      case SDLK_s:
      case SDLK_F12:
        return Key::Screenshot;
      case SDLK_F11:
        return Key::Fullscreen;
      case SDLK_SPACE:
      case SDLK_PAUSE:
        return Key::Pause;
      case SDLK_RIGHTBRACKET:
      case SDLK_GREATER:
        return Key::Faster;
      case SDLK_LEFTBRACKET:
      case SDLK_LESS:
        return Key::Slower;
      case SDLK_LEFT:
        return Key::Left;
      case SDLK_RIGHT:
        return Key::Right;
      case SDLK_UP:
        return Key::Up;
      case SDLK_DOWN:
        return Key::Down;
      case SDLK_HOME:
        return Key::Home;
      case SDLK_0:
      case SDLK_9:
        digit = static_cast<int>(sym - SDLK_0);
        return Key::Zero;
      default:
        if (sym >= SDLK_1 && sym <= SDLK_8) {
          digit = static_cast<int>(sym - SDLK_0);
          return Key::Digit;
        }
        return Key::Other;
    }
  }

  SDL_Window* window_;
  SDL_Surface* frame_ = nullptr;  // wraps the executable's picture
  bool fullscreen_ = false;
  bool byHand_ = false;            // fullscreen without a window manager's help
  SDL_Rect windowed_{0, 0, 0, 0};  // where the window was before fullscreen
  std::string error_;
};

}  // namespace

extern "C" WindowBackend* prime_window_sdl_open(int interfaceVersion, int width, int height,
                                                char* error, std::size_t errorSize) {
  try {
    if (interfaceVersion != prime::display::module::kInterfaceVersion) {
      copyError("the window module was built for interface version " +
                    std::to_string(prime::display::module::kInterfaceVersion) + ", prime uses " +
                    std::to_string(interfaceVersion) + " (a module from another build?)",
                error, errorSize);
      return nullptr;
    }
    std::string why;
    SdlWindow* window = SdlWindow::open(width, height, why);
    if (window == nullptr) copyError(why, error, errorSize);
    return window;
  } catch (const std::exception& e) {
    copyError(std::string("the window module failed: ") + e.what(), error, errorSize);
    return nullptr;
  }
}
