// The window module of the web build (PRIME_WEB, docs/web.md): the page's
// canvas behind window_module.h, in place of the SDL module. `prime` runs in
// a Web Worker (web/worker.js); what the window shows goes to the page as
// rectangles of XRGB8888 pixels, by postMessage, and the page draws them into
// its canvas. The page's keys and mouse come back through a ring of events in
// a SharedArrayBuffer (a worker busy in `prime` cannot receive messages), which
// the page writes and this reads. The key names are mapped here, as the SDL
// module maps SDL's, so that the page only forwards what the browser says.
//
// The ring, an Int32Array (web/worker.js creates it; web/app.js writes it):
// [0] events written, [1] events read, then kSlots slots of kSlotInts ints:
// type, key code, shift, x, y, dx, dy, button, down, buttons, wheel, exposed.
#include <emscripten.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "palette/window/window_module.h"

namespace {

using prime::display::module::Event;
using prime::display::module::Key;
using prime::display::module::WindowBackend;

// What the page's key codes are: a printable key is its character code
// (KeyboardEvent.key of one character); a named key is one of these.
enum : int {
  kEscape = 0x10001,
  kLeft,
  kRight,
  kUp,
  kDown,
  kHome,
  kF11,
  kF12,
  kPause,
};

// The event types as the page writes them.
enum : int { kQuit = 1, kKey, kRedraw, kMotion, kButton, kWheel };

// clang-format off
EM_JS(int, prime_web_canvas, (), {
  return (typeof Module !== "undefined" && Module["primeWindow"]) ? 1 : 0;
});
EM_JS(void, prime_web_post, (const char* kind, int a, int b, int c, int d), {
  Module["primeWindow"](UTF8ToString(kind), a, b, c, d);
});
EM_JS(void, prime_web_title, (const char* title), {
  Module["primeWindow"]("title", UTF8ToString(title));
});
EM_JS(void, prime_web_rect, (const std::uint32_t* pixels, int pitch, int x, int y, int w, int h), {
  // A copy of the rectangle (the memory is shared and goes on changing).
  const rows = new Uint32Array(w * h);
  const words = pitch >> 2;
  for (let r = 0; r < h; ++r) {
    const from = (pixels >> 2) + (y + r) * words + x;
    rows.set(HEAPU32.subarray(from, from + w), r * w);
  }
  Module["primeWindow"]("rect", x, y, w, h, rows);
});
EM_JS(int, prime_web_bounds, (int* size), {
  const v = Module["primeViewport"];
  if (!v) return 0;
  HEAP32[size >> 2] = v[0];
  HEAP32[(size >> 2) + 1] = v[1];
  return 1;
});
EM_JS(int, prime_web_next, (int* out, int count), {
  const ring = Module["primeEvents"];
  if (!ring) return 0;
  const read = Atomics.load(ring, 1);
  if (read === Atomics.load(ring, 0)) return 0;
  const slots = (ring.length - 4) / count;
  const at = 4 + (read % slots) * count;
  for (let k = 0; k < count; ++k) HEAP32[(out >> 2) + k] = ring[at + k];
  Atomics.store(ring, 1, read + 1);
  return 1;
});
// clang-format on

constexpr int kSlotInts = 16;

Key keyOf(int code, int& digit) {
  switch (code) {
    case kEscape:
      return Key::Escape;
    case '+':
    case '=':
      return Key::ZoomIn;
    case '-':
      return Key::ZoomOut;
    case 'p':
    case 'P':
      return Key::Palette;
    case 'd':
    case 'D':
      return Key::Dac;
    case 's':
    case 'S':
    case kF12:
      return Key::Screenshot;
    case kF11:
      return Key::Fullscreen;
    case ' ':
    case kPause:
      return Key::Pause;
    case ']':
    case '>':
      return Key::Faster;
    case '[':
    case '<':
      return Key::Slower;
    case kLeft:
      return Key::Left;
    case kRight:
      return Key::Right;
    case kUp:
      return Key::Up;
    case kDown:
      return Key::Down;
    case kHome:
      return Key::Home;
    case '0':
    case '9':
      digit = code - '0';
      return Key::Zero;
    default:
      if (code >= '1' && code <= '8') {
        digit = code - '0';
        return Key::Digit;
      }
      return Key::Other;
  }
}

class WebWindow final : public WindowBackend {
 public:
  WebWindow(int width, int height) : width_(width), height_(height) {
    prime_web_post("open", width, height, 0, 0);
  }
  ~WebWindow() override { prime_web_post("close", 0, 0, 0, 0); }

  void setTitle(const char* title) override { prime_web_title(title); }
  void resize(int width, int height) override {
    width_ = width;
    height_ = height;
    prime_web_post("resize", width, height, 0, 0);
  }
  void show() override { prime_web_post("show", width_, height_, 0, 0); }
  bool usableBounds(int& width, int& height) override {
    int size[2] = {0, 0};
    if (prime_web_bounds(size) == 0) return false;
    width = size[0];
    height = size[1];
    return width > 0 && height > 0;
  }
  void setFullscreen(bool on) override { prime_web_post("fullscreen", on ? 1 : 0, 0, 0, 0); }
  void size(int& width, int& height) override {
    width = width_;
    height = height_;
  }
  bool setFrame(const std::uint32_t* pixels, int width, int height, int pitch) override {
    frame_ = pixels;
    frameWidth_ = width;
    frameHeight_ = height;
    pitch_ = pitch;
    return true;
  }
  bool ready() override { return true; }
  void present(int x, int y, int width, int height) override {
    if (frame_ == nullptr) return;
    const int x0 = std::max(0, x), y0 = std::max(0, y);
    const int x1 = std::min(frameWidth_, x + width), y1 = std::min(frameHeight_, y + height);
    if (x1 <= x0 || y1 <= y0) return;
    prime_web_rect(frame_, pitch_, x0, y0, x1 - x0, y1 - y0);
  }
  bool nextEvent(Event& event) override {
    int e[kSlotInts] = {};
    if (prime_web_next(e, kSlotInts) == 0) return false;
    event = Event{};
    switch (e[0]) {
      case kQuit:
        event.type = Event::Type::Quit;
        break;
      case kKey:
        event.type = Event::Type::Key;
        event.key = keyOf(e[1], event.digit);
        if (e[1] >= 'a' && e[1] <= 'z') event.letter = static_cast<char>(e[1]);
        if (e[1] >= 'A' && e[1] <= 'Z') event.letter = static_cast<char>(e[1] - 'A' + 'a');
        event.shift = e[2] != 0;
        break;
      case kRedraw:
        event.type = Event::Type::Redraw;
        event.exposed = e[11] != 0;
        break;
      case kMotion:
        event.type = Event::Type::MouseMotion;
        event.x = e[3];
        event.y = e[4];
        event.dx = e[5];
        event.dy = e[6];
        event.buttons = static_cast<unsigned>(e[9]);
        break;
      case kButton:
        event.type = Event::Type::MouseButton;
        event.x = e[3];
        event.y = e[4];
        event.button = e[7];
        event.down = e[8] != 0;
        break;
      case kWheel:
        event.type = Event::Type::Wheel;
        event.wheel = e[10];
        break;
      default:
        break;
    }
    return true;
  }
  unsigned long nativeId() const override { return 0; }
  const char* error() const override { return ""; }

 private:
  int width_, height_;
  const std::uint32_t* frame_ = nullptr;
  int frameWidth_ = 0, frameHeight_ = 0, pitch_ = 0;
};

}  // namespace

extern "C" bool prime_window_web_available() {
  return prime_web_canvas() != 0;
}

extern "C" WindowBackend* prime_window_sdl_open(int interfaceVersion, int width, int height,
                                                char* error, std::size_t errorSize) {
  auto say = [&](const std::string& text) {
    prime::display::module::copyError(text, error, errorSize);
  };
  if (interfaceVersion != prime::display::module::kInterfaceVersion) {
    say("the page's window is interface " +
        std::to_string(prime::display::module::kInterfaceVersion) + ", not " +
        std::to_string(interfaceVersion));
    return nullptr;
  }
  if (!prime_window_web_available()) {
    say("no canvas: the page gives one to the program; node does not");
    return nullptr;
  }
  return new WebWindow(width, height);
}
