#include "palette/prime/graph_diff.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace prime {

namespace {

const Rgb8& colourOf(const Rgb8Table& colours, std::int16_t value) {
  return colours[static_cast<std::size_t>(value & 0xFF)];  // Q12
}

int channelDifference(const Rgb8& p, const Rgb8& q) {
  return std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)});
}

}  // namespace

GraphDiff diffGraphs(const io::GraphFile& a, const io::GraphFile& b, const Rgb8Table& colours) {
  GraphDiff d;
  d.sameGraphType = a.graphType == b.graphType;
  d.sameSize =
      a.width() == b.width() && a.height() == b.height() && a.pixels.size() == b.pixels.size();
  if (!d.sameSize) return d;
  d.pixels = a.pixels.size();
  const std::size_t w = static_cast<std::size_t>(std::max(1, a.width()));
  for (std::size_t i = 0; i < d.pixels; ++i) {
    if (a.pixels[i] == b.pixels[i]) continue;
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    if (d.differing++ == 0) {
      d.firstX = x;
      d.firstY = y;
    }
    const int diff =
        channelDifference(colourOf(colours, a.pixels[i]), colourOf(colours, b.pixels[i]));
    if (diff > 0) ++d.lookDifferent;
    if (diff > d.maxColourDifference) {
      d.maxColourDifference = diff;
      d.maxX = x;
      d.maxY = y;
    }
  }
  return d;
}

Image8 diffImage(const io::GraphFile& a, const io::GraphFile& b, const Rgb8Table& colours) {
  if (a.width() != b.width() || a.height() != b.height() || a.pixels.size() != b.pixels.size())
    throw std::invalid_argument("diffImage: the graph files differ in size");
  Image8 img;
  img.width = a.width();
  img.height = a.height();
  img.rgb.resize(a.pixels.size() * 3);
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const Rgb8& ca = colourOf(colours, a.pixels[i]);
    Rgb8 out;
    if (a.pixels[i] == b.pixels[i]) {
      const int luma = (ca.r * 299 + ca.g * 587 + ca.b * 114) / 1000;
      const auto grey = static_cast<std::uint8_t>(64 + luma / 4);
      out = {grey, grey, grey};
    } else if (channelDifference(ca, colourOf(colours, b.pixels[i])) > 0) {
      out = {255, 0, 255};
    } else {
      out = {0, 255, 255};
    }
    img.rgb[i * 3] = out.r;
    img.rgb[i * 3 + 1] = out.g;
    img.rgb[i * 3 + 2] = out.b;
  }
  return img;
}

}  // namespace prime
