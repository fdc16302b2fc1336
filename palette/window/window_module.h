// The boundary between `prime` and its SDL2 window module,
// libprime_window_sdl.so, which `prime` loads with dlopen() only when a window
// opens (screen_window.cpp): a headless run never loads libSDL2 and the ~50
// libraries it needs. The module makes the SDL calls and nothing else; what
// the window shows (palette, DAC conversion, zoom, the converted picture) and
// what each key means stay in the executable.
//
// No SDL types here, and nothing crosses the boundary but plain values, C
// strings and the executable's own pixel buffer; nothing throws across it.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace prime::display::module {

// Changes whenever WindowBackend, Event or the factory change: a module from
// another build refuses to open rather than being called wrongly.
// 2: mouse, arrows, letters (G20). 3: hidden until show(), resizable,
// fullscreen, the display's usable size, F11 (G23). 4: Space, [ and ] (the
// pace's pause and speed).
inline constexpr int kInterfaceVersion = 4;

// The keys the window knows, already sorted by meaning.
enum class Key {
  Other,
  Escape,
  ZoomIn,      // + = keypad +
  ZoomOut,     // - keypad -
  Palette,     // P
  Dac,         // D
  Screenshot,  // S F12
  Digit,       // 1..8: Event::digit
  Left,
  Right,
  Up,
  Down,
  Home,
  Zero,        // 0 and 9 (Digit stays 1..8, the zoom keys): Event::digit 0 or 9
  Fullscreen,  // F11
  Pause,       // Space, Pause
  Faster,      // ] >
  Slower,      // [ <
};

struct Event {
  enum class Type {
    Other,        // anything else (mouse, focus, ...)
    Quit,         // the close button, SIGINT, SIGTERM
    Key,          // a key went down
    Redraw,       // shown, exposed, resized or restored: send the whole picture
    MouseMotion,  // x, y, dx, dy, buttons
    MouseButton,  // x, y, button, down
    Wheel,        // wheel: + away from the user
  };
  Type type = Type::Other;
  Key key = Key::Other;
  int digit = 0;         // Key::Digit, Key::Zero
  char letter = 0;       // Key: 'a'..'z' for a letter key (whatever `key` says), else 0
  bool shift = false;    // Key: a shift key was held
  bool exposed = false;  // Redraw: the window was exposed (it is on the display)
  int x = 0, y = 0;      // mouse position in window pixels
  int dx = 0, dy = 0;    // MouseMotion: the move since the last one
  int button = 0;        // MouseButton: 1 left, 2 middle, 3 right
  bool down = false;     // MouseButton: pressed (false: released)
  unsigned buttons = 0;  // MouseMotion: held buttons, bit 0 left, bit 1 middle, bit 2 right
  int wheel = 0;         // Wheel
};

// One open window. Every call comes from the thread that opened it.
class WindowBackend {
 public:
  virtual ~WindowBackend() = default;  // closes the window and shuts SDL down

  virtual void setTitle(const char* title) = 0;
  // A new size in pixels; the window is centred again (without a window
  // manager a grown window would otherwise be kept inside the display from
  // where it was, and come out smaller).
  virtual void resize(int width, int height) = 0;
  // The window opens hidden (so that its size can follow the display's
  // first); this maps it.
  virtual void show() = 0;
  // The usable bounds of the display the window is on (without panels and
  // docks), in pixels; false when SDL cannot tell.
  virtual bool usableBounds(int& width, int& height) = 0;
  // Fullscreen at the desktop's resolution (true) or back to a window.
  virtual void setFullscreen(bool on) = 0;
  // The window's size now, in pixels (after a resize by the user, or
  // fullscreen).
  virtual void size(int& width, int& height) = 0;
  // From now on the window shows `pixels`: width x height, XRGB8888
  // (0x00RRGGBB), `pitch` bytes a row. The memory stays the caller's and must
  // live until the next setFrame or the end of the window. False (why in
  // error()) when SDL cannot.
  virtual bool setFrame(const std::uint32_t* pixels, int width, int height, int pitch) = 0;
  // Whether the window can be drawn into (it may not be mapped yet).
  virtual bool ready() = 0;
  // Copies that rectangle of the frame to the window and sends it to the
  // display.
  virtual void present(int x, int y, int width, int height) = 0;
  // The next pending event, without waiting; false when there is none.
  virtual bool nextEvent(Event& event) = 0;
  // The X11 window id (0 on other video drivers).
  virtual unsigned long nativeId() const = 0;
  // Why the last call that could fail did.
  virtual const char* error() const = 0;
};

// A factory's reason for failing, into out[0 .. size), cut to fit and
// NUL-terminated (every module's prime_window_sdl_open says it this way).
inline void copyError(std::string_view text, char* out, std::size_t size) {
  if (out == nullptr || size == 0) return;
  const std::size_t n = std::min(text.size(), size - 1);
  text.copy(out, n);
  out[n] = '\0';
}

}  // namespace prime::display::module

// The module's only exported symbol. Opens a hidden, resizable window of
// width x height pixels titled "PRIME" (WindowBackend::show maps it); on failure returns nullptr
// with the reason, NUL-terminated, in error[0 .. errorSize). `interfaceVersion` is the caller's
// kInterfaceVersion. (Visible even though the module hides everything else.)
extern "C" __attribute__((visibility("default"))) prime::display::module::WindowBackend*
prime_window_sdl_open(int interfaceVersion, int width, int height, char* error,
                      std::size_t errorSize);

#ifdef __EMSCRIPTEN__
// The web build links its window in (web_window_module.cpp): whether the page
// gave the program a canvas (node gives none, and runs headless).
extern "C" bool prime_window_web_available();
#endif
