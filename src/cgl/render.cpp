#include "src/cgl/render.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstring>
#include <string>

namespace prime::cgl {

TraceSettings traceSettings(const RenderSettings& settings) {
  TraceSettings t;
  t.depth = settings.program.depth;
  t.shadows = settings.program.shadows;
  t.background = settings.program.background;
  t.phosphors = settings.phosphors;
  t.epsilon = settings.epsilon;
  t.linearSearch = settings.linearSearch;
  return t;
}

namespace {

constexpr int kSub = 8;  // corner lattice: eighths of a pixel (aalevel 8's finest squares)

void checkSettings(const Scene& scene, const ProgramParameters& p) {
  io::InputLocation where;
  where.file = scene.path;
  auto inRange = [&](int v, const char* name) {
    if (v < 0 || v > 511) throw io::InputError(where, name, "0..511", std::to_string(v));
  };
  inRange(p.xleft, "xleft");
  inRange(p.xright, "xright");
  inRange(p.ylow, "ylow");
  inRange(p.yhigh, "yhigh");
  if (p.xleft > p.xright)
    throw io::InputError(where, "xleft/xright", "xleft <= xright",
                         std::to_string(p.xleft) + " > " + std::to_string(p.xright));
  if (p.ylow > p.yhigh)
    throw io::InputError(where, "ylow/yhigh", "ylow <= yhigh",
                         std::to_string(p.ylow) + " > " + std::to_string(p.yhigh));
  if (p.aalevel != 0 && p.aalevel != 1 && p.aalevel != 2 && p.aalevel != 4 && p.aalevel != 8)
    throw io::InputError(where, "aalevel", "0, 1, 2, 4 or 8", std::to_string(p.aalevel));
}

// One thread's corner table: the corners of the current scanline's strip
// (pixel row y: corners from y + 1 down to y), on the lattice of eighths of
// a pixel. When the thread's next scanline is the one just below, the
// strip's lower edge becomes the new strip's upper edge (CGL-D40): with one
// thread every distinct corner is traced exactly once. A corner's colour
// depends on its coordinates only, so the bytes do not depend on which
// thread traced it.
class CornerTable {
 public:
  CornerTable(const Tracer& tracer, const ProgramParameters& p, bool record)
      : tracer_(tracer),
        xleft_(p.xleft),
        columns_((p.xright - p.xleft + 1) * kSub + 1),
        threshold_(p.aathreshold),
        aalevel_(p.aalevel),
        record_(record),
        colour_(static_cast<std::size_t>(columns_) * (kSub + 1)),
        have_(static_cast<std::size_t>(columns_) * (kSub + 1), 0) {}

  void startScanline(int y) {
    if (y + 1 == scanline_) {
      // The old lower edge (row kSub) is the new upper edge (row 0).
      std::copy_n(colour_.begin() + static_cast<std::ptrdiff_t>(kSub) * columns_, columns_,
                  colour_.begin());
      std::copy_n(have_.begin() + static_cast<std::ptrdiff_t>(kSub) * columns_, columns_,
                  have_.begin());
      std::fill(have_.begin() + columns_, have_.end(), 0);
    } else {
      std::fill(have_.begin(), have_.end(), 0);
    }
    scanline_ = y;
  }

  // Figure 44: Subdivid(x, y + 1.0, x + 1.0, y, aalevel).
  Rgb8 pixel(int x, TraceStats& stats) {
    const int ix = (x - xleft_) * kSub;
    return subdivide(ix, 0, ix + kSub, kSub, aalevel_, stats);
  }

  std::vector<std::pair<int, int>> corners;

 private:
  const Rgb8& corner(int ix, int iy, TraceStats& stats) {
    const std::size_t at = static_cast<std::size_t>(iy) * columns_ + ix;
    if (!have_[at]) {
      const double x = xleft_ + static_cast<double>(ix) / kSub;
      const double y = (scanline_ + 1) - static_cast<double>(iy) / kSub;
      colour_[at] = tracer_.screenPoint(x, y, stats);
      have_[at] = 1;
      if (record_) corners.emplace_back(xleft_ * kSub + ix, (scanline_ + 1) * kSub - iy);
    }
    return colour_[at];
  }

  // Corners as lattice indices: ix from xleft, iy from the strip's top.
  Rgb8 subdivide(int xl, int yu, int xr, int yl, int level, TraceStats& stats) {
    Rgb8 ul = corner(xl, yu, stats), ur = corner(xr, yu, stats), ll = corner(xl, yl, stats),
         lr = corner(xr, yl, stats);
    level /= 2;
    if (level > 0 && difference(ul, ur, ll, lr) > threshold_) {
      const int xm = (xl + xr) / 2, ym = (yu + yl) / 2;
      ul = subdivide(xl, yu, xm, ym, level, stats);
      ur = subdivide(xm, yu, xr, ym, level, stats);
      ll = subdivide(xl, ym, xm, yl, level, stats);  // CGL-E41: printed (xmid, ymid, xmid, ylower)
      lr = subdivide(xm, ym, xr, yl, level, stats);
    }
    // CGL-Q52: the average of four rgb values, each channel summed and
    // divided by 4 in integers (truncated, as C does with int fields).
    return Rgb8{(ul.r + ur.r + ll.r + lr.r) / 4, (ul.g + ur.g + ll.g + lr.g) / 4,
                (ul.b + ur.b + ll.b + lr.b) / 4};
  }

  // CGL-Q53: "the sum of the differences in their red, green and blue
  // components": per channel max - min over the four corners, summed.
  static double difference(const Rgb8& a, const Rgb8& b, const Rgb8& c, const Rgb8& d) {
    auto spread = [](int p, int q, int r, int s) {
      return std::max({p, q, r, s}) - std::min({p, q, r, s});
    };
    return spread(a.r, b.r, c.r, d.r) + spread(a.g, b.g, c.g, d.g) + spread(a.b, b.b, c.b, d.b);
  }

  const Tracer& tracer_;
  int xleft_, columns_;
  double threshold_;
  int aalevel_;
  bool record_;
  int scanline_ = INT_MIN;
  std::vector<Rgb8> colour_;
  std::vector<unsigned char> have_;
};

}  // namespace

RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const RenderCallbacks& callbacks) {
  const ProgramParameters& p = settings.program;
  checkSettings(scene, p);
  const auto start = std::chrono::steady_clock::now();
  const Tracer tracer(scene, traceSettings(settings));
  RenderResult result;
  result.setupSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The doubles are for a live window only: 6 MiB written for nothing
  // otherwise (most of a small render's page faults).
  const bool keepImage = static_cast<bool>(callbacks.rowDone);
  if (keepImage) result.image.assign(Frame::kSize, Frame::kSize);

  const int rows = p.yhigh - p.ylow + 1;
  const int threads = threadCount(settings.threads, rows);
  std::vector<ThreadSlot<TraceStats>> perThread(static_cast<std::size_t>(threads));
  std::vector<CornerTable> tables;
  if (p.aalevel > 0)
    for (int t = 0; t < threads; ++t) tables.emplace_back(tracer, p, settings.recordCorners);
  std::vector<std::vector<std::pair<int, int>>> plainCorners(static_cast<std::size_t>(threads));

  RowCallbacks rowCallbacks;
  rowCallbacks.progress = callbacks.progress;
  rowCallbacks.abort = callbacks.abort;
  // A band of the frame's rows from the top: render row r is the frame's
  // row 511 - yhigh + r.
  const int top = Frame::kSize - 1 - p.yhigh;
  rowCallbacks.first = std::max(0, callbacks.firstRow - top);
  rowCallbacks.last = callbacks.lastRow < 0 ? -1 : callbacks.lastRow - top;
  if (callbacks.lastRow >= 0 && rowCallbacks.last < 0) rowCallbacks.first = rows;  // above it
  if (callbacks.rowDone)
    rowCallbacks.rowDone = [&](int row) {
      const int imageRow = Frame::kSize - 1 - (p.yhigh - row);
      callbacks.rowDone(imageRow, std::span<const Rgb>(&result.image.at(imageRow, 0),
                                                       static_cast<std::size_t>(Frame::kSize)));
    };
  result.run = renderRows(
      rows, threads,
      [&](int row, int thread) -> std::uint64_t {
        TraceStats& stats = perThread[static_cast<std::size_t>(thread)].value;
        const std::uint64_t before = stats.rays.rays();
        const int y = p.yhigh - row;  // "Images are rendered from the top down"
        const int imageRow = Frame::kSize - 1 - y;
        if (!tables.empty()) tables[static_cast<std::size_t>(thread)].startScanline(y);
        for (int x = p.xleft; x <= p.xright; ++x) {
          checkAbort(callbacks.abort);  // R9
          Rgb8 c;
          if (tables.empty()) {
            // Figure 41 (CGL-Q1): one ray through the pixel's corner (x, y).
            c = tracer.screenPoint(x, y, stats);
            if (settings.recordCorners)
              plainCorners[static_cast<std::size_t>(thread)].emplace_back(x * kSub, y * kSub);
          } else {
            c = tables[static_cast<std::size_t>(thread)].pixel(x, stats);
          }
          result.frame.at(y, x) = packPixel(c.r, c.g, c.b);
          if (keepImage) result.image.at(imageRow, x) = Rgb{c.r / 255.0, c.g / 255.0, c.b / 255.0};
        }
        return stats.rays.rays() - before;
      },
      rowCallbacks);
  for (const auto& s : perThread) result.stats += s.value;
  if (settings.recordCorners) {
    for (auto& t : tables)
      result.corners.insert(result.corners.end(), t.corners.begin(), t.corners.end());
    for (auto& c : plainCorners) result.corners.insert(result.corners.end(), c.begin(), c.end());
  }
  return result;
}

ProbeReport probe(const Scene& scene, const RenderSettings& settings, double x, double y) {
  // The probe walks the object list as printed: its "shadowed by" names the
  // first opaque object of the list in the way.
  TraceSettings ts = traceSettings(settings);
  ts.linearSearch = true;
  const Tracer tracer(scene, ts);
  ProbeReport report;
  TraceStats stats;
  tracer.screenPoint(x, y, stats, &report);
  return report;
}

}  // namespace prime::cgl
