// The Waterloo CGL package's Render (M. A. J. Sweeney, "The Waterloo CGL Ray
// Tracing Package", University of Waterloo CS-85-35, 1985, sections 8.2 and
// 8.6, Figures 41 and 44): the 512 x 512 picture, scanlines from yhigh down
// to ylow and pixels xleft to xright, the rest black; without anti-aliasing
// (aalevel 0, CGL-Q1) one ray per pixel through its integer corner (x, y);
// with it, Subdivid over the pixel's corners, each corner traced once
// through a corner table, squares split while their corners differ by more
// than aathreshold, `level /= 2` before the test (aalevel 1 = corners only,
// 2, 4, 8 = one, two, three levels), the average of four integer RGB values
// truncated (CGL-Q52). Rows run over the shared scheduler (src/render/
// render_rows.h); the picture is the same bytes for any thread count.
#pragma once
#include <atomic>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "legacy_io/cgl/frame.h"
#include "src/cgl/tracer.h"
#include "src/render/render_rows.h"
#include "src/render/rgb_image.h"

namespace prime::cgl {

struct RenderSettings {
  ProgramParameters program;  // as the file gave them, with the command line's overrides
  Phosphors phosphors = Phosphors::Electrohome;
  int threads = 0;        // 0: all cores
  double epsilon = 1e-6;  // TraceSettings::epsilon (CGL-Q44)
  // The document's object list for every ray (TraceSettings::linearSearch):
  // the same pixels as the BVH, and the operation counts of Table 5's program.
  bool linearSearch = false;
  // Record every primary ray's screen point (for tests of the corner table):
  // RenderResult::corners.
  bool recordCorners = false;
};

struct RenderResult {
  Frame frame;  // the 512 x 512 words; outside the window black
  // The same picture as doubles 0..1 (byte / 255), row 0 at the top, kept
  // only when RenderCallbacks::rowDone is set (a live window); else empty:
  // toRgbImage(frame) makes it.
  RgbImage image;
  TraceStats stats;
  RowsRun run;
  double setupSeconds = 0;  // the tracer's set-up (the background's spectrum)
  // With RenderSettings::recordCorners: every primary ray's screen point in
  // eighths of a pixel (8x, 8y), in the order traced by each thread.
  std::vector<std::pair<int, int>> corners;
};

// A finished scanline is image row 511 - scanline, its 512 colours.
using RenderCallbacks = PictureCallbacks<Rgb>;

TraceSettings traceSettings(const RenderSettings& settings);

// Throws io::InputError (naming the scene) for a window outside 0..511 or
// an aalevel other than 0, 1, 2, 4, 8.
RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const RenderCallbacks& callbacks = {});

// The probe: one primary ray through the screen point (x, y) (a pixel's
// integer corner is what aalevel 0 traces for that pixel; any sub-pixel point
// may be given), every ray it spawned and every light's terms.
ProbeReport probe(const Scene& scene, const RenderSettings& settings, double x, double y);

}  // namespace prime::cgl
