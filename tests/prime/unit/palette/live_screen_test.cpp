// The screen the window shares with the renderer: rows drawn where PutPixel
// put them, and the rectangle the window must redraw (header-only, no SDL).
#include "palette/prime/live_screen.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace prime::display {
namespace {

Rect take(LiveScreen& s) {
  Rect r;
  s.takeDirty([&](const Screen&, Rect changed) { r = changed; });
  return r;
}

TEST(LiveScreen, ChangedRectangleCoversTheRowsDrawnSinceTheLastLook) {
  LiveScreen s(1024, 768);
  EXPECT_FALSE(s.dirty());
  const std::vector<std::int16_t> row(350, 109);
  s.drawRow({675, 0}, 10, row);  // columns 675..1024: 1024 is off-screen
  s.drawRow({675, 0}, 3, row);
  EXPECT_TRUE(s.dirty());
  EXPECT_EQ(take(s), (Rect{675, 3, 349, 8}));
  EXPECT_FALSE(s.dirty());
  EXPECT_TRUE(take(s).empty());   // nothing new
  s.drawRow({675, 0}, 768, row);  // off the screen: nothing to redraw
  EXPECT_FALSE(s.dirty());
  s.draw([](Screen& screen) { screen.line(0, 0, 9, 9, 5); });
  EXPECT_EQ(take(s), (Rect{0, 0, 1024, 768}));
  bool seen = false;
  s.takeDirty([&](const Screen&, Rect) { seen = true; });
  EXPECT_FALSE(seen);
  s.markAllDirty();
  s.takeDirty([&](const Screen& screen, Rect) {
    EXPECT_EQ(screen.getPixel(675, 10), 109);
    EXPECT_EQ(screen.getPixel(9, 9), 5);
  });
}

TEST(LiveScreen, DrawingFromAnotherThreadWhileTheWindowLooks) {
  LiveScreen s(64, 64);
  std::thread drawer([&] {
    const std::vector<std::int16_t> row(64, 7);
    for (int y = 0; y < 64; ++y) s.drawRow({0, 0}, y, row);
  });
  int rowsSeen = 0;
  while (rowsSeen < 64) {
    s.takeDirty([&](const Screen&, Rect r) { rowsSeen = std::max(rowsSeen, r.y + r.h); });
    std::this_thread::yield();
  }
  drawer.join();
  s.markAllDirty();
  s.takeDirty([](const Screen& screen, Rect) {
    for (int y = 0; y < 64; ++y) ASSERT_EQ(screen.getPixel(63, y), 7);
  });
}

}  // namespace
}  // namespace prime::display
