// The drawing itself kept: a graph file drawn on the emulated 8514/A pixel
// by pixel in RayTrace.c's order (rows from the top, each row left to right,
// PutPixel(j, i, color)), recorded as an animated GIF of the whole screen.
// Each row takes the time it took (the 1991 era model's estimate, or a
// --pace of rows a second); the clip is that drawing sped up, its frames'
// times computed, never slept, so a 20-minute replay is written in
// moments, with or without a window. GIF fits the 8514/A exactly: 256
// colours, the DAC's (docs/prime/pace-1991.md, "Recording the drawing").
//
//   - Frame 0 is the screen before the first pixel (cleared to index 0, as
//     initgraph leaves it); each later frame holds only what changed since
//     the one before (the rows or the part of a row drawn meanwhile, clipped
//     to the screen); the last one shows the final screen and is held.
//   - The same graph file, times and settings give the same bytes.
#pragma once
#include <span>
#include <string>

#include "legacy_io/prime/graph_file.h"
#include "palette/prime/dac.h"
#include "palette/prime/screen.h"

namespace prime {

struct DrawingRecordOptions {
  double speed = 1.0;        // drawing seconds a clip second (> 0)
  double fps = 25.0;         // clip frames a second at most (frames without change are merged)
  double holdSeconds = 3.0;  // the final screen held this long before the clip loops
  int loop = 0;              // 0: for ever
};

struct DrawingRecordSummary {
  int frames = 0;               // GIF frames written (the first, the changes, the last)
  double drawingSeconds = 0.0;  // the drawing's time (the rows' times summed)
  double clipSeconds = 0.0;     // the clip's length, the hold included
};

// The drawing's time: the sum of `rowSeconds` (one per graph-file row, >= 0).
double drawingSeconds(std::span<const double> rowSeconds);

// Records the drawing of `graph` at `at` on a screenW x screenH screen, shown
// through `colours`, into `path` (written all or nothing). `rowSeconds` has
// one time per graph-file row. Throws std::invalid_argument for a wrong
// count or option, std::runtime_error when the GIF cannot be written.
DrawingRecordSummary recordDrawing(const std::string& path, const io::GraphFile& graph,
                                   Placement at, int screenW, int screenH, const Rgb8Table& colours,
                                   std::span<const double> rowSeconds,
                                   const DrawingRecordOptions& options);

}  // namespace prime
