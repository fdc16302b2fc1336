// Screen and graph-file pictures as 8-bit RGB images (for PNG and the diff).
//
// Three areas, one geometry: a graph file drawn at a Placement on a Screen.
//   image   the part of the screen the graph file covers (the default): what a
//           photograph of the 8514/A's monitor shows of the picture. For the
//           listing's 350 x 769 file at (675, 0) that is 349 x 768 pixels,
//           column 1024 and row 768 being off-screen (K21)
//   screen  the whole emulated screen (1024 x 768), as the window shows it
//   file    every pixel the graph file holds (350 x 769), off-screen ones too,
//           each as its `value & 0xFF` index
#pragma once
#include <optional>
#include <span>
#include <string_view>

#include "legacy_io/prime/graph_file.h"
#include "palette/png_image.h"
#include "palette/prime/color_num.h"
#include "palette/prime/dac.h"
#include "palette/prime/screen.h"

namespace prime {

enum class ImageArea { Image, Screen, File };
std::string_view imageAreaName(ImageArea area);  // "image", "screen", "file"
std::optional<ImageArea> imageAreaFromName(std::string_view name);

// The screen's pixels inside `area` (clipped to the screen), through `colours`.
Image8 screenImage(const Screen& screen, const Rgb8Table& colours, Rect area);

// The picture of a graph file that has been drawn on `screen` at `at`. For
// the file area, the first `pixelsPresent` pixels come from the file and the
// rest show index 0 (a partial file). Throws std::runtime_error when the
// image area is empty (the file lies entirely off the screen).
Image8 exportImage(const Screen& screen, const io::GraphFile& graph, std::size_t pixelsPresent,
                   Placement at, const Rgb8Table& colours, ImageArea area);
// The same picture as the screen holds it: its palette indices (each the
// graph file's `value & 0xFF`, Q12), with `colours` as the 256-entry palette
// (exportImage is this picture's colours).
IndexedImage8 exportIndexed(const Screen& screen, const io::GraphFile& graph,
                            std::size_t pixelsPresent, Placement at, const Rgb8Table& colours,
                            ImageArea area);
// The palette of an indexed PNG: the 256 colours in index order.
std::vector<std::uint8_t> pngPalette(const Rgb8Table& colours);

// One unquantised colour on an 8-bit display: each channel clamped to 0..1
// and rounded to the nearest of 0..255; NaN is 0.
Rgb8 trueColour(const Rgb& colour);
// The render's unquantised colours (`rgb`, one per graph-file pixel, same
// order) over the same area as exportImage; the rest of a screen-area image
// is black.
Image8 exportTrueColour(int screenWidth, int screenHeight, const io::GraphFile& graph,
                        std::span<const Rgb> rgb, Placement at, ImageArea area);

}  // namespace prime
