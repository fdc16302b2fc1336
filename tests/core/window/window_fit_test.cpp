// The window's placement of the picture (window_fit.h, G23) and the --pace
// logic (G24), with sizes and a clock given by hand.
#include "palette/window/window_fit.h"

#include <gtest/gtest.h>

namespace prime::display {
namespace {

TEST(FitPicture, IntegerTakesTheLargestWholeFactorCentred) {
  // 320 x 240 in 800 x 600: min(800/320, 600/240) = min(2, 2) = 2 -> 640 x 480,
  // borders (800-640)/2 = 80 and (600-480)/2 = 60 (the fullscreen screenshot).
  EXPECT_EQ(fitPicture({320, 240}, {800, 600}, ScaleMode::Integer), (Rect{80, 60, 640, 480}));
  // 100 x 50 in 350 x 1000: min(3, 20) = 3 -> 300 x 150 at (25, 425).
  EXPECT_EQ(fitPicture({100, 50}, {350, 1000}, ScaleMode::Integer), (Rect{25, 425, 300, 150}));
}

TEST(FitPicture, AspectFillsOneSideKeepingTheShape) {
  // 320 x 240 in 800 x 700: the width limits (800*240 <= 700*320), h = 240*800/320 = 600,
  // centred at y (700-600)/2 = 50.
  EXPECT_EQ(fitPicture({320, 240}, {800, 700}, ScaleMode::Aspect), (Rect{0, 50, 800, 600}));
  // 100 x 50 in 350 x 1000: width limits, h = 50*350/100 = 175, y = (1000-175)/2 = 412.
  EXPECT_EQ(fitPicture({100, 50}, {350, 1000}, ScaleMode::Aspect), (Rect{0, 412, 350, 175}));
  // The height limits: 100 x 50 in 1000 x 120 -> w = 100*120/50 = 240, x = 380.
  EXPECT_EQ(fitPicture({100, 50}, {1000, 120}, ScaleMode::Aspect), (Rect{380, 0, 240, 120}));
}

TEST(FitPicture, AWindowSmallerThanThePictureShrinksItEvenInIntegerMode) {
  // 1024 x 768 in 800 x 600: no whole factor fits; 4:3 into 4:3 -> all of it.
  EXPECT_EQ(fitPicture({1024, 768}, {800, 600}, ScaleMode::Integer), (Rect{0, 0, 800, 600}));
  // 1024 x 768 in 500 x 600: width limits, h = 768*500/1024 = 375, y = 112.
  EXPECT_EQ(fitPicture({1024, 768}, {500, 600}, ScaleMode::Integer), (Rect{0, 112, 500, 375}));
  EXPECT_TRUE(fitPicture({1024, 768}, {0, 600}, ScaleMode::Integer).empty());
}

TEST(FirstShowing, NearestNeighbourCoversEveryWindowPixelOnce) {
  // 3 picture pixels onto 7 window pixels: pixel d shows floor(d*3/7):
  // 0 0 0 1 1 2 2 -> pixel 1 starts at 3, pixel 2 at 5, the end at 7.
  EXPECT_EQ(firstShowing(0, 3, 7), 0);
  EXPECT_EQ(firstShowing(1, 3, 7), 3);
  EXPECT_EQ(firstShowing(2, 3, 7), 5);
  EXPECT_EQ(firstShowing(3, 3, 7), 7);
  // An integer zoom: pixel p starts at p*k.
  EXPECT_EQ(firstShowing(5, 10, 30), 15);
}

TEST(ClampZoom, TheWindowNeverExceedsTheDisplay) {
  // 320 x 240 on 800 x 600: 8 -> 3 would be 960 wide, 2 is 640 x 480.
  EXPECT_EQ(clampZoomToDisplay(8, {320, 240}, {800, 600}), 2);
  EXPECT_EQ(clampZoomToDisplay(2, {320, 240}, {800, 600}), 2);
  EXPECT_EQ(clampZoomToDisplay(1, {320, 240}, {800, 600}), 1);
  // Heights limit too: 100 x 300 on 1920 x 1000 -> 3 (900), not 4 (1200).
  EXPECT_EQ(clampZoomToDisplay(8, {100, 300}, {1920, 1000}), 3);
  // Unknown display: only 1..8.
  EXPECT_EQ(clampZoomToDisplay(12, {320, 240}, {0, 0}), 8);
  EXPECT_EQ(clampZoomToDisplay(0, {320, 240}, {800, 600}), 1);
}

TEST(WindowSizeFor, ZoomedOrFittedToTheDisplay) {
  EXPECT_EQ(windowSizeFor({320, 240}, 8, {800, 600}), (Size{640, 480}));
  // 1024 x 768 does not fit 800 x 600 even at zoom 1: the aspect fit, 800 x 600.
  EXPECT_EQ(windowSizeFor({1024, 768}, 4, {800, 600}), (Size{800, 600}));
  EXPECT_EQ(windowSizeFor({1024, 768}, 1, {1280, 1000}), (Size{1024, 768}));
}

TEST(RowPacer, ShowsNoFasterThanThePace) {
  RowPacer p;
  // 10 rows a second, the render already has 100 rows at t = 0.
  EXPECT_EQ(p.advance(100, 0.0, 10.0), 0);
  EXPECT_EQ(p.advance(100, 0.5, 10.0), 5);
  EXPECT_EQ(p.advance(100, 2.0, 10.0), 20);
  // The render done (240 rows) early: the display still catches up at 10/s.
  EXPECT_EQ(p.advance(240, 3.0, 10.0), 30);
  EXPECT_EQ(p.advance(240, 100.0, 10.0), 240);  // never past the rows done
}

TEST(RowPacer, ASlowRenderEarnsNoCredit) {
  RowPacer p;
  EXPECT_EQ(p.advance(0, 0.0, 10.0), 0);
  // The render stalls 5 s with 2 rows done: 2 shown, not 50 banked.
  EXPECT_EQ(p.advance(2, 5.0, 10.0), 2);
  // Then 100 rows appear at once: 0.5 s later only 2 + 5 are shown.
  EXPECT_EQ(p.advance(100, 5.5, 10.0), 7);
}

TEST(RowPacer, TheRateMayChangeAndTimeNeverRunsBack) {
  RowPacer p;
  p.advance(1000, 0.0, 4.0);
  EXPECT_EQ(p.advance(1000, 1.0, 4.0), 4);
  EXPECT_EQ(p.advance(1000, 2.0, 20.0), 24);
  EXPECT_EQ(p.advance(1000, 1.5, 20.0), 24);  // a clock going back adds nothing
}

}  // namespace
}  // namespace prime::display
