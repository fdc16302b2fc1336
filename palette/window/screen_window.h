// A live picture (a LiveFrame: PRIME's emulated 8514/A screen, or any
// system's true-colour rows) in a real window (SDL2), scaled by an integer
// zoom. It draws with SDL's window surface (no GPU renderer), sending only
// the band of rows that changed, so what the X server shows is exactly what
// the frame converted.
//
// The zoom never makes the window larger than the display; the window can be
// resized, and F11 (or --fullscreen) shows the picture fullscreen, both
// scaled by fitPicture (window_fit.h, G23).
//
// Keys: Esc quit (or abort a render), + / - zoom, 1..8 set zoom, F11
// fullscreen, S or F12
// save a screenshot PNG, and the frame's own keys (PRIME: P next palette, D
// next DAC conversion). The close button, SIGINT and SIGTERM count as Esc.
//
// The SDL calls are in a module, libprime_window_sdl.so (window_module.h),
// that the first ScreenWindow loads with dlopen(): `prime` does not link
// libSDL2, and a headless run (headlessReason() needs no SDL) never loads it.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "palette/window/live_frame.h"
#include "palette/window/window_fit.h"

namespace prime::display {

class WindowError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Why no window should be tried (`--no-window`, or neither DISPLAY nor
// WAYLAND_DISPLAY set), or nullopt.
std::optional<std::string> headlessReason(bool noWindowFlag);

struct WindowConfig {
  std::string caption;  // first part of the title: scene or file
  int zoom = 1;         // 1..8, reduced to what fits the display (G23)
  std::string screenshotDir = ".";
  bool fullscreen = false;               // --fullscreen (F11 toggles)
  ScaleMode scale = ScaleMode::Integer;  // --scale: fullscreen and resized windows
  bool paced = false;                    // --pace: no row shown before setRowLimit
  // What the S key's screenshots say made them (tEXt, pHYs); the frame's
  // describe() is added as "Display".
  PngMeta screenshot;
};

class ScreenWindow {
 public:
  // Loads the window module and opens the window; throws WindowError when
  // the module (or libSDL2) cannot be loaded or SDL cannot open a window.
  ScreenWindow(LiveFrame& frame, WindowConfig config);
  ~ScreenWindow();
  ScreenWindow(const ScreenWindow&) = delete;
  ScreenWindow& operator=(const ScreenWindow&) = delete;

  // Handles the events that arrive within `timeoutMs` (at least the pending
  // ones) and sends the rows that changed to the display. Returns true once
  // the user has asked to stop.
  bool poll(int timeoutMs);
  // Input goes to `handler` first (G21): keys and mouse events it returns
  // true for are its own (`prime walk` steers with them); the rest keep
  // their meaning above. Call from the window's thread.
  void setInputHandler(std::function<bool(const module::Event&)> handler);
  // The last part of the title (progress, "done", ...).
  void setStatus(const std::string& status);
  // The display has everything drawn so far: the window has been exposed and
  // no changed row is waiting.
  bool upToDate() const;
  // The X11 window id (0 on other video drivers), for tools such as xwd.
  unsigned long nativeId() const;
  int zoom() const;
  // Only rows [0, rows) of the frame reach the display; the others wait
  // (--pace, G24). Any thread but the window's is wrong: call it from there.
  void setRowLimit(int rows);
  // The picture pixel (column, row of the frame) under window pixel (x, y),
  // wherever zoom, fullscreen or a resize put the picture; nullopt off it.
  std::optional<std::array<int, 2>> pictureAt(int x, int y) const;
  // The frame's picture as the window has it (before any overlay), unscaled.
  Image8 picture() const;
  // Shows `drawing` (the frame's size: a probed pixel's ray tree over
  // picture()) instead of the frame, until clearOverlay() or until the frame
  // changes (a new render, another palette). Throws WindowError for another size.
  void showOverlay(const Image8& drawing);
  void clearOverlay();
  bool overlayShown() const;
  // Saves the window's pixels, as sent to the display, as a PNG in the
  // screenshot directory; returns the path.
  std::string saveScreenshot();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace prime::display
