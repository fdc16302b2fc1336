// graph_scr: the rendered screen as RayTrace.c writes it (lines 7119-7137):
// int graphType, int numPixAcross, int numPixDown, then one 16-bit palette
// index per pixel, row by row. The listing's loops are inclusive (K21, K22),
// so the file holds (numPixAcross+1) x (numPixDown+1) pixels, one more in each
// direction than the header says. Both that and an exact-count file are read;
// `inclusive` records which, and writing reproduces it.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "legacy_io/prime/turbo_c.h"
#include "src/render/picture_buffer.h"

namespace prime::io {

struct GraphFile {
  std::int16_t graphType = 1;                     // 0 = VGA (DETECT), 1 = IBM8514HI
  std::int16_t numPixAcross = 0, numPixDown = 0;  // header values, as written
  bool inclusive = true;                          // pixel grid is (across+1) x (down+1)
  LargeBuffer<std::int16_t> pixels;               // raw 16-bit values (Q12: not masked)

  int width() const { return numPixAcross + (inclusive ? 1 : 0); }
  int height() const { return numPixDown + (inclusive ? 1 : 0); }
  std::int16_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width() + x]; }
};

std::vector<std::uint8_t> toBytes(const GraphFile& f);
// What kind of picture `bytes` begin like ("a PNG picture"), or nullopt: the
// graph-file readers refuse such a file naming it, rather than reading its
// bytes as a header and pixels.
std::optional<std::string> pictureKindOf(std::span<const std::uint8_t> bytes);
GraphFile graphFileFromBytes(std::span<const std::uint8_t> bytes, const std::string& name);
GraphFile readGraphFile(const std::string& path);

// A graph file that may stop early: the `.partial` file an aborted
// `prime trace` leaves (docs/prime/palette.md), or a graph_scr cut short the way the
// listing's exit(1) in ExitOnEsc left it. The header, then as many whole
// pixels as there are, in the listing's inclusive layout. A complete file
// reads exactly as readGraphFile reads it; a longer one is the same error.
struct GraphFilePrefix {
  GraphFile graph;                // all width() x height() pixels; the missing ones are 0
  std::size_t pixelsPresent = 0;  // how many the file holds
  bool complete() const { return pixelsPresent == graph.pixels.size(); }
};
GraphFilePrefix graphFilePrefixFromBytes(std::span<const std::uint8_t> bytes,
                                         const std::string& name);
GraphFilePrefix readGraphFilePrefix(const std::string& path);
void writeGraphFile(const std::string& path, const GraphFile& f);
// toBytes(f) handed to `piece` in consecutive pieces, without building it:
// on a little-endian host the pixels are their own file bytes (the header,
// then the pixel array as it is in memory); elsewhere they are converted a
// block at a time. For writing and hashing a full-size picture.
void forEachGraphFileBytes(const GraphFile& f,
                           const std::function<void(std::span<const std::uint8_t>)>& piece);
// The file bytes of a run of pixels (a row, or all of them), the same way.
void forEachPixelBytes(std::span<const std::int16_t> pixels,
                       const std::function<void(std::span<const std::uint8_t>)>& piece);

}  // namespace prime::io
