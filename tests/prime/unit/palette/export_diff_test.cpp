// Pictures of graph files (the three areas, true colour), partial graph files,
// and the diff of constructed files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "legacy_io/common/error.h"
#include "palette/prime/export.h"
#include "palette/prime/graph_diff.h"
#include "palette/prime/palettes.h"

namespace prime {
namespace {

io::GraphFile graph(int across, int down, std::int16_t value = 1, std::int16_t type = 1) {
  io::GraphFile g;
  g.graphType = type;
  g.numPixAcross = static_cast<std::int16_t>(across);
  g.numPixDown = static_cast<std::int16_t>(down);
  g.pixels.assign(static_cast<std::size_t>(across + 1) * (down + 1), value);
  return g;
}

Rgb8 pixel(const Image8& img, int x, int y) {
  const std::uint8_t* p = &img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3];
  return {p[0], p[1], p[2]};
}

// Screen colours that are easy to read back: index i -> (i, 255 - i, 7).
Rgb8Table colours() {
  Rgb8Table t{};
  for (int i = 0; i < 256; ++i)
    t[static_cast<std::size_t>(i)] = {static_cast<std::uint8_t>(i),
                                      static_cast<std::uint8_t>(255 - i), 7};
  return t;
}

TEST(ExportImage, ThreeAreasOfTheListingsFile) {
  io::GraphFile g = graph(349, 768, 109);
  g.pixels[0] = -146;  // top-left: index 110 on the screen (Q12)
  g.pixels[349] = 5;   // column 349 of row 0: screen column 1024, off-screen
  g.pixels[static_cast<std::size_t>(768) * 350] = 6;  // row 768: off-screen
  Screen s;
  const Placement at = listingPlacement(1024, 768);
  drawGraph(s, g, at);
  const Rgb8Table c = colours();

  const Image8 image = exportImage(s, g, g.pixels.size(), at, c, ImageArea::Image);
  EXPECT_EQ(image.width, 349);
  EXPECT_EQ(image.height, 768);
  EXPECT_EQ(pixel(image, 0, 0), (Rgb8{110, 145, 7}));
  EXPECT_EQ(pixel(image, 348, 767), (Rgb8{109, 146, 7}));

  const Image8 screen = exportImage(s, g, g.pixels.size(), at, c, ImageArea::Screen);
  EXPECT_EQ(screen.width, 1024);
  EXPECT_EQ(screen.height, 768);
  EXPECT_EQ(pixel(screen, 674, 0), (Rgb8{0, 255, 7}));  // index 0: the cleared screen
  EXPECT_EQ(pixel(screen, 675, 0), (Rgb8{110, 145, 7}));

  const Image8 file = exportImage(s, g, g.pixels.size(), at, c, ImageArea::File);
  EXPECT_EQ(file.width, 350);
  EXPECT_EQ(file.height, 769);
  EXPECT_EQ(pixel(file, 349, 0), (Rgb8{5, 250, 7}));  // the off-screen column is in the file
  EXPECT_EQ(pixel(file, 0, 768), (Rgb8{6, 249, 7}));
  EXPECT_EQ(pixel(file, 0, 0), (Rgb8{110, 145, 7}));

  EXPECT_THROW(exportImage(s, g, g.pixels.size(), {1024, 0}, c, ImageArea::Image),
               std::runtime_error);
  EXPECT_EQ(imageAreaFromName("screen"), ImageArea::Screen);
  EXPECT_FALSE(imageAreaFromName("window").has_value());
}

TEST(ExportImage, PngRoundTrip) {
  const io::GraphFile g = graph(3, 2, 255);
  Screen s(8, 8);
  drawGraph(s, g, {1, 1});
  const Image8 img =
      exportImage(s, g, g.pixels.size(), {1, 1}, present(listingDac()), ImageArea::Screen);
  const auto path = std::filesystem::temp_directory_path() / "prime-export-test.png";
  writePng(path.string(), img);
  const Image8 back = readPng(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(back.width, 8);
  EXPECT_EQ(back.height, 8);
  EXPECT_EQ(back.rgb, img.rgb);
  EXPECT_EQ(pixel(back, 1, 1), (Rgb8{227, 227, 194}));  // listing 255 -> DAC (56, 56, 48)
  EXPECT_EQ(pixel(back, 0, 0), (Rgb8{0, 0, 0}));
  EXPECT_THROW(readPng("/nonexistent.png"), std::runtime_error);
}

// Found by the png_image fuzzer: 52 bytes whose sPLT chunk claims 963071495
// bytes made libpng allocate them before reading the chunk. A chunk longer
// than what is left of the file is refused, at its byte offset, before
// libpng sees the file.
TEST(ExportImage, PngChunkLongerThanTheFileIsRefusedUnread) {
  const std::vector<std::uint8_t> bytes = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49,
      0x48, 0x44, 0x52, 0x00, 0x00, 0x05, 0xff, 0x00, 0x00, 0x06, 0xfe, 0x08, 0x02,
      0x00, 0x00, 0x00, 0x63, 0x48, 0x52, 0x4d, 0x39, 0x67, 0x4e, 0x07, 0x73, 0x50,
      0x4c, 0x54, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78, 0x7a, 0x44};
  try {
    pngFromBytes(bytes, "cut.png");
    FAIL() << "a chunk longer than the file was read";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.where().file, "cut.png");
    EXPECT_EQ(e.where().byte, 33u);
    EXPECT_EQ(e.field(), "chunk 'sPLT' length");
    EXPECT_EQ(e.found(), "963071495 (a cut or damaged file)");
    EXPECT_EQ(std::string(e.what()).rfind("cut.png (byte 33): chunk 'sPLT' length: expected at "
                                          "most 7 bytes",
                                          0),
              0u)
        << e.what();
  }
  // A whole file still reads, from bytes as from its path.
  Image8 one;
  one.width = one.height = 1;
  one.rgb = {10, 20, 30};
  const auto path = std::filesystem::temp_directory_path() / "prime-png-bytes-test.png";
  writePng(path.string(), one);
  const Image8 back = readPng(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(back.rgb, one.rgb);
}

TEST(TrueColour, ClampRoundAndNaN) {
  EXPECT_EQ(trueColour({0, 0.5, 1}), (Rgb8{0, 128, 255}));  // 127.5 rounds away from zero
  EXPECT_EQ(trueColour({-0.2, 1.7, std::nan("")}), (Rgb8{0, 255, 0}));
  EXPECT_EQ(trueColour({0.999999, 1.0 / 255, 0.6 / 255}), (Rgb8{255, 1, 1}));
  const io::GraphFile g = graph(2, 1);  // 3 x 2
  std::vector<Rgb> rgb(6, Rgb{1, 0, 0});
  rgb[5] = {0, 0, 1};
  const Image8 img =
      exportTrueColour(5, 5, g, rgb, {3, 4}, ImageArea::Image);  // only 2 x 1 on screen
  EXPECT_EQ(img.width, 2);
  EXPECT_EQ(img.height, 1);
  const Image8 all = exportTrueColour(5, 5, g, rgb, {3, 4}, ImageArea::File);
  EXPECT_EQ(pixel(all, 2, 1), (Rgb8{0, 0, 255}));
  const Image8 scr = exportTrueColour(5, 5, g, rgb, {3, 4}, ImageArea::Screen);
  EXPECT_EQ(scr.width, 5);
  EXPECT_EQ(pixel(scr, 3, 4), (Rgb8{255, 0, 0}));
  EXPECT_EQ(pixel(scr, 2, 4), (Rgb8{0, 0, 0}));
}

TEST(GraphPrefix, PartialFilesReadWithTheirRowsPresent) {
  const io::GraphFile g = graph(3, 2, 9);  // 4 x 3
  auto bytes = io::toBytes(g);
  const io::GraphFilePrefix whole = io::graphFilePrefixFromBytes(bytes, "g");
  EXPECT_TRUE(whole.complete());
  EXPECT_EQ(whole.pixelsPresent, 12u);
  bytes.resize(6 + 2 * 5);  // header + 5 pixels: row 0 and one of row 1
  const io::GraphFilePrefix part = io::graphFilePrefixFromBytes(bytes, "g");
  EXPECT_FALSE(part.complete());
  EXPECT_EQ(part.pixelsPresent, 5u);
  EXPECT_EQ(part.graph.pixels.size(), 12u);
  EXPECT_EQ(part.graph.pixels[4], 9);
  EXPECT_EQ(part.graph.pixels[5], 0);
  bytes.resize(6);
  EXPECT_EQ(io::graphFilePrefixFromBytes(bytes, "g").pixelsPresent, 0u);
  bytes.resize(4);
  EXPECT_THROW(io::graphFilePrefixFromBytes(bytes, "g"), io::InputError);
  auto longer = io::toBytes(g);
  longer.push_back(0);
  longer.push_back(0);
  EXPECT_THROW(io::graphFilePrefixFromBytes(longer, "g"), io::InputError);
}

TEST(GraphDiff, IdenticalFiles) {
  const io::GraphFile a = graph(9, 4, 109);
  const GraphDiff d = diffGraphs(a, a, present(listingDac()));
  EXPECT_TRUE(d.identical());
  EXPECT_EQ(d.pixels, 50u);
  EXPECT_EQ(d.differing, 0u);
  EXPECT_EQ(d.maxColourDifference, 0);
  EXPECT_EQ(d.firstX, -1);
}

TEST(GraphDiff, CountsShareLargestColourAndLookalikes) {
  const io::GraphFile a = graph(9, 4, 109);  // 10 x 5
  io::GraphFile b = a;
  b.pixels[12] = 110;   // (2, 1): DAC (24,24,16) -> (24,24,32): blue 65 -> 130
  b.pixels[13] = -147;  // (3, 1): -147 & 0xFF = 109: differs in the file, same on the screen
  b.pixels[40] = 8;     // (0, 4): white vs (97, 97, 65): 255 - 65 = 190 in blue
  const GraphDiff d = diffGraphs(a, b, present(listingDac()));
  EXPECT_FALSE(d.identical());
  EXPECT_EQ(d.differing, 3u);
  EXPECT_EQ(d.lookDifferent, 2u);
  EXPECT_DOUBLE_EQ(d.share(), 3.0 / 50.0);
  EXPECT_EQ(d.firstX, 2);
  EXPECT_EQ(d.firstY, 1);
  EXPECT_EQ(d.maxColourDifference, 190);
  EXPECT_EQ(d.maxX, 0);
  EXPECT_EQ(d.maxY, 4);

  const Image8 img = diffImage(a, b, present(listingDac()));
  EXPECT_EQ(img.width, 10);
  EXPECT_EQ(img.height, 5);
  EXPECT_EQ(pixel(img, 2, 1), (Rgb8{255, 0, 255}));
  EXPECT_EQ(pixel(img, 3, 1), (Rgb8{0, 255, 255}));
  // equal pixels: 64 + luma/4 of (97, 97, 65): luma (97*299 + 97*587 + 65*114)/1000 = 93
  EXPECT_EQ(pixel(img, 0, 0), (Rgb8{87, 87, 87}));
}

TEST(GraphDiff, SizeAndGraphTypeDifferences) {
  const io::GraphFile a = graph(9, 4);
  const GraphDiff bySize = diffGraphs(a, graph(4, 9), present(listingDac()));
  EXPECT_FALSE(bySize.sameSize);
  EXPECT_FALSE(bySize.identical());
  EXPECT_EQ(bySize.pixels, 0u);
  EXPECT_THROW(diffImage(a, graph(4, 9), present(listingDac())), std::invalid_argument);
  const GraphDiff byType = diffGraphs(a, graph(9, 4, 1, 0), present(listingDac()));
  EXPECT_TRUE(byType.sameSize);
  EXPECT_FALSE(byType.sameGraphType);
  EXPECT_EQ(byType.differing, 0u);
  EXPECT_FALSE(byType.identical());
}

}  // namespace
}  // namespace prime
