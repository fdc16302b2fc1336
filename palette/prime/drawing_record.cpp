#include "palette/prime/drawing_record.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "legacy_io/common/output_file.h"
#include "palette/gif_film.h"
#include "palette/rect.h"

namespace prime {

double drawingSeconds(std::span<const double> rowSeconds) {
  double t = 0.0;
  for (double s : rowSeconds) t += s;
  return t;
}

namespace {

// Pixels of the file drawn (in RayTrace.c's order) by drawing time `t`:
// whole rows before the row whose time `t` falls in, and that row's share.
std::size_t pixelsBy(double t, const std::vector<double>& rowStart,
                     std::span<const double> rowSeconds, std::size_t columns) {
  const std::size_t rows = rowSeconds.size();
  const auto after = std::upper_bound(rowStart.begin(), rowStart.end(), t);
  std::size_t r = static_cast<std::size_t>(after - rowStart.begin());
  if (r == 0) return 0;
  --r;
  if (r >= rows) return rows * columns;
  std::size_t share = columns;
  if (rowSeconds[r] > 0.0) {
    const double f = std::floor(static_cast<double>(columns) * (t - rowStart[r]) / rowSeconds[r]);
    share = static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(columns)));
  }
  return r * columns + share;
}

// Clip hundredths of a second at clip frame k.
long hundredths(long k, double fps) {
  return std::lround(100.0 * static_cast<double>(k) / fps);
}

struct Step {
  long k;             // clip frame: shown from k / fps
  std::size_t drawn;  // pixels of the file drawn by then
  Rect changed;       // on the screen, since the step before
};

}  // namespace

DrawingRecordSummary recordDrawing(const std::string& path, const io::GraphFile& graph,
                                   Placement at, int screenW, int screenH, const Rgb8Table& colours,
                                   std::span<const double> rowSeconds,
                                   const DrawingRecordOptions& o) {
  const auto columns = static_cast<std::size_t>(graph.width());
  const auto rows = static_cast<std::size_t>(graph.height());
  if (rowSeconds.size() != rows)
    throw std::invalid_argument("recordDrawing: " + std::to_string(rowSeconds.size()) +
                                " row times for " + std::to_string(rows) + " rows");
  if (!(o.speed > 0.0) || !(o.fps > 0.0) || !(o.fps <= 100.0) || !(o.holdSeconds >= 0.0))
    throw std::invalid_argument("recordDrawing: speed and fps must be > 0 (fps at most 100)");
  std::vector<double> rowStart(rows + 1, 0.0);
  for (std::size_t r = 0; r < rows; ++r) {
    if (!(rowSeconds[r] >= 0.0) || !std::isfinite(rowSeconds[r]))
      throw std::invalid_argument("recordDrawing: row " + std::to_string(r) + "'s time is " +
                                  std::to_string(rowSeconds[r]));
    rowStart[r + 1] = rowStart[r] + rowSeconds[r];
  }
  const double total = rowStart[rows];
  const std::size_t all = rows * columns;
  const Rect screenRect{0, 0, screenW, screenH};

  // The steps at which something on the screen changes.
  const double perFrame = o.speed / o.fps;  // drawing seconds a clip frame
  const long last = std::max<long>(1, static_cast<long>(std::ceil(total / perFrame)));
  std::vector<Step> steps{{0, 0, {}}};
  std::size_t drawn = 0;
  for (long k = 1; k <= last && drawn < all; ++k) {
    const std::size_t now =
        k == last ? all
                  : pixelsBy(static_cast<double>(k) * perFrame, rowStart, rowSeconds, columns);
    if (now <= drawn) continue;
    const std::size_t r0 = drawn / columns, r1 = (now - 1) / columns;
    const std::size_t c0 = r0 == r1 ? drawn % columns : 0;
    const std::size_t c1 = r0 == r1 ? (now - 1) % columns + 1 : columns;
    const Rect changed =
        intersect(screenRect, {at.left + static_cast<int>(c0), at.top + static_cast<int>(r0),
                               static_cast<int>(c1 - c0), static_cast<int>(r1 - r0 + 1)});
    drawn = now;
    if (changed.empty()) {  // off the screen (K21's row 768): nothing to show
      if (now == all) steps.back().drawn = all;
      continue;
    }
    steps.push_back({k, now, changed});
  }

  std::vector<GifColour> palette;
  for (const Rgb8& c : colours) palette.push_back({c.r, c.g, c.b});
  io::OutputFile out(path);
  GifFilm gif(out, screenW, screenH, o.loop);
  Screen screen(screenW, screenH);
  IndexedFrame frame;
  frame.palette = palette;
  std::size_t done = 0;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const Step& step = steps[s];
    for (; done < step.drawn; ++done)  // PutPixel(j, i, color), in the listing's order
      screen.putPixel(at.left + static_cast<int>(done % columns),
                      at.top + static_cast<int>(done / columns), graph.pixels[done]);
    const Rect r = s == 0 ? screenRect : step.changed;
    const bool lastStep = s + 1 == steps.size();
    const long delay = lastStep ? std::lround(100.0 * o.holdSeconds)
                                : hundredths(steps[s + 1].k, o.fps) - hundredths(step.k, o.fps);
    frame.width = r.w;
    frame.height = r.h;
    frame.indices.resize(static_cast<std::size_t>(r.w) * static_cast<std::size_t>(r.h));
    for (int y = 0; y < r.h; ++y) {
      const auto row =
          screen.row(r.y + y).subspan(static_cast<std::size_t>(r.x), static_cast<std::size_t>(r.w));
      std::copy(row.begin(), row.end(),
                frame.indices.begin() + static_cast<std::ptrdiff_t>(y) * r.w);
    }
    gif.addFrameAt(frame, r.x, r.y, static_cast<int>(std::min<long>(delay, 65535)));
  }
  gif.close();
  out.commit();
  DrawingRecordSummary summary;
  summary.frames = gif.frames();
  summary.drawingSeconds = total;
  summary.clipSeconds = static_cast<double>(hundredths(steps.back().k, o.fps)) / 100.0 +
                        static_cast<double>(std::lround(100.0 * o.holdSeconds)) / 100.0;
  return summary;
}

}  // namespace prime
