#include "palette/prime/export.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "src/render/rgb_image.h"

namespace prime {

namespace {

Image8 blank(int w, int h) {
  Image8 img;
  img.width = w;
  img.height = h;
  img.rgb.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0);
  return img;
}

void set(Image8& img, int x, int y, Rgb8 c) {
  std::uint8_t* p =
      &img.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + x) * 3];
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}

Rect imageAreaOrThrow(int screenWidth, int screenHeight, const io::GraphFile& graph, Placement at) {
  const Rect area = intersect({0, 0, screenWidth, screenHeight},
                              {at.left, at.top, graph.width(), graph.height()});
  if (area.empty())
    throw std::runtime_error("the " + std::to_string(graph.width()) + " x " +
                             std::to_string(graph.height()) + " image at (" +
                             std::to_string(at.left) + ", " + std::to_string(at.top) +
                             ") lies entirely off the " + std::to_string(screenWidth) + " x " +
                             std::to_string(screenHeight) + " screen; use --area file or --at");
  return area;
}

}  // namespace

std::string_view imageAreaName(ImageArea area) {
  switch (area) {
    case ImageArea::Screen:
      return "screen";
    case ImageArea::File:
      return "file";
    case ImageArea::Image:
      break;
  }
  return "image";
}

std::optional<ImageArea> imageAreaFromName(std::string_view name) {
  for (ImageArea a : {ImageArea::Image, ImageArea::Screen, ImageArea::File})
    if (name == imageAreaName(a)) return a;
  return std::nullopt;
}

std::vector<std::uint8_t> pngPalette(const Rgb8Table& colours) {
  std::vector<std::uint8_t> out;
  out.reserve(colours.size() * 3);
  for (const Rgb8& c : colours) out.insert(out.end(), {c.r, c.g, c.b});
  return out;
}

namespace {

IndexedImage8 screenIndices(const Screen& screen, Rect area) {
  area = intersect(area, screen.bounds());
  IndexedImage8 img;
  img.width = area.w;
  img.height = area.h;
  img.indices.reserve(static_cast<std::size_t>(area.w) * static_cast<std::size_t>(area.h));
  for (int y = 0; y < area.h; ++y) {
    const auto row =
        screen.row(area.y + y)
            .subspan(static_cast<std::size_t>(area.x), static_cast<std::size_t>(area.w));
    img.indices.insert(img.indices.end(), row.begin(), row.end());
  }
  return img;
}

}  // namespace

Image8 screenImage(const Screen& screen, const Rgb8Table& colours, Rect area) {
  IndexedImage8 img = screenIndices(screen, area);
  img.palette = pngPalette(colours);
  return colourImage(img);
}

IndexedImage8 exportIndexed(const Screen& screen, const io::GraphFile& graph,
                            std::size_t pixelsPresent, Placement at, const Rgb8Table& colours,
                            ImageArea area) {
  IndexedImage8 img;
  switch (area) {
    case ImageArea::Screen:
      img = screenIndices(screen, screen.bounds());
      break;
    case ImageArea::File:
      img.width = graph.width();
      img.height = graph.height();
      img.indices.resize(graph.pixels.size());
      for (std::size_t i = 0; i < graph.pixels.size(); ++i)
        img.indices[i] =
            i < pixelsPresent ? static_cast<std::uint8_t>(graph.pixels[i] & 0xFF) : 0;  // Q12
      break;
    case ImageArea::Image:
      img = screenIndices(screen, imageAreaOrThrow(screen.width(), screen.height(), graph, at));
      break;
  }
  img.palette = pngPalette(colours);
  return img;
}

Image8 exportImage(const Screen& screen, const io::GraphFile& graph, std::size_t pixelsPresent,
                   Placement at, const Rgb8Table& colours, ImageArea area) {
  return colourImage(exportIndexed(screen, graph, pixelsPresent, at, colours, area));
}

Rgb8 trueColour(const Rgb& c) {
  return {channelByte(c[0]), channelByte(c[1]), channelByte(c[2])};
}

Image8 exportTrueColour(int screenWidth, int screenHeight, const io::GraphFile& graph,
                        std::span<const Rgb> rgb, Placement at, ImageArea area) {
  const int gw = graph.width(), gh = graph.height();
  if (rgb.size() != static_cast<std::size_t>(gw) * static_cast<std::size_t>(gh))
    throw std::invalid_argument("exportTrueColour: one colour per graph-file pixel expected");
  auto colourAt = [&](int gx, int gy) {
    return trueColour(rgb[static_cast<std::size_t>(gy) * gw + gx]);
  };
  if (area == ImageArea::File) {
    Image8 img = blank(gw, gh);
    for (int y = 0; y < gh; ++y)
      for (int x = 0; x < gw; ++x) set(img, x, y, colourAt(x, y));
    return img;
  }
  const Rect on = imageAreaOrThrow(screenWidth, screenHeight, graph, at);
  const Rect frame = area == ImageArea::Screen ? Rect{0, 0, screenWidth, screenHeight} : on;
  Image8 img = blank(frame.w, frame.h);
  for (int y = on.y; y < on.y + on.h; ++y)
    for (int x = on.x; x < on.x + on.w; ++x)
      set(img, x - frame.x, y - frame.y, colourAt(x - at.left, y - at.top));
  return img;
}

}  // namespace prime
