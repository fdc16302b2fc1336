// raster2ppm (legacy_io/malone/ppm.h): the P6 header and bytes, the byte
// rule round(255 * clamp(v, 0, 1)) (notes section 3.3), and a write/read round trip.
#include "legacy_io/malone/ppm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "legacy_io/common/error.h"
#include "tests/support/temp_dir.h"

namespace prime::malone {
namespace {

TEST(MalonePpm, ByteRule) {
  EXPECT_EQ(toByte(0.0), 0);
  EXPECT_EQ(toByte(0.5), 128);  // 127.5 + 0.5 = 128
  EXPECT_EQ(toByte(1.0), 255);
  EXPECT_EQ(toByte(1.0 / 255), 1);     // 1 + 0.5 -> 1
  EXPECT_EQ(toByte(0.25), 64);         // 63.75 + 0.5 = 64.25 -> 64
  EXPECT_EQ(toByte(0.026375), 7);      // the document scene's centre: 6.73 + 0.5 -> 7
  EXPECT_EQ(toByte(0.0019), 0);        // 0.4845 + 0.5 = 0.9845 -> 0
  EXPECT_EQ(toByte(0.002), 1);         // 0.51 + 0.5 = 1.01 -> 1
  EXPECT_EQ(toByte(-0.5), 0);          // clamped
  EXPECT_EQ(toByte(7.0), 255);         // clamped
  EXPECT_EQ(toByte(std::nan("")), 0);  // NaN: 0
  EXPECT_EQ(toByte(-std::numeric_limits<double>::infinity()), 0);
  EXPECT_EQ(toByte(std::numeric_limits<double>::infinity()), 255);
}

TEST(MalonePpm, HeaderAndBytes) {
  RgbImage image;
  image.assign(2, 1);
  image.at(0, 0) = {0.0, 0.5, 1.0};
  image.at(0, 1) = {-1.0, std::nan(""), 2.0};
  const std::vector<std::uint8_t> bytes = ppmBytes(image);
  const std::string header = "P6\n2 1\n255\n";
  ASSERT_EQ(bytes.size(), header.size() + 6);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + header.size()), header);
  const std::vector<std::uint8_t> pixels(bytes.begin() + header.size(), bytes.end());
  EXPECT_EQ(pixels, (std::vector<std::uint8_t>{0, 128, 255, 0, 0, 255}));
}

TEST(MalonePpm, RowsFromTheTop) {
  RgbImage image;
  image.assign(1, 2);
  image.at(0, 0) = {1, 1, 1};  // the top row first
  const std::vector<std::uint8_t> bytes = ppmBytes(image);
  const std::size_t h = std::string("P6\n1 2\n255\n").size();
  EXPECT_EQ(bytes[h], 255);
  EXPECT_EQ(bytes[h + 3], 0);
}

TEST(MalonePpm, WriteReadRoundTrip) {
  const test::TempDir dir("malone-ppm-");
  const std::string path = (dir / "out.ppm").string();
  RgbImage image;
  image.assign(5, 3);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (auto& p : image.pixels) p = {u(gen), u(gen), u(gen)};
  writePpm(path, image);
  const RgbImage back = readPpm(path);
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      // What was written is the byte; what is read is byte / 255.
      const double v = image.pixels[i][k];
      const double clamped = v < 0 ? 0 : v > 1 ? 1 : v;
      EXPECT_EQ(back.pixels[i][k], std::floor(255 * clamped + 0.5) / 255.0);
    }
  // A second write of what was read gives the same bytes.
  EXPECT_EQ(ppmBytes(back), ppmBytes(image));
}

TEST(MalonePpm, ReadRefusesOtherFormats) {
  const test::TempDir dir("malone-ppm-");
  const std::string path = (dir / "p3.ppm").string();
  { std::ofstream(path, std::ios::binary) << "P3\n1 1\n255\n0 0 0\n"; }
  EXPECT_THROW(readPpm(path), io::InputError);
  {
    std::ofstream(path, std::ios::binary) << "P6\n2 2\n255\nabc";  // 12 bytes needed
  }
  try {
    readPpm(path);
    ADD_FAILURE() << "short file read";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.field(), "pixels");
    EXPECT_EQ(e.found(), "3 bytes");
  }
}

}  // namespace
}  // namespace prime::malone
