// A small chart renderer for the benchmark figures, drawn into an Image8
// (palette/png_image.h) without any plotting library: axes with decade or
// 1-2-5 ticks, labels in a built-in 3x5 bitmap font (upper case, digits and a
// few signs), dots, polylines and hollow square markers, and a legend.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "palette/png_image.h"

namespace prime::bench {

using Colour = std::array<std::uint8_t, 3>;

struct PlotPoint {
  double x = 0, y = 0;
};

struct Series {
  std::string name;
  Colour colour{0, 0, 0};
  std::vector<PlotPoint> dots;    // small filled dots
  std::vector<PlotPoint> line;    // a polyline, drawn in the given order
  std::vector<PlotPoint> marked;  // hollow squares (e.g. the Pareto front)
  bool dashed = false;            // draw `line` dashed
};

struct PlotSpec {
  std::string title, xLabel, yLabel;
  bool logX = true, logY = true;
  // On a log axis, values at or below this are drawn at it (0: the smallest
  // positive value). Lets zero errors show at the bottom of the chart.
  double xFloor = 0, yFloor = 0;
  bool yFromZero = false;  // a linear y axis starts at 0
  int width = 960, height = 640;
  std::vector<std::string> notes;  // extra legend lines (no marker)
};

Image8 drawPlot(const PlotSpec& spec, std::span<const Series> series);

// A distinct colour for series number i (cycles after 12).
Colour seriesColour(int i);

// Draws `text` with its top-left corner at (x, y), each font pixel `scale`
// pixels wide; lower case is drawn as upper case, unknown characters as a
// box. Returns the width drawn. Exposed for tests.
int drawText(Image8& image, int x, int y, const std::string& text, Colour colour, int scale = 2);
int textWidth(const std::string& text, int scale = 2);

// Tick label of a decade 10^e: "0.001" .. "1000", else "1E-4", "1E5".
std::string decadeLabel(int e);

}  // namespace prime::bench
